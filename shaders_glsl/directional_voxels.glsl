// The six directional radiance chains of anisotropic voxels, one array binding that every pass
// that traces cones uses: element DIRECTION_* holds the chain for rays along that direction.
#ifndef VCT_DIRECTIONAL_VOXELS_GLSL
#define VCT_DIRECTIONAL_VOXELS_GLSL

const uint DIRECTION_POS_X = 0u;
const uint DIRECTION_NEG_X = 1u;
const uint DIRECTION_POS_Y = 2u;
const uint DIRECTION_NEG_Y = 3u;
const uint DIRECTION_POS_Z = 4u;
const uint DIRECTION_NEG_Z = 5u;
layout(set = 0, binding = 12) uniform sampler3D directionalVoxels[6];

#endif
