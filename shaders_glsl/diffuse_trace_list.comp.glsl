#version 460
// Reduced diffuse cones, steps 2 and 4 (reduced_diffuse.glsl): the listed samples trace their own
// cones, into their texel of `target`: the reduced image (targetDownscale = f) for the
// representatives, the per-sample one (1) for the samples that could not be upsampled.
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.h"

layout(local_size_x = WORK_LIST_GROUP_SIZE) in;

layout(set = 0, binding = FRAME_BINDING) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = LISTED_TARGET_BINDING, rgba32f) uniform writeonly image2D target;
layout(std430, set = 0, binding = LISTED_SAMPLES_BINDING) readonly buffer Samples { uint listedSamples[]; };
layout(std430, set = 0, binding = LISTED_SAMPLES_LIST_BINDING) readonly buffer SampleList { WorkListHeader list; };
layout(set = 0, binding = G_POSITION_BINDING) uniform sampler2D gPosition;
layout(set = 0, binding = G_NORMAL_BINDING) uniform sampler2D gNormal;
layout(set = 0, binding = VOXEL_RADIANCE_BINDING) uniform sampler3D voxelRadiance;
layout(set = 0, binding = VOXEL_NORMAL_BINDING) uniform sampler3D voxelNormal;
layout(push_constant) uniform Push { uint targetDownscale; };
#include "directional_voxels.glsl"

// Where a cone meets a surface, on which side (cone_tracing.glsl).
vec3 voxelNormalAt(ivec3 cell) { return texelFetch(voxelNormal, cell, 0).xyz; }
#include "surface_planes.glsl"
#include "cone_tracing.glsl"
#include "reduced_diffuse.glsl"

void main() {
    // The dispatch may be capped below ⌈count / group size⌉: each invocation strides over the rest.
    uint stride = gl_NumWorkGroups.x * WORK_LIST_GROUP_SIZE;
    for (uint i = gl_GlobalInvocationID.x; i < list.count; i += stride) {
        ivec2 pixel = unpackSample(listedSamples[i]);
        vec3 position = texelFetch(gPosition, pixel, 0).xyz;
        // A representative's block holds it: its texel is the sample's coordinates / f.
        imageStore(target, pixel / int(targetDownscale),
                   gatherDiffuse(position, normalize(texelFetch(gNormal, pixel, 0).xyz)));
    }
}
