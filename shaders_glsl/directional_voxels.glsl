// The six directional radiance chains of anisotropic voxels (rays along +x, −x, +y, −y, +z, −z),
// at the bindings every pass that traces cones uses for them.
#ifndef VCT_DIRECTIONAL_VOXELS_GLSL
#define VCT_DIRECTIONAL_VOXELS_GLSL

layout(set = 0, binding = 12) uniform sampler3D voxelPosX;
layout(set = 0, binding = 13) uniform sampler3D voxelNegX;
layout(set = 0, binding = 14) uniform sampler3D voxelPosY;
layout(set = 0, binding = 15) uniform sampler3D voxelNegY;
layout(set = 0, binding = 16) uniform sampler3D voxelPosZ;
layout(set = 0, binding = 17) uniform sampler3D voxelNegZ;

#endif
