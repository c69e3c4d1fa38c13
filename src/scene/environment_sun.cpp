#include "scene/environment_sun.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "equirectangular.h"
#include "luminance.h"

namespace vct {

namespace {

using glsl::luminance;

// The direction of texel (x, y)'s centre (unturned) and the solid angle it spans.
glm::dvec3 texelDirection(const EnvironmentMap& map, uint32_t x, uint32_t y) {
    return glm::dvec3(
        glsl::equirectangularDirection(glm::vec2((x + 0.5f) / float(map.width), (y + 0.5f) / float(map.height)), 0.0f));
}

double texelSolidAngle(const EnvironmentMap& map, uint32_t y) {
    return equirectangularCellSolidAngle(y, map.width, map.height);
}

// The texel's four neighbours, wrapping around in u; at the top and bottom rows the texel itself
// stands in for the one beyond.
std::array<size_t, 4> neighboursOf(const EnvironmentMap& map, size_t texel) {
    const uint32_t width = map.width, x = uint32_t(texel % width), y = uint32_t(texel / width);
    return {size_t(y) * width + (x + 1) % width, size_t(y) * width + (x + width - 1) % width,
            y > 0 ? texel - width : texel, y + 1 < map.height ? texel + width : texel};
}

}  // namespace

std::optional<EnvironmentSun> separateSun(const EnvironmentMap& map) {
    const uint32_t width = map.width, height = map.height;
    if (width == 0 || height == 0) return std::nullopt;
    double total = 0.0, brightest = 0.0;
    size_t brightestTexel = 0;
    for (uint32_t y = 0; y < height; ++y) {
        const double solidAngle = texelSolidAngle(map, y);
        for (uint32_t x = 0; x < width; ++x) {
            const double value = luminance(glm::dvec3(map.texel(x, y)));
            total += value * solidAngle;
            if (value > brightest) {
                brightest = value;
                brightestTexel = size_t(y) * width + x;
            }
        }
    }
    if (!(brightest > 0.0) || !(total > 0.0)) return std::nullopt;

    // The sun: the texels joined to the brightest one (4-neighbours, wrapping around in u) at
    // least 1/32 as bright; too wide a region is no sun, and the search stops there.
    std::vector<uint8_t> inSun(size_t(width) * height, 0);
    std::vector<size_t> region, pending = {brightestTexel};
    inSun[brightestTexel] = 1;
    double regionSolidAngle = 0.0;
    while (!pending.empty()) {
        const size_t texel = pending.back();
        pending.pop_back();
        region.push_back(texel);
        regionSolidAngle += texelSolidAngle(map, uint32_t(texel / width));
        if (regionSolidAngle > kMaxSunSolidAngle) return std::nullopt;
        for (size_t next : neighboursOf(map, texel)) {
            if (inSun[next] ||
                luminance(glm::dvec3(map.texel(uint32_t(next % width), uint32_t(next / width)))) < brightest / 32.0)
                continue;
            inSun[next] = 1;
            pending.push_back(next);
        }
    }

    // The sky around it: the mean of the texels that border the region.
    glm::dvec3 ringSum(0.0);
    double ringCount = 0.0;
    for (size_t texel : region) {
        for (size_t next : neighboursOf(map, texel)) {
            if (inSun[next]) continue;
            ringSum += glm::dvec3(map.texel(uint32_t(next % width), uint32_t(next / width)));
            ringCount += 1.0;
        }
    }
    const glm::dvec3 sky = ringCount > 0.0 ? ringSum / ringCount : glm::dvec3(0.0);

    // What the sun adds to that sky, and where it is on the whole.
    glm::dvec3 illuminance(0.0), towards(0.0);
    for (size_t texel : region) {
        const uint32_t x = uint32_t(texel % width), y = uint32_t(texel / width);
        const glm::dvec3 excess =
            glm::max(glm::dvec3(map.texel(x, y)) - sky, glm::dvec3(0.0)) * texelSolidAngle(map, y);
        illuminance += excess;
        towards += luminance(excess) * texelDirection(map, x, y);
    }
    if (!(luminance(illuminance) >= kMinSunShare * total) || !(glm::length(towards) > 0.0)) return std::nullopt;

    auto withoutSun = std::make_shared<EnvironmentMap>(map);
    for (size_t texel : region)
        for (int c = 0; c < 3; ++c) withoutSun->rgba[4 * texel + size_t(c)] = float(sky[c]);
    EnvironmentSun sun;
    sun.towardsSun = glm::vec3(glm::normalize(towards));
    sun.illuminance = glm::vec3(illuminance);
    sun.withoutSun = std::move(withoutSun);
    return sun;
}

}  // namespace vct
