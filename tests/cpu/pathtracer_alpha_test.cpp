// The path tracer's glTF alphaMode: rays pass a MASK surface's holes (camera, path and shadow rays
// alike) and a BLEND surface with probability 1 − alpha.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "alpha_test_scenes.h"
#include "path_tracer.h"
#include "sampling.h"

namespace vct::pt {
namespace {

using vct::test::checkerOpaqueAt;
using vct::test::distanceToCheckerEdge;
using vct::test::kOccluderZ;
using vct::test::occluderBeforeWall;
using vct::test::occluderSeenFromBehind;

constexpr float kTolerance = 1e-3f;

// The direct light seen along a ray from above the occluder through its plane at `throughOccluder`
// and on to the wall at `onWall` (straight down when they are the same point).
glm::vec3 directLightAlong(const PathTracer& tracer, glm::vec2 throughOccluder, glm::vec2 onWall, Rng& rng) {
    const glm::vec3 through(throughOccluder, kOccluderZ), target(onWall, 0.0f);
    const glm::vec3 direction = glm::normalize(target - through);
    return tracePath(tracer, Ray{through - 0.5f * direction, direction}, Component::Direct, rng);
}

TEST(PathTracerAlpha, MaskLetsCameraAndShadowRaysThroughItsHolesOnly) {
    const Scene scene = occluderBeforeWall(AlphaMode::Mask, true);
    const PathTracer tracer = createPathTracer(scene);
    Rng rng = Rng::forSample(1, 0, 0);
    uint32_t occluder = 0, litWall = 0, shadowedWall = 0;
    for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i) {
            const glm::vec2 point(-0.95f + 1.9f * (float(i) + 0.5f) / 16.0f, -0.95f + 1.9f * (float(j) + 0.5f) / 16.0f);
            if (distanceToCheckerEdge(point) < 0.02f) continue;
            // Straight down: the red quad where it is opaque (lit, nothing above it), else the wall,
            // lit through the same hole.
            const glm::vec3 straight = directLightAlong(tracer, point, point, rng);
            const glm::vec3 expected = checkerOpaqueAt(point) ? glm::vec3(1, 0, 0) : glm::vec3(1);
            ++(checkerOpaqueAt(point) ? occluder : litWall);
            EXPECT_NEAR(straight.r, expected.r, kTolerance) << point.x << "," << point.y;
            EXPECT_NEAR(straight.g, expected.g, kTolerance) << point.x << "," << point.y;
            // Through a hole at a slant onto the wall under the square to its right: in the shadow
            // of that opaque square.
            if (checkerOpaqueAt(point)) continue;
            const glm::vec2 nextSquare = point + glm::vec2(0.25f, 0.0f);
            if (std::abs(nextSquare.x) >= 0.99f) continue;
            ++shadowedWall;
            const glm::vec3 slanted = directLightAlong(tracer, point, nextSquare, rng);
            EXPECT_NEAR(slanted.g, 0.0f, kTolerance) << point.x << "," << point.y;
        }
    EXPECT_GT(occluder, 50u);
    EXPECT_GT(litWall, 50u);
    EXPECT_GT(shadowedWall, 30u);
}

TEST(PathTracerAlpha, BlendAtHalfAlphaStopsHalfTheRays) {
    // Straight down at one point: the camera ray stops at the red quad half the time (red, lit);
    // passing it, it meets the wall, lit when the shadow ray passes too: mean (0.75, 0.25, 0.25).
    const Scene scene = occluderBeforeWall(AlphaMode::Blend, false, 0.5f);
    const PathTracer tracer = createPathTracer(scene);
    constexpr int kSamples = 8000;
    glm::dvec3 sum(0.0);
    for (int sample = 0; sample < kSamples; ++sample) {
        Rng rng = Rng::forSample(7, 0, uint64_t(sample));
        sum += glm::dvec3(directLightAlong(tracer, glm::vec2(0.1f, 0.2f), glm::vec2(0.1f, 0.2f), rng));
    }
    const glm::dvec3 mean = sum / double(kSamples);
    std::printf("BLEND 0.5 in the path tracer: mean direct light (%.4f, %.4f, %.4f), expected (0.75, 0.25, 0.25)\n",
                mean.r, mean.g, mean.b);
    // Standard errors: sqrt(p(1 − p)/N) ≤ 0.0056 for these Bernoulli shares; 4σ.
    EXPECT_NEAR(mean.r, 0.75, 0.022);
    EXPECT_NEAR(mean.g, 0.25, 0.022);
}

TEST(PathTracerDoubleSided, TheCameraDoesNotSeeASingleSidedSurfaceFromBehindButItsShadowStays) {
    // As the renderer's G-buffer culls back faces, a camera ray passes the back of a single-sided
    // occluder and meets the wall in its shadow; double-sided, it meets the occluder's lit back.
    const Scene singleSidedScene = occluderSeenFromBehind(false), doubleSidedScene = occluderSeenFromBehind(true);
    const PathTracer singleSided = createPathTracer(singleSidedScene);
    const PathTracer doubleSided = createPathTracer(doubleSidedScene);
    Rng rng = Rng::forSample(3, 0, 0);
    for (const glm::vec2 point : {glm::vec2(0.0f), glm::vec2(0.5f, -0.3f), glm::vec2(-0.7f, 0.6f)}) {
        const glm::vec3 behind = directLightAlong(singleSided, point, point, rng);
        const glm::vec3 back = directLightAlong(doubleSided, point, point, rng);
        EXPECT_NEAR(behind.r, 0.0f, kTolerance) << point.x << "," << point.y;
        EXPECT_NEAR(back.r, 1.0f, kTolerance) << point.x << "," << point.y;
        EXPECT_NEAR(back.g, 0.0f, kTolerance) << point.x << "," << point.y;
    }
}

}  // namespace
}  // namespace vct::pt
