#include "render/inject_pass.h"

#include <algorithm>

#include "gpu/commands.h"

namespace vct {

InjectPass::InjectPass(GpuContext& context)
    : pipeline(createComputePipeline(context, "inject.comp")), context_(context) {}

void InjectPass::record(VkCommandBuffer commands, VkBuffer frameConstants, VkBuffer lights, VkBuffer shadowViews,
                        const ShadowPass& shadows, VoxelVolumes& volumes) {
    // Level 0 is rewritten whole; the previous frame's cone tracing must be done reading it.
    memoryBarrier(commands, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_READ_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    dispatch(commands, frameConstants, lights, shadowViews, shadows, volumes, volumes.lightLevelZeroViews()[0], 0u);
}

void InjectPass::recordBounce(VkCommandBuffer commands, VkBuffer frameConstants, VkBuffer lights, VkBuffer shadowViews,
                              const ShadowPass& shadows, VoxelVolumes& volumes) {
    const GpuImage &bounceTarget = volumes.bounceTarget, &radiance = volumes.radiance;
    dispatch(commands, frameConstants, lights, shadowViews, shadows, volumes, bounceTarget.view, 1u);
    // The bounce's level 0 replaces the first bounce's: every occupied texel is written, and the
    // voxelizer zeroed the empty ones. Copies want the transfer layouts, so the two images leave
    // GENERAL for the copy only.
    imageBarrier(commands, bounceTarget.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                 VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                 VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    imageBarrier(commands, radiance.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                 VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, 0,
                 1);
    VkImageCopy region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.extent = {volumes.resolution, volumes.resolution, volumes.resolution};
    vkCmdCopyImage(commands, bounceTarget.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, radiance.image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    imageBarrier(commands, bounceTarget.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                 VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                 VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    imageBarrier(commands, radiance.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                 VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT, 0, 1);
}

void InjectPass::dispatch(VkCommandBuffer commands, VkBuffer frameConstants, VkBuffer lights, VkBuffer shadowViews,
                          const ShadowPass& shadows, const VoxelVolumes& volumes, VkImageView target,
                          uint32_t gatherBounce) {
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline);
    const VkSampler sampler = volumes.sampler.sampler;
    DescriptorPush()
        .sampledImages(12, volumes.directionalViews(), sampler, VK_IMAGE_LAYOUT_GENERAL)
        .buffer(0, frameConstants, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
        .buffer(1, lights)
        .buffer(2, shadowViews)
        .sampledImage(3, shadows.sunMaps.view, shadows.compareSampler.sampler)
        .sampledImage(4, shadows.localMaps.view, shadows.compareSampler.sampler)
        .storageImage(5, volumes.albedoOpacity.view)
        .storageImage(6, volumes.normal.view)
        .storageImage(7, volumes.emission.view)
        .storageImage(8, target)
        .sampledImage(9, volumes.radiance.view, sampler, VK_IMAGE_LAYOUT_GENERAL)
        .buffer(10, volumes.occupiedVoxels.buffer)
        .buffer(11, volumes.occupiedDispatch.buffer)
        .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout);
    vkCmdPushConstants(commands, pipeline.layout, VK_SHADER_STAGE_ALL, 0, sizeof(gatherBounce), &gatherBounce);
    vkCmdDispatchIndirect(commands, volumes.occupiedDispatch.buffer, 0);
    memoryBarrier(commands, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

float radianceStorageScale(const std::vector<Light>& lights, const Scene& scene, float voxelSize) {
    float brightest = 0.0f;
    for (const Light& light : lights) {
        const float intensity = light.intensity * std::max({light.color.r, light.color.g, light.color.b});
        // A Lambertian voxel one voxel from a point light reflects at most I/d²/π.
        brightest += light.type == LightType::Directional ? intensity / 3.14159265f
                                                          : intensity / (voxelSize * voxelSize * 3.14159265f);
    }
    for (const Material& material : scene.materials)
        brightest = std::max({brightest, material.emission.r, material.emission.g, material.emission.b});
    // float16 holds up to 65504: the brightest voxel maps to 1024, leaving room for sums in the mips.
    return brightest > 0.0f ? 1024.0f / brightest : 1.0f;
}

}  // namespace vct
