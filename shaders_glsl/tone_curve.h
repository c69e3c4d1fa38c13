// The tone curve of every image made for people (PNG files, the viewer's window), written once for
// C++ and GLSL: radiance × exposure, Narkowicz's fit of the ACES filmic curve (a familiar look,
// monotonic, [0, ∞) onto [0, 1)), then sRGB encoding. PFM output and the benchmark never use it.
#ifndef VCT_TONE_CURVE_H
#define VCT_TONE_CURVE_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

SHARED_FN float tonemapAces(float x) {
    x = max(x, 0.0f) * 0.6f;
    return clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}

SHARED_FN float encodeSrgb(float linear) {
    return linear <= 0.0031308f ? 12.92f * linear : 1.055f * pow(linear, 1.0f / 2.4f) - 0.055f;
}

VCT_SHARED_END

#endif
