#include "gpu/access.h"

namespace vct {

namespace {

constexpr VkAccessFlags2 kWriteAccess =
    VK_ACCESS_2_SHADER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT |
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_HOST_WRITE_BIT |
    VK_ACCESS_2_MEMORY_WRITE_BIT;

bool covers(VkFlags64 have, VkFlags64 wanted) { return (have & wanted) == wanted; }

}  // namespace

bool Access::writes() const { return (access & kWriteAccess) != 0; }

VkMemoryBarrier2 waitBeforeUse(SyncState& state, const Access& access, bool layoutChanges) {
    VkMemoryBarrier2 wait{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    if (access.writes() || layoutChanges) {
        // After the last write (its writes made available) and every read since (an execution
        // dependency is enough for those): a layout change rewrites the image's memory too.
        wait.srcStageMask = state.writeStages | state.readStages;
        wait.srcAccessMask = state.writeAccess;
        wait.dstStageMask = access.stages;
        wait.dstAccessMask = access.access;
        if (access.writes()) {
            state.writeStages = access.stages;
            state.writeAccess = access.access & kWriteAccess;
            state.readStages = VK_PIPELINE_STAGE_2_NONE;
            state.visibleAccess = VK_ACCESS_2_NONE;
        } else {  // the layout change is the last write, finished before this read
            state.writeStages = access.stages;
            state.writeAccess = VK_ACCESS_2_NONE;
            state.readStages = access.stages;
            state.visibleAccess = access.access;
        }
        return wait;
    }
    // A read: the last write must be visible to it, once per stage and kind of read.
    const bool visible = covers(state.readStages, access.stages) && covers(state.visibleAccess, access.access);
    if (state.writeStages != VK_PIPELINE_STAGE_2_NONE && !visible) {
        wait.srcStageMask = state.writeStages;
        wait.srcAccessMask = state.writeAccess;
        wait.dstStageMask = access.stages;
        wait.dstAccessMask = access.access;
        state.visibleAccess |= access.access;
    }
    state.readStages |= access.stages;
    return wait;
}

}  // namespace vct
