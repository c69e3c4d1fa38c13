// The tone curves of every image made for people (PNG files, the viewer's window), written once for
// C++ and GLSL: radiance × exposure, a curve, then sRGB encoding. PFM output and the benchmark never
// use them. Two curves: Khronos PBR Neutral (the default: base colours under unit light come out as
// themselves, hue kept, only highlights compressed) and Narkowicz's fit of ACES filmic (a familiar,
// contrasty film look, per channel).
#ifndef VCT_TONE_CURVE_H
#define VCT_TONE_CURVE_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

SHARED_FN float tonemapAces(float x) {
    x = max(x, 0.0f) * 0.6f;
    return clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}

const uint TONE_CURVE_PBR_NEUTRAL = 0u;
const uint TONE_CURVE_ACES = 1u;

// Khronos PBR Neutral tone mapping (Khronos 3D Commerce, 2024), on linear Rec. 709 RGB.
SHARED_FN vec3 tonemapPbrNeutral(vec3 color) {
    const float startCompression = 0.8f - 0.04f;
    const float desaturation = 0.15f;
    color = max(color, vec3(0.0f));
    float darkest = min(color.x, min(color.y, color.z));
    float offset = darkest < 0.08f ? darkest - 6.25f * darkest * darkest : 0.04f;
    color = color - vec3(offset);
    float peak = max(color.x, max(color.y, color.z));
    if (peak < startCompression) return color;
    const float d = 1.0f - startCompression;
    float newPeak = 1.0f - d * d / (peak + d - startCompression);
    color = color * (newPeak / peak);
    float g = 1.0f - 1.0f / (desaturation * (peak - newPeak) + 1.0f);
    return mix(color, vec3(newPeak), g);
}

// A curve by its TONE_CURVE_* number.
SHARED_FN vec3 toneMap(vec3 color, uint curve) {
    if (curve == TONE_CURVE_ACES) return vec3(tonemapAces(color.x), tonemapAces(color.y), tonemapAces(color.z));
    return clamp(tonemapPbrNeutral(color), vec3(0.0f), vec3(1.0f));
}

SHARED_FN float encodeSrgb(float linear) {
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * pow(linear, 1.0f / 2.4f) - 0.055f;
}

VCT_SHARED_END

#endif
