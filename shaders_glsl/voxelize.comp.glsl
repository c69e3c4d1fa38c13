#version 460
// Conservative voxelization: one workgroup per (triangle, tile) work item, one invocation per voxel
// of the tile (see voxelize.h for the work split and the fixed-point sums). Every voxel the closed
// triangle touches, set back along its normal (voxelizationSetback), gets the triangle's attributes
// added to the integer accumulation buffers.
// Base colour and emission are the material's factors times its textures averaged over the voxel's
// footprint (textureOverVoxel), so the light the voxels bounce has the colour of the surface there,
// not of a white baseColorFactor. A material emits into the voxels where its voxelEmission (the
// emissive texture's mean) is above zero.
// Opacity is the largest voxel coverage of the touching triangles (voxelEmission.w, a mean over the
// texture; with a base colour texture, for BLEND the alpha over the voxel's footprint, for MASK the
// share of the footprint whose alpha reaches the cutoff); where a triangle's coverage is 0 it adds
// nothing.
#extension GL_GOOGLE_include_directive : require
#include "alpha_coverage.h"
#include "gpu_types.h"
#include "voxelize.h"
#include "texture_transform.h"
#include "perpendicular.glsl"
#include "triangle_box.glsl"

layout(local_size_x = VOXELIZE_TILE, local_size_y = VOXELIZE_TILE, local_size_z = VOXELIZE_TILE) in;
layout(std430, set = 0, binding = VERTICES_BINDING) readonly buffer Vertices { GpuVertex vertices[]; };
layout(std430, set = 0, binding = INDICES_BINDING) readonly buffer Indices { uint indices[]; };
layout(std430, set = 0, binding = TRIANGLE_MATERIALS_BINDING) readonly buffer TriangleMaterials { uint triangleMaterials[]; };
layout(std430, set = 0, binding = MATERIALS_BINDING) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, set = 0, binding = VOXELIZER_WORK_ITEMS_BINDING) readonly buffer WorkItems { uvec2 workItems[]; };  // (triangle, packed tile)
layout(std430, set = 0, binding = VOXEL_ACCUMULATION_BINDING) buffer Accumulation { uint values[]; } accumulation[ACCUM_CHANNELS];
layout(push_constant) uniform Push { VoxelizeParams params; };
// The scene's base colour and emissive textures (SceneGpu::voxelTextureSet). A workgroup voxelizes
// one triangle, so the material's texture index is dynamically uniform.
layout(constant_id = TEXTURE_COUNT_CONSTANT_ID) const uint TEXTURE_COUNT = 1;
layout(set = TEXTURES_SET, binding = COLOR_TEXTURES_BINDING) uniform sampler2D colorTextures[TEXTURE_COUNT];
// Whether the scene has a MASK material with a base colour texture: only then is the 16-sample
// read of maskedOverVoxel compiled in (lavapipe ran it for every triangle, untaken: the Cornell box
// at 64³ voxelized in 72-91 ms, against 41-50 ms without it).
layout(constant_id = MASK_TEXTURES_CONSTANT_ID) const bool MASK_TEXTURES = false;

// Both texture-coordinate sets of a corner: xy TEXCOORD_0, zw TEXCOORD_1.
vec4 cornerTexCoords(uint triangle, uint corner) {
    GpuVertex vertex = vertices[indices[3u * triangle + corner]];
    return vec4(vertex.positionU.w, vertex.normalV.w, vertex.texCoord1.xy);
}

// Whether a triangle's edges e1, e2 span a plane in float (their Gram determinant not negligible).
bool spansPlane(vec3 e1, vec3 e2) {
    float d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
    return d11 * d22 - d12 * d12 > 1e-12f * d11 * d22;
}

// (s, t) such that s·e1 + t·e2 is `d` projected onto the plane the edges span (their Gram matrix
// inverted). Only for edges that span one.
vec2 edgeCoordinates(vec3 e1, vec3 e2, vec3 d) {
    float d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
    float denominator = d11 * d22 - d12 * d12;
    return vec2(d22 * dot(d, e1) - d12 * dot(d, e2), d11 * dot(d, e2) - d12 * dot(d, e1)) / denominator;
}

// Barycentric weights of the voxel's centre p projected onto the triangle's plane (some negative
// where it falls outside the triangle). Equal weights if the triangle is degenerate.
vec3 planeWeights(vec3 a, vec3 b, vec3 c, vec3 p) {
    if (!spansPlane(b - a, c - a)) return vec3(1.0f / 3.0f);
    vec2 vw = edgeCoordinates(b - a, c - a, p - a);
    return vec3(1.0f - vw.x - vw.y, vw.x, vw.y);
}

// The weights of a point of the triangle near the voxel's centre: its projection pulled inside
// the triangle (negative weights dropped).
vec3 weightsNear(vec3 planeWeights) {
    vec3 weights = max(planeWeights, vec3(0.0f));
    return weights / (weights.x + weights.y + weights.z);
}

// A material texture's coordinates at the triangle's corners, through its transform.
vec2[3] cornerCoordinates(GpuTextureTransform transform, vec4 texCoords[3]) {
    return vec2[3](transformedTexCoord(transform, texCoords[0].xy, texCoords[0].zw),
                   transformedTexCoord(transform, texCoords[1].xy, texCoords[1].zw),
                   transformedTexCoord(transform, texCoords[2].xy, texCoords[2].zw));
}

// How many of the texture's texels span a voxel's side on the triangle: its area in texels over its
// area in voxels (`voxelArea` twice that), square-rooted. 0 where its coordinates do not change.
float texelsPerVoxel(int index, vec2 t[3], float voxelArea) {
    vec2 size = vec2(textureSize(colorTextures[index], 0));
    vec2 e1 = (t[1] - t[0]) * size, e2 = (t[2] - t[0]) * size;
    return sqrt(abs(e1.x * e2.y - e1.y * e2.x) / max(voxelArea, 1e-20f));
}

// The mip level whose texels are `texels` level-0 texels wide (level 0 below one).
float levelAcross(float texels) { return texels > 1.0f ? log2(texels) : 0.0f; }

// A material texture averaged over the voxel: read at `weights` on the triangle, at the mip level
// whose texels are as wide on the surface as a voxel. A triangle whose coordinates do not change
// reads its one point's texel.
vec4 textureOverVoxel(int index, GpuTextureTransform transform, vec4 texCoords[3], vec3 weights, float voxelArea) {
    vec2 t[3] = cornerCoordinates(transform, texCoords);
    float level = levelAcross(texelsPerVoxel(index, t, voxelArea));
    return textureLod(colorTextures[index], weights.x * t[0] + weights.y * t[1] + weights.z * t[2], level);
}

// MASK over the voxel: 4 × 4 samples of the base colour over a voxel-sized square of the triangle's
// plane around the voxel centre's projection (`planeWeights`; the coordinates run on past the
// triangle), its sides along axes of the plane alone, so that the triangles of one quad read the
// same square wherever their edges cross the voxel; each sample read at the level whose texels are
// as wide as its quarter of the square. Returns the mean colour of the samples whose alpha (× the
// factor's) reaches the cutoff, and their share: as much of the voxel is there as of the surface
// the camera sees (a fence's solid half opaque, its gap empty, where the material's share made
// every voxel of it half opaque).
const int MASK_SAMPLES = 4;  // per side
vec4 maskedOverVoxel(GpuMaterial material, vec4 texCoords[3], vec3 planeWeights, vec3 a, vec3 b, vec3 c,
                     float voxelArea) {
    int index = material.baseColorTexture;
    vec2 t[3] = cornerCoordinates(material.baseColorTransform, texCoords);
    // How the coordinates change along two unit axes of the plane. A degenerate triangle reads its
    // one point.
    vec3 e1 = b - a, e2 = c - a;
    vec2 alongX = vec2(0.0f), alongY = vec2(0.0f);
    if (spansPlane(e1, e2)) {
        vec3 normal = normalize(cross(e1, e2));
        vec3 axisX = perpendicularTo(normal);
        vec3 axisY = cross(normal, axisX);
        mat2 coordinatesPerEdge = mat2(t[1] - t[0], t[2] - t[0]);
        alongX = coordinatesPerEdge * edgeCoordinates(e1, e2, axisX);
        alongY = coordinatesPerEdge * edgeCoordinates(e1, e2, axisY);
    }
    float level = levelAcross(texelsPerVoxel(index, t, voxelArea) / float(MASK_SAMPLES));
    vec2 centre = planeWeights.x * t[0] + planeWeights.y * t[1] + planeWeights.z * t[2];
    vec3 colourSum = vec3(0.0f);
    float present = 0.0f;
    for (int i = 0; i < MASK_SAMPLES; ++i)
        for (int j = 0; j < MASK_SAMPLES; ++j) {
            vec2 offset = (vec2(i, j) + 0.5f) / float(MASK_SAMPLES) - 0.5f;
            vec4 texel = textureLod(colorTextures[index], centre + offset.x * alongX + offset.y * alongY, level);
            if (material.baseColorFactor.a * texel.a >= material.alphaCutoff) {
                colourSum += texel.rgb;
                present += 1.0f;
            }
        }
    float samples = float(MASK_SAMPLES * MASK_SAMPLES);
    return present > 0.0f ? vec4(colourSum / present, present / samples) : vec4(vec3(1.0f), 0.0f);
}

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
    if (item >= params.grid.workItems) return;
    uint resolution = params.grid.resolution;
    uvec2 work = workItems[item];
    uvec3 voxel = unpackCell(work.y) * VOXELIZE_TILE + gl_LocalInvocationID;
    uint triangle = work.x;
    vec3 a = gridVertex(triangle, 0u), b = gridVertex(triangle, 1u), c = gridVertex(triangle, 2u);
    GpuMaterial material = materials[triangleMaterials[triangle]];
    float coverage = clamp(material.voxelEmission.w, 0.0f, 1.0f);
    if (!(coverage > 0.0f)) return;
    // Without emitters in the scene (emission scale 0) the emission channels are one word each.
    bool emits = params.emission.x > 0.0f &&
                 max(material.voxelEmission.r, max(material.voxelEmission.g, material.voxelEmission.b)) > 0.0f;
    vec3 albedo = material.baseColorFactor.rgb;
    vec3 emission = emits ? material.emission.rgb : vec3(0.0f);
    if (material.baseColorTexture >= 0 || (emits && material.emissiveTexture >= 0)) {
        vec4 texCoords[3] = vec4[3](cornerTexCoords(triangle, 0u), cornerTexCoords(triangle, 1u),
                                    cornerTexCoords(triangle, 2u));
        vec3 projected = planeWeights(a, b, c, vec3(voxel) + 0.5f);
        vec3 weights = weightsNear(projected);
        float voxelArea = length(cross(b - a, c - a));
        if (MASK_TEXTURES && material.baseColorTexture >= 0 && material.alphaMode == ALPHA_MASK) {
            vec4 masked = maskedOverVoxel(material, texCoords, projected, a, b, c, voxelArea);
            albedo *= masked.rgb;
            coverage = masked.a;
        } else if (material.baseColorTexture >= 0) {
            vec4 baseColor = textureOverVoxel(material.baseColorTexture, material.baseColorTransform, texCoords,
                                              weights, voxelArea);
            albedo *= baseColor.rgb;
            // BLEND: as opaque as the mean alpha over the voxel's footprint, not over the whole texture
            // (an atlas's other parts counted there).
            if (material.alphaMode == ALPHA_BLEND)
                coverage = clamp(material.baseColorFactor.a * baseColor.a, 0.0f, 1.0f);
        }
        if (emits && material.emissiveTexture >= 0)
            emission *= textureOverVoxel(material.emissiveTexture, material.emissiveTransform, texCoords, weights,
                                         voxelArea).rgb;
    }
    // Only after the texture reads may the invocations of a workgroup part: lavapipe takes an explicit
    // level of detail from one invocation of a SIMD group, which must have computed it (voxels read
    // the wrong level where a neighbour had left early).
    // The voxels it marks are those its set-back copy touches (voxelizationSetback); its plane,
    // for where the surface lies in them, is its own.
    vec3 normal = unitNormal(a, b, c);
    vec3 setback = -voxelizationSetback(normal) * normal;
    if (any(greaterThanEqual(voxel, uvec3(resolution))) ||
        !triangleTouchesBox(a + setback, b + setback, c + setback, vec3(voxel) + 0.5f, 0.5f) || !(coverage > 0.0f))
        return;
    albedo = clamp(albedo, 0.0f, 1.0f);
    emission = clamp(emission * params.emission.x, 0.0f, EMISSION_FIXED_MAX);
    // The same whichever way the normal points: the two faces of a thin wall agree on it.
    vec3 toPlane = normal * dot(normal, a - (vec3(voxel) + 0.5f));
    uint index = voxel.x + resolution * (voxel.y + resolution * voxel.z);
    atomicAdd(accumulation[ACCUM_COUNT].values[index], 1u);
    if (params.dispatch.z != 0u)
        atomicMax(accumulation[ACCUM_OPACITY].values[index], toFixed(coverage, OPACITY_FIXED_SCALE));
    for (uint i = 0u; i < 3u; ++i) {
        atomicAdd(accumulation[ACCUM_ALBEDO + i].values[index], toFixed(albedo[i], ALBEDO_FIXED_SCALE));
        atomicAdd(accumulation[ACCUM_NORMAL + i].values[index], toFixed(normal[i], NORMAL_FIXED_SCALE));
        atomicAdd(accumulation[ACCUM_SURFACE + i].values[index], toFixed(toPlane[i], SURFACE_FIXED_SCALE));
    }
    if (emits) {
        atomicAdd(accumulation[ACCUM_EMITTERS].values[index], 1u);
        for (uint i = 0u; i < 3u; ++i)
            atomicAdd(accumulation[ACCUM_EMISSION + i].values[index], toFixed(emission[i], 1.0f));
    }
}
