#include "app/options.h"

#include <cstdio>
#include <set>
#include <sstream>

#include "app/scene_overrides.h"
#include "error.h"
#include "render/presets.h"
#include "render/setting_table.h"
#include "scene/load.h"

namespace vct {
namespace {

void applyPreset(const OptionValue& value, RenderSettings& settings) {
    const std::optional<RenderSettings> preset = findRenderPreset(value.text());
    if (!preset) throw Error("--preset must be one of " + presetNameList() + ", not '" + value.text() + "'");
    settings = *preset;
}

void applyDisabled(const OptionValue& value, RenderSettings& settings) {
    std::istringstream disabled(value.text());
    for (std::string name; std::getline(disabled, name, ',');) {
        if (name.empty()) continue;
        bool known = false;
        for (const ComponentInfo& component : componentTable()) {
            if (name != component.option) continue;
            settings.shading.components.*component.member = false;
            known = true;
        }
        if (!known) throw Error("--disable: unknown component '" + name + "'");
    }
}

std::string componentOptionNames() {
    std::string names;
    for (const ComponentInfo& component : componentTable())
        names += (names.empty() ? "" : ",") + std::string(component.option);
    return names;
}

// A setting's row as an option: its help says what it takes unless its shape lists it.
Option settingOption(const SettingRow& row) {
    const std::string domain = row.namesOnly ? "" : "; " + settingDomain(row);
    return {
        row.option, row.shape, row.help + domain,
        [&row](const OptionValue& value, RenderSettings& settings) {
            const std::string text = value.text();
            const std::optional<double> parsed = parseSetting(row, text);
            if (!parsed)
                throw Error("--" + std::string(row.option) + " must be " + settingDomain(row) + ", not '" + text + "'");
            row.set(settings, *parsed);
        },
        [&row](const RenderSettings& settings) { return settingText(row, settings); }};
}

std::vector<Option> makeSharedOptions() {
    std::string sceneNames;
    for (const std::string& name : builtinSceneNames()) sceneNames += " " + name;
    std::vector<Option> options = {{"preset", "NAME",
                                    "start from a preset (" + presetNameList() + "); the options below override it",
                                    applyPreset}};
    // The render settings, from their table (src/render/setting_table.h).
    for (const SettingRow& row : settingTable()) {
        options.push_back(settingOption(row));
        if (row.option == std::string("mode"))
            options.push_back({"disable", "LIST",
                               "components to switch off, comma-separated: " + componentOptionNames(), applyDisabled});
    }
    options.push_back({"scene", "FILE|NAME", "a .gltf/.glb file or a built-in scene (default cornell):" + sceneNames});
    // The camera, sun and sky, from their table (app/scene_overrides.h).
    for (const SceneOverrideRow& row : sceneOverrideTable()) options.push_back({row.option, row.shape, row.help});
    const std::vector<Option> device = {
        {"device", "NAME", "use the Vulkan device whose name contains NAME (or $VCT_DEVICE)"},
        {"validate", "", "enable the Khronos validation layer"},
        {"strict", "", "treat scene warnings (e.g. a missing texture) as errors"},
        {"allowed-root", "DIR", "let the scene's URIs reach files under DIR (default: its folder)"},
        {"gpu-timeout", "SECONDS", "longest wait for the GPU before giving up (default 120)"},
    };
    options.insert(options.end(), device.begin(), device.end());
    return options;
}

}  // namespace

const std::vector<Option>& sharedOptions() {
    static const std::vector<Option> options = makeSharedOptions();
    return options;
}

const Option& sharedOption(const std::string& name) {
    for (const Option& option : sharedOptions())
        if (option.name == name) return option;
    throw std::out_of_range("no shared option --" + name);
}

std::string presetsHelp() {
    std::string help =
        "\npresets (--preset NAME; the committed bench run: a still frame at 128x128 on lavapipe, 2 cores,\n"
        "and the relMSE of full light against the path tracer, over the built-in scenes):\n";
    for (const PresetSummary& preset : presetSummaries()) {
        char line[256];
        const std::string name = std::string(preset.name) + (preset.name == std::string(kDefaultPreset) ? " *" : "");
        std::snprintf(line, sizeof line, "  %-11s %6.1f ms  relMSE %.3f  %s\n", name.c_str(), preset.stillFrameMs,
                      preset.fullRelMse, preset.what);
        help += line;
    }
    return help + "  (* the default)\n";
}

std::string versionText() { return std::string("vct ") + VCT_VERSION; }

Arguments parseArguments(const std::vector<std::string>& arguments, const std::vector<Option>& options) {
    std::set<std::string> flags = {"help", "version"}, valued;
    for (const Option& option : options) (option.value.empty() ? flags : valued).insert(option.name);
    return Arguments(arguments, flags, valued);
}

std::string optionsHelp(const std::vector<Option>& options, const RenderSettings& defaults) {
    std::string help;
    for (const Option& option : options) {
        std::string left = "  --" + option.name + (option.value.empty() ? "" : " " + option.value);
        left.resize(std::max<size_t>(left.size() + 1, 27), ' ');
        help += left + option.help;
        if (option.show) help += " (default " + option.show(defaults) + ")";
        help += "\n";
    }
    return help;
}

bool answerHelpOrVersion(const Arguments& arguments, const std::string& usage, const std::vector<Option>& options,
                         const RenderSettings& defaults, const std::string& footer) {
    if (arguments.has("help")) {
        const std::vector<Option> always = {{"help", "", "this help (also -h)"},
                                            {"version", "", "print the version of vct and exit"}};
        std::printf("usage: %s\n\n%s%s%s", usage.c_str(), optionsHelp(options, defaults).c_str(),
                    optionsHelp(always, defaults).c_str(), footer.c_str());
        return true;
    }
    if (arguments.has("version")) {
        std::printf("%s\n", versionText().c_str());
        return true;
    }
    return false;
}

RenderSettings renderSettingsFromArguments(const Arguments& arguments, const std::vector<Option>& options,
                                           RenderSettings defaults) {
    for (const Option& option : options)
        if (option.apply && arguments.has(option.name)) option.apply(OptionValue{arguments, option.name}, defaults);
    return defaults;
}

}  // namespace vct
