// Light sampling of an environment image (--environment FILE.hdr) for the path tracer: directions
// drawn in proportion to the sky's luminance over the solid angle it spans, so that a sun painted
// into the image is found by shadow rays towards it rather than by the few BRDF samples that happen
// to hit it. The image is read in cells of up to 512 × 256 (whole texels each); within a cell a
// direction is uniform in solid angle.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace vct::pt {

struct SkyDistribution {
    uint32_t columns = 0, rows = 0;  // cells, equal in u and in v (equirectangular.h)
    float turns = 0.0f;              // Scene::environmentRotation, in turns
    std::vector<float> cdf;          // cumulative probability of the cells, row by row from the top
    std::vector<float> probability;  // of each cell
    bool empty() const { return cdf.empty(); }
};

// The distribution of the scene's environment image; empty where there is none, or it is black.
SkyDistribution buildSkyDistribution(const Scene& scene);

struct SkySample {
    glm::vec3 direction;  // unit
    float pdf;            // per unit solid angle
};

// A direction from three uniform numbers in [0, 1); none where the distribution is empty.
std::optional<SkySample> sampleSky(const SkyDistribution& sky, float uCell, float u1, float u2);

// The density sampleSky draws the unit `direction` with, per unit solid angle.
float skyPdf(const SkyDistribution& sky, const glm::vec3& direction);

}  // namespace vct::pt
