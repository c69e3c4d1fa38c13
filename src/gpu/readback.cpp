#include "gpu/readback.h"

#include <algorithm>
#include <cstring>

#include <glm/gtc/packing.hpp>

#include "error.h"
#include "gpu/commands.h"

namespace vct {
namespace {

uint32_t texelBytes(VkFormat format) {
    switch (format) {
        case VK_FORMAT_R8G8B8A8_UNORM: return 4;
        case VK_FORMAT_R16G16B16A16_SFLOAT: return 8;
        case VK_FORMAT_R32G32B32A32_SFLOAT: return 16;
        default: throw Error("readImage3D cannot read format " + std::to_string(int(format)));
    }
}

glm::vec4 decodeTexel(VkFormat format, const uint8_t* bytes) {
    if (format == VK_FORMAT_R8G8B8A8_UNORM) return glm::vec4(bytes[0], bytes[1], bytes[2], bytes[3]) / 255.0f;
    if (format == VK_FORMAT_R16G16B16A16_SFLOAT) {
        uint64_t packed;
        std::memcpy(&packed, bytes, sizeof(packed));
        return glm::unpackHalf4x16(packed);
    }
    glm::vec4 texel;
    std::memcpy(&texel, bytes, sizeof(texel));
    return texel;
}

}  // namespace

std::vector<glm::vec4> readImage3D(GpuContext& context, const GpuImage& image, uint32_t mip) {
    if (mip >= image.desc.mipLevels)
        throw Error(std::string("readImage3D: '") + image.desc.debugName + "' has no mip level " + std::to_string(mip));
    if (image.sync.layout == VK_IMAGE_LAYOUT_UNDEFINED)
        throw Error(std::string("readImage3D: '") + image.desc.debugName + "' holds no defined contents");
    const VkFormat format = image.desc.format;
    const uint32_t bytesPerTexel = texelBytes(format);
    const VkExtent3D extent{std::max(image.desc.extent.width >> mip, 1u), std::max(image.desc.extent.height >> mip, 1u),
                            std::max(image.desc.extent.depth >> mip, 1u)};
    const size_t texels = size_t(extent.width) * extent.height * extent.depth;
    Buffer staging(context, texels * bytesPerTexel, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);

    submitAndWait(context, [&](VkCommandBuffer commands) {
        VkBufferImageCopy region{};
        region.imageSubresource = {image.aspect, mip, 0, 1};
        region.imageExtent = extent;
        copyForHost(commands, image, staging, region);
    });

    std::vector<glm::vec4> result(texels);
    const auto* bytes = static_cast<const uint8_t*>(staging.mapped);
    for (size_t i = 0; i < texels; ++i) result[i] = decodeTexel(format, bytes + i * bytesPerTexel);
    return result;
}

std::vector<uint32_t> readBufferWords(GpuContext& context, const Buffer& buffer, size_t count) {
    const VkDeviceSize bytes = VkDeviceSize(count) * sizeof(uint32_t);
    if (bytes > buffer.size)
        throw Error("readBufferWords: " + std::to_string(count) + " words asked of a buffer of " +
                    std::to_string(buffer.size) + " bytes");
    std::vector<uint32_t> words(count);
    if (count == 0) return words;
    Buffer staging(context, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    submitAndWait(context, [&](VkCommandBuffer commands) { copyForHost(commands, buffer, staging, {{0, 0, bytes}}); });
    std::memcpy(words.data(), staging.mapped, bytes);
    return words;
}

}  // namespace vct
