#version 460
// Turns the integer sums of the voxelize pass into averages: one invocation per voxel.
//   albedoOpacity: mean linear base colour; opacity the largest coverage of the touching triangles
//                  (1 for opaque ones, voxelize.h), at least 1/255 where any triangle touched (so an
//                  occupied voxel never reads as empty), else 0.
//   normal: xyz the mean of the touching triangles' unit normals, deliberately not renormalized (its
//           length says how much they agree: the two faces of a thin wall cancel to ~0); w where the
//           surface lies, in voxels from the centre along the unit mean normal (the mean way to the
//           triangles' planes projected on it; 0 where the normals cancel).
//   emission: mean emitted radiance of the emitting triangles (scene units), clamped to the largest
//             half float; a = opacity.
// It also lists the occupied voxels (voxel_grid.h), and zeroes level 0 of the light volumes where a
// voxel is empty: the light passes visit only the listed voxels, so light left where the geometry
// was would stay. Where a voxel stays occupied its old light stays too: a bounce gathered from the
// last frame's light (the viewer) still has it when an object moves.
#extension GL_GOOGLE_include_directive : require
#include "bindings.h"
#include "voxelize.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(std430, set = 0, binding = VOXEL_ACCUMULATION_BINDING) readonly buffer Accumulation { uint values[]; } accumulation[ACCUM_CHANNELS];
layout(set = 0, binding = VOXEL_ALBEDO_BINDING, rgba8) uniform writeonly image3D albedoOpacity;
layout(set = 0, binding = VOXEL_NORMAL_BINDING, rgba16f) uniform writeonly image3D normalSurface;
layout(set = 0, binding = VOXEL_EMISSION_BINDING, rgba16f) uniform writeonly image3D emission;
layout(std430, set = 0, binding = OCCUPIED_VOXELS_BINDING) writeonly buffer OccupiedVoxels { uint occupiedVoxels[]; };
layout(std430, set = 0, binding = OCCUPIED_LIST_BINDING) buffer Occupied { WorkListHeader occupied; };
layout(set = 0, binding = LIGHT_VOLUMES_BINDING, rgba16f) uniform writeonly image3D lightVolumes[2];  // radiance level 0, next bounce
layout(push_constant) uniform Push { VoxelizeParams params; };

vec3 channelMean(uint first, uint index, float divisor, bool isSigned) {
    vec3 sum;
    for (uint i = 0u; i < 3u; ++i) {
        uint raw = accumulation[first + i].values[index];
        sum[i] = isSigned ? float(int(raw)) : float(raw);
    }
    return sum / divisor;
}

void main() {
    uvec3 voxel = gl_GlobalInvocationID;
    uint resolution = params.grid.resolution;
    if (any(greaterThanEqual(voxel, uvec3(resolution)))) return;
    uint index = voxel.x + resolution * (voxel.y + resolution * voxel.z);
    uint count = accumulation[ACCUM_COUNT].values[index];
    ivec3 texel = ivec3(voxel);
    if (count == 0u) {
        imageStore(albedoOpacity, texel, vec4(0.0f));
        imageStore(normalSurface, texel, vec4(0.0f));
        imageStore(emission, texel, vec4(0.0f));
        for (int volume = 0; volume < 2; ++volume) imageStore(lightVolumes[volume], texel, vec4(0.0f));
        return;
    }
    uint slot = atomicAdd(occupied.count, 1u);
    occupiedVoxels[slot] = packCell(voxel);
    if (startsWorkgroup(slot, params.dispatch.y)) atomicAdd(occupied.groupsX, 1u);
    float n = float(count);
    vec3 albedo = channelMean(ACCUM_ALBEDO, index, n * ALBEDO_FIXED_SCALE, false);
    vec3 normal = channelMean(ACCUM_NORMAL, index, n * NORMAL_FIXED_SCALE, true);
    uint emitters = params.emission.x > 0.0f ? accumulation[ACCUM_EMITTERS].values[index] : 0u;
    vec3 radiance = emitters == 0u ? vec3(0.0f)
                                   : channelMean(ACCUM_EMISSION, index, float(emitters), false) * params.emission.y;
    float opacity = params.dispatch.z == 0u
                        ? 1.0f
                        : max(float(accumulation[ACCUM_OPACITY].values[index]) / OPACITY_FIXED_SCALE, 1.0f / 255.0f);
    imageStore(albedoOpacity, texel, vec4(albedo, opacity));
    vec3 toSurface = channelMean(ACCUM_SURFACE, index, n * SURFACE_FIXED_SCALE, true);
    float normalLength = length(normal);
    float offset = normalLength > SURFACE_NORMAL_MIN ? dot(normal, toSurface) / normalLength : 0.0f;
    imageStore(normalSurface, texel, vec4(normal, offset));
    imageStore(emission, texel, vec4(min(radiance, vec3(HALF_FLOAT_MAX)), opacity));
}
