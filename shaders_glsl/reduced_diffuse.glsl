// Indirect diffuse light at a reduced resolution (ImageSettings::diffuseDownscale = f), reused
// across frames: the diffuse cones are most of a frame's cost, and the light they gather changes
// over voxels, not pixels, and from frame to frame only as fast as the light moves.
//   1. diffuse_reproject.comp, per reduced texel: the G-buffer sample at the centre of its f×f
//      block is its representative. It takes the last frame's light where the representative was,
//      blended from the last frame's representatives on the same surface (lastLight below), or,
//      where there is none (a surface hidden last frame, off its image, or no history: the first
//      frame, a light converged anew), lists the representative to trace. A quarter of the texels
//      each frame (a 2×2 pattern, in turn) trace anew whatever their history.
//   2. diffuse_trace_list.comp traces the listed representatives' cones, 64 to a workgroup.
//   3. diffuse_upsample.comp blends, for every sample, the four representatives around it,
//      bilinearly, keeping those on the sample's own surface: facing the same way and within half
//      a voxel of its tangent plane. Where those carry less than half of the weight (an edge, a
//      corner, a thin object), the sample is listed: near a concave corner the far side is
//      rejected, and renormalizing over the near side alone would carry its brighter light into
//      the corner (+1.3 % on the Cornell box at a quarter).
//   3b. diffuse_edge_history.comp: each listed sample takes its own light of the last frame as
//      step 1 does (from the last frame's per-sample light and G-buffer), a quarter of them
//      tracing anew each frame, or is listed again.
//   4. diffuse_trace_list.comp traces the listed samples' own cones.
// The shading pass then reads one texel per sample. Without history every block and edge sample
// traces, and the image is the same as without reuse; a still view is the same to rounding; light
// that moves reaches every block and sample within four frames.
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

// Where a point at `samplePosition` (in samples, their centres at integers) lies among the
// representatives: representative t sits at sample t·f + f/2.
vec2 reducedCoordinate(vec2 samplePosition) {
    float f = float(frame.diffuseDownscale);
    return (samplePosition - 0.5f * f) / f;
}

// A sample's position packed for a work list: 16 bits a coordinate.
uint packSample(ivec2 sample_) { return uint(sample_.x) | (uint(sample_.y) << 16u); }
ivec2 unpackSample(uint packed) { return ivec2(packed & 0xffffu, packed >> 16u); }

// The light (`light`) of the four samples or representatives around `q` (in their image's texels),
// bilinearly weighted, each kept as far as it (`positions`: xyz, w ≥ 0.5 where there is a surface;
// `normals`) lies on the surface at `position` facing `normal`. Returns Σ w·light (rgba) and Σ w.
struct SurfaceBlend {
    vec4 sum;
    float weight;
};

// The four texels from `base` (+x, +y), clamped to the image: what blendOnSurface reads.
struct TexelQuad {
    vec4 positions[4];
    vec3 normals[4];
    vec4 light[4];
};

TexelQuad fetchQuad(sampler2D light, sampler2D positions, sampler2D normals, ivec2 base) {
    ivec2 last = textureSize(light, 0) - 1;
    TexelQuad quad;
    for (int i = 0; i < 4; ++i) {
        ivec2 texel = clamp(base + ivec2(i & 1, i >> 1), ivec2(0), last);
        quad.positions[i] = texelFetch(positions, texel, 0);
        quad.normals[i] = normalize(texelFetch(normals, texel, 0).xyz);
        quad.light[i] = texelFetch(light, texel, 0);
    }
    return quad;
}

// The blend of a quad at `fraction` of the way from its first texel to its last.
SurfaceBlend blendQuad(TexelQuad quad, vec2 fraction, vec3 position, vec3 normal) {
    float voxelSize = frame.grid.voxelSize;
    SurfaceBlend blend = SurfaceBlend(vec4(0.0f), 0.0f);
    for (int i = 0; i < 4; ++i) {
        vec4 sourcePosition = quad.positions[i];
        if (sourcePosition.w < 0.5f) continue;  // background: nothing was gathered
        float planeDistance = abs(dot(normal, sourcePosition.xyz - position)) / voxelSize;
        if (planeDistance > UPSAMPLE_PLANE_TOLERANCE) continue;
        vec2 bilinear = mix(1.0f - fraction, fraction, vec2(ivec2(i & 1, i >> 1)));
        float weight = bilinear.x * bilinear.y * pow(max(dot(normal, quad.normals[i]), 0.0f), UPSAMPLE_NORMAL_POWER);
        blend.sum += weight * quad.light[i];
        blend.weight += weight;
    }
    return blend;
}

SurfaceBlend blendOnSurface(sampler2D light, sampler2D positions, sampler2D normals, vec2 q, vec3 position,
                            vec3 normal) {
    ivec2 base = ivec2(floor(q));
    return blendQuad(fetchQuad(light, positions, normals, base), q - vec2(base), position, normal);
}

// Whether the reduced texel or the sample at `coordinate` traces anew this frame whatever its history: a
// quarter of them each frame, in turn.
bool refreshes(ivec2 coordinate, uint refreshPhase) {
    return uint((coordinate.x & 1) + 2 * (coordinate.y & 1)) == refreshPhase;
}

// The last frame's light at `position` on the surface facing `normal`, from the last frame's
// samples (reduced: representatives; their `light`, `positions` and `normals`), where the last
// frame saw that surface.
bool lastLight(mat4 lastViewProjection, sampler2D light, sampler2D positions, sampler2D normals, bool reduced,
               vec3 position, vec3 normal, out vec4 result) {
    vec4 clip = lastViewProjection * vec4(position, 1.0f);
    if (clip.w <= 0.0f) return false;  // behind the last camera
    vec2 samplePosition = (clip.xy / clip.w * 0.5f + 0.5f) * frame.renderSize - 0.5f;
    if (any(lessThan(samplePosition, vec2(-0.5f))) || any(greaterThan(samplePosition, frame.renderSize - 0.5f)))
        return false;  // off the last frame's image
    vec2 q = reduced ? reducedCoordinate(samplePosition) : samplePosition;
    SurfaceBlend blend = blendOnSurface(light, positions, normals, q, position, normal);
    result = blend.sum / max(blend.weight, 1e-20f);
    return blend.weight > UPSAMPLE_MIN_WEIGHT;
}

#ifdef VCT_CONE_TRACING_GLSL
#include "cone_start.glsl"

// Σ wᵢ Lᵢ of the diffuse cones (rgb) and their weighted occlusion (a) at a surface point; the
// cones start frame.coneStartOffset voxels off the surface, clear of its own voxels, unless
// another surface faces back across that gap: then every cone meets it at once.
vec4 gatherDiffuse(vec3 position, vec3 normal) {
    vec4 across = surfaceAcrossTheGap(position, normal);
    if (across.a > 0.0f) return across;
    vec3 origin = position + normal * (frame.coneStartOffset * frame.grid.voxelSize);
    return traceDiffuseCones(origin, normal, frame.coneStartOffset);
}
#endif

#endif
