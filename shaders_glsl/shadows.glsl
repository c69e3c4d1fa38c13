// Shadow-map visibility with 5×5 percentage-closer filtering.
// Requires: shadowViews[] (ShadowView), sunShadowMaps and localShadowMaps (sampler2DArrayShadow),
// frame (FrameConstants).
#ifndef VCT_SHADOWS_GLSL
#define VCT_SHADOWS_GLSL

// The view of a point light that sees `toSurface`: cube face by the major axis, ordered
// +X, −X, +Y, −Y, +Z, −Z as the CPU builds them.
uint cubeFace(vec3 toSurface) {
    vec3 a = abs(toSurface);
    if (a.x >= a.y && a.x >= a.z) return toSurface.x >= 0.0f ? 0u : 1u;
    if (a.y >= a.z) return toSurface.y >= 0.0f ? 2u : 3u;
    return toSurface.z >= 0.0f ? 4u : 5u;
}

float sampleShadowMap(uint array, vec4 coordinate) {
    return array == 0u ? texture(sunShadowMaps, coordinate) : texture(localShadowMaps, coordinate);
}

// Fraction of the light's view that reaches `position` (1 = lit). The position is pushed along
// the normal by a few shadow-map texels (normal-offset shadows) on top of the slope-scaled
// depth bias the shadow pass applies, which removes acne without detaching shadows.
// `filtered` = false takes one bilinear comparison instead of 25: enough for a voxel, whose
// footprint is far wider than the kernel.
float shadowVisibility(GpuLight light, vec3 position, vec3 normal, float distanceToLight, bool filtered) {
    uint viewCount = uint(light.spotShadow.w);
    if (viewCount == 0u || (frame.componentFlags & USE_SHADOWS) == 0u) return 1.0f;
    uint viewIndex = uint(light.spotShadow.z);
    if (viewCount == 6u) viewIndex += cubeFace(position - light.positionRange.xyz);
    ShadowView view = shadowViews[viewIndex];

    float texelWorld = view.params.z * (view.params.w > 0.5f ? distanceToLight : 1.0f);
    vec3 offsetPosition = position + normal * (frame.shadowNormalOffset * texelWorld);
    vec4 clip = view.viewProjection * vec4(offsetPosition, 1.0f);
    if (clip.w <= 0.0f) return 1.0f;
    vec3 ndc = clip.xyz / clip.w;
    vec2 uv = ndc.xy * 0.5f + 0.5f;
    if (any(lessThan(uv, vec2(0.0f))) || any(greaterThan(uv, vec2(1.0f))) || ndc.z > 1.0f) return 1.0f;

    uint array = uint(view.params.x);
    if (!filtered) return sampleShadowMap(array, vec4(uv, view.params.y, ndc.z));
    vec2 texel = 1.0f / vec2(array == 0u ? textureSize(sunShadowMaps, 0).xy : textureSize(localShadowMaps, 0).xy);
    float radius = frame.pcfRadius;
    float lit = 0.0f;
    // 5×5 taps spread over ±radius texels; each tap is itself a bilinear 2×2 comparison.
    for (int y = -2; y <= 2; ++y)
        for (int x = -2; x <= 2; ++x)
            lit += sampleShadowMap(array, vec4(uv + vec2(x, y) * (0.5f * radius) * texel, view.params.y, ndc.z));
    return lit / 25.0f;
}

#endif
