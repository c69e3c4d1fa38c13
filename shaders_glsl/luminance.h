// Rec. 709 luminance of linear RGB (sRGB primaries): the one weighting of colours the renderer, the
// scene analysis (area lights, the environment's sun, the default light), the bench's metrics and
// the path tracer share.
#ifndef VCT_LUMINANCE_H
#define VCT_LUMINANCE_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

const vec3 REC709_LUMINANCE = vec3(0.2126f, 0.7152f, 0.0722f);

SHARED_FN float luminance(vec3 rgb) { return dot(rgb, REC709_LUMINANCE); }

VCT_SHARED_END

#ifdef __cplusplus
namespace vct::glsl {
// In double precision, for sums over many pixels or texels.
inline double luminance(const glm::dvec3& rgb) { return glm::dot(rgb, glm::dvec3(REC709_LUMINANCE)); }
}  // namespace vct::glsl
#endif

#endif
