#include "sky_sampling.h"

#include <algorithm>
#include <cmath>

#include "equirectangular.h"
#include "luminance.h"
#include "sampling.h"
#include "scene/environment_map.h"

namespace vct::pt {

namespace {

constexpr uint32_t kMaxColumns = 512, kMaxRows = 256;

double cellSolidAngle(const SkyDistribution& sky, uint32_t row) {
    return equirectangularCellSolidAngle(row, sky.columns, sky.rows);
}

}  // namespace

SkyDistribution buildSkyDistribution(const Scene& scene) {
    SkyDistribution sky;
    const EnvironmentMap* map = scene.environmentMap.get();
    if (!map || map->width == 0 || map->height == 0) return sky;
    const glm::dvec3 toLuminance = glm::dvec3(glsl::REC709_LUMINANCE) * glm::dvec3(scene.environment);
    sky.columns = std::min(map->width, kMaxColumns);
    sky.rows = std::min(map->height, kMaxRows);
    sky.turns = environmentTurns(scene.environmentRotation);
    // Each cell's mean luminance over the texels whose centres it holds (at least one: a cell is
    // no narrower than a texel), each texel's the mean of the bilinear reconstruction over it (¾ of
    // itself and ⅛ of each neighbour along each axis, wrapping in u, clamped at the poles), as the
    // path tracer reads the image: a sun's light spills half a texel into the sky around it, which
    // sampled by the sky's own luminance made rare, large samples.
    auto luminanceAt = [&](uint32_t x, uint32_t y) {
        return std::max(glm::dot(glm::dvec3(map->texel(x, y)), toLuminance), 0.0);
    };
    auto rowFiltered = [&](uint32_t y, std::vector<double>& row) {
        for (uint32_t x = 0; x < map->width; ++x) {
            const uint32_t left = x == 0 ? map->width - 1 : x - 1, right = x + 1 == map->width ? 0 : x + 1;
            row[x] = 0.75 * luminanceAt(x, y) + 0.125 * (luminanceAt(left, y) + luminanceAt(right, y));
        }
    };
    std::vector<double> above(map->width), current(map->width), below(map->width);
    rowFiltered(0, current);
    above = current;
    std::vector<double> sums(size_t(sky.columns) * sky.rows, 0.0);
    std::vector<uint32_t> counts(sums.size(), 0);
    for (uint32_t y = 0; y < map->height; ++y) {
        if (y + 1 < map->height) rowFiltered(y + 1, below);
        else below = current;
        const uint32_t row = std::min(uint32_t((double(y) + 0.5) * sky.rows / map->height), sky.rows - 1);
        for (uint32_t x = 0; x < map->width; ++x) {
            const uint32_t column = std::min(uint32_t((double(x) + 0.5) * sky.columns / map->width), sky.columns - 1);
            const size_t cell = size_t(row) * sky.columns + column;
            sums[cell] += 0.75 * current[x] + 0.125 * (above[x] + below[x]);
            ++counts[cell];
        }
        std::swap(above, current);
        std::swap(current, below);
    }
    std::vector<double> weights(sums.size());
    double total = 0.0;
    for (size_t cell = 0; cell < sums.size(); ++cell) {
        const double mean = counts[cell] ? sums[cell] / counts[cell] : 0.0;
        weights[cell] = mean * cellSolidAngle(sky, uint32_t(cell / sky.columns));
        total += weights[cell];
    }
    if (!(total > 0.0) || !std::isfinite(total)) return SkyDistribution{};
    sky.cdf.resize(weights.size());
    sky.probability.resize(weights.size());
    double running = 0.0;
    for (size_t cell = 0; cell < weights.size(); ++cell) {
        sky.probability[cell] = float(weights[cell] / total);
        running += weights[cell];
        sky.cdf[cell] = float(running / total);
    }
    sky.cdf.back() = 1.0f;
    return sky;
}

std::optional<SkySample> sampleSky(const SkyDistribution& sky, float uCell, float u1, float u2) {
    if (sky.empty()) return std::nullopt;
    const size_t cell = pickFromCdf(sky.cdf, uCell);
    if (!(sky.probability[cell] > 0.0f)) return std::nullopt;
    const uint32_t row = uint32_t(cell / sky.columns), column = uint32_t(cell % sky.columns);
    // Uniform in solid angle within the cell: u uniform, cos θ uniform between the row's edges.
    const double u = (double(column) + double(u1)) / double(sky.columns);
    const double cosTop = std::cos(M_PI * double(row) / double(sky.rows));
    const double cosBottom = std::cos(M_PI * double(row + 1) / double(sky.rows));
    const double cosTheta = cosTop - double(u2) * (cosTop - cosBottom);
    const double v = std::acos(std::clamp(cosTheta, -1.0, 1.0)) / M_PI;
    SkySample sample;
    sample.direction = glsl::equirectangularDirection(glm::vec2(float(u), float(v)), sky.turns);
    sample.pdf = float(double(sky.probability[cell]) / cellSolidAngle(sky, row));
    if (!(sample.pdf > 0.0f) || !std::isfinite(sample.pdf)) return std::nullopt;
    return sample;
}

float skyPdf(const SkyDistribution& sky, const glm::vec3& direction) {
    if (sky.empty()) return 0.0f;
    const glm::vec2 uv = glsl::equirectangularCoordinates(direction, sky.turns);
    const double u = double(uv.x) - std::floor(double(uv.x));
    const uint32_t column = std::min(uint32_t(u * sky.columns), sky.columns - 1);
    const uint32_t row = std::min(uint32_t(std::max(double(uv.y), 0.0) * sky.rows), sky.rows - 1);
    const double solidAngle = cellSolidAngle(sky, row);
    return solidAngle > 0.0 ? float(double(sky.probability[size_t(row) * sky.columns + column]) / solidAngle) : 0.0f;
}

}  // namespace vct::pt
