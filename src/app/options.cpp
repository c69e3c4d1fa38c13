#include "app/options.h"

#include <cstdio>
#include <set>
#include <sstream>

#include "error.h"
#include "render/presets.h"
#include "scene/load.h"

namespace vct {
namespace {

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

void applyPreset(const OptionValue& value, RenderSettings& settings) {
    const std::optional<RenderSettings> preset = findRenderPreset(value.text());
    if (!preset) throw Error("--preset must be one of " + presetNameList() + ", not '" + value.text() + "'");
    settings = *preset;
}

void applyMode(const OptionValue& value, RenderSettings& settings) {
    const std::optional<RenderMode> mode = parseRenderMode(value.text());
    if (!mode) throw Error("--mode must be full, direct or indirect, not '" + value.text() + "'");
    settings.shading.mode = *mode;
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

std::vector<Option> makeSharedOptions() {
    using S = RenderSettings;
    using V = OptionValue;
    std::string sceneNames;
    for (const std::string& name : builtinSceneNames()) sceneNames += " " + name;
    return {
        {"preset", "NAME", "start from a preset (" + presetNameList() + "); the options below override it",
         applyPreset},
        {"width", "W", "image width in pixels", [](const V& v, S& s) { s.image.width = v.whole(1, 16384); },
         [](const S& s) { return std::to_string(s.image.width); }},
        {"height", "H", "image height in pixels", [](const V& v, S& s) { s.image.height = v.whole(1, 16384); },
         [](const S& s) { return std::to_string(s.image.height); }},
        {"supersample", "N", "samples per pixel side, averaged over the pixel",
         [](const V& v, S& s) { s.image.supersample = v.whole(1, 8); },
         [](const S& s) { return std::to_string(s.image.supersample); }},
        {"diffuse-resolution", "full|half|quarter",
         "diffuse cones for every sample, or for one in 2×2 or 4×4, upsampled along the surfaces",
         [](const V& v, S& s) {
             const std::string& text = v.text();
             if (text != "full" && text != "half" && text != "quarter")
                 throw Error("--diffuse-resolution must be full, half or quarter, not '" + text + "'");
             s.image.diffuseDownscale = text == "full" ? 1u : text == "half" ? 2u : 4u;
         },
         [](const S& s) { return diffuseResolutionName(s.image.diffuseDownscale); }},
        {"mode", "full|direct|indirect", "which light the image holds", applyMode,
         [](const S& s) { return std::string(renderModeName(s.shading.mode)); }},
        {"disable", "LIST", "components to switch off, comma-separated: " + componentOptionNames(), applyDisabled},
        {"ambient", "F", "non-physical ambient light factor",
         [](const V& v, S& s) { s.shading.ambientFactor = v.number(0.0f, 1e6f); },
         [](const S& s) { return number(s.shading.ambientFactor); }},
        {"voxels", "N", "voxels per side of the grid, a power of two 32..512",
         [](const V& v, S& s) {
             const uint32_t resolution = v.whole(32, 512);
             // Checked here too, not only by the renderer: before the scene loads or the device opens.
             if ((resolution & (resolution - 1)) != 0)
                 throw Error("--voxels: the voxel resolution must be a power of two from 32 to 512, not " +
                             std::to_string(resolution));
             s.resources.voxelResolution = resolution;
         },
         [](const S& s) { return std::to_string(s.resources.voxelResolution); }},
        {"voxel-mips", "isotropic|anisotropic", "one mip chain or six directional ones",
         [](const V& v, S& s) {
             if (v.text() != "isotropic" && v.text() != "anisotropic")
                 throw Error("--voxel-mips must be isotropic or anisotropic, not '" + v.text() + "'");
             s.resources.anisotropicVoxels = v.text() == "anisotropic";
         },
         [](const S& s) { return std::string(s.resources.anisotropicVoxels ? "anisotropic" : "isotropic"); }},
        {"visibility", "mips|rays",
         "what stops a cone: the filtered mips alone, or also a ray along it through the finest voxels "
         "(no light through walls with voxels of their own; slower)",
         [](const V& v, S& s) {
             if (v.text() != "mips" && v.text() != "rays")
                 throw Error("--visibility must be mips or rays, not '" + v.text() + "'");
             s.resources.rayVisibility = v.text() == "rays";
         },
         [](const S& s) { return std::string(s.resources.rayVisibility ? "rays" : "mips"); }},
        {"bounces", "N|converged", "bounces of indirect light; converged iterates until it changes < 1 %",
         [](const V& v, S& s) {
             s.resources.bounces = v.text() == "converged" ? kConvergedBounces : v.whole(1, kMaxBouncesPerFrame);
         },
         [](const S& s) { return bouncesText(s.resources.bounces); }},
        {"cones", "N", "diffuse cones", [](const V& v, S& s) { s.shading.diffuseConeCount = v.whole(1, 32); },
         [](const S& s) { return std::to_string(s.shading.diffuseConeCount); }},
        {"cone-aperture", "DEGREES", "full angle of each diffuse cone",
         [](const V& v, S& s) { s.shading.diffuseConeAperture = v.number(1.0f, 120.0f); },
         [](const S& s) { return number(s.shading.diffuseConeAperture); }},
        {"cone-turns", "N",
         "the diffuse cones' ring turned N times about the normal, one still frame each, and the frames averaged "
         "(1 = fixed directions)",
         [](const V& v, S& s) { s.shading.diffuseConeTurns = v.whole(1, 16); },
         [](const S& s) { return std::to_string(s.shading.diffuseConeTurns); }},
        {"cone-step", "F", "cone step as a fraction of its diameter",
         [](const V& v, S& s) { s.shading.coneStep = v.number(0.05f, 4.0f); },
         [](const S& s) { return number(s.shading.coneStep); }},
        {"cone-max-distance", "F", "longest cone, as a fraction of the grid's side; past it a cone sees the sky",
         [](const V& v, S& s) { s.shading.coneMaxDistance = v.number(0.01f, 2.0f); },
         [](const S& s) { return number(s.shading.coneMaxDistance); }},
        {"cone-start-offset", "VOXELS", "gap between the surface and a cone's apex",
         [](const V& v, S& s) { s.shading.coneStartOffset = v.number(0.0f, 8.0f); },
         [](const S& s) { return number(s.shading.coneStartOffset); }},
        {"shadow-map", "N", "sun shadow-map size",
         [](const V& v, S& s) { s.resources.sunShadowMapSize = v.whole(16, 16384); },
         [](const S& s) { return std::to_string(s.resources.sunShadowMapSize); }},
        {"local-shadow-map", "N", "shadow-map size of each spot light and point-light cube face",
         [](const V& v, S& s) { s.resources.localShadowMapSize = v.whole(16, 16384); },
         [](const S& s) { return std::to_string(s.resources.localShadowMapSize); }},
        {"area-shadow-map", "N", "shadow-map size of each cube face of an area light (an emissive surface)",
         [](const V& v, S& s) { s.resources.areaShadowMapSize = v.whole(16, 16384); },
         [](const S& s) { return std::to_string(s.resources.areaShadowMapSize); }},
        {"scene", "FILE|NAME", "a .gltf/.glb file or a built-in scene (default cornell):" + sceneNames},
        {"camera-pos", "x,y,z", "camera position (overrides the scene's camera)"},
        {"camera-target", "x,y,z", "the point the camera looks at"},
        {"fov", "DEGREES", "vertical field of view"},
        {"light-dir", "x,y,z", "direction the sun's light travels (adds a sun if the scene has none)"},
        {"light-intensity", "E",
         "illuminance (lux) of the scene's first sun, or of the one --light-dir adds (default 3); "
         "refused without --light-dir if the scene has no sun"},
        {"environment", "R,G,B|FILE.hdr",
         "the sky every ray leaving the scene sees: a uniform radiance, or an equirectangular Radiance "
         "image (its centre looks along -Z, its top up) (default black; a scene without light gets a "
         "default sky with its default sun, unless this names its sky, 0,0,0 included)"},
        {"environment-rotation", "DEGREES",
         "turn the --environment image about +Y, counter-clockwise seen from above (default 0)"},
        {"device", "NAME", "use the Vulkan device whose name contains NAME (or $VCT_DEVICE)"},
        {"validate", "", "enable the Khronos validation layer"},
        {"strict", "", "treat scene warnings (e.g. a missing texture) as errors"},
        {"allowed-root", "DIR", "let the scene's URIs reach files under DIR (default: its folder)"},
        {"gpu-timeout", "SECONDS", "longest wait for the GPU before giving up (default 120)"},
    };
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
