#include "render/inject_pass.h"

#include <algorithm>

#include "bindings.h"
#include "gpu/commands.h"
#include "gpu/pass_uses.h"
#include "surface_planes.h"

namespace vct {

InjectPass::InjectPass(GpuContext& context)
    : pipeline(createComputePipeline(context, "inject.comp", {},
                                     specializationConstants({{glsl::AREA_LIGHTS_CACHED_CONSTANT_ID, 0u}}))),
      cachedAreaPipeline(createComputePipeline(context, "inject.comp", {},
                                               specializationConstants({{glsl::AREA_LIGHTS_CACHED_CONSTANT_ID, 1u}}))),
      gatherPipeline(context, "bounce_gather.comp"),
      context_(context) {
    forgetAreaLights(0);
}

void InjectPass::forgetAreaLights(uint32_t occupiedVoxels) {
    areaLightsCached_ = false;
    if (occupiedVoxels == areaLightCapacity_ && areaLightCache_.buffer != VK_NULL_HANDLE) return;
    // A buffer of at least one item, so the binding is valid where nothing is kept.
    areaLightCapacity_ = occupiedVoxels;
    areaLightCache_ = Buffer(context_, VkDeviceSize(std::max(occupiedVoxels, 1u)) * 3 * sizeof(float),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
}

void InjectPass::record(VkCommandBuffer commands, VkBuffer frameConstants, const LightBuffers& lights,
                        const ShadowPass& shadows, VoxelVolumes& volumes, bool addGathered) {
    // Level 0 is rewritten whole, after the cones that read it (the last frame's, a gather's).
    PassUses uses;
    for (const GpuImage* voxels : {&volumes.albedoOpacity, &volumes.normal, &volumes.emission})
        uses.use(*voxels, access::computeRead);
    for (const GpuImage* maps : {&shadows.sunMaps, &shadows.localMaps, &shadows.areaMaps})
        uses.use(*maps, access::computeSampled);
    uses.use(volumes.radiance, access::computeWrite);
    if (addGathered) uses.use(volumes.gatheredLight, access::computeRead);
    uses.use(volumes.occupiedVoxels, access::computeRead)
        .use(volumes.occupiedDispatch, access::computeRead | access::indirectArguments)
        .use(areaLightCache_, access::computeWrite)
        .record(commands);
    const Pipeline& chosen = areaLightsCached_ ? cachedAreaPipeline : pipeline;
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, chosen.pipeline);
    // Without a bounce target (one bounce) nothing is added: the radiance volume stands in.
    const VkImageView gathered = addGathered ? volumes.gatheredLight.view : volumes.lightLevelZeroViews()[0];
    DescriptorPush()
        .buffer(glsl::FRAME_BINDING, frameConstants, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
        .buffer(glsl::LIGHTS_BINDING, lights.lights)
        .buffer(glsl::SHADOW_VIEWS_BINDING, lights.shadowViews)
        .sampledImage(glsl::SUN_SHADOW_MAPS_BINDING, shadows.sunMaps.view, shadows.compareSampler.sampler)
        .sampledImage(glsl::LOCAL_SHADOW_MAPS_BINDING, shadows.localMaps.view, shadows.compareSampler.sampler)
        .storageImage(glsl::VOXEL_ALBEDO_BINDING, volumes.albedoOpacity.view)
        .storageImage(glsl::VOXEL_NORMAL_BINDING, volumes.normal.view)
        .buffer(glsl::EMITTER_TRIANGLES_BINDING, lights.emitterTriangles)
        .storageImage(glsl::VOXEL_RADIANCE_BINDING, volumes.lightLevelZeroViews()[0])
        .storageImage(glsl::GATHERED_LIGHT_BINDING, gathered)
        .buffer(glsl::OCCUPIED_VOXELS_BINDING, volumes.occupiedVoxels.buffer)
        .buffer(glsl::OCCUPIED_LIST_BINDING, volumes.occupiedDispatch.buffer)
        .storageImage(glsl::VOXEL_EMISSION_BINDING, volumes.emission.view)
        .sampledImage(glsl::AREA_SHADOW_MAPS_BINDING, shadows.areaMaps.view, shadows.compareSampler.sampler)
        .buffer(glsl::AREA_LIGHT_CACHE_BINDING, areaLightCache_.buffer)
        .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, chosen);
    const uint32_t add = addGathered ? 1u : 0u;
    vkCmdPushConstants(commands, chosen.layout, VK_SHADER_STAGE_ALL, 0, sizeof(add), &add);
    vkCmdDispatchIndirect(commands, volumes.occupiedDispatch.buffer, 0);
    areaLightsCached_ = areaLightCapacity_ > 0;  // what this injection wrote, the next ones read
}

void InjectPass::recordGather(VkCommandBuffer commands, VkBuffer frameConstants, const VoxelVolumes& volumes,
                              const SkyImage& sky, Slice slice, uint32_t occupiedVoxels, bool skipEmptySpace) {
    // Sized on the host, not by the list's indirect dispatch: lavapipe runs each workgroup through
    // the whole shader, every loop once, even where no invocation has an item, and a 1/20 slice
    // dispatched over the whole list cost twice its own gather.
    const uint32_t items = (occupiedVoxels + slice.count - 1 - slice.phase) / slice.count;
    const uint32_t groups = std::min((items + glsl::WORK_LIST_GROUP_SIZE - 1) / glsl::WORK_LIST_GROUP_SIZE,
                                     context_.properties.limits.maxComputeWorkGroupCount[0]);
    if (groups == 0) return;
    const Pipeline& gather = gatherPipeline.get(skipEmptySpace);
    PassUses uses;
    for (const GpuImage* voxels : {&volumes.albedoOpacity, &volumes.normal}) uses.use(*voxels, access::computeRead);
    for (const GpuImage* light : volumes.tracedLight()) uses.use(*light, access::computeRead);
    uses.use(volumes.gatheredLight, access::computeWrite)
        .use(volumes.occupiedVoxels, access::computeRead)
        .use(volumes.occupiedDispatch, access::computeRead)
        .record(commands);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, gather.pipeline);
    const VkSampler sampler = volumes.sampler.sampler;
    DescriptorPush()
        .buffer(glsl::FRAME_BINDING, frameConstants, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
        .storageImage(glsl::VOXEL_ALBEDO_BINDING, volumes.albedoOpacity.view)
        .storageImage(glsl::VOXEL_NORMAL_BINDING, volumes.normal.view)
        .storageImage(glsl::GATHERED_LIGHT_BINDING, volumes.gatheredLight.view)
        .sampledImage(glsl::VOXEL_RADIANCE_BINDING, volumes.radiance.view, sampler, VK_IMAGE_LAYOUT_GENERAL)
        .sampledImage(glsl::SURFACE_PLANES_BINDING, volumes.surfacePlanesView(), sampler, VK_IMAGE_LAYOUT_GENERAL)
        .buffer(glsl::OCCUPIED_VOXELS_BINDING, volumes.occupiedVoxels.buffer)
        .buffer(glsl::OCCUPIED_LIST_BINDING, volumes.occupiedDispatch.buffer)
        .sampledImages(glsl::DIRECTIONAL_VOXELS_BINDING, volumes.directionalViews(), sampler, VK_IMAGE_LAYOUT_GENERAL)
        .sampledImage(glsl::SKY_BINDING, sky.view(), sky.sampler())
        .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, gather);
    vkCmdPushConstants(commands, gather.layout, VK_SHADER_STAGE_ALL, 0, sizeof(slice), &slice);
    vkCmdDispatch(commands, groups, 1, 1);
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
