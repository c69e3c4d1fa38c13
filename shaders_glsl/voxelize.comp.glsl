#version 460
// Conservative voxelization: one workgroup per (triangle, tile) work item, one invocation per voxel
// of the tile (see voxelize.h for the work split and the fixed-point sums). Every voxel the closed
// triangle touches gets the triangle's attributes added to the integer accumulation buffers.
// Base colour is the material's baseColorFactor only: textures are ignored for now (a voxel covers
// many texels, and sampling them here needs the texture array and the UVs; a later refinement).
// Emission is the material's voxelEmission: its emission times its emissive texture's mean colour.
// Opacity is the largest voxel coverage (voxelEmission.w: alpha as a mean over the texture) of the
// touching triangles; a triangle of coverage 0 (a fully transparent material) adds nothing.
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.h"
#include "voxelize.h"
#include "triangle_box.glsl"

layout(local_size_x = VOXELIZE_TILE, local_size_y = VOXELIZE_TILE, local_size_z = VOXELIZE_TILE) in;
layout(std430, set = 0, binding = 0) readonly buffer Vertices { GpuVertex vertices[]; };
layout(std430, set = 0, binding = 1) readonly buffer Indices { uint indices[]; };
layout(std430, set = 0, binding = 2) readonly buffer TriangleMaterials { uint triangleMaterials[]; };
layout(std430, set = 0, binding = 3) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, set = 0, binding = 4) readonly buffer WorkItems { uvec2 workItems[]; };  // (triangle, packed tile)
layout(std430, set = 0, binding = 5) buffer Accumulation { uint values[]; } accumulation[ACCUM_CHANNELS];
layout(push_constant) uniform Push { VoxelizeParams params; };

vec3 gridVertex(uint triangle, uint corner) {
    return worldToGrid(params.grid, vertices[indices[3u * triangle + corner]].positionU.xyz);
}

// The geometric unit normal; scaled by its largest component first so tiny triangles neither
// underflow to 0/0 nor overflow. A triangle that is degenerate in float (the CPU skips those that
// are degenerate in double) contributes a zero normal rather than NaN.
vec3 unitNormal(vec3 a, vec3 b, vec3 c) {
    vec3 n = cross(b - a, c - a);
    float largest = max(abs(n.x), max(abs(n.y), abs(n.z)));
    if (!(largest > 0.0f)) return vec3(0.0f);
    return normalize(n / largest);
}

uint toFixed(float value, float scale) { return uint(int(floor(value * scale + 0.5f))); }

void main() {
    uint item = gl_WorkGroupID.y * params.dispatch.x + gl_WorkGroupID.x;
    if (item >= params.grid.resolution.w) return;
    uint resolution = params.grid.resolution.x;
    uvec2 work = workItems[item];
    uvec3 voxel = unpackCell(work.y) * VOXELIZE_TILE + gl_LocalInvocationID;
    if (any(greaterThanEqual(voxel, uvec3(resolution)))) return;

    uint triangle = work.x;
    vec3 a = gridVertex(triangle, 0u), b = gridVertex(triangle, 1u), c = gridVertex(triangle, 2u);
    if (!triangleTouchesBox(a, b, c, vec3(voxel) + 0.5f, 0.5f)) return;

    GpuMaterial material = materials[triangleMaterials[triangle]];
    float coverage = clamp(material.voxelEmission.w, 0.0f, 1.0f);
    if (!(coverage > 0.0f)) return;
    vec3 albedo = clamp(material.baseColorFactor.rgb, 0.0f, 1.0f);
    vec3 normal = unitNormal(a, b, c);
    vec3 emission = clamp(material.voxelEmission.rgb * params.emission.x, 0.0f, EMISSION_FIXED_MAX);
    uint index = voxel.x + resolution * (voxel.y + resolution * voxel.z);
    atomicAdd(accumulation[ACCUM_COUNT].values[index], 1u);
    if (params.dispatch.z != 0u)
        atomicMax(accumulation[ACCUM_OPACITY].values[index], toFixed(coverage, OPACITY_FIXED_SCALE));
    for (uint i = 0u; i < 3u; ++i) {
        atomicAdd(accumulation[ACCUM_ALBEDO + i].values[index], toFixed(albedo[i], ALBEDO_FIXED_SCALE));
        atomicAdd(accumulation[ACCUM_NORMAL + i].values[index], toFixed(normal[i], NORMAL_FIXED_SCALE));
    }
    if (max(material.voxelEmission.r, max(material.voxelEmission.g, material.voxelEmission.b)) > 0.0f) {
        atomicAdd(accumulation[ACCUM_EMITTERS].values[index], 1u);
        for (uint i = 0u; i < 3u; ++i)
            atomicAdd(accumulation[ACCUM_EMISSION + i].values[index], toFixed(emission[i], 1.0f));
    }
}
