#include "gpu/commands.h"

#include <cstdio>

#include "gpu/pass_uses.h"
#include "gpu/vk_check.h"
#include "io/exit_immediately.h"

namespace vct {
namespace {

std::string formatSeconds(float seconds) {
    char text[32];
    std::snprintf(text, sizeof(text), "%g s", double(seconds));
    return text;
}

}  // namespace

void waitForFence(GpuContext& context, VkFence fence) {
    const uint64_t timeoutNs = uint64_t(context.fenceTimeoutSeconds * 1e9);
    const VkResult result = vkWaitForFences(context.device, 1, &fence, VK_TRUE, timeoutNs);
    // The work goes on after the wait gives up, reading and writing memory that unwinding would free
    // under it: the process ends here instead of throwing.
    if (result == VK_TIMEOUT)
        exitImmediately("the GPU (" + context.deviceName() + ") did not finish its work within " +
                        formatSeconds(context.fenceTimeoutSeconds) +
                        "; it may be stuck (--gpu-timeout sets the limit)");
    VK_CHECK(result);
}

void submitAndWait(GpuContext& context, const std::function<void(VkCommandBuffer)>& record) {
    VkCommandBufferAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocateInfo.commandPool = context.commandPool;
    allocateInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocateInfo.commandBufferCount = 1;
    VkCommandBuffer commands = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateCommandBuffers(context.device, &allocateInfo, &commands));
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFence(context.device, &fenceInfo, nullptr, &fence));
    struct Cleanup {
        GpuContext& context;
        VkCommandBuffer commands;
        VkFence fence;
        ~Cleanup() {
            vkDestroyFence(context.device, fence, nullptr);
            vkFreeCommandBuffers(context.device, context.commandPool, 1, &commands);
        }
    } cleanup{context, commands, fence};

    VkCommandBufferBeginInfo beginInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(commands, &beginInfo));
    record(commands);
    VK_CHECK(vkEndCommandBuffer(commands));

    VkCommandBufferSubmitInfo commandInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    commandInfo.commandBuffer = commands;
    VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &commandInfo;
    VK_CHECK(vkQueueSubmit2(context.queue, 1, &submit, fence));
    waitForFence(context, fence);
}

void imageBarrier(VkCommandBuffer commands, VkImage image, VkImageAspectFlags aspect, VkImageLayout oldLayout,
                  VkImageLayout newLayout, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                  VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess, uint32_t baseMip, uint32_t mipCount) {
    VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    barrier.srcStageMask = srcStage;
    barrier.srcAccessMask = srcAccess;
    barrier.dstStageMask = dstStage;
    barrier.dstAccessMask = dstAccess;
    barrier.oldLayout = oldLayout;
    barrier.newLayout = newLayout;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {aspect, baseMip, mipCount, 0, VK_REMAINING_ARRAY_LAYERS};
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.imageMemoryBarrierCount = 1;
    dependency.pImageMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(commands, &dependency);
}

void copyForHost(VkCommandBuffer commands, const Buffer& source, const Buffer& destination,
                 std::initializer_list<VkBufferCopy> regions) {
    PassUses().use(source, access::copySource).use(destination, access::transferWrite).record(commands);
    vkCmdCopyBuffer(commands, source.buffer, destination.buffer, uint32_t(regions.size()), regions.begin());
    PassUses().use(destination, access::hostRead).record(commands);
}

void copyForHost(VkCommandBuffer commands, const GpuImage& source, const Buffer& destination,
                 const VkBufferImageCopy& region) {
    PassUses().use(source, access::copySource).use(destination, access::transferWrite).record(commands);
    vkCmdCopyImageToBuffer(commands, source.image, access::copySource.layout, destination.buffer, 1, &region);
    PassUses().use(destination, access::hostRead).record(commands);
}

void drawFullScreen(VkCommandBuffer commands, VkImageView target, uint32_t width, uint32_t height,
                    const std::function<void()>& bind) {
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = target;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;  // every pixel is written
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {width, height}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    vkCmdBeginRendering(commands, &rendering);
    bind();
    const VkViewport viewport{0.0f, 0.0f, float(width), float(height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, {width, height}};
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &scissor);
    vkCmdDraw(commands, 3, 1, 0, 0);
    vkCmdEndRendering(commands);
}

}  // namespace vct
