// An equirectangular environment image (--environment FILE.hdr): the sky's radiance by direction,
// in scene units, the file's values as they are. The renderer's cones that leave the grid, its
// camera's view of the sky and the path tracer's escaping paths all read it through
// shaders_glsl/equirectangular.h.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vct {

struct EnvironmentMap {
    std::string name;  // the file, for messages
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> rgba;  // width × height texels, rows from the top (+Y); alpha 1

    glm::vec3 texel(uint32_t x, uint32_t y) const;
};

// The most texels an environment image may have (16384 × 8192: 2 GiB as float RGBA).
constexpr uint64_t kMaxEnvironmentTexels = uint64_t(16384) * 8192;

// A vct::Error naming `path` unless it is a file (checked before any work, read later).
void checkEnvironmentImageExists(const std::string& path);

// Reads a Radiance .hdr file. A missing, unreadable or non-HDR file, one larger than
// kMaxEnvironmentTexels, or a texel that is negative or not finite is a vct::Error naming the file.
EnvironmentMap loadEnvironmentMap(const std::string& path);

// The radiance seen along the unit `direction` with the image turned `rotation` radians about +Y
// (Scene::environmentRotation): bilinear between the four nearest texels, wrapping around in u and
// clamped at the poles, as the renderer's sampler reads level 0.
glm::vec3 environmentRadiance(const EnvironmentMap& map, const glm::vec3& direction, float rotation);

// The solid angle of a cell in row `row` of an equirectangular grid of `columns` × `rows` cells: its
// share of the longitudes times its band of latitudes.
double equirectangularCellSolidAngle(uint32_t row, uint32_t columns, uint32_t rows);

// A rotation about +Y in radians as the shaders take it: turns, in [0, 1) (equirectangular.h).
float environmentTurns(float rotation);

// Whether an --environment value names an image (a path ending in .hdr, any case) rather than a
// uniform radiance R,G,B.
bool namesEnvironmentImage(const std::string& value);

// The scene's sky becomes `map` (its radiance as read: Scene::environment = 1); null leaves it.
struct Scene;
void useEnvironmentImage(Scene& scene, std::shared_ptr<const EnvironmentMap> map);

// The mean over all directions (each texel weighted by the solid angle it spans).
glm::vec3 meanEnvironmentRadiance(const EnvironmentMap& map);

}  // namespace vct
