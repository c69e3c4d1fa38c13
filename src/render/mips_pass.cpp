#include "render/mips_pass.h"

#include <algorithm>

#include "bindings.h"
#include "gpu/commands.h"
#include "gpu/pass_uses.h"
#include "work_list.h"

namespace vct {

MipsPass::MipsPass(GpuContext& context)
    : pipeline(createComputePipeline(context, "mips.comp")),
      directionalFromScenePipeline(
          createComputePipeline(context, "mips_anisotropic.comp", {},
                                specializationConstants({{glsl::FINER_IS_SCENE_LEVEL_CONSTANT_ID, 1u}}))),
      directionalPipeline(
          createComputePipeline(context, "mips_anisotropic.comp", {},
                                specializationConstants({{glsl::FINER_IS_SCENE_LEVEL_CONSTANT_ID, 0u}}))),
      surfacePlanesPipeline(createComputePipeline(context, "surface_planes.comp")),
      context_(context) {}

static VkImageView mipView(const GpuImage& image, uint32_t level) {
    return image.mipViews.empty() ? image.view : image.mipViews[level];
}

void MipsPass::record(VkCommandBuffer commands, const VoxelVolumes& volumes, bool rayVisibility) {
    recordIsotropic(commands, volumes.radiance);
    recordDirectional(commands, volumes, rayVisibility);
    recordSurfacePlanes(commands, volumes);
}

void MipsPass::recordSurfacePlanes(VkCommandBuffer commands, const VoxelVolumes& volumes) {
    const GpuImage& planes = volumes.surfacePlanes;
    if (planes.image == VK_NULL_HANDLE) return;
    PassUses()
        .use(volumes.radiance, access::computeRead)
        .use(volumes.normal, access::computeRead)
        .use(planes, access::computeWrite)
        .record(commands);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, surfacePlanesPipeline.pipeline);
    DescriptorPush()
        .storageImage(glsl::VOXEL_RADIANCE_BINDING, mipView(volumes.radiance, 0))
        .storageImage(glsl::VOXEL_NORMAL_BINDING, volumes.normal.view)
        .storageImage(glsl::SURFACE_PLANES_BINDING, mipView(planes, 0))
        .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, surfacePlanesPipeline);
    const uint32_t groups = (planes.desc.extent.width + 3) / 4;
    vkCmdDispatch(commands, groups, groups, groups);
    recordIsotropic(commands, planes);
}

void MipsPass::recordDirectional(VkCommandBuffer commands, const VoxelVolumes& volumes, bool rayVisibility) {
    const GpuImage& volume = volumes.radiance;
    const std::vector<GpuImage>& directional = volumes.directional;
    if (directional.empty()) return;
    const uint32_t levels = directional[0].desc.mipLevels;
    for (uint32_t level = 0; level < levels; ++level) {
        const Pipeline& levelPipeline = level == 0 ? directionalFromScenePipeline : directionalPipeline;
        // Each level is built from the one before (the first from the radiance's level 0).
        PassUses uses;
        uses.use(volume, access::computeRead).use(volumes.normal, access::computeRead);
        for (uint32_t axis = 0; axis < 3; ++axis)
            uses.use(directional[axis], access::computeWrite).use(volumes.leavingSurfaces[axis], access::computeWrite);
        uses.record(commands);
        vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, levelPipeline.pipeline);
        const uint32_t size = std::max(directional[0].desc.extent.width >> level, 1u);
        for (uint32_t axis = 0; axis < 3; ++axis) {
            // The first directional level is built from the shared finest level.
            const GpuImage& chains = directional[axis];
            const GpuImage& leaving = volumes.leavingSurfaces[axis];
            // The first level takes its surfaces from the scene's normals; its finer flags are
            // bound but not read.
            DescriptorPush()
                .storageImage(glsl::FINER_LEVEL_BINDING, level == 0 ? mipView(volume, 0) : mipView(chains, level - 1))
                .storageImage(glsl::COARSER_LEVEL_BINDING, mipView(chains, level))
                .storageImage(glsl::VOXEL_NORMAL_BINDING, volumes.normal.view)
                .storageImage(glsl::FINER_LEAVING_BINDING, mipView(leaving, level == 0 ? 0 : level - 1))
                .storageImage(glsl::COARSER_LEAVING_BINDING, mipView(leaving, level))
                .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, levelPipeline);
            const uint32_t push[2] = {axis, rayVisibility ? 1u : 0u};  // mips_anisotropic.comp's Push
            vkCmdPushConstants(commands, levelPipeline.layout, VK_SHADER_STAGE_ALL, 0, sizeof(push), push);
            // One invocation per line of texels along the axis.
            const uint32_t lines = size * size;
            vkCmdDispatch(commands, (lines + glsl::WORK_LIST_GROUP_SIZE - 1) / glsl::WORK_LIST_GROUP_SIZE, 1, 1);
        }
    }
}

void MipsPass::recordIsotropic(VkCommandBuffer commands, const GpuImage& volume) {
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline);
    for (uint32_t level = 1; level < volume.desc.mipLevels; ++level) {
        // Each level from the one before.
        PassUses().use(volume, access::computeWrite).record(commands);
        DescriptorPush()
            .storageImage(glsl::FINER_LEVEL_BINDING, mipView(volume, level - 1))
            .storageImage(glsl::COARSER_LEVEL_BINDING, mipView(volume, level))
            .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
        const uint32_t size = std::max(volume.desc.extent.width >> level, 1u);
        const uint32_t groups = (size + 3) / 4;
        vkCmdDispatch(commands, groups, groups, groups);
    }
}

}  // namespace vct
