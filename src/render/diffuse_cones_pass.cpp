#include "render/diffuse_cones_pass.h"

#include "gpu/commands.h"

namespace vct {

DiffuseConesPass::DiffuseConesPass(GpuContext& context, uint32_t samplesWide, uint32_t samplesHigh, uint32_t downscale)
    : width((samplesWide + downscale - 1) / downscale),
      height((samplesHigh + downscale - 1) / downscale),
      context_(context) {
    ImageDesc desc;
    desc.format = VK_FORMAT_R32G32B32A32_SFLOAT;  // scene units: a sun's light can exceed float16
    desc.extent = {width, height, 1};
    desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    desc.debugName = "reduced diffuse cones";
    gathered = GpuImage(context, desc);
    pointSampler = Sampler(context, nearestClampSampler());

    GraphicsPipelineDesc pipelineDesc;
    pipelineDesc.vertexShader = "fullscreen.vert";
    pipelineDesc.fragmentShader = "diffuse_gather.frag";
    pipelineDesc.colorFormats = {desc.format};
    pipeline = createGraphicsPipeline(context, pipelineDesc);
}

void DiffuseConesPass::record(VkCommandBuffer commands, VkBuffer frameConstants, const GBufferPass& gbuffer,
                              const VoxelVolumes& volumes) {
    // The last frame's shading must be done sampling the target before it is rewritten.
    imageBarrier(commands, gathered.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                 VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_NONE,
                 VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    drawFullScreen(commands, gathered.view, width, height, [&] {
        vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.pipeline);
        const VkSampler volumeSampler = volumes.sampler.sampler;
        DescriptorPush()
            .sampledImages(12, volumes.directionalViews(), volumeSampler, VK_IMAGE_LAYOUT_GENERAL)
            .buffer(0, frameConstants, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
            .sampledImage(6, gbuffer.position.view, pointSampler.sampler)
            .sampledImage(7, gbuffer.normal.view, pointSampler.sampler)
            .sampledImage(9, volumes.radiance.view, volumeSampler, VK_IMAGE_LAYOUT_GENERAL)
            .push(context_, commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout);
    });
    imageBarrier(commands, gathered.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                 VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                 VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

}  // namespace vct
