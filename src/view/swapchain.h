// The window's swapchain: images to present, recreated whole when the window changes size.
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

#include "gpu/context.h"

namespace vct {

class Swapchain {
public:
    // vsync = FIFO (every implementation has it); otherwise MAILBOX, else IMMEDIATE, else FIFO.
    // `previous` (may be null) is handed to the driver so it can reuse its images. The extent is the
    // surface's current one (or `wanted` where the surface lets the swapchain decide), no larger than
    // `wanted`, within the surface's limits.
    Swapchain(GpuContext& context, VkSurfaceKHR surface, VkExtent2D wanted, bool vsync, VkSwapchainKHR previous);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    VkSwapchainKHR swapchain = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;  // an 8-bit UNORM format: the tone-mapping shader encodes sRGB
    VkExtent2D extent{};
    VkPresentModeKHR presentMode = VK_PRESENT_MODE_FIFO_KHR;
    uint32_t minImageCount = 2;
    bool canCopyFrom = false;  // TRANSFER_SRC usage, for screenshots
    std::vector<VkImage> images;
    std::vector<VkImageView> views;
    // One per image: a present waits on the semaphore of the image it shows, so a semaphore is
    // never signalled again while a present may still be waiting on it.
    std::vector<VkSemaphore> renderFinished;

private:
    VkDevice device_;
};

const char* presentModeName(VkPresentModeKHR mode);

// The largest window size, no larger than `window`, that the viewer can draw: each side at most
// `maxSide` (the device's maxImageDimension2D), and at most `maxPixels` pixels (what the device's
// memory allows for the swapchain and the render targets), keeping the window's aspect ratio.
// A window of 100000² (X wraps it to 34464²) asked for 14 GB of swapchain images on lavapipe.
VkExtent2D fitWindowExtent(VkExtent2D window, uint32_t maxSide, uint64_t maxPixels);

}  // namespace vct
