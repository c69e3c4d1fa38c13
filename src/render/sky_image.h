// The sky's image on the device (shaders_glsl/sky.glsl, at SKY_BINDING in every pass that traces
// cones or shows the sky): the scene's environment image with a mip chain the cones read blurred
// over their aperture, or a 1 × 1 white image where the scene has none (the sky is then
// FrameConstants::environment alone).
#pragma once

#include "equirectangular.h"  // SKY_BINDING
#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "scene/environment_map.h"

namespace vct {

class SkyImage {
public:
    // `map` null: the white placeholder.
    SkyImage(GpuContext& context, const EnvironmentMap* map);

    VkImageView view() const { return image_.view; }
    VkSampler sampler() const { return sampler_.sampler; }
    bool mapped() const { return mapped_; }  // an environment image, not the placeholder

private:
    GpuImage image_;
    Sampler sampler_;
    bool mapped_ = false;
};

}  // namespace vct
