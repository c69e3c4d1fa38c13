// Indirect diffuse light at a reduced resolution (ImageSettings::diffuseDownscale = f): the diffuse
// cones are most of a frame's cost, and the light they gather changes over voxels, not pixels. The
// gather pass traces one G-buffer sample per f×f block (its centre, the block's representative);
// the shading pass blends the four representatives around each sample, bilinearly, keeping those
// on the sample's own surface: facing the same way and within half a voxel of its tangent plane.
// Where those carry less than half of the weight (an edge, a corner, a thin object) the sample
// traces its own cones: near a concave corner the far side is rejected, and renormalizing over the
// near side alone would carry its brighter light into the corner (+1.3 % on the Cornell box at 1/4).
// Requires: frame, gPosition, gNormal, and for upsampling the gathered image reducedDiffuse.
#ifndef VCT_REDUCED_DIFFUSE_GLSL
#define VCT_REDUCED_DIFFUSE_GLSL

#include "cone_tracing.glsl"

// Σ wᵢ Lᵢ of the diffuse cones (rgb) and their weighted occlusion (a) at a surface point; the
// cones start frame.coneStartOffset voxels off the surface, clear of its own voxels.
vec4 gatherDiffuse(vec3 position, vec3 normal) {
    vec3 origin = position + normal * (frame.coneStartOffset * frame.grid.originVoxelSize.w);
    return traceDiffuseCones(origin, normal, frame.coneStartOffset);
}

// The G-buffer sample that the reduced texel `texel` traces for.
ivec2 representativeSample(ivec2 texel) {
    int f = int(frame.diffuseDownscale);
    return min(texel * f + f / 2, ivec2(frame.renderSize) - 1);
}

#ifdef VCT_UPSAMPLE_DIFFUSE
const float UPSAMPLE_PLANE_TOLERANCE = 0.5f;  // voxels off the sample's tangent plane
const float UPSAMPLE_NORMAL_POWER = 8.0f;     // cos⁸: 0.5 at 24° between the normals
const float UPSAMPLE_MIN_WEIGHT = 0.5f;      // of the four bilinear weights' sum, 1

vec4 upsampledDiffuse(ivec2 pixel, vec3 position, vec3 normal) {
    float f = float(frame.diffuseDownscale);
    // Representative t sits at t·f + f/2 + ½ in samples: sample `pixel` is at reduced coordinate q.
    vec2 q = (vec2(pixel) - 0.5f * f) / f;
    ivec2 base = ivec2(floor(q));
    vec2 fraction = q - vec2(base);
    ivec2 last = textureSize(reducedDiffuse, 0) - 1;
    float voxelSize = frame.grid.originVoxelSize.w;
    vec4 sum = vec4(0.0f);
    float weightSum = 0.0f;
    for (int i = 0; i < 4; ++i) {
        ivec2 offset = ivec2(i & 1, i >> 1);
        ivec2 texel = clamp(base + offset, ivec2(0), last);
        ivec2 source = representativeSample(texel);
        vec4 sourcePosition = texelFetch(gPosition, source, 0);
        if (sourcePosition.w < 0.5f) continue;  // background: nothing was gathered
        vec3 sourceNormal = normalize(texelFetch(gNormal, source, 0).xyz);
        float planeDistance = abs(dot(normal, sourcePosition.xyz - position)) / voxelSize;
        if (planeDistance > UPSAMPLE_PLANE_TOLERANCE) continue;
        vec2 bilinear = mix(1.0f - fraction, fraction, vec2(offset));
        float weight = bilinear.x * bilinear.y * pow(max(dot(normal, sourceNormal), 0.0f), UPSAMPLE_NORMAL_POWER);
        sum += weight * texelFetch(reducedDiffuse, texel, 0);
        weightSum += weight;
    }
    return weightSum > UPSAMPLE_MIN_WEIGHT ? sum / weightSum : gatherDiffuse(position, normal);
}
#endif

#endif
