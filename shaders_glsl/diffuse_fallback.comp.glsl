#version 460
// Reduced diffuse cones, step 3 (reduced_diffuse.glsl): the listed samples trace their own cones.
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.h"

layout(local_size_x = WORK_LIST_GROUP_SIZE) in;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, rgba32f) uniform writeonly image2D diffuse;
layout(std430, set = 0, binding = 2) readonly buffer Fallback { uint fallbackSamples[]; };
layout(std430, set = 0, binding = 3) readonly buffer FallbackList { WorkListHeader fallback; };
layout(set = 0, binding = 6) uniform sampler2D gPosition;
layout(set = 0, binding = 7) uniform sampler2D gNormal;
layout(set = 0, binding = 9) uniform sampler3D voxelRadiance;
layout(set = 0, binding = 11) uniform sampler3D voxelNormal;
#include "directional_voxels.glsl"

#include "cone_tracing.glsl"
#include "reduced_diffuse.glsl"

void main() {
    // The dispatch may be capped below ⌈count / group size⌉: each invocation strides over the rest.
    uint stride = gl_NumWorkGroups.x * WORK_LIST_GROUP_SIZE;
    for (uint i = gl_GlobalInvocationID.x; i < fallback.count; i += stride) {
        ivec2 pixel = unpackSample(fallbackSamples[i]);
        vec3 position = texelFetch(gPosition, pixel, 0).xyz;
        imageStore(diffuse, pixel, gatherDiffuse(position, normalize(texelFetch(gNormal, pixel, 0).xyz)));
    }
}
