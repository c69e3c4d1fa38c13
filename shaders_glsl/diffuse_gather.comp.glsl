#version 460
// Reduced diffuse cones, step 1 (reduced_diffuse.glsl): the cones of each block's representative
// sample. A compute pass, not a full-screen draw: the target is small (32×32 for a 128² image at a
// quarter), and lavapipe rasterizes each 64×64 tile of a draw on one thread, where a dispatch
// spreads its workgroups over every core (20 → 7 ms on the Cornell box).
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, rgba32f) uniform writeonly image2D gathered;
layout(set = 0, binding = 6) uniform sampler2D gPosition;
layout(set = 0, binding = 7) uniform sampler2D gNormal;
layout(set = 0, binding = 9) uniform sampler3D voxelRadiance;
layout(set = 0, binding = 11) uniform sampler3D voxelNormal;
#include "directional_voxels.glsl"

#include "cone_tracing.glsl"
#include "reduced_diffuse.glsl"

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, imageSize(gathered)))) return;
    ivec2 source = representativeSample(texel);
    vec4 positionMaterial = texelFetch(gPosition, source, 0);
    vec4 result = vec4(0.0f);
    if (positionMaterial.w >= 0.5f)
        result = gatherDiffuse(positionMaterial.xyz, normalize(texelFetch(gNormal, source, 0).xyz));
    imageStore(gathered, texel, result);
}
