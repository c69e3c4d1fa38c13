// Everything a frame can be asked to do: image size, light components, shadow and cone parameters.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <glm/glm.hpp>

namespace vct {

// What the final image holds. `indirect` is everything but direct light (the same split as the
// reference path tracer's: direct = punctual lights at the first hit + emission seen directly).
enum class RenderMode { Full, Direct, Indirect };

std::optional<RenderMode> parseRenderMode(const std::string& name);
const char* renderModeName(RenderMode mode);

struct Components {
    bool directDiffuse = true;
    bool directSpecular = true;
    bool indirectDiffuse = true;
    bool indirectSpecular = true;
    bool ambientOcclusion = true;
    bool emission = true;
    bool shadows = true;
};

struct RenderSettings {
    uint32_t width = 512;
    uint32_t height = 512;
    // Each pixel averages supersample² samples over its square, as "radiance of a pixel" means.
    uint32_t supersample = 2;
    RenderMode mode = RenderMode::Full;
    Components components;
    // Light that is not physical: off by default so `full` converges towards the ground truth.
    float ambientFactor = 0.0f;

    uint32_t sunShadowMapSize = 4096;    // directional lights
    uint32_t localShadowMapSize = 1024;  // each spot light and each cube face of a point light
    float shadowNormalOffset = 1.5f;     // texels
    float shadowSlopeBias = 2.0f;
    float pcfRadius = 2.0f;              // texels covered by the 5×5 kernel on each side
};

// The components a mode shows (toggles switched off stay off).
Components effectiveComponents(const RenderSettings& settings);

}  // namespace vct
