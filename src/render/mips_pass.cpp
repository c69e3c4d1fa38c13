#include "render/mips_pass.h"

#include <algorithm>

#include "gpu/commands.h"

namespace vct {

MipsPass::MipsPass(GpuContext& context) : context_(context) {
    VkDescriptorSetLayout setLayout =
        createPushDescriptorLayout(context, {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT},
                                             {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT}});
    VkPipelineLayout layout = createPipelineLayout(context, {setLayout});
    pipeline = Pipeline(context, createComputePipeline(context, layout, "mips.comp"), layout, setLayout);
}

void MipsPass::record(VkCommandBuffer commands, const GpuImage& volume) {
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline);
    for (uint32_t level = 1; level < volume.desc.mipLevels; ++level) {
        DescriptorPush()
            .storageImage(0, volume.mipViews[level - 1])
            .storageImage(1, volume.mipViews[level])
            .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout);
        const uint32_t size = std::max(volume.desc.extent.width >> level, 1u);
        const uint32_t groups = (size + 3) / 4;
        vkCmdDispatch(commands, groups, groups, groups);
        // Each level is read by the next one.
        memoryBarrier(commands, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    }
}

}  // namespace vct
