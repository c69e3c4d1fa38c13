// The still frames an image averages (settings.h): every turn of the diffuse ring with every still
// sample, and the samples' offsets spread evenly over the pixel, the first at its centre.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

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

TEST(StillFrames, TurnsInFoursTraceOneBeamEachWeighedAsTheFiveAre) {
    ShadingSettings shading;
    shading.diffuseConeTurns = 16;
    for (uint32_t turn = 0; turn < 16; ++turn)
        EXPECT_EQ(diffuseBeamOfTurn(shading, false, turn).beam, glsl::ALL_BEAMS) << "without rays a cone is one cone";
    // Over the turns the axis a quarter of them, the beams around it evenly spread: their mean
    // direction is the axis, and no azimuth comes twice.
    uint32_t axis = 0;
    glm::vec2 around(0.0f);
    std::vector<float> azimuths;
    for (uint32_t turn = 0; turn < 16; ++turn) {
        const DiffuseBeam beam = diffuseBeamOfTurn(shading, true, turn);
        ASSERT_TRUE(beam.beam == glsl::AXIS_BEAM || beam.beam == glsl::BEAM_AROUND_AXIS);
        if (beam.beam == glsl::AXIS_BEAM) {
            ++axis;
            continue;
        }
        around += glm::vec2(std::cos(beam.azimuth), std::sin(beam.azimuth));
        for (float seen : azimuths) EXPECT_GT(std::abs(seen - beam.azimuth), 1e-3f);
        azimuths.push_back(beam.azimuth);
    }
    EXPECT_EQ(axis, 4u);
    EXPECT_EQ(azimuths.size(), 12u);
    EXPECT_LT(glm::length(around), 1e-4f);
    // Neighbouring turns do not walk round the axis together with the ring.
    const float step = diffuseBeamOfTurn(shading, true, 2).azimuth - diffuseBeamOfTurn(shading, true, 1).azimuth;
    EXPECT_GT(std::abs(std::remainder(step, 2.0f * 3.14159265f)), 1.0f);
    // Turns not in fours keep all five beams a turn: one beam each could not weigh them right.
    shading.diffuseConeTurns = 6;
    EXPECT_EQ(diffuseBeamOfTurn(shading, true, 1).beam, glsl::ALL_BEAMS);
}

}  // namespace
}  // namespace vct
