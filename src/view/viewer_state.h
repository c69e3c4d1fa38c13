// What the viewer's panels show and change: the settings asked for, the sun, the frame numbers.
// The main loop (viewer.cpp) applies requests from here to the renderer; the panels (ui.cpp)
// only read and write this struct.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <string>
#include <vector>

#include "io/display_transform.h"
#include "render/renderer.h"
#include "render/settings.h"
#include "view/controls.h"

namespace vct {

// Frame and pass times over the last frames, for the profiler window.
struct FrameHistory {
    static constexpr size_t length = 120;
    std::deque<float> frameMilliseconds;       // wall clock, loop iteration to loop iteration
    std::deque<float> gpuMilliseconds;         // the renderer's passes, summed
    std::map<std::string, float> passAverage;  // moving average of each pass over the frames it ran
    FrameStats last;                           // the last frame the renderer drew
    bool lastFrameIdle = false;                // nothing changed: the renderer did not run
    float presentMilliseconds = 0.0f;          // tone mapping + UI, GPU

    void add(float frameMs, const FrameStats& stats);
    float averageFrameMilliseconds() const;
};

struct ViewerState {
    // Wanted settings; width and height follow the window. New resources (voxels, shadow maps)
    // take a new Renderer, new image settings a resize, shading settings nothing.
    RenderSettings settings;
    std::string presetName = "custom";  // the preset the settings came from, as the panel shows it
    float exposure = 1.0f;              // the radiance multiplier the present pass applies now
    bool autoExposure = true;           // adapt `exposure` to the image (display_transform.h), else 2^exposureStops
    float exposureStops = 0.0f;         // the fixed exposure, EV
    ToneCurve toneCurve = ToneCurve::PbrNeutral;
    float renderScale = 1.0f;  // renderer image size / window size
    SunControl sun;
    // The scene's lights as the scene panel edits them; the main loop hands them to the renderer
    // when they differ from its own. The sun's direction and intensity come from `sun`.
    std::vector<Light> lights;
    size_t sunIndex = 0;
    glm::vec3 environment{0.0f};      // the sky's radiance, as the scene panel edits it
    std::string skyImage;             // the environment image's file (then `environment` scales it), or empty
    bool skyImageSun = false;         // the image's sun is lit as a sun (environment_sun.h)
    float skyRotation = 0.0f;         // radians the environment image is turned about +Y (Scene::environmentRotation)
    std::vector<Material> materials;  // shown, not edited
    float sceneSize = 1.0f;           // the bounds' diagonal, for drag speeds
    bool showGuide = false;           // F1 opens it; the status bar says so
    bool showHint = true;             // that one-line hint (--no-guide: neither)
    bool guideOpened = false;
    float statusBarHeight = 0.0f;  // last frame's, so the settings window ends above it
    float settingsWidth = 0.0f;    // this frame's docked settings, 0 when collapsed or hidden
    bool showProfiler = false;     // one click away, in the settings' first row
    bool wasNarrow = false;        // the window was too narrow for the settings and the profiler side by side
    bool showPanels = true;
    bool showGridBounds = false;  // the voxel grid's box as lines over the image (G)
    bool vsync = true;
    bool screenshotWithUi = false;

    std::string sceneName;                 // what is loaded now
    char scenePathField[512] = {};         // the panel's text field
    std::string requestedScene;            // set by the panel or a drop; loaded by the main loop
    std::vector<std::string> recentFiles;  // scenes opened from files, newest first (recent_files.h)
    bool requestScreenshot = false;
    bool requestCameraReset = false;
    bool requestOrbitToggle = false;
    bool cameraIsOrbiting = false;
    float cameraSpeed = 1.0f;

    std::string error;                  // the last failure the user caused (a scene that did not load)
    std::vector<std::string> warnings;  // the scene's, e.g. a missing texture
    std::string notice;                 // e.g. where a screenshot went
    FrameHistory history;
};

}  // namespace vct
