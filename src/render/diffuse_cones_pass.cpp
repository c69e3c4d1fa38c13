#include "render/diffuse_cones_pass.h"

#include "gpu/commands.h"
#include "work_list.h"

namespace vct {
namespace {

GpuImage diffuseImage(GpuContext& context, uint32_t width, uint32_t height, const char* name) {
    ImageDesc desc;
    desc.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    desc.extent = {width, height, 1};
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    desc.debugName = name;
    return GpuImage(context, desc);
}

// Every texel of `image` is about to be rewritten by compute: the last frame's reads must be done.
void beginWriting(VkCommandBuffer commands, const GpuImage& image) {
    imageBarrier(commands, image.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                 VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_NONE,
                 VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

void finishWriting(VkCommandBuffer commands, const GpuImage& image, VkPipelineStageFlags2 readers) {
    imageBarrier(commands, image.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                 VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, readers, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

}  // namespace

DiffuseConesPass::DiffuseConesPass(GpuContext& context, uint32_t samplesWide, uint32_t samplesHigh, uint32_t downscale)
    : context_(context) {
    gathered = diffuseImage(context, (samplesWide + downscale - 1) / downscale,
                            (samplesHigh + downscale - 1) / downscale, "reduced diffuse cones");
    diffuse = diffuseImage(context, samplesWide, samplesHigh, "diffuse cones per sample");
    fallbackSamples = Buffer(context, VkDeviceSize(samplesWide) * samplesHigh * sizeof(uint32_t),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
    fallbackList = Buffer(
        context, sizeof(glsl::WorkListHeader),
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
        false);
    pointSampler = Sampler(context, nearestClampSampler());
    gatherPipeline = createComputePipeline(context, "diffuse_gather.comp");
    upsamplePipeline = createComputePipeline(context, "diffuse_upsample.comp");
    fallbackPipeline = createComputePipeline(context, "diffuse_fallback.comp");
}

void DiffuseConesPass::record(VkCommandBuffer commands, VkBuffer frameConstants, const GBufferPass& gbuffer,
                              const VoxelVolumes& volumes) {
    const VkSampler volumeSampler = volumes.sampler.sampler, point = pointSampler.sampler;
    const uint32_t reducedWidth = gathered.desc.extent.width, reducedHeight = gathered.desc.extent.height;
    const uint32_t width = diffuse.desc.extent.width, height = diffuse.desc.extent.height;

    // 1. The representatives' cones.
    beginWriting(commands, gathered);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, gatherPipeline.pipeline);
    DescriptorPush()
        .sampledImages(12, volumes.directionalViews(), volumeSampler, VK_IMAGE_LAYOUT_GENERAL)
        .buffer(0, frameConstants, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
        .storageImage(1, gathered.view)
        .sampledImage(6, gbuffer.position.view, point)
        .sampledImage(7, gbuffer.normal.view, point)
        .sampledImage(9, volumes.radiance.view, volumeSampler, VK_IMAGE_LAYOUT_GENERAL)
        .sampledImage(11, volumes.normal.view, volumeSampler, VK_IMAGE_LAYOUT_GENERAL)
        .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, gatherPipeline.layout);
    vkCmdDispatch(commands, (reducedWidth + 7) / 8, (reducedHeight + 7) / 8, 1);
    finishWriting(commands, gathered, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);

    // 2. Every sample upsampled, or listed. The list starts empty, once the last frame's
    //    fallback dispatch has read it.
    memoryBarrier(commands, VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_NONE);
    const glsl::WorkListHeader empty{0u, 1u, 1u, 0u};
    vkCmdUpdateBuffer(commands, fallbackList.buffer, 0, sizeof(empty), &empty);
    memoryBarrier(commands, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    beginWriting(commands, diffuse);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, upsamplePipeline.pipeline);
    DescriptorPush()
        .buffer(0, frameConstants, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
        .storageImage(1, diffuse.view)
        .buffer(2, fallbackSamples.buffer)
        .buffer(3, fallbackList.buffer)
        .sampledImage(6, gbuffer.position.view, point)
        .sampledImage(7, gbuffer.normal.view, point)
        .sampledImage(8, gathered.view, point)
        .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, upsamplePipeline.layout);
    const uint32_t groupLimit = context_.properties.limits.maxComputeWorkGroupCount[0];
    vkCmdPushConstants(commands, upsamplePipeline.layout, VK_SHADER_STAGE_ALL, 0, sizeof(groupLimit), &groupLimit);
    vkCmdDispatch(commands, (width + 7) / 8, (height + 7) / 8, 1);
    memoryBarrier(commands, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                      VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);

    // 3. The listed samples' own cones, into the texels step 2 left.
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, fallbackPipeline.pipeline);
    DescriptorPush()
        .sampledImages(12, volumes.directionalViews(), volumeSampler, VK_IMAGE_LAYOUT_GENERAL)
        .buffer(0, frameConstants, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
        .storageImage(1, diffuse.view)
        .buffer(2, fallbackSamples.buffer)
        .buffer(3, fallbackList.buffer)
        .sampledImage(6, gbuffer.position.view, point)
        .sampledImage(7, gbuffer.normal.view, point)
        .sampledImage(9, volumes.radiance.view, volumeSampler, VK_IMAGE_LAYOUT_GENERAL)
        .sampledImage(11, volumes.normal.view, volumeSampler, VK_IMAGE_LAYOUT_GENERAL)
        .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, fallbackPipeline.layout);
    vkCmdDispatchIndirect(commands, fallbackList.buffer, 0);
    finishWriting(commands, diffuse, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
}

}  // namespace vct
