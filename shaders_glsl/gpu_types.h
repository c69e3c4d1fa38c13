// Structs that cross the CPU/GPU boundary, declared once for C++ and GLSL.
// Every member is a vec4, uvec4 or mat4 (or four scalars), so std140 and std430 agree with C++.
#ifndef VCT_GPU_TYPES_H
#define VCT_GPU_TYPES_H

#include "cpp_glsl.h"
#include "voxel_grid.h"

VCT_SHARED_BEGIN

struct GpuVertex {
    vec4 positionU;  // xyz position, w texture u
    vec4 normalV;    // xyz normal, w texture v
};

struct GpuMaterial {
    vec4 baseColorFactor;  // linear rgb, alpha
    vec4 emission;         // rgb radiance from the front face
    float metallic;
    float roughness;
    float specularWeight;
    int baseColorTexture;  // -1 = none
};

struct GpuLight {
    vec4 radiantIntensity;  // rgb colour × intensity (cd, or lux for directional), w = type
    vec4 positionRange;     // xyz world position, w range (0 = infinite)
    vec4 direction;         // xyz direction the light travels
    vec4 spotShadow;        // x inner cone angle, y outer cone angle, z first shadow view, w shadow view count
};

// One rendered shadow map: a sun or spot light has one, a point light six (cube faces).
struct ShadowView {
    mat4 viewProjection;
    vec4 params;  // x array (0 = sun maps, 1 = local maps), y layer, z texel size at unit distance, w 1 = perspective
};

// Bits of FrameConstants.counts.z: which light components the final image contains.
const uint SHOW_DIRECT_DIFFUSE = 1u;
const uint SHOW_DIRECT_SPECULAR = 2u;
const uint SHOW_INDIRECT_DIFFUSE = 4u;
const uint SHOW_INDIRECT_SPECULAR = 8u;
const uint SHOW_AMBIENT_OCCLUSION = 16u;
const uint SHOW_EMISSION = 32u;
const uint USE_SHADOWS = 64u;

struct FrameConstants {
    mat4 viewProjection;
    vec4 cameraPosition;  // xyz, w unused
    uvec4 counts;         // x lights, y shadow views, z SHOW_* / USE_* flags, w 1 = anisotropic voxels
    vec4 shading;         // x ambient factor, y shadow normal offset (texels), z PCF radius (texels), w unused
    vec4 renderSize;      // width, height, 1/width, 1/height of the render target

    // Voxel cone tracing (Crassin et al. 2011). Distances are in voxels of the finest level.
    VoxelGridParams grid;
    vec4 cone;        // x tan(diffuse half-aperture), y step (fraction of the cone diameter),
                      // z max distance, w start offset along the normal
    vec4 coneWeights; // x AO distance falloff, y opacity at which a cone stops, z centre cone weight,
                      // w radiance scale (the volume stores radiance × scale to stay inside float16)
    uvec4 coneCounts; // x diffuse cones, y 1 = skip empty space with coarse mips, z debug view (DEBUG_*),
                      // w mip level the voxel debug views show
    mat4 inverseViewProjection;
};

// What the shading pass shows instead of light (FrameConstants.coneCounts.z), for understanding.
const uint DEBUG_NONE = 0u;
const uint DEBUG_BASE_COLOR = 1u;
const uint DEBUG_NORMAL = 2u;
const uint DEBUG_DEPTH = 3u;
const uint DEBUG_AMBIENT_OCCLUSION = 4u;
const uint DEBUG_VOXEL_ALBEDO = 5u;
const uint DEBUG_VOXEL_NORMAL = 6u;
const uint DEBUG_VOXEL_RADIANCE = 7u;
const uint DEBUG_VIEW_COUNT = 8u;


VCT_SHARED_END

#endif
