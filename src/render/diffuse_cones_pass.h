// The diffuse cones at a reduced resolution (ImageSettings::diffuseDownscale): one G-buffer sample
// per block traces them, every sample blends the nearest along its own surface, and the samples
// where that fails trace their own, from a work list (shaders_glsl/reduced_diffuse.glsl). Only
// created when the downscale is above 1.
#pragma once

#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "render/gbuffer_pass.h"
#include "render/voxel_volumes.h"

namespace vct {

struct DiffuseConesPass {
    // `samplesWide` × `samplesHigh` is the G-buffer's size; the reduced image is that / downscale,
    // rounded up.
    DiffuseConesPass(GpuContext& context, uint32_t samplesWide, uint32_t samplesHigh, uint32_t downscale);

    // Leaves `diffuse` in SHADER_READ_ONLY_OPTIMAL for the shading pass's fragment shader.
    void record(VkCommandBuffer commands, VkBuffer frameConstants, const GBufferPass& gbuffer,
                const VoxelVolumes& volumes);

    // RGBA32F (scene units: a sun's light can exceed float16): Σ wᵢ Lᵢ of the diffuse cones and
    // their weighted occlusion, per representative (`gathered`) and per sample (`diffuse`).
    GpuImage gathered;
    GpuImage diffuse;
    Buffer fallbackSamples;  // the samples that trace their own cones, packed 16 bits a coordinate
    Buffer fallbackList;     // glsl::WorkListHeader over them
    Sampler pointSampler;
    Pipeline gatherPipeline, upsamplePipeline, fallbackPipeline;

private:
    GpuContext& context_;
};

}  // namespace vct
