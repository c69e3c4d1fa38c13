#include "render/texture_upload.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include "gpu/commands.h"
#include "gpu/pass_uses.h"

namespace vct {
namespace {

bool canBlitLinearly(GpuContext& context, VkFormat format) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(context.physicalDevice, format, &properties);
    const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT |
                                        VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
    return (properties.optimalTilingFeatures & needed) == needed;
}

void toLayout(VkCommandBuffer commands, const GpuImage& image, uint32_t level, uint32_t levels, VkImageLayout from,
              VkImageLayout to, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
              VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    imageBarrier(commands, image.image, VK_IMAGE_ASPECT_COLOR_BIT, from, to, srcStage, srcAccess, dstStage, dstAccess,
                 level, levels);
}

// The levels of a full mip chain down to 1×1: ⌊log2 max(width, height)⌋ + 1.
uint32_t fullMipCount(uint32_t width, uint32_t height) { return std::bit_width(std::max({width, height, 1u})); }

}  // namespace

GpuImage uploadTexture(GpuContext& context, uint32_t width, uint32_t height, const uint8_t* rgba8, bool srgb) {
    ImageDesc desc;
    // glTF's colour textures (base colour, emission) are sRGB-encoded, its data textures linear.
    desc.format = srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
    desc.extent = {width, height, 1};
    desc.mipLevels = canBlitLinearly(context, desc.format) ? fullMipCount(width, height) : 1;
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    desc.debugName = srgb ? "colour texture" : "data texture";
    GpuImage image(context, desc);
    const VkDeviceSize size = VkDeviceSize(width) * height * 4;
    Buffer staging(context, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
    std::memcpy(staging.mapped, rgba8, size);
    submitAndWait(context, [&](VkCommandBuffer commands) {
        toLayout(commands, image, 0, desc.mipLevels, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                 VK_ACCESS_2_TRANSFER_WRITE_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {width, height, 1};
        vkCmdCopyBufferToImage(commands, staging.buffer, image.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        // Each level from the one above: that one becomes a blit source once written.
        for (uint32_t level = 1; level < desc.mipLevels; ++level) {
            toLayout(commands, image, level - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                     VK_ACCESS_2_TRANSFER_READ_BIT);
            const auto extent = [&](uint32_t l) {
                return VkOffset3D{int32_t(std::max(width >> l, 1u)), int32_t(std::max(height >> l, 1u)), 1};
            };
            VkImageBlit blit{};
            blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, 1};
            blit.srcOffsets[1] = extent(level - 1);
            blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
            blit.dstOffsets[1] = extent(level);
            vkCmdBlitImage(commands, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.image,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
        }
        // Every level but the last is a blit source now; the last is still a copy or blit target.
        if (desc.mipLevels > 1)
            toLayout(commands, image, 0, desc.mipLevels - 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                     VK_ACCESS_2_TRANSFER_READ_BIT, access::kShaders, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        toLayout(commands, image, desc.mipLevels - 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                 VK_ACCESS_2_TRANSFER_WRITE_BIT, access::kShaders, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    });
    // Sampled by the G-buffer's fragment shaders and the voxelizer's compute shader alike.
    settle(image, access::shadersSampled);
    return image;
}

}  // namespace vct
