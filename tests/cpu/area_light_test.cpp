// The area lights' irradiance formula (shaders_glsl/area_light.h) against numerical integration
// of E = ∫ L cosθ cosθ' / r² dA over the triangle, and against the closed forms it must reach.
#include <gtest/gtest.h>

#include "area_light.h"

namespace {

using glm::vec3;

// E per unit radiance at the origin, normal n, from a triangle that emits towards it from both
// faces, by the midpoint rule on a 2·steps² subdivision (only the part above the horizon counts).
float integratedIrradiance(vec3 a, vec3 b, vec3 c, vec3 n, int steps = 400) {
    const vec3 normal = glm::normalize(glm::cross(b - a, c - a));
    const float cellArea = glm::length(glm::cross(b - a, c - a)) * 0.5f / float(steps * steps);
    double sum = 0.0;
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps - i; ++j)
            for (int upper = 0; upper < (j < steps - i - 1 ? 2 : 1); ++upper) {
                // Centroid of the small triangle (i, j) in barycentric steps; `upper` the flipped one.
                const float u = (float(i) + (upper ? 2.0f : 1.0f) / 3.0f) / float(steps);
                const float v = (float(j) + (upper ? 2.0f : 1.0f) / 3.0f) / float(steps);
                const vec3 p = a + (b - a) * u + (c - a) * v;
                const float r2 = glm::dot(p, p);
                const vec3 toPoint = p / std::sqrt(r2);
                const float cosReceiver = glm::dot(n, toPoint);
                if (cosReceiver <= 0.0f) continue;
                sum += double(cosReceiver * std::abs(glm::dot(normal, toPoint)) / r2 * cellArea);
            }
    return float(sum);
}

TEST(AreaLight, TriangleAboveThePointMatchesIntegration) {
    const vec3 a(-0.3f, 1.0f, -0.2f), b(0.4f, 1.2f, -0.1f), c(0.1f, 0.9f, 0.5f);
    const vec3 n(0.0f, 1.0f, 0.0f);
    const float exact = vct::glsl::triangleIrradiance(a, b, c, n);
    EXPECT_NEAR(exact, integratedIrradiance(a, b, c, n), 2e-3f * exact);
    // Either winding: the formula does not care which face is seen (the caller checks the front).
    EXPECT_FLOAT_EQ(exact, vct::glsl::triangleIrradiance(a, c, b, n));
}

TEST(AreaLight, TriangleCutByTheHorizonCountsOnlyItsVisiblePart) {
    // A tilted receiver: one corner of the triangle lies below its horizon, then two.
    for (const vec3 n : {glm::normalize(vec3(0.9f, 0.4f, 0.0f)), glm::normalize(vec3(1.0f, 0.1f, 0.3f))}) {
        const vec3 a(-1.0f, 1.0f, -0.2f), b(1.0f, 0.8f, -0.3f), c(0.2f, 0.6f, 1.0f);
        const float exact = vct::glsl::triangleIrradiance(a, b, c, n);
        const float integrated = integratedIrradiance(a, b, c, n, 800);
        EXPECT_GT(integrated, 0.01f);
        EXPECT_NEAR(exact, integrated, 3e-3f * integrated) << n.x << " " << n.y << " " << n.z;
    }
}

TEST(AreaLight, AnUnboundedEmitterGivesPiTimesItsRadiance) {
    // Two triangles forming a huge square just above the point: the whole hemisphere, E = π L.
    const float s = 1e5f;
    const vec3 n(0.0f, 0.0f, 1.0f);
    const float e = vct::glsl::triangleIrradiance(vec3(-s, -s, 1), vec3(s, -s, 1), vec3(s, s, 1), n) +
                    vct::glsl::triangleIrradiance(vec3(-s, -s, 1), vec3(s, s, 1), vec3(-s, s, 1), n);
    EXPECT_NEAR(e, 3.14159265f, 1e-3f);
    // The same square cut in half by the receiver's horizon (it stands edge on): half of π.
    const vec3 sideways(1.0f, 0.0f, 0.0f);
    const float half = vct::glsl::triangleIrradiance(vec3(-s, -s, 1), vec3(s, -s, 1), vec3(s, s, 1), sideways) +
                       vct::glsl::triangleIrradiance(vec3(-s, -s, 1), vec3(s, s, 1), vec3(-s, s, 1), sideways);
    EXPECT_NEAR(half, 0.5f * 3.14159265f, 1e-3f);  // the half of the hemisphere on the plane's side
}

TEST(AreaLight, BelowTheHorizonGivesNothingAndFarAwayActsLikeAPoint) {
    const vec3 n(0.0f, 1.0f, 0.0f);
    EXPECT_EQ(vct::glsl::triangleIrradiance(vec3(0, -1, 0), vec3(1, -1, 0), vec3(0, -1, 1), n), 0.0f);
    // A small triangle far away: E = L · A cosθ cosθ' / d², with full float precision left.
    const float d = 1000.0f, side = 0.01f;
    const float e = vct::glsl::triangleIrradiance(vec3(0, d, 0), vec3(side, d, 0), vec3(0, d, side), n);
    EXPECT_NEAR(e, 0.5f * side * side / (d * d), 1e-3f * 0.5f * side * side / (d * d));
}

}  // namespace
