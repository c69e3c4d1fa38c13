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
void drawProfilerWindow(const ViewerState& state, const UiFacts& facts);
void drawGuideWindow(ViewerState& state);
// The last failure the user caused (a scene that did not load), until dismissed.
void drawErrorWindow(ViewerState& state);

}  // namespace vct
