// glTF alphaMode on screen and in the shadow maps: which fragments of a surface are drawn, given its
// coverage (the base colour's alpha, factor × texture). Shared by C++ (the tests' twins) and GLSL.
#ifndef VCT_ALPHA_COVERAGE_H
#define VCT_ALPHA_COVERAGE_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

// GpuMaterial::alphaMode, in the order of vct::AlphaMode.
const uint ALPHA_OPAQUE = 0u;
const uint ALPHA_MASK = 1u;
const uint ALPHA_BLEND = 2u;

// Interleaved gradient noise (Jimenez 2014, "Next Generation Post Processing in Call of Duty:
// Advanced Warfare"): a threshold in [0, 1) per pixel, the same every frame, spread evenly over any
// few pixels, so a coverage c keeps close to a fraction c of a small block.
SHARED_FN float blendThreshold(vec2 pixel) {
    return fract(52.9829189f * fract(dot(floor(pixel), vec2(0.06711056f, 0.00583715f))));
}

// Whether the fragment at `pixel` (framebuffer coordinates) is drawn.
// MASK (glTF 2.0 §3.9.4): the surface is there where its coverage reaches the cutoff, a hole elsewhere.
// BLEND, approximated as stochastic ("screen-door") transparency: the fragment is drawn where its
// coverage exceeds the pixel's threshold, so a surface of coverage c covers a fraction c of the
// pixels and what lies behind it shows through the rest. The shading pass sees one surface per
// pixel (no sorting, no blending); at full resolution a 50 % glass looks dithered, not tinted.
SHARED_FN bool coversPixel(uint alphaMode, float alphaCutoff, float coverage, vec2 pixel) {
    if (alphaMode == ALPHA_MASK) return coverage >= alphaCutoff;
    if (alphaMode == ALPHA_BLEND) return coverage > blendThreshold(pixel);
    return true;
}

VCT_SHARED_END

#endif
