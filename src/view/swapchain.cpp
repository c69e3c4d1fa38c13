#include "view/swapchain.h"

#include <algorithm>
#include <cmath>

#include "error.h"
#include "gpu/vk_check.h"

namespace vct {

static VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice physicalDevice, VkSurfaceKHR surface) {
    uint32_t count = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physicalDevice, surface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physicalDevice, surface, &count, formats.data()));
    if (formats.empty()) throw Error("the window surface offers no image formats");
    // UNORM, not SRGB: Dear ImGui's colours are already sRGB-encoded, and so is the tone-mapped image.
    for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM})
        for (const VkSurfaceFormatKHR& format : formats)
            if (format.format == wanted && format.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return format;
    throw Error("the window surface offers no B8G8R8A8_UNORM or R8G8B8A8_UNORM format");
}

static VkPresentModeKHR choosePresentMode(VkPhysicalDevice physicalDevice, VkSurfaceKHR surface, bool vsync) {
    if (vsync) return VK_PRESENT_MODE_FIFO_KHR;
    uint32_t count = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physicalDevice, surface, &count, nullptr));
    std::vector<VkPresentModeKHR> modes(count);
    VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physicalDevice, surface, &count, modes.data()));
    for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
        if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) return wanted;
    return VK_PRESENT_MODE_FIFO_KHR;
}

const char* presentModeName(VkPresentModeKHR mode) {
    switch (mode) {
        case VK_PRESENT_MODE_FIFO_KHR: return "FIFO (vsync)";
        case VK_PRESENT_MODE_MAILBOX_KHR: return "MAILBOX";
        case VK_PRESENT_MODE_IMMEDIATE_KHR: return "IMMEDIATE";
        default: return "other";
    }
}

VkExtent2D fitWindowExtent(VkExtent2D window, uint32_t maxSide, uint64_t maxPixels) {
    double scale = 1.0;
    scale = std::min(scale, double(maxSide) / double(std::max(window.width, window.height)));
    const double pixels = double(window.width) * double(window.height);
    if (pixels * scale * scale > double(maxPixels)) scale = std::sqrt(double(maxPixels) / pixels);
    if (scale >= 1.0) return window;
    return {std::clamp(uint32_t(double(window.width) * scale), 1u, maxSide),
            std::clamp(uint32_t(double(window.height) * scale), 1u, maxSide)};
}

Swapchain::Swapchain(GpuContext& context, VkSurfaceKHR surface, VkExtent2D wanted, bool vsync, VkSwapchainKHR previous)
    : device_(context.device) {
    VkBool32 supported = VK_FALSE;
    VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(context.physicalDevice, context.queueFamily, surface, &supported));
    if (!supported) throw Error("the device '" + context.deviceName() + "' cannot present to this window");
    VkSurfaceCapabilitiesKHR capabilities{};
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context.physicalDevice, surface, &capabilities));
    const VkSurfaceFormatKHR surfaceFormat = chooseFormat(context.physicalDevice, surface);
    format = surfaceFormat.format;
    presentMode = choosePresentMode(context.physicalDevice, surface, vsync);
    // A current extent of 0xFFFFFFFF means the window takes whatever size the swapchain has. A
    // window larger than `wanted` (what the device can draw) gets a smaller swapchain, which the
    // limits allow, until the window has shrunk too.
    extent = wanted;
    if (capabilities.currentExtent.width != UINT32_MAX) {
        extent.width = std::min(extent.width, capabilities.currentExtent.width);
        extent.height = std::min(extent.height, capabilities.currentExtent.height);
    }
    extent.width = std::clamp(extent.width, capabilities.minImageExtent.width, capabilities.maxImageExtent.width);
    extent.height = std::clamp(extent.height, capabilities.minImageExtent.height, capabilities.maxImageExtent.height);
    minImageCount = capabilities.minImageCount + 1;
    if (capabilities.maxImageCount > 0) minImageCount = std::min(minImageCount, capabilities.maxImageCount);
    canCopyFrom = (capabilities.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;

    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface;
    info.minImageCount = minImageCount;
    info.imageFormat = surfaceFormat.format;
    info.imageColorSpace = surfaceFormat.colorSpace;
    info.imageExtent = extent;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | (canCopyFrom ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0);
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = capabilities.currentTransform;
    info.compositeAlpha =
        (capabilities.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
            ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
            : VkCompositeAlphaFlagBitsKHR(capabilities.supportedCompositeAlpha & -capabilities.supportedCompositeAlpha);
    info.presentMode = presentMode;
    info.clipped = VK_TRUE;
    info.oldSwapchain = previous;
    VK_CHECK(vkCreateSwapchainKHR(device_, &info, nullptr, &swapchain));

    uint32_t count = 0;
    VK_CHECK(vkGetSwapchainImagesKHR(device_, swapchain, &count, nullptr));
    images.resize(count);
    VK_CHECK(vkGetSwapchainImagesKHR(device_, swapchain, &count, images.data()));
    for (VkImage image : images) {
        VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        viewInfo.image = image;
        viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
        viewInfo.format = format;
        viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        views.push_back(VK_NULL_HANDLE);
        VK_CHECK(vkCreateImageView(device_, &viewInfo, nullptr, &views.back()));
        const VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        renderFinished.push_back(VK_NULL_HANDLE);
        VK_CHECK(vkCreateSemaphore(device_, &semaphoreInfo, nullptr, &renderFinished.back()));
    }
}

Swapchain::~Swapchain() {
    for (VkSemaphore semaphore : renderFinished) vkDestroySemaphore(device_, semaphore, nullptr);
    for (VkImageView view : views) vkDestroyImageView(device_, view, nullptr);
    vkDestroySwapchainKHR(device_, swapchain, nullptr);
}

}  // namespace vct
