// The directional radiance chains of anisotropic voxels, one array binding that every pass that
// traces cones uses: element AXIS_* holds the chains for rays along +axis and −axis
// (directional_chains.h).
#ifndef VCT_DIRECTIONAL_VOXELS_GLSL
#define VCT_DIRECTIONAL_VOXELS_GLSL

#include "directional_chains.h"

const uint AXIS_X = 0u;
const uint AXIS_Y = 1u;
const uint AXIS_Z = 2u;
layout(set = 0, binding = DIRECTIONAL_VOXELS_BINDING) uniform sampler3D directionalVoxels[3];

#endif
