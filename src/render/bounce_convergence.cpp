#include "render/bounce_convergence.h"

#include <cmath>

#include <glm/gtc/packing.hpp>

#include "gpu/commands.h"
#include "luminance.h"
#include "render/settings.h"

namespace vct {

BounceConvergence::BounceConvergence(GpuContext& context) : mean_(context, 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true) {}

void BounceConvergence::record(VkCommandBuffer commands, const GpuImage& radiance) {
    // The radiance volume's coarsest level is one texel: the mean over the grid.
    const uint32_t top = radiance.desc.mipLevels - 1;
    imageBarrier(commands, radiance.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
                 VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                 VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT, top,
                 1);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, top, 0, 1};
    region.imageExtent = {1, 1, 1};
    vkCmdCopyImageToBuffer(commands, radiance.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, mean_.buffer, 1, &region);
    imageBarrier(commands, radiance.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                 VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE,
                 VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                 VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT, top, 1);
    memoryBarrier(commands, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                  VK_ACCESS_2_HOST_READ_BIT);
}

bool BounceConvergence::settled() {
    const uint16_t* half = static_cast<const uint16_t*>(mean_.mapped);
    const float luminance = glsl::luminance(
        glm::vec3(glm::unpackHalf1x16(half[0]), glm::unpackHalf1x16(half[1]), glm::unpackHalf1x16(half[2])));
    const float change = std::abs(luminance - lastLuminance_);
    lastLuminance_ = luminance;
    return change <= kBounceTolerance * luminance;
}

}  // namespace vct
