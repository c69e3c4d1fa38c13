// The viewer's Dear ImGui windows: settings, profiler, usage guide.
#pragma once

#include <string>

#include "view/viewer_state.h"

namespace vct {

// Facts the panels show but do not change.
struct UiFacts {
    std::string deviceName;
    std::string presentMode;
    uint32_t width = 0, height = 0;              // the window
    uint32_t renderWidth = 0, renderHeight = 0;  // the renderer's image
    uint32_t voxelResolution = 0;
    uint32_t voxelMips = 1;
    uint64_t deviceMemoryBytes = 0;
    size_t triangles = 0;
    size_t lights = 0;
};

void drawSettingsWindow(ViewerState& state, const UiFacts& facts);
void drawProfilerWindow(ViewerState& state, const UiFacts& facts);
void drawGuideWindow(ViewerState& state);
// The bottom line: the last notice (where a screenshot went, why the preset changed) and, until
// the guide has been opened once, a one-line hint to it. Draw it before the settings window, which
// ends above it.
void drawStatusBar(ViewerState& state);
// The last failure the user caused (a scene that did not load), until dismissed.
void drawErrorWindow(ViewerState& state);
// The scene's warnings (a missing texture...), which also go to stderr, until dismissed.
void drawWarningsWindow(ViewerState& state);

// "32768" for 32³, "2.1 M" for 128³.
std::string voxelCountText(uint32_t resolution);

}  // namespace vct
