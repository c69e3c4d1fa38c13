// The full-screen lighting pass: direct light (and, with cone tracing, indirect light) per sample
// of the G-buffer, into an HDR radiance target in the scene's units.
#pragma once

#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "render/gbuffer_pass.h"
#include "render/shadow_pass.h"
#include "render/voxel_volumes.h"

namespace vct {

struct ShadeInputs {
    VkBuffer frameConstants;
    VkBuffer materials;
    VkBuffer lights;
    VkBuffer shadowViews;
    VkImageView reducedDiffuse = VK_NULL_HANDLE;  // DiffuseConesPass::diffuse, when the cones run reduced
};

struct ShadePass {
    ShadePass(GpuContext& context, uint32_t width, uint32_t height);

    // Leaves `radiance` in SHADER_READ_ONLY_OPTIMAL.
    void record(VkCommandBuffer commands, const ShadeInputs& inputs, const GBufferPass& gbuffer,
                const ShadowPass& shadows, const VoxelVolumes& volumes);

    uint32_t width, height;
    GpuImage radiance;  // RGBA32F
    Sampler pointSampler;
    Pipeline pipeline;

private:
    GpuContext& context_;
};

}  // namespace vct
