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
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, top, 0, 1};
    region.imageExtent = {1, 1, 1};
    copyForHost(commands, radiance, mean_, region);
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
