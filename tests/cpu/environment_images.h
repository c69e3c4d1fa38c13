// Environment images the tests make (scene/environment_map.h): in memory for the renderer and the
// path tracer, as .hdr files for the loader.
#pragma once

#include <functional>
#include <memory>

#include "scene/environment_map.h"

namespace vct::test {

// width × height texels of `radiance(x, y)`, rows from the top.
inline std::shared_ptr<const EnvironmentMap> makeEnvironmentMap(
    uint32_t width, uint32_t height, const std::function<glm::vec3(uint32_t, uint32_t)>& radiance) {
    auto map = std::make_shared<EnvironmentMap>();
    map->name = "test sky";
    map->width = width;
    map->height = height;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            const glm::vec3 texel = radiance(x, y);
            map->rgba.insert(map->rgba.end(), {texel.r, texel.g, texel.b, 1.0f});
        }
    return map;
}

// Red where the image's directions have x < 0 (its left half), green where x > 0, over the upper
// hemisphere (its top half); black below the horizon. 64 × 32 texels, so within ±3° of the
// meridian (the texels' bilinear blend) the halves stay pure.
inline std::shared_ptr<const EnvironmentMap> redLeftGreenRightSky() {
    return makeEnvironmentMap(64, 32, [](uint32_t x, uint32_t y) {
        if (y >= 16) return glm::vec3(0.0f);
        return x < 32 ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    });
}

}  // namespace vct::test
