#version 460
// Reduced diffuse cones, step 3 (reduced_diffuse.glsl): every sample's light from the four
// representatives around it on its own surface, or the sample listed for step 3b
// (diffuse_edge_history.comp). The samples that cannot be upsampled are few (edges, corners, thin
// objects), and lavapipe runs both sides of a branch for every sample: their history lookup runs
// over a list of them, not here.
// One invocation per cell between four representatives: its f×f samples blend the same four, read
// once (a twelfth of the reads at a quarter's resolution).
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = FRAME_BINDING) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = DIFFUSE_SAMPLES_BINDING, rgba32f) uniform writeonly image2D diffuse;
layout(std430, set = 0, binding = EDGE_SAMPLES_BINDING) writeonly buffer Edge { uint edgeSamples[]; };
layout(std430, set = 0, binding = EDGE_LIST_BINDING) buffer EdgeList { WorkListHeader edge; };
layout(set = 0, binding = G_POSITION_BINDING) uniform sampler2D gPosition;
layout(set = 0, binding = G_NORMAL_BINDING) uniform sampler2D gNormal;
layout(set = 0, binding = REDUCED_LIGHT_BINDING) uniform sampler2D gathered;
layout(set = 0, binding = REDUCED_POSITIONS_BINDING) uniform sampler2D representatives;
layout(set = 0, binding = REDUCED_NORMALS_BINDING) uniform sampler2D representativeNormals;
layout(push_constant) uniform Push {
    mat4 lastViewProjection;
    uint groupLimit;
    uint refreshPhase;
    uint haveHistory;
};

#include "reduced_diffuse.glsl"

void upsample(ivec2 pixel, TexelQuad quad, ivec2 base) {
    vec4 positionMaterial = texelFetch(gPosition, pixel, 0);
    if (positionMaterial.w < 0.5f) {
        imageStore(diffuse, pixel, vec4(0.0f));  // background: shading reads nothing here
        return;
    }
    vec3 normal = normalize(texelFetch(gNormal, pixel, 0).xyz);
    SurfaceBlend blend = blendQuad(quad, reducedCoordinate(vec2(pixel)) - vec2(base), positionMaterial.xyz, normal);
    if (blend.weight > UPSAMPLE_MIN_WEIGHT) {
        imageStore(diffuse, pixel, blend.sum / blend.weight);
        return;
    }
    uint slot = atomicAdd(edge.count, 1u);
    edgeSamples[slot] = packSample(pixel);
    if (startsWorkgroup(slot, groupLimit)) atomicAdd(edge.groupsX, 1u);
}

void main() {
    // Cell c (per axis) holds the samples whose representatives start at c: c·f + f/2 up to f more,
    // from c = −1 (the image's first samples, before the first representative).
    int f = int(frame.diffuseDownscale);
    ivec2 base = ivec2(gl_GlobalInvocationID.xy) - 1;
    ivec2 first = base * f + f / 2;
    if (any(greaterThanEqual(first, ivec2(frame.renderSize)))) return;
    TexelQuad quad = fetchQuad(gathered, representatives, representativeNormals, base);
    for (int i = 0; i < f * f; ++i) {
        ivec2 pixel = first + ivec2(i % f, i / f);
        if (all(greaterThanEqual(pixel, ivec2(0))) && all(lessThan(pixel, ivec2(frame.renderSize))))
            upsample(pixel, quad, base);
    }
}
