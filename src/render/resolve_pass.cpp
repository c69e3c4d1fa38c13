#include "render/resolve_pass.h"

#include "bindings.h"
#include "gpu/pass_uses.h"

namespace vct {

ResolvePass::ResolvePass(GpuContext& context, uint32_t targetWidth, uint32_t targetHeight, uint32_t factor)
    : width(targetWidth), height(targetHeight), supersample(factor), context_(context) {
    ImageDesc desc;
    desc.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    desc.extent = {width, height, 1};
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    desc.debugName = "resolved radiance";
    resolved = GpuImage(context, desc);
    pointSampler = Sampler(context, nearestClampSampler());
    pipeline = createComputePipeline(context, "resolve.comp");
}

void ResolvePass::record(VkCommandBuffer commands, const GpuImage& supersampled, float frameShare) {
    // The last mean is kept where this frame adds to it, and may be discarded where it replaces it.
    const bool keeps = frameShare < 1.0f;
    PassUses()
        .use(supersampled, access::computeRead)
        .use(resolved, access::computeWrite, keeps ? Contents::Keep : Contents::Discard)
        .record(commands);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline);
    DescriptorPush()
        .sampledImage(glsl::SUPERSAMPLED_BINDING, supersampled.view, pointSampler.sampler, VK_IMAGE_LAYOUT_GENERAL)
        .storageImage(glsl::RESOLVED_BINDING, resolved.view)
        .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    const struct {
        uint32_t factor;
        float weight;
    } push{supersample, frameShare};
    vkCmdPushConstants(commands, pipeline.layout, VK_SHADER_STAGE_ALL, 0, sizeof(push), &push);
    vkCmdDispatch(commands, (width + 7) / 8, (height + 7) / 8, 1);
}

}  // namespace vct
