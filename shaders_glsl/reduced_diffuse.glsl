// Indirect diffuse light at a reduced resolution (ImageSettings::diffuseDownscale = f): the diffuse
// cones are most of a frame's cost, and the light they gather changes over voxels, not pixels.
//   1. diffuse_gather.comp traces one G-buffer sample per f×f block (its centre, the block's
//      representative) into the reduced image.
//   2. diffuse_upsample.comp blends, for every sample, the four representatives around it,
//      bilinearly, keeping those on the sample's own surface: facing the same way and within half
//      a voxel of its tangent plane. Where those carry less than half of the weight (an edge, a
//      corner, a thin object), it lists the sample instead: near a concave corner the far side is
//      rejected, and renormalizing over the near side alone would carry its brighter light into
//      the corner (+1.3 % on the Cornell box at a quarter).
//   3. diffuse_fallback.comp traces the listed samples' own cones, 64 to a workgroup: traced in
//      the shading pass, each would hold up the neighbours that share its SIMD lanes.
// The shading pass then reads one texel per sample.
// Requires: frame (FrameConstants).
#ifndef VCT_REDUCED_DIFFUSE_GLSL
#define VCT_REDUCED_DIFFUSE_GLSL

const float UPSAMPLE_PLANE_TOLERANCE = 0.5f;  // voxels off the sample's tangent plane
const float UPSAMPLE_NORMAL_POWER = 8.0f;     // cos⁸: 0.5 at 24° between the normals
const float UPSAMPLE_MIN_WEIGHT = 0.5f;       // of the four bilinear weights' sum, 1

// The G-buffer sample that the reduced texel `texel` traces for.
ivec2 representativeSample(ivec2 texel) {
    int f = int(frame.diffuseDownscale);
    return min(texel * f + f / 2, ivec2(frame.renderSize) - 1);
}

// A sample's position packed for the fallback list: 16 bits a coordinate.
uint packSample(ivec2 sample_) { return uint(sample_.x) | (uint(sample_.y) << 16u); }
ivec2 unpackSample(uint packed) { return ivec2(packed & 0xffffu, packed >> 16u); }

#ifdef VCT_CONE_TRACING_GLSL
#include "cone_start.glsl"

// Σ wᵢ Lᵢ of the diffuse cones (rgb) and their weighted occlusion (a) at a surface point; the
// cones start frame.coneStartOffset voxels off the surface, clear of its own voxels, unless
// another surface faces back across that gap: then every cone meets it at once.
vec4 gatherDiffuse(vec3 position, vec3 normal) {
    vec4 across = surfaceAcrossTheGap(position, normal);
    if (across.a > 0.0f) return across;
    vec3 origin = position + normal * (frame.coneStartOffset * frame.grid.originVoxelSize.w);
    return traceDiffuseCones(origin, normal, frame.coneStartOffset);
}
#endif

#endif
