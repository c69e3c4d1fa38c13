#include "gpu/pass_uses.h"

namespace vct {

// Waits without a layout change share one global barrier: fewer, wider barriers, as the passes
// wrote them by hand.
void PassUses::addMemoryWait(const VkMemoryBarrier2& wait) {
    if (wait.srcStageMask == VK_PIPELINE_STAGE_2_NONE) return;
    memory_.srcStageMask |= wait.srcStageMask;
    memory_.srcAccessMask |= wait.srcAccessMask;
    memory_.dstStageMask |= wait.dstStageMask;
    memory_.dstAccessMask |= wait.dstAccessMask;
}

PassUses& PassUses::use(const Buffer& buffer, const Access& access) {
    addMemoryWait(waitBeforeUse(buffer.sync, access, false));
    return *this;
}

PassUses& PassUses::use(const GpuImage& image, const Access& access, Contents contents) {
    SyncState& state = image.sync;
    const VkImageLayout oldLayout = contents == Contents::Discard ? VK_IMAGE_LAYOUT_UNDEFINED : state.layout;
    const bool layoutChanges = oldLayout != access.layout;
    const VkMemoryBarrier2 wait = waitBeforeUse(state, access, layoutChanges);
    state.layout = access.layout;
    if (!layoutChanges) {
        addMemoryWait(wait);
        return *this;
    }
    VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    barrier.srcStageMask = wait.srcStageMask;
    barrier.srcAccessMask = wait.srcAccessMask;
    barrier.dstStageMask = wait.dstStageMask;
    barrier.dstAccessMask = wait.dstAccessMask;
    barrier.oldLayout = oldLayout;
    barrier.newLayout = access.layout;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image.image;
    barrier.subresourceRange = {image.aspect, 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS};
    images_.push_back(barrier);
    return *this;
}

void PassUses::record(VkCommandBuffer commands) {
    const bool memory = memory_.dstStageMask != VK_PIPELINE_STAGE_2_NONE;
    if (!memory && images_.empty()) return;
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.memoryBarrierCount = memory ? 1 : 0;
    dependency.pMemoryBarriers = &memory_;
    dependency.imageMemoryBarrierCount = uint32_t(images_.size());
    dependency.pImageMemoryBarriers = images_.data();
    vkCmdPipelineBarrier2(commands, &dependency);
    memory_ = {VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    images_.clear();
}

void settle(const GpuImage& image, const Access& access) {
    image.sync = {access.layout, access.stages, VK_ACCESS_2_NONE, access.stages, access.access};
}

}  // namespace vct
