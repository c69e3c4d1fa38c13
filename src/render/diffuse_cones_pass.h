// The diffuse cones at a reduced resolution (ImageSettings::diffuseDownscale): one G-buffer sample
// per block traces them, and the shading pass upsamples the result along the surfaces
// (shaders_glsl/reduced_diffuse.glsl). Only created when the downscale is above 1.
#pragma once

#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "render/gbuffer_pass.h"
#include "render/voxel_volumes.h"

namespace vct {

struct DiffuseConesPass {
    // `samplesWide` × `samplesHigh` is the G-buffer's size; the target is that / downscale, rounded up.
    DiffuseConesPass(GpuContext& context, uint32_t samplesWide, uint32_t samplesHigh, uint32_t downscale);

    // Leaves `gathered` in SHADER_READ_ONLY_OPTIMAL for the shading pass's fragment shader.
    void record(VkCommandBuffer commands, VkBuffer frameConstants, const GBufferPass& gbuffer,
                const VoxelVolumes& volumes);

    uint32_t width, height;
    GpuImage gathered;  // RGBA32F: Σ wᵢ Lᵢ of the diffuse cones (scene units), weighted occlusion
    Sampler pointSampler;
    Pipeline pipeline;

private:
    GpuContext& context_;
};

}  // namespace vct
