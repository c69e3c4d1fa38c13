// Recording and submitting work.
#pragma once

#include <initializer_list>

#include <vulkan/vulkan.h>

#include <functional>

#include "gpu/context.h"
#include "gpu/resources.h"

namespace vct {

// Records `record` into a fresh command buffer, submits it and waits, with a bounded wait:
// a GPU that does not finish within context.fenceTimeoutSeconds ends the process with a clear
// error (exitImmediately), not a hang.
void submitAndWait(GpuContext& context, const std::function<void(VkCommandBuffer)>& record);

// Waits for `fence` at most context.fenceTimeoutSeconds; past that the work still runs and owns
// its memory, so the process ends with a clear error (exitImmediately) instead of unwinding.
void waitForFence(GpuContext& context, VkFence fence);

// One image layout transition with synchronization2 masks, for work outside the passes' declared
// uses (gpu/pass_uses.h): a texture's mip chain built level by level, the swapchain's images.
void imageBarrier(VkCommandBuffer commands, VkImage image, VkImageAspectFlags aspect, VkImageLayout oldLayout,
                  VkImageLayout newLayout, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                  VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess, uint32_t baseMip = 0,
                  uint32_t mipCount = VK_REMAINING_MIP_LEVELS);

// Copies what the GPU wrote into `source` (`regions`) to the host-visible `destination`, readable
// by the host once the commands have run (e.g. a work list's count).
void copyForHost(VkCommandBuffer commands, const Buffer& source, const Buffer& destination,
                 std::initializer_list<VkBufferCopy> regions);
// The same for `region` of an image (a level, a layer); the next pass that uses the image moves it
// back to the layout it needs.
void copyForHost(VkCommandBuffer commands, const GpuImage& source, const Buffer& destination,
                 const VkBufferImageCopy& region);

// One full-screen triangle (fullscreen.vert) into `target`, every pixel of it written: begins
// rendering, sets the viewport, calls `bind` (the pipeline, its descriptors), draws, ends. The
// target must already be in COLOR_ATTACHMENT_OPTIMAL.
void drawFullScreen(VkCommandBuffer commands, VkImageView target, uint32_t width, uint32_t height,
                    const std::function<void()>& bind);

}  // namespace vct
