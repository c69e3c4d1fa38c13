#include "scene/environment_map.h"

#include <stb/stb_image.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <memory>

#include "equirectangular.h"  // shaders_glsl: where a direction reads the image
#include "error.h"
#include "scene/material_textures.h"
#include "scene/scene.h"

namespace vct {

glm::vec3 EnvironmentMap::texel(uint32_t x, uint32_t y) const {
    const float* t = &rgba[4 * (size_t(y) * width + x)];
    return glm::vec3(t[0], t[1], t[2]);
}

void checkEnvironmentImageExists(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) throw Error(path + ": environment image not found");
}

EnvironmentMap loadEnvironmentMap(const std::string& path) {
    checkEnvironmentImageExists(path);
    int width = 0, height = 0, channels = 0;
    if (!stbi_info(path.c_str(), &width, &height, &channels))
        throw Error(path + ": not an image stb_image can read (" + stbi_failure_reason() + ")");
    if (!stbi_is_hdr(path.c_str()))
        throw Error(path + ": not a Radiance .hdr image (an environment holds radiance, which 8-bit images cannot)");
    if (width <= 0 || height <= 0 || uint64_t(width) * uint64_t(height) > kMaxEnvironmentTexels)
        throw Error(path + ": an environment image of " + std::to_string(width) + " × " + std::to_string(height) +
                    " texels, more than the " + std::to_string(kMaxEnvironmentTexels) + " allowed");
    const std::unique_ptr<float, void (*)(void*)> pixels(stbi_loadf(path.c_str(), &width, &height, &channels, 4),
                                                         stbi_image_free);
    if (!pixels) throw Error(path + ": the environment image cannot be decoded (" + stbi_failure_reason() + ")");
    EnvironmentMap map;
    map.name = path;
    map.width = uint32_t(width);
    map.height = uint32_t(height);
    map.rgba.assign(pixels.get(), pixels.get() + size_t(width) * size_t(height) * 4);
    for (size_t i = 0; i < map.rgba.size(); ++i) {
        if (!std::isfinite(map.rgba[i]) || map.rgba[i] < 0.0f)
            throw Error(path + ": texel " + std::to_string(i / 4) +
                        " of the environment image is not a finite, "
                        "non-negative radiance");
        if (i % 4 == 3) map.rgba[i] = 1.0f;
    }
    return map;
}

void useEnvironmentImage(Scene& scene, std::shared_ptr<const EnvironmentMap> map) {
    if (!map) return;
    scene.environmentMap = std::move(map);
    scene.environment = glm::vec3(1.0f);
}

bool namesEnvironmentImage(const std::string& value) {
    std::string extension = std::filesystem::path(value).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".hdr";
}

double equirectangularCellSolidAngle(uint32_t row, uint32_t columns, uint32_t rows) {
    const double top = M_PI * double(row) / double(rows), bottom = M_PI * double(row + 1) / double(rows);
    return 2.0 * M_PI / double(columns) * (std::cos(top) - std::cos(bottom));
}

float environmentTurns(float rotation) {
    const double turns = double(rotation) / (2.0 * M_PI);
    return float(turns - std::floor(turns));
}

glm::vec3 environmentRadiance(const EnvironmentMap& map, const glm::vec3& direction, float rotation) {
    if (map.width == 0 || map.height == 0) return glm::vec3(0.0f);
    // Texel centres sit at (i + ½)/size, as a GPU sampler places them.
    const glm::vec2 at =
        glsl::equirectangularCoordinates(direction, environmentTurns(rotation)) * glm::vec2(map.width, map.height) -
        0.5f;
    const glm::vec2 low = glm::floor(at), t = at - low;
    // Around the horizon the image wraps; at the poles it ends (as the renderer's sampler).
    const uint32_t x0 = wrapTexel(low.x, map.width, TextureWrap::Repeat);
    const uint32_t x1 = wrapTexel(low.x + 1.0, map.width, TextureWrap::Repeat);
    const uint32_t y0 = wrapTexel(low.y, map.height, TextureWrap::ClampToEdge);
    const uint32_t y1 = wrapTexel(low.y + 1.0, map.height, TextureWrap::ClampToEdge);
    return glm::mix(glm::mix(map.texel(x0, y0), map.texel(x1, y0), t.x),
                    glm::mix(map.texel(x0, y1), map.texel(x1, y1), t.x), t.y);
}

glm::vec3 meanEnvironmentRadiance(const EnvironmentMap& map) {
    glm::dvec3 sum(0.0);
    double weights = 0.0;
    for (uint32_t y = 0; y < map.height; ++y) {
        // A row's texels span solid angles ∝ sin θ at the row's centre.
        const double weight = std::sin(M_PI * (double(y) + 0.5) / double(map.height));
        for (uint32_t x = 0; x < map.width; ++x) sum += weight * glm::dvec3(map.texel(x, y));
        weights += weight * map.width;
    }
    return weights > 0.0 ? glm::vec3(sum / weights) : glm::vec3(0.0f);
}

}  // namespace vct
