// A sun painted into an environment image, separated from it (src/scene/environment_sun.h): found
// where it is, with the light it adds to the sky around it, and only where it is compact and
// dominant.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "environment_images.h"
#include "scene/environment_sun.h"

namespace vct {
namespace {

constexpr double kPi = 3.14159265358979323846;

// 64 × 32 texels: a dim blue sky over the upper half, black below, and a 4 × 4-texel sun of
// radiance `sun` at columns 40-43, rows 6-9 (45° from the zenith, 56° round from −Z towards +X).
std::shared_ptr<const EnvironmentMap> skyWithASun(float sun) {
    return test::makeEnvironmentMap(64, 32, [sun](uint32_t x, uint32_t y) {
        if (x >= 40 && x < 44 && y >= 6 && y < 10) return glm::vec3(sun);
        return y < 16 ? glm::vec3(0.02f, 0.04f, 0.08f) : glm::vec3(0.0f);
    });
}

double rowSolidAngle(uint32_t row, uint32_t width, uint32_t height) {
    return 2.0 * kPi / width * (std::cos(kPi * row / height) - std::cos(kPi * (row + 1.0) / height));
}

TEST(EnvironmentSun, IsFoundWhereItIsWithTheLightItAddsToTheSky) {
    const auto map = skyWithASun(2000.0f);
    const std::optional<EnvironmentSun> sun = separateSun(*map);
    ASSERT_TRUE(sun);
    // Its texels' solid angle times what they hold above the sky around them.
    double solidAngle = 0.0;
    for (uint32_t row = 6; row < 10; ++row) solidAngle += 4.0 * rowSolidAngle(row, 64, 32);
    std::printf("[ sun ] towards (%.3f %.3f %.3f), illuminance (%.2f %.2f %.2f), expected %.2f\n", sun->towardsSun.x,
                sun->towardsSun.y, sun->towardsSun.z, sun->illuminance.r, sun->illuminance.g, sun->illuminance.b,
                (2000.0 - 0.02) * solidAngle);
    EXPECT_NEAR(sun->illuminance.r, (2000.0 - 0.02) * solidAngle, 1e-3 * 2000.0 * solidAngle);
    EXPECT_NEAR(sun->illuminance.b, (2000.0 - 0.08) * solidAngle, 1e-3 * 2000.0 * solidAngle);
    // Its centre: u = 42/64, v = 8/32 (the block's middle, weighted towards the rows that span more).
    const double phi = (42.0 / 64.0 - 0.5) * 2.0 * kPi;
    EXPECT_NEAR(std::atan2(sun->towardsSun.x, -sun->towardsSun.z), phi, 0.01);
    EXPECT_NEAR(std::acos(sun->towardsSun.y), 0.25 * kPi, 0.03);
    // The image without it holds the sky where it was.
    ASSERT_TRUE(sun->withoutSun);
    EXPECT_EQ(sun->withoutSun->texel(41, 7), glm::vec3(0.02f, 0.04f, 0.08f));
    EXPECT_EQ(sun->withoutSun->texel(20, 7), map->texel(20, 7));
}

TEST(EnvironmentSun, AWideOrFaintBrightPatchIsLeftToTheSky) {
    // A uniform sky; the upper half bright (far wider than a sun); a sun too faint to matter.
    EXPECT_FALSE(separateSun(*test::makeEnvironmentMap(64, 32, [](uint32_t, uint32_t) { return glm::vec3(1.0f); })));
    EXPECT_FALSE(separateSun(*test::makeEnvironmentMap(
        64, 32, [](uint32_t, uint32_t y) { return y < 16 ? glm::vec3(100.0f) : glm::vec3(0.1f); })));
    EXPECT_FALSE(separateSun(*skyWithASun(0.5f)));
    EXPECT_FALSE(separateSun(*test::makeEnvironmentMap(64, 32, [](uint32_t, uint32_t) { return glm::vec3(0.0f); })));
}

}  // namespace
}  // namespace vct
