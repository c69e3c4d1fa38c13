// The settings window's "Lights" and "Materials" sections: the scene's lights, editable, and its
// materials, read-only. They only write ViewerState; the main loop hands edited lights to the
// renderer the same way as a sun moved by the arrow keys (Renderer::setLights: the shadow maps
// of the lights that moved are redrawn, the light re-injected, the voxels kept).
#pragma once

#include "view/viewer_state.h"

namespace vct {

// Each light a tree node, numbered in the scene's order; the sun (the light the arrow keys steer) open.
void drawLightsSection(ViewerState& state);
// One row per material: base colour, metallic, roughness, emission.
void drawMaterialsSection(const ViewerState& state);

// "directional", "point" or "spot".
const char* lightTypeName(LightType type);

}  // namespace vct
