#include "render/cone_tracing_pipeline.h"

#include <algorithm>

#include "bindings.h"
#include "gpu_types.h"

namespace vct {

std::vector<uint32_t> coneTracingSpecialization(bool skipEmptySpace, std::vector<uint32_t> own) {
    own.resize(std::max<size_t>(own.size(), glsl::SKIP_EMPTY_SPACE_CONSTANT_ID + 1), 0u);
    own[glsl::SKIP_EMPTY_SPACE_CONSTANT_ID] = skipEmptySpace ? 1u : 0u;
    return own;
}

ConeTracingComputePipeline::ConeTracingComputePipeline(GpuContext& context, std::string shaderName)
    : context_(context), shaderName_(std::move(shaderName)) {}

const Pipeline& ConeTracingComputePipeline::get(bool skipEmptySpace) {
    Pipeline& slot = pipelines_[skipEmptySpace ? 1 : 0];
    if (slot.pipeline == VK_NULL_HANDLE)
        slot = createComputePipeline(context_, shaderName_, {}, coneTracingSpecialization(skipEmptySpace));
    return slot;
}

}  // namespace vct
