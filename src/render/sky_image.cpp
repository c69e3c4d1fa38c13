#include "render/sky_image.h"

#include <algorithm>
#include <cstring>

#include <glm/gtc/packing.hpp>

#include "gpu/commands.h"
#include "gpu/pass_uses.h"

namespace vct {
namespace {

// One level of the chain: float RGBA, rows from the top; level 0 is the map's own texels.
struct Level {
    uint32_t width, height;
    const float* rgba;
    size_t values() const { return size_t(width) * height * 4; }
};

// Each level the box-filtered half of the one above (an odd last row or column counted once more):
// the mean radiance of the directions each texel covers, as the cones want it. Down to 1 × 1. The
// levels past 0 are held in `storage`.
std::vector<Level> mipChain(const EnvironmentMap& map, std::vector<std::vector<float>>& storage) {
    std::vector<Level> levels{{map.width, map.height, map.rgba.data()}};
    while (levels.back().width > 1 || levels.back().height > 1) {
        const Level above = levels.back();
        Level level{std::max(above.width / 2, 1u), std::max(above.height / 2, 1u), nullptr};
        std::vector<float>& rgba = storage.emplace_back(level.values());
        for (uint32_t y = 0; y < level.height; ++y)
            for (uint32_t x = 0; x < level.width; ++x)
                for (uint32_t c = 0; c < 4; ++c) {
                    float sum = 0.0f;
                    for (uint32_t dy = 0; dy < 2; ++dy)
                        for (uint32_t dx = 0; dx < 2; ++dx) {
                            const uint32_t sx = std::min(2 * x + dx, above.width - 1);
                            const uint32_t sy = std::min(2 * y + dy, above.height - 1);
                            sum += above.rgba[4 * (size_t(sy) * above.width + sx) + c];
                        }
                    rgba[4 * (size_t(y) * level.width + x) + c] = 0.25f * sum;
                }
        level.rgba = rgba.data();
        levels.push_back(level);
    }
    return levels;
}

bool filtersLinearly(GpuContext& context, VkFormat format) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(context.physicalDevice, format, &properties);
    return (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) != 0;
}

}  // namespace

SkyImage::SkyImage(GpuContext& context, const EnvironmentMap* map) : mapped_(map && map->width > 0) {
    EnvironmentMap placeholder;
    placeholder.width = placeholder.height = 1;
    placeholder.rgba = {1.0f, 1.0f, 1.0f, 1.0f};
    std::vector<std::vector<float>> storage;
    const std::vector<Level> levels = mipChain(mapped_ ? *map : placeholder, storage);
    // 32-bit floats keep a sun's radiance whole; a device that cannot filter them gets half
    // floats (filtering them is required), which hold up to 65504.
    const bool full = filtersLinearly(context, VK_FORMAT_R32G32B32A32_SFLOAT);
    ImageDesc desc;
    desc.format = full ? VK_FORMAT_R32G32B32A32_SFLOAT : VK_FORMAT_R16G16B16A16_SFLOAT;
    desc.extent = {levels[0].width, levels[0].height, 1};
    desc.mipLevels = uint32_t(levels.size());
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    desc.debugName = "sky image";
    image_ = GpuImage(context, desc);

    const size_t texelBytes = full ? 16 : 8;
    VkDeviceSize total = 0;
    for (const Level& level : levels) total += VkDeviceSize(level.values() / 4) * texelBytes;
    Buffer staging(context, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
    std::vector<VkBufferImageCopy> regions;
    VkDeviceSize offset = 0;
    for (uint32_t i = 0; i < levels.size(); ++i) {
        const Level& level = levels[i];
        auto* bytes = static_cast<uint8_t*>(staging.mapped) + offset;
        if (full) {
            std::memcpy(bytes, level.rgba, level.values() * sizeof(float));
        } else {
            for (size_t t = 0; t < level.values(); ++t) {
                const uint16_t half = glm::packHalf1x16(std::min(level.rgba[t], 65504.0f));
                std::memcpy(bytes + 2 * t, &half, 2);
            }
        }
        VkBufferImageCopy region{};
        region.bufferOffset = offset;
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, i, 0, 1};
        region.imageExtent = {level.width, level.height, 1};
        regions.push_back(region);
        offset += VkDeviceSize(level.values() / 4) * texelBytes;
    }
    submitAndWait(context, [&](VkCommandBuffer commands) {
        PassUses().use(image_, access::transferWrite, Contents::Discard).record(commands);
        vkCmdCopyBufferToImage(commands, staging.buffer, image_.image, access::transferWrite.layout,
                               uint32_t(regions.size()), regions.data());
        PassUses().use(image_, access::shadersSampled).record(commands);
    });
    // Around the horizon the image wraps; at the poles it ends.
    VkSamplerCreateInfo info = linearClampSampler();
    info.addressModeU = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    sampler_ = Sampler(context, info);
}

}  // namespace vct
