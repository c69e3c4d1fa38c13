// vct view: opens a window on a scene (src/view/). Built only where GLFW and Dear ImGui were found.
#include <cstdio>
#include <fstream>
#include <sstream>

#include "app/commands.h"
#include "app/scene_setup.h"
#include "error.h"

#ifdef VCT_WITH_VIEWER
#include "view/viewer.h"
#endif

namespace vct {

#ifndef VCT_WITH_VIEWER

int runView(const std::vector<std::string>&) {
    throw Error("this vct was built without the viewer: it needs GLFW 3.3 and Dear ImGui "
                "(Debian: libglfw3-dev libimgui-dev); install them and build again");
}

#else

static void printHelp() {
    std::printf("usage: vct view [options]\n\n%s"
                "  --exposure F             radiance multiplier before tone mapping (default 1)\n"
                "  --no-vsync               present as fast as possible (MAILBOX or IMMEDIATE when offered)\n"
                "  --screenshot FILE.png    save the image shown on the last of --frames and exit\n"
                "  --frames N               with --screenshot: frames to draw first (default 1)\n"
                "  --screenshot-ui          the screenshot includes the panels\n"
                "  --no-guide               start without the usage guide\n"
                "  --events TEXT            scripted input, e.g. \"2 key W down; 5 key W up\" (see src/view/input.h)\n"
                "  --script FILE            the same, read from a file\n"
                "  --render-scale 1|0.5|0.25   image size relative to the window (default 1; 0.5 on a\n"
                "                           software rasterizer such as lavapipe)\n"
                "  --render-every-frame     redraw even when nothing changed (for measuring)\n"
                "\nThe window's default size is 960x540, one sample per pixel and a 2048 sun shadow map;\n"
                "press F1 in the window for the controls.\n",
                sceneOptionsHelp().c_str());
}

static std::string readTextFile(const std::string& path) {
    std::ifstream file(path);
    if (!file) throw Error("cannot read the script '" + path + "'");
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

int runView(const std::vector<std::string>& rawArguments) {
    std::set<std::string> flags = sceneFlagNames();
    flags.insert({"help", "no-vsync", "screenshot-ui", "no-guide", "render-every-frame"});
    std::set<std::string> valued = sceneOptionNames();
    valued.insert({"exposure", "screenshot", "frames", "events", "script", "render-scale"});
    const Arguments arguments(rawArguments, flags, valued);
    if (arguments.has("help")) {
        printHelp();
        return 0;
    }
    ViewerOptions options;
    options.settings = renderSettingsFromArguments(arguments);
    // Interactive defaults where `render` aims at accuracy: a window-sized image, one sample per
    // pixel, a smaller sun shadow map. Explicit options win.
    if (!arguments.has("width")) options.settings.width = 960;
    if (!arguments.has("height")) options.settings.height = 540;
    if (!arguments.has("supersample")) options.settings.supersample = 1;
    if (!arguments.has("shadow-map")) options.settings.sunShadowMapSize = 2048;
    options.exposure = arguments.number("exposure", 1.0f, 0.0f, 1e9f);
    options.vsync = !arguments.has("no-vsync");
    options.showGuide = !arguments.has("no-guide");
    options.renderEveryFrame = arguments.has("render-every-frame");
    // 0 = not given: the viewer picks 1, or 0.5 on a software rasterizer.
    options.renderScale = arguments.number("render-scale", 0.0f, 0.25f, 1.0f);
    if (arguments.has("render-scale") && options.renderScale != 1.0f && options.renderScale != 0.5f &&
        options.renderScale != 0.25f)
        throw Error("--render-scale must be 1, 0.5 or 0.25");
    options.screenshotPath = arguments.text("screenshot", "");
    options.screenshotWithUi = arguments.has("screenshot-ui");
    if (arguments.has("frames") && options.screenshotPath.empty()) throw Error("--frames needs --screenshot FILE.png");
    if (!options.screenshotPath.empty()) options.frames = arguments.unsignedInt("frames", 1, 1, 1000000);
    if (arguments.has("events") && arguments.has("script")) throw Error("give --events or --script, not both");
    if (arguments.has("events")) options.script = parseScript(arguments.text("events", ""));
    if (arguments.has("script")) options.script = parseScript(readTextFile(arguments.text("script", "")));
    options.context = contextOptionsFromArguments(arguments);
    options.gpuTimeoutSeconds = arguments.number("gpu-timeout", 120.0f, 0.1f, 1e6f);
    options.sceneName = arguments.text("scene", "cornell");
    options.scene = loadSceneFromArguments(arguments);
    return runViewer(std::move(options));
}

#endif

}  // namespace vct
