// The display transform of PNG output and the viewer: automatic exposure and the tone curves.
#include <gtest/gtest.h>

#include <cmath>

#include "io/display_transform.h"

namespace vct {
namespace {

Image uniformImage(uint32_t width, uint32_t height, float value) {
    Image image{width, height, std::vector<float>(size_t(width) * height * 3, value)};
    return image;
}

TEST(DisplayTransform, AutomaticExposurePutsTheLogAverageAtMiddleGrey) {
    // Half the pixels at 4, half at 1: log-average 2, so the exposure is 0.18 / 2.
    Image image = uniformImage(4, 2, 1.0f);
    for (size_t i = 0; i < 12; ++i) image.rgb[i] = 4.0f;
    EXPECT_NEAR(automaticExposure(image), kMiddleGrey / 2.0f, 1e-5f);
}

TEST(DisplayTransform, AutomaticExposureIgnoresBlackPixelsAndScalesWithTheLight) {
    // An object against a black sky is exposed for itself, and ten times the light gets a tenth
    // of the exposure (the picture stays the same).
    Image image = uniformImage(4, 4, 0.0f);
    for (size_t i = 0; i < 6; ++i) image.rgb[i] = 0.5f;
    const float exposure = automaticExposure(image);
    EXPECT_NEAR(exposure, kMiddleGrey / 0.5f, 1e-5f);
    for (float& value : image.rgb) value *= 10.0f;
    EXPECT_NEAR(automaticExposure(image), exposure / 10.0f, 1e-5f);
    EXPECT_EQ(automaticExposure(uniformImage(2, 2, 0.0f)), 1.0f);  // no light: left as it is
}

TEST(DisplayTransform, PbrNeutralKeepsBaseColoursAndCompressesOnlyHighlights) {
    // Khronos PBR Neutral: a colour whose channels stay under the start of compression comes out
    // less the small offset for its darkest channel, so its hue is kept.
    const glm::vec3 red = glsl::toneMap(glm::vec3(0.6f, 0.1f, 0.1f), glsl::TONE_CURVE_PBR_NEUTRAL);
    EXPECT_NEAR(red.x, 0.6f - 0.04f, 1e-5f);
    EXPECT_NEAR(red.y, 0.1f - 0.04f, 1e-5f);
    // Highlights compress towards 1 and never reach past it, monotonic in the light.
    float last = 0.0f;
    for (float value : {0.5f, 0.9f, 2.0f, 8.0f, 1000.0f}) {
        const float mapped = glsl::toneMap(glm::vec3(value), glsl::TONE_CURVE_PBR_NEUTRAL).x;
        EXPECT_GT(mapped, last) << value;
        EXPECT_LE(mapped, 1.0f) << value;
        last = mapped;
    }
    EXPECT_GT(last, 0.99f);
    EXPECT_EQ(glsl::toneMap(glm::vec3(0.0f), glsl::TONE_CURVE_PBR_NEUTRAL), glm::vec3(0.0f));
}

TEST(DisplayTransform, CurvesAreNamed) {
    EXPECT_EQ(parseToneCurve("pbr-neutral"), ToneCurve::PbrNeutral);
    EXPECT_EQ(parseToneCurve("aces"), ToneCurve::Aces);
    EXPECT_FALSE(parseToneCurve("filmic").has_value());
    EXPECT_STREQ(toneCurveName(ToneCurve::Aces), "aces");
    EXPECT_NEAR(exposureFromStops(-1.0f), 0.5f, 1e-6f);
}

}  // namespace
}  // namespace vct
