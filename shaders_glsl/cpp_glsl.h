// Lets one header be read both by GLSL and by C++ (with GLM), so that the CPU and GPU
// versions of a struct or a formula cannot drift apart (the niagara pattern).
// Shared code uses float literals with an `f` suffix and no `out` parameters, which
// both languages read the same way.
#ifndef VCT_CPP_GLSL_H
#define VCT_CPP_GLSL_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
#define VCT_SHARED_BEGIN \
    namespace vct::glsl { \
    using namespace glm; \
    using uint = uint32_t;
#define VCT_SHARED_END }
#define SHARED_FN inline
#else
#define VCT_SHARED_BEGIN
#define VCT_SHARED_END
#define SHARED_FN
#endif

#endif
