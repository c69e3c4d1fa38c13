// Buffers and images with their memory, owned RAII-style (move-only).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "gpu/access.h"
#include "gpu/context.h"

namespace vct {

class Buffer {
public:
    Buffer() = default;
    // Host-visible buffers stay mapped (`mapped`); device-local ones are filled by upload().
    Buffer(GpuContext& context, VkDeviceSize size, VkBufferUsageFlags usage, bool hostVisible);
    ~Buffer() { release(); }
    Buffer(Buffer&& other) noexcept { *this = std::move(other); }
    Buffer& operator=(Buffer&& other) noexcept;

    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr;
    // What the queue last did with it (pass_uses.h); mutable: passes that only read a buffer still
    // record that they did.
    mutable SyncState sync;

private:
    void release();
    VkDevice device_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
};

struct ImageDesc {
    VkImageType type = VK_IMAGE_TYPE_2D;
    VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
    VkExtent3D extent{1, 1, 1};
    uint32_t mipLevels = 1;
    uint32_t layers = 1;
    bool arrayView = false;  // view a 2D image as an array even with one layer (shadow-map arrays)
    VkImageUsageFlags usage = 0;
    const char* debugName = "";
};

class GpuImage {
public:
    GpuImage() = default;
    GpuImage(GpuContext& context, const ImageDesc& desc);
    ~GpuImage() { release(); }
    GpuImage(GpuImage&& other) noexcept { *this = std::move(other); }
    GpuImage& operator=(GpuImage&& other) noexcept;

    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;    // all mips and layers
    std::vector<VkImageView> mipViews;    // one per mip level (3D images, for compute writes)
    std::vector<VkImageView> layerViews;  // one per layer (array images, for rendering into)
    ImageDesc desc;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
    VkDeviceSize memorySize = 0;
    mutable SyncState sync;  // as Buffer::sync

private:
    void release();
    VkDevice device_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
};

uint32_t findMemoryType(const GpuContext& context, uint32_t typeBits, VkMemoryPropertyFlags properties);

// Copies `bytes` into a new device-local buffer through a staging buffer (waits for completion).
Buffer uploadBuffer(GpuContext& context, const void* bytes, VkDeviceSize size, VkBufferUsageFlags usage);

}  // namespace vct
