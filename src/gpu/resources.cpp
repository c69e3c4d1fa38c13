#include "gpu/resources.h"

#include <cstring>

#include "gpu/commands.h"
#include "gpu/vk_check.h"

namespace vct {

uint32_t findMemoryType(const GpuContext& context, uint32_t typeBits, VkMemoryPropertyFlags properties) {
    const VkPhysicalDeviceMemoryProperties& memory = context.memoryProperties;
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & properties) == properties) return i;
    throw Error(context.deviceName() + " has no memory type with the needed properties");
}

static VkDeviceMemory allocate(GpuContext& context, const VkMemoryRequirements& requirements,
                               VkMemoryPropertyFlags properties, const char* what) {
    VkMemoryAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    allocateInfo.allocationSize = requirements.size;
    allocateInfo.memoryTypeIndex = findMemoryType(context, requirements.memoryTypeBits, properties);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    const VkResult result = vkAllocateMemory(context.device, &allocateInfo, nullptr, &memory);
    if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
        throw Error(std::string("out of GPU memory allocating ") + what + " (" +
                    std::to_string(requirements.size >> 20) + " MiB); try fewer voxels or a smaller image");
    VK_CHECK(result);
    return memory;
}

Buffer::Buffer(GpuContext& context, VkDeviceSize bufferSize, VkBufferUsageFlags usage, bool hostVisible)
    : size(bufferSize), device_(context.device) {
    // No destructor runs for an unfinished constructor: when a step below throws (out of memory is
    // an error a user can meet), free what the earlier steps created, so the error exits cleanly.
    struct ReleaseOnThrow {
        Buffer* self;
        ~ReleaseOnThrow() {
            if (self) self->release();
        }
    } releaseOnThrow{this};
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = bufferSize;
    info.usage = usage;
    VK_CHECK(vkCreateBuffer(device_, &info, nullptr, &buffer));
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device_, buffer, &requirements);
    const VkMemoryPropertyFlags properties =
        hostVisible ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                    : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    memory_ = allocate(context, requirements, properties, "a buffer");
    VK_CHECK(vkBindBufferMemory(device_, buffer, memory_, 0));
    if (hostVisible) VK_CHECK(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped));
    releaseOnThrow.self = nullptr;
}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    if (this != &other) {
        release();
        std::swap(buffer, other.buffer);
        std::swap(size, other.size);
        std::swap(mapped, other.mapped);
        std::swap(sync, other.sync);
        std::swap(device_, other.device_);
        std::swap(memory_, other.memory_);
    }
    return *this;
}

void Buffer::release() {
    if (!device_) return;
    vkDestroyBuffer(device_, buffer, nullptr);
    vkFreeMemory(device_, memory_, nullptr);
    buffer = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
    mapped = nullptr;
    device_ = VK_NULL_HANDLE;
}

static bool isDepthFormat(VkFormat format) {
    return format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D16_UNORM || format == VK_FORMAT_D24_UNORM_S8_UINT;
}

static VkImageView createView(VkDevice device, VkImage image, const ImageDesc& desc, VkImageViewType viewType,
                              VkImageAspectFlags aspect, uint32_t baseMip, uint32_t mipCount, uint32_t baseLayer,
                              uint32_t layerCount) {
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image;
    info.viewType = viewType;
    info.format = desc.format;
    info.subresourceRange = {aspect, baseMip, mipCount, baseLayer, layerCount};
    VkImageView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(device, &info, nullptr, &view));
    return view;
}

GpuImage::GpuImage(GpuContext& context, const ImageDesc& imageDesc) : desc(imageDesc), device_(context.device) {
    // No destructor runs for an unfinished constructor: when a step below throws (out of memory is
    // an error a user can meet), free what the earlier steps created, so the error exits cleanly.
    struct ReleaseOnThrow {
        GpuImage* self;
        ~ReleaseOnThrow() {
            if (self) self->release();
        }
    } releaseOnThrow{this};
    aspect = isDepthFormat(desc.format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = desc.type;
    info.format = desc.format;
    info.extent = desc.extent;
    info.mipLevels = desc.mipLevels;
    info.arrayLayers = desc.layers;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = desc.usage;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    const VkResult created = vkCreateImage(device_, &info, nullptr, &image);
    if (created == VK_ERROR_FORMAT_NOT_SUPPORTED || created == VK_ERROR_OUT_OF_DEVICE_MEMORY)
        throw Error(std::string("cannot create the image '") + desc.debugName + "' (" +
                    std::to_string(desc.extent.width) + "×" + std::to_string(desc.extent.height) + "×" +
                    std::to_string(desc.extent.depth) + "): " + vkResultName(created));
    VK_CHECK(created);
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(device_, image, &requirements);
    memorySize = requirements.size;
    memory_ = allocate(context, requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, desc.debugName);
    VK_CHECK(vkBindImageMemory(device_, image, memory_, 0));

    const VkImageViewType wholeType = desc.type == VK_IMAGE_TYPE_3D       ? VK_IMAGE_VIEW_TYPE_3D
                                      : desc.layers > 1 || desc.arrayView ? VK_IMAGE_VIEW_TYPE_2D_ARRAY
                                                                          : VK_IMAGE_VIEW_TYPE_2D;
    view = createView(device_, image, desc, wholeType, aspect, 0, desc.mipLevels, 0, desc.layers);
    if (desc.mipLevels > 1)
        for (uint32_t mip = 0; mip < desc.mipLevels; ++mip)
            mipViews.push_back(createView(device_, image, desc, wholeType, aspect, mip, 1, 0, desc.layers));
    if (desc.layers > 1 || desc.arrayView)
        for (uint32_t layer = 0; layer < desc.layers; ++layer)
            layerViews.push_back(
                createView(device_, image, desc, VK_IMAGE_VIEW_TYPE_2D, aspect, 0, desc.mipLevels, layer, 1));
    releaseOnThrow.self = nullptr;
}

GpuImage& GpuImage::operator=(GpuImage&& other) noexcept {
    if (this != &other) {
        release();
        std::swap(image, other.image);
        std::swap(view, other.view);
        std::swap(mipViews, other.mipViews);
        std::swap(layerViews, other.layerViews);
        std::swap(desc, other.desc);
        std::swap(aspect, other.aspect);
        std::swap(memorySize, other.memorySize);
        std::swap(sync, other.sync);
        std::swap(device_, other.device_);
        std::swap(memory_, other.memory_);
    }
    return *this;
}

void GpuImage::release() {
    if (!device_) return;
    for (VkImageView mipView : mipViews) vkDestroyImageView(device_, mipView, nullptr);
    for (VkImageView layerView : layerViews) vkDestroyImageView(device_, layerView, nullptr);
    vkDestroyImageView(device_, view, nullptr);
    vkDestroyImage(device_, image, nullptr);
    vkFreeMemory(device_, memory_, nullptr);
    mipViews.clear();
    layerViews.clear();
    view = VK_NULL_HANDLE;
    image = VK_NULL_HANDLE;
    memory_ = VK_NULL_HANDLE;
    device_ = VK_NULL_HANDLE;
}

Buffer uploadBuffer(GpuContext& context, const void* bytes, VkDeviceSize size, VkBufferUsageFlags usage) {
    const VkDeviceSize allocationSize = size > 0 ? size : 16;  // Vulkan forbids empty buffers
    Buffer staging(context, allocationSize, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
    if (size > 0) std::memcpy(staging.mapped, bytes, size);
    Buffer target(context, allocationSize, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false);
    submitAndWait(context, [&](VkCommandBuffer commands) {
        const VkBufferCopy region{0, 0, allocationSize};
        vkCmdCopyBuffer(commands, staging.buffer, target.buffer, 1, &region);
    });
    return target;
}

}  // namespace vct
