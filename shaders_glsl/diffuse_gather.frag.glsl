#version 460
// The diffuse cones of one G-buffer sample per block of diffuseDownscale² samples, for the shading
// pass to upsample (reduced_diffuse.glsl).
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.h"

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 6) uniform sampler2D gPosition;
layout(set = 0, binding = 7) uniform sampler2D gNormal;
layout(set = 0, binding = 9) uniform sampler3D voxelRadiance;
#include "directional_voxels.glsl"

#include "reduced_diffuse.glsl"

layout(location = 0) out vec4 outGathered;

void main() {
    ivec2 source = representativeSample(ivec2(gl_FragCoord.xy));
    vec4 positionMaterial = texelFetch(gPosition, source, 0);
    if (positionMaterial.w < 0.5f) {
        outGathered = vec4(0.0f);
        return;
    }
    outGathered = gatherDiffuse(positionMaterial.xyz, normalize(texelFetch(gNormal, source, 0).xyz));
}
