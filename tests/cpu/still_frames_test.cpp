// The still frames an image averages (settings.h): every turn of the diffuse ring with every still
// sample, and the samples' offsets spread evenly over the pixel, the first at its centre.
#include <gtest/gtest.h>

#include "render/settings.h"

namespace vct {
namespace {

TEST(StillFrames, TurnsAndSamplesMeetInTheirLeastCommonMultiple) {
    ShadingSettings shading;
    shading.diffuseConeTurns = 3;
    shading.stillSamples = 2;
    EXPECT_EQ(stillFramesAveraged(shading), 6u);
    shading.stillSamples = 6;
    EXPECT_EQ(stillFramesAveraged(shading), 6u);
    // Without a ring of cones in the image (direct light) only the samples count.
    shading.mode = RenderMode::Direct;
    EXPECT_EQ(diffuseRingTurns(shading), 1u);
    EXPECT_EQ(stillFramesAveraged(shading), 6u);
    shading.stillSamples = 1;
    EXPECT_EQ(stillFramesAveraged(shading), 1u);
}

TEST(StillFrames, SixteenSamplesCoverThePixelEvenlyFromItsCentre) {
    ShadingSettings shading;
    shading.stillSamples = 16;
    EXPECT_EQ(stillSampleOffset(shading, 0), glm::vec2(0.0f));
    EXPECT_EQ(stillSampleOffset(shading, 16), glm::vec2(0.0f)) << "the sequence repeats";
    int perQuarter[2][2] = {};
    glm::vec2 mean(0.0f);
    for (uint32_t frame = 0; frame < 16; ++frame) {
        const glm::vec2 offset = stillSampleOffset(shading, frame);
        ASSERT_GE(offset.x, -0.5f);
        ASSERT_LT(offset.x, 0.5f);
        ASSERT_GE(offset.y, -0.5f);
        ASSERT_LT(offset.y, 0.5f);
        ++perQuarter[offset.x < 0.0f][offset.y < 0.0f];
        mean += offset / 16.0f;
    }
    for (auto& row : perQuarter)
        for (int count : row) EXPECT_EQ(count, 4);
    EXPECT_LT(glm::length(mean + glm::vec2(1.0f / 32.0f)), 0.1f) << "centred on the pixel, to a sample's spacing";
}

}  // namespace
}  // namespace vct
