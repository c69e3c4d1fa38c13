// The pipelines of compute shaders that trace cones (cone_tracing.glsl), one per setting of the
// empty-space skipping: a specialization constant, since lavapipe runs the skip's test at every
// step even where it is off.
#pragma once

#include <string>
#include <vector>

#include "gpu/pipelines.h"

namespace vct {

// `own` (a shader's own constants, element i is constant_id i) with the empty-space skipping's.
std::vector<uint32_t> coneTracingSpecialization(bool skipEmptySpace, std::vector<uint32_t> own = {});

class ConeTracingComputePipeline {
public:
    ConeTracingComputePipeline(GpuContext& context, std::string shaderName);
    // Built on first use for each setting: a renderer uses one.
    const Pipeline& get(bool skipEmptySpace);

private:
    GpuContext& context_;
    std::string shaderName_;
    Pipeline pipelines_[2];
};

}  // namespace vct
