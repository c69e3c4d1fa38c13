// vct view: opens a window on a scene (src/view/). Built only where GLFW and Dear ImGui were found.
#include <cstdio>
#include <fstream>
#include <sstream>

#include "app/commands.h"
#include "app/options.h"
#include "app/scene_setup.h"
#include "error.h"
#include "io/output_paths.h"
#include "render/presets.h"

#ifdef VCT_WITH_VIEWER
#include "view/viewer.h"
#endif

namespace vct {

#ifndef VCT_WITH_VIEWER

int runView(const std::vector<std::string>&) {
    throw Error(
        "this vct was built without the viewer: it needs GLFW 3.3 and Dear ImGui "
        "(Debian: libglfw3-dev libimgui-dev); install them and build again");
}

#else

static std::vector<Option> viewOptions() {
    std::vector<Option> options = {
        {"exposure", "EV", "a fixed exposure, radiance × 2^EV (default: automatic, adapting to the image)"},
        {"no-vsync", "", "present as fast as possible (MAILBOX or IMMEDIATE when offered)"},
        {"screenshot", "FILE.png", "save the image shown on the last of --frames and exit"},
        {"frames", "N", "with --screenshot: frames to draw first (default 1)"},
        {"screenshot-ui", "", "the screenshot includes the panels"},
        {"no-guide", "", "start without the one-line hint to the usage guide (F1 opens the guide)"},
        {"verbose", "", "print which passes each frame ran"},
        {"events", "TEXT",
         "scripted input: entries 'FRAME ACTION ...' separated by ';' (e.g. \"2 key W down; 5 key W up\"), the "
         "actions below"},
        {"script", "FILE", "the same, read from a file"},
        {"render-scale", "1|0.5|0.25", "image size relative to the window (default 1; 0.5 on a software rasterizer)"},
        {"render-every-frame", "", "redraw even when nothing changed (for measuring)"},
    };
    options.insert(options.end(), sharedOptions().begin(), sharedOptions().end());
    return options;
}

// Interactive defaults where `render` aims at accuracy: a window-sized image, one sample per
// pixel, a smaller sun shadow map. Explicit options (and a preset's resources) win.
static RenderSettings viewDefaults() {
    RenderSettings settings;
    settings.image = {.width = 960, .height = 540, .supersample = 1};
    settings.resources.sunShadowMapSize = 2048;
    return settings;
}

// What the window, not the preset, decides: the image's size and sampling, and the sun's shadow
// map unless asked for; and one bounce per frame, so a moving light never waits for, or resets,
// the converged light.
static RenderSettings forTheWindow(RenderSettings settings, const Arguments& arguments) {
    const RenderSettings defaults = viewDefaults();
    if (!arguments.has("width")) settings.image.width = defaults.image.width;
    if (!arguments.has("height")) settings.image.height = defaults.image.height;
    if (!arguments.has("supersample")) settings.image.supersample = defaults.image.supersample;
    if (!arguments.has("shadow-map")) settings.resources.sunShadowMapSize = defaults.resources.sunShadowMapSize;
    settings.shading.progressiveBounces = true;
    return settings;
}

static std::string readTextFile(const std::string& path) {
    std::ifstream file(path);
    if (!file) throw Error("cannot read the script '" + path + "'");
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

int runView(const std::vector<std::string>& rawArguments) {
    const std::vector<Option> rows = viewOptions();
    const Arguments arguments = parseArguments(rawArguments, rows);
    if (answerHelpOrVersion(
            arguments, "vct view [options]", rows, viewDefaults(),
            "\n--events / --script actions (FRAME counts loop iterations from 0; '#' starts a comment):\n"
            "  key NAME down|up|press      a letter or digit, F1..F12, left, right, up, down, shift,\n"
            "                              ctrl, tab, space, escape, [ or ]\n"
            "  mouse X Y                   move the cursor to window coordinates X, Y\n"
            "  button left|right down|up   scroll DY   resize W H   iconify   restore\n"
            "  screenshot FILE.png [ui]    the image alone, or the whole window with \"ui\"\n"
            "  drop FILE                   as if FILE were dropped on the window\n"
            "  type TEXT                   typed into the text field that has the focus\n"
            "  light INDEX intensity X     the scene panel's intensity field (cd, or lux for a sun)\n"
            "  sky R G B                   the scene panel's sky radiance   quit\n"
            "\npress F1 in the window for the controls.\n"))
        return 0;
    ViewerOptions options;
    options.settings = forTheWindow(renderSettingsFromArguments(arguments, rows, viewDefaults()), arguments);
    // Without a preset, a software rasterizer starts on `fast`, with the other options over it.
    if (!arguments.has("preset"))
        options.softwareSettings =
            forTheWindow(renderSettingsFromArguments(arguments, rows, *findRenderPreset("fast")), arguments);
    if (arguments.has("exposure")) options.exposureStops = arguments.number("exposure", 0.0f, -64.0f, 64.0f);
    options.vsync = !arguments.has("no-vsync");
    options.showHint = !arguments.has("no-guide");
    options.verbose = arguments.has("verbose");
    options.presetName = arguments.has("preset") ? arguments.text("preset", "") : "custom";
    options.renderEveryFrame = arguments.has("render-every-frame");
    // 0 = not given: the viewer picks 1, or 0.5 on a software rasterizer.
    options.renderScale = arguments.number("render-scale", 0.0f, 0.25f, 1.0f);
    if (arguments.has("render-scale") && options.renderScale != 1.0f && options.renderScale != 0.5f &&
        options.renderScale != 0.25f)
        throw Error("--render-scale must be 1, 0.5 or 0.25");
    options.screenshotPath = arguments.text("screenshot", "");
    if (!options.screenshotPath.empty()) checkOutputFile(options.screenshotPath, {".png"});
    options.screenshotWithUi = arguments.has("screenshot-ui");
    if (arguments.has("frames") && options.screenshotPath.empty()) throw Error("--frames needs --screenshot FILE.png");
    if (!options.screenshotPath.empty()) options.frames = arguments.unsignedInt("frames", 1, 1, 1000000);
    if (arguments.has("events") && arguments.has("script")) throw Error("give --events or --script, not both");
    if (arguments.has("events")) options.script = parseScript(arguments.text("events", ""));
    if (arguments.has("script")) options.script = parseScript(readTextFile(arguments.text("script", "")));
    for (const ScriptEvent& event : options.script)
        if (event.action == "screenshot") checkOutputFile(event.arguments.at(0), {".png"});
    options.context = contextOptionsFromArguments(arguments);
    options.gpuTimeoutSeconds = arguments.number("gpu-timeout", 120.0f, 0.1f, 1e6f);
    options.sceneName = arguments.text("scene", "cornell");
    // Every argument is checked before the scene loads and the window opens.
    checkSceneArguments(arguments);
    options.scene = loadSceneFromArguments(arguments);
    options.environment = sceneOverridesFromArguments(arguments).environment;
    options.environmentMap = options.scene.environmentMap;  // read once, for every scene opened
    options.environmentRotation = options.scene.environmentRotation;
    printSceneWarnings(options.scene);
    return runViewer(std::move(options));
}

#endif

}  // namespace vct
