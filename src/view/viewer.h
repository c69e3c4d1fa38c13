// vct view: a window showing the renderer's image live, with camera, sun and settings controls.
#pragma once

#include <optional>

#include <cstdint>
#include <string>
#include <vector>

#include "gpu/context.h"
#include "render/settings.h"
#include "scene/scene.h"
#include "view/input.h"

namespace vct {

struct ViewerOptions {
    Scene scene;
    std::string sceneName;
    std::optional<glm::vec3> environment;  // --environment: the sky of every scene opened, dropped ones too
    std::shared_ptr<const EnvironmentMap> environmentMap;  // --environment FILE.hdr, likewise
    float environmentRotation = 0.0f;                      // --environment-rotation (radians), likewise
    RenderSettings settings;                               // width and height: the window's initial size
    // Used instead of `settings` on a software rasterizer, where those would not be interactive
    // (none: `settings` everywhere).
    std::optional<RenderSettings> softwareSettings;
    ContextOptions context;
    double gpuTimeoutSeconds = 120.0;
    std::optional<float> exposureStops;  // a fixed exposure (EV); none: automatic
    bool vsync = true;
    bool showHint = true;               // the status bar's one-line hint to the guide (F1)
    std::string presetName = "custom";  // --preset's, shown in the panel
    bool verbose = false;               // a line a frame on stdout: the passes it ran and skipped
    // Scripted use: save the image shown on frame `frames` to `screenshotPath` and exit
    // (frames = 0: run until the window closes).
    std::string screenshotPath;
    uint32_t frames = 0;
    bool screenshotWithUi = false;
    std::vector<ScriptEvent> script;
    float renderScale = 1.0f;       // image size / window size (0.5 = a quarter of the pixels)
    bool renderEveryFrame = false;  // redraw even when nothing changed (for measuring)
};

// Opens the window and runs until it is closed (or the scripted frames are done). Returns the
// process exit code; throws vct::Error for what the user can fix (no display, no device).
int runViewer(ViewerOptions options);

}  // namespace vct
