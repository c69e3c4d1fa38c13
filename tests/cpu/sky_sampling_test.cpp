// The path tracer's light sampling of an environment image (tools/pathtrace/sky_sampling.h): its
// directions and densities agree, it finds a sun painted into the image, and a plane under such a
// sky converges to its analytic light with far less noise than BRDF sampling alone.
#include <gtest/gtest.h>

#include <cmath>

#include "environment_images.h"
#include "luminance.h"
#include "path_tracer.h"
#include "pathtracer_test_helpers.h"
#include "scene/environment_map.h"
#include "sky_sampling.h"

namespace vct::pt {
namespace {

// 64 × 32 texels: a dim blue sky over the upper half, black below, and a 4 × 4-texel sun of
// radiance 2000 about 42° from the zenith, to the right of −Z.
std::shared_ptr<const EnvironmentMap> skyWithASun() {
    return vct::test::makeEnvironmentMap(64, 32, [](uint32_t x, uint32_t y) {
        if (x >= 40 && x < 44 && y >= 6 && y < 10) return glm::vec3(2000.0f);
        return y < 16 ? glm::vec3(0.02f, 0.04f, 0.08f) : glm::vec3(0.0f);
    });
}

// Whether `direction` sees the sun's light: in the sun, or in the half texel around it where the
// bilinear reading blends it with the sky.
bool seesTheSun(const EnvironmentMap& map, const glm::vec3& direction, float rotation) {
    return environmentRadiance(map, direction, rotation).r > 1.0f;
}

TEST(SkySampling, DirectionsFallWhereTheLightIsWithTheDensityTheyWereDrawnWith) {
    // The sun holds nearly all of the sky's power: nearly every sample sees it, turned with the image
    // (a few fall in the far halves of the texels around it, which the bilinear reading leaves
    // dark); each sample's density is the one skyPdf gives its direction.
    for (const float rotation : {0.0f, 1.0f}) {
        Scene scene;
        scene.environment = glm::vec3(1.0f);
        scene.environmentMap = skyWithASun();
        scene.environmentRotation = rotation;
        const SkyDistribution sky = buildSkyDistribution(scene);
        ASSERT_FALSE(sky.empty());
        Rng rng = Rng::forSample(7, 0, 0);
        int sunny = 0;
        constexpr int kSamples = 2000;
        for (int i = 0; i < kSamples; ++i) {
            const float uCell = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
            const std::optional<SkySample> sample = sampleSky(sky, uCell, u1, u2);
            ASSERT_TRUE(sample);
            EXPECT_NEAR(glm::length(sample->direction), 1.0f, 1e-5f);
            EXPECT_NEAR(skyPdf(sky, sample->direction), sample->pdf, 1e-3f * sample->pdf) << i;
            sunny += seesTheSun(*scene.environmentMap, sample->direction, rotation) ? 1 : 0;
        }
        EXPECT_GT(sunny, kSamples * 90 / 100) << "turned " << rotation;
    }
    // No image, or a black one: nothing to sample.
    Scene plain;
    plain.environment = glm::vec3(1.0f);
    EXPECT_TRUE(buildSkyDistribution(plain).empty());
    plain.environmentMap = skyWithASun();
    plain.environment = glm::vec3(0.0f);
    EXPECT_TRUE(buildSkyDistribution(plain).empty());
}

// The luminance of E = ∫ L(ω) cosθ dω over the upper hemisphere, by a fine quadrature of the image
// as the path tracer reads it.
double irradianceFromAbove(const EnvironmentMap& map) {
    constexpr int kColumns = 2048, kRows = 512;  // over the upper hemisphere
    double sum = 0.0;
    for (int row = 0; row < kRows; ++row) {
        const double theta = 0.5 * kPi * (row + 0.5) / kRows;
        for (int column = 0; column < kColumns; ++column) {
            const double phi = 2.0 * kPi * (column + 0.5) / kColumns;
            const glm::vec3 direction(float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)),
                                      float(-std::sin(theta) * std::cos(phi)));
            const glm::vec3 radiance = environmentRadiance(map, direction, 0.0f);
            sum += glsl::luminance(glm::dvec3(radiance)) * std::cos(theta) * std::sin(theta);
        }
    }
    return sum * (0.5 * kPi / kRows) * (2.0 * kPi / kColumns);
}

TEST(SkySampling, APlaneUnderASunnySkyConvergesToItsLightWithLittleNoise) {
    // A grey Lambertian plane (albedo 0.5) under the sky alone reflects L = 0.5 E / π. BRDF
    // sampling finds the sun with a few percent of its samples; light sampling with nearly all.
    Scene scene;
    scene.name = "plane under a sunny sky";
    test::addSunlitPlaneSeenFromAbove(scene, test::lambertian(glm::vec3(0.5f)), glm::vec3(0, -1, 0));
    scene.lights.clear();
    scene.environment = glm::vec3(1.0f);
    scene.environmentMap = skyWithASun();
    const double truth = 0.5 * irradianceFromAbove(*scene.environmentMap) / kPi;
    const RenderSettings settings = test::smallRender(scene, 4, 256, Component::Indirect, 3);

    PathTracer sampled = createPathTracer(scene);
    sampled.maxDepth = 1;  // the plane's own light: nothing else to bounce off
    const RenderResult withSky = render(sampled, settings);
    PathTracer bsdfOnly = createPathTracer(scene);
    bsdfOnly.maxDepth = 1;
    bsdfOnly.sampleSky = false;
    const RenderResult withoutSky = render(bsdfOnly, settings);
    std::printf("[ sky ] truth %.4f; light sampling %.4f ± %.4f, BRDF sampling alone %.4f ± %.4f\n", truth,
                withSky.meanLuminance, withSky.meanLuminanceStandardError, withoutSky.meanLuminance,
                withoutSky.meanLuminanceStandardError);
    EXPECT_NEAR(withSky.meanLuminance, truth, 4.0 * withSky.meanLuminanceStandardError);
    EXPECT_LT(withSky.meanLuminanceStandardError, 0.015 * truth);
    EXPECT_GT(withoutSky.meanLuminanceStandardError, 5.0 * withSky.meanLuminanceStandardError);
    // Both estimate the same light: BRDF sampling alone is unbiased too, only noisier.
    EXPECT_NEAR(withoutSky.meanLuminance, truth, 4.0 * withoutSky.meanLuminanceStandardError);
}

}  // namespace
}  // namespace vct::pt
