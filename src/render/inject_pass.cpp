#include "render/inject_pass.h"

#include <algorithm>

#include "gpu/commands.h"
#include "render/voxel_grid_fit.h"

namespace vct {

InjectPass::InjectPass(GpuContext& context, uint32_t voxelResolution, bool anisotropic, uint32_t bounces)
    : resolution(voxelResolution), context_(context) {
    ImageDesc desc;
    desc.type = VK_IMAGE_TYPE_3D;
    desc.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    desc.extent = {resolution, resolution, resolution};
    desc.mipLevels = voxelMipCount(resolution);
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                 VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    desc.debugName = "voxel radiance";
    radiance = GpuImage(context, desc);
    if (bounces >= 2) {
        ImageDesc bounceDesc = desc;
        bounceDesc.mipLevels = 1;
        bounceDesc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        bounceDesc.debugName = "voxel radiance, second bounce";
        bounceTarget = GpuImage(context, bounceDesc);
    }
    volumeSampler = Sampler(context, vct::volumeSampler());
    if (anisotropic) {
        const char* names[6] = {"voxel radiance +x", "voxel radiance -x", "voxel radiance +y",
                                "voxel radiance -y", "voxel radiance +z", "voxel radiance -z"};
        ImageDesc directionalDesc = desc;
        directionalDesc.extent = {resolution / 2, resolution / 2, resolution / 2};
        directionalDesc.mipLevels = desc.mipLevels - 1;
        for (const char* name : names) {
            directionalDesc.debugName = name;
            directional.push_back(GpuImage(context, directionalDesc));
        }
    }

    pipeline = createComputePipeline(context, "inject.comp");
}

void InjectPass::record(VkCommandBuffer commands, VkBuffer frameConstants, VkBuffer lights, VkBuffer shadowViews,
                        const ShadowPass& shadows, const VoxelizePass& voxels) {
    // Level 0 is rewritten whole; the previous frame's cone tracing must be done reading it.
    prepareLayouts(commands);
    dispatch(commands, frameConstants, lights, shadowViews, shadows, voxels,
             radiance.mipViews.empty() ? radiance.view : radiance.mipViews[0], 0u);
}

void InjectPass::recordBounce(VkCommandBuffer commands, VkBuffer frameConstants, VkBuffer lights,
                              VkBuffer shadowViews, const ShadowPass& shadows, const VoxelizePass& voxels) {
    imageBarrier(commands, bounceTarget.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                 VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE,
                 VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    dispatch(commands, frameConstants, lights, shadowViews, shadows, voxels, bounceTarget.view, 1u);
    // The bounce's level 0 replaces the first bounce's; every texel is written.
    imageBarrier(commands, bounceTarget.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                 VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                 VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    imageBarrier(commands, radiance.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                 VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                 0, 1);
    VkImageCopy region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.extent = {resolution, resolution, resolution};
    vkCmdCopyImage(commands, bounceTarget.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, radiance.image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    imageBarrier(commands, radiance.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                 VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT, 0, 1);
}

void InjectPass::dispatch(VkCommandBuffer commands, VkBuffer frameConstants, VkBuffer lights, VkBuffer shadowViews,
                          const ShadowPass& shadows, const VoxelizePass& voxels, VkImageView target,
                          uint32_t gatherBounce) {
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline);
    DescriptorPush push;
    push.sampledImages(12, directionalViews(), volumeSampler.sampler, VK_IMAGE_LAYOUT_GENERAL)
        .buffer(0, frameConstants, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
        .buffer(1, lights)
        .buffer(2, shadowViews)
        .sampledImage(3, shadows.sunMaps.view, shadows.compareSampler.sampler)
        .sampledImage(4, shadows.localMaps.view, shadows.compareSampler.sampler)
        .storageImage(5, voxels.albedoOpacity.view)
        .storageImage(6, voxels.normal.view)
        .storageImage(7, voxels.emission.view)
        .storageImage(8, target)
        .sampledImage(9, radiance.view, volumeSampler.sampler, VK_IMAGE_LAYOUT_GENERAL)
        .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout);
    vkCmdPushConstants(commands, pipeline.layout, VK_SHADER_STAGE_ALL, 0, sizeof(gatherBounce), &gatherBounce);
    const uint32_t groups = (resolution + 3) / 4;
    vkCmdDispatch(commands, groups, groups, groups);
    memoryBarrier(commands, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

void InjectPass::prepareLayouts(VkCommandBuffer commands) {
    std::vector<const GpuImage*> volumes = {&radiance};
    for (const GpuImage& chain : directional) volumes.push_back(&chain);
    for (const GpuImage* volume : volumes)
        imageBarrier(commands, volume->image, VK_IMAGE_ASPECT_COLOR_BIT,
                     initialized ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                     VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                     VK_ACCESS_2_SHADER_READ_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                     VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    initialized = true;
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
