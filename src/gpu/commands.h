// Recording and submitting work, and the barriers between passes.
#pragma once

#include <initializer_list>

#include <vulkan/vulkan.h>

#include <functional>

#include "gpu/context.h"

namespace vct {

// Records `record` into a fresh command buffer, submits it and waits, with a bounded wait:
// a GPU that does not finish within context.fenceTimeoutSeconds ends the process with a clear
// error (exitImmediately), not a hang.
void submitAndWait(GpuContext& context, const std::function<void(VkCommandBuffer)>& record);

// Waits for `fence` at most context.fenceTimeoutSeconds; past that the work still runs and owns
// its memory, so the process ends with a clear error (exitImmediately) instead of unwinding.
void waitForFence(GpuContext& context, VkFence fence);

// One image layout transition with synchronization2 masks.
void imageBarrier(VkCommandBuffer commands, VkImage image, VkImageAspectFlags aspect, VkImageLayout oldLayout,
                  VkImageLayout newLayout, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                  VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess, uint32_t baseMip = 0,
                  uint32_t mipCount = VK_REMAINING_MIP_LEVELS);

// A global memory barrier (buffer and image writes of one pass made visible to the next).
void memoryBarrier(VkCommandBuffer commands, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

// Copies what compute shaders wrote into `source` (`regions`) to the host-visible `destination`,
// readable by the host once the commands have run (e.g. a work list's count).
void copyForHost(VkCommandBuffer commands, VkBuffer source, VkBuffer destination,
                 std::initializer_list<VkBufferCopy> regions);

// One full-screen triangle (fullscreen.vert) into `target`, every pixel of it written: begins
// rendering, sets the viewport, calls `bind` (the pipeline, its descriptors), draws, ends. The
// target must already be in COLOR_ATTACHMENT_OPTIMAL.
void drawFullScreen(VkCommandBuffer commands, VkImageView target, uint32_t width, uint32_t height,
                    const std::function<void()>& bind);

}  // namespace vct
