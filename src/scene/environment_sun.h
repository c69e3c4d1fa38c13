// A sun painted into an environment image, taken out of it to be lit as a sun. Read through the
// cones alone, a sun in an HDR sky was blurred over their aperture and cast no shadow (terrain
// under a 128 × 64 sky with a 4° sun of radiance 800, beside its own sun: 0.59 of the path tracer's
// mean luminance, 1.01 with the sun separated). The renderer lights
// the part of the image that is the sun as a directional light, with its shadow map, and the rest
// of the image as the sky; the path tracer reads the whole image, the truth both are held to.
#pragma once

#include <memory>
#include <optional>

#include <glm/glm.hpp>

#include "scene/environment_map.h"

namespace vct {

struct EnvironmentSun {
    glm::vec3 towardsSun{0.0f, 1.0f, 0.0f};  // unit, in the image's own frame (unturned)
    // ∫ L dω over the sun's texels, less the sky that replaces them: the illuminance the sun gives
    // a surface facing it, per unit of Scene::environment.
    glm::vec3 illuminance{0.0f};
    std::shared_ptr<const EnvironmentMap> withoutSun;  // the sun's texels hold the sky around them
};

// The sun: the texels around the brightest one that are at least 1/32 as bright, where they span at
// most kMaxSunSolidAngle and hold at least kMinSunShare of the image's ∫ L dω (a compact source
// that dominates the light: an overcast sky's bright patch is left to the cones). None otherwise.
// 0.2 sr is a disc of 14.5°: still narrow beside a 40-60° cone, and room for a sun's glow, or for a
// low-resolution image whose sun spans a few texels (a 64 × 32 image's texel is up to 0.01 sr).
inline constexpr float kMaxSunSolidAngle = 0.2f;
inline constexpr float kMinSunShare = 0.2f;
std::optional<EnvironmentSun> separateSun(const EnvironmentMap& map);

}  // namespace vct
