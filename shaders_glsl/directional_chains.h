// How anisotropic voxels lay out their directional chains: one image per axis holds the chain for
// rays along +axis and the one for rays along −axis, stacked along z. Level k of an image is
// (s, s, 3s) texels for chains of side s = (grid side / 2) >> k: the +axis chain fills z in [0, s),
// the −axis chain [2s, 3s), and the third between them stays empty (cleared at creation, never
// written). At every level that third is at least one texel, so trilinear filtering near the
// grid's z faces reads zeros from it, as the transparent border outside the grid. Shared by C++
// and GLSL.
#ifndef VCT_DIRECTIONAL_CHAINS_H
#define VCT_DIRECTIONAL_CHAINS_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

const uint DIRECTIONAL_DEPTH_SIDES = 3u;     // an image's depth, in chain sides
const uint DIRECTIONAL_NEGATIVE_SIDES = 2u;  // where the −axis chain starts, in chain sides

// The normalized z at which a chain's image holds grid coordinate z (0..1 over the grid). Outside
// the grid by more than half its side the two schemes both read nothing, so z is clamped there: a
// sample further out would reach through the empty third into the other chain.
SHARED_FN float directionalDepth(float z, bool negative) {
    return (clamp(z, -0.5f, 1.5f) + (negative ? float(DIRECTIONAL_NEGATIVE_SIDES) : 0.0f)) /
           float(DIRECTIONAL_DEPTH_SIDES);
}

VCT_SHARED_END

#endif
