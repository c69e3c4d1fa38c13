// What shares a G-buffer channel, written by gbuffer.frag.glsl and read by the shading pass.
#ifndef VCT_GBUFFER_PACKING_H
#define VCT_GBUFFER_PACKING_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

// The normal target's alpha holds which side of the surface the camera sees (emission leaves the
// front face only) and the occlusion texture's value o ∈ [0, 1] as ±(1 + o): the sign is the side,
// the magnitude the occlusion, in float16's steps of 2⁻¹⁰ over [1, 2].
SHARED_FN float gbufferSideOcclusion(bool frontFace, float occlusion) {
    return frontFace ? 1.0f + occlusion : -1.0f - occlusion;
}

SHARED_FN bool gbufferFrontFace(float sideOcclusion) { return sideOcclusion > 0.0f; }

SHARED_FN float gbufferOcclusion(float sideOcclusion) { return clamp(abs(sideOcclusion) - 1.0f, 0.0f, 1.0f); }

VCT_SHARED_END

#endif
