// The failures users of other VCT renderers report most, measured (src/bench/failure_modes.h) and
// held to stated bounds: light leaking through thin walls, brightness that drifts with the voxel
// resolution, and flicker under small camera or light moves.
#include <cstdio>
#include <iterator>

#include "bench/failure_modes.h"
#include "gpu_test.h"
#include "io/image_io.h"
#include "path_tracer.h"
#include "render/presets.h"
#include "render/renderer.h"
#include "scene/load.h"

namespace vct::test {
namespace {

// Regression guards (suite FailureModesGuard): bounds at today's figures, with the mips alone or
// at `balanced`, so that a regression shows; each names its target, which ray visibility (`walls`)
// is held to in suite FailureModes where a test here can measure it (the full image's error is the
// bench's). Measured at 32² with converged bounces, the mips alone:
// - leak (truth 0), the wall on a voxel boundary, a third and half a voxel in: a single sheet
//   facing the lit room 41 / 40 / 33 % of the lit room's mean, facing the dark room 0.4 / 0.6 /
//   2.6 % (but the lit room then loses a third of its light through it), two faces 1 cm apart 5.9 /
//   10.7 / 11.3 %. Walls thinner than the coarse texels the cones read leak through their
//   trilinear filtering, and a sheet's voxels are see-through from behind.
// - brightness against resolution (Cornell box, first bounce, 32² × 2², anisotropic): 0.98, 0.92,
//   0.95, 0.92 × its one-bounce path-traced truth at 32³, 64³, 128³, 256³ (spread 6.6 %). The
//   coarsest grid's voxels are thicker than the surfaces they hold and reflect a little more.
struct RegressionGuards {
    // Dark room / lit room mean luminance, by wall (bench::kSharedWalls' order). Target 0.02.
    double leakRatio[3] = {0.45, 0.03, 0.13};
    // (max − min) / mean of the first bounce's luminance, 32³…256³. Target 0.10 (0.05 over 64³…256³).
    double resolutionSpread = 0.20;
    // First-bounce luminance / its path-traced truth, each resolution. Target 0.90-1.10.
    double groundTruthRatioLow = 0.55;
    double groundTruthRatioHigh = 1.10;
};
constexpr RegressionGuards kGuards;

RenderSettings smallSettings(uint32_t size, uint32_t voxels) {
    RenderSettings settings;
    settings.image.width = settings.image.height = size;
    settings.image.supersample = 1;
    settings.resources.voxelResolution = voxels;
    settings.resources.sunShadowMapSize = 512;
    settings.resources.localShadowMapSize = 256;
    return settings;
}

class FailureModes : public GpuTest {};
class FailureModesGuard : public FailureModes {};

TEST_F(FailureModesGuard, WithTheMipsAloneThinWallsLeakNoMoreLightIntoTheDarkRoomThanTheyDid) {
    // The wall on a voxel boundary (x = 0 is one, the grid being centred on the scene) and inside
    // a voxel (a third of the way through one at 64³), as one sheet facing either room or as two
    // faces. Target 2 %, which ray visibility meets (FailureModes.WithRayVisibility…).
    const RenderSettings settings = smallSettings(32, 64);
    const float voxel = bench::twoRoomVoxelSize(64);
    for (size_t w = 0; w < std::size(bench::kSharedWalls); ++w)
        for (float wallX : {0.0f, voxel / 3.0f, -voxel / 2.0f}) {
            const bench::SharedWall wall = bench::kSharedWalls[w];
            const bench::LeakMeasurement leak = bench::measureLightLeak(gpu(), settings, wallX, wall);
            std::printf("[ leak ] %s wall at x = %+.4f m: lit room %.5f, dark room %.6f, ratio %.5f\n",
                        bench::sharedWallName(wall), wallX, leak.litRoomLuminance, leak.darkRoomLuminance,
                        leak.leakRatio());
            EXPECT_GT(leak.litRoomLuminance, 0.01);
            EXPECT_LE(leak.leakRatio(), kGuards.leakRatio[w])
                << bench::sharedWallName(wall) << " at x = " << wallX << " (regression guard; target 0.02)";
        }
}

TEST_F(FailureModes, ATwoFacedWallLeaksLessTheThickerItIs) {
    // Where the leak comes from once both faces are opaque: a cone from the dark room that reaches
    // the wall has a footprint as wide as a fair part of its distance (a 40° cone 1 m out: 0.73 m),
    // so its coarse texels straddle the wall, and the chains along the wall (rays going up, down,
    // sideways) see the lit face edge on, opaque with its light. (Edge-on voxels made black, tried
    // at 64² images: the 2-voxel wall's leak fell from 5.5 to 1.1-1.6 %, but the lit room lost half
    // its light, every wall seen obliquely turning dark.) So the leak falls with the wall's thickness
    // against the cones' footprints, not with the voxels' size: here (32² images, 64³) 5.9 / 3.7 /
    // 0.7 % for walls 1/3, 2 and 8 voxels thick; at 64² images 7.2 / 5.3 / 2.2 / 0.9 % for 1/3, 2, 4
    // and 8 voxels, and at 128³ 8.8 / 6.2 / 1.6 % for 1/3, 2 and 8 voxels of 64³. Only a wall thicker
    // than the footprints the cones reach it with stops leaking: no sided voxel format alone takes a
    // thin wall below a few per cent.
    const RenderSettings settings = smallSettings(32, 64);
    const float voxel = bench::twoRoomVoxelSize(64);
    double thinnerLeak = 1.0;
    for (float thicknessVoxels : {1.0f / 3.0f, 2.0f, 8.0f}) {
        const bench::LeakMeasurement leak = bench::measureLightLeak(
            gpu(), settings, bench::makeTwoRoomScene(0.0f, bench::SharedWall::TwoFaces, thicknessVoxels * voxel));
        std::printf("[ leak ] two faces %.2f voxels apart: lit room %.5f, ratio %.5f\n", thicknessVoxels,
                    leak.litRoomLuminance, leak.leakRatio());
        EXPECT_LT(leak.leakRatio(), thinnerLeak) << thicknessVoxels << " voxels thick";
        thinnerLeak = leak.leakRatio();
    }
}

// With ray visibility (withRayVisibility, gpu_test.h) the targets of the visibility issue hold
// for walls with voxels of their own; bounds are the targets unless named a guard.

TEST_F(FailureModes, WithRayVisibilityTwoFacedWallsAVoxelOrThickerLeakUnderOnePercent) {
    // Measured 0.06 / 0.19 / 0.004 % for 1, 2 and 4 voxels (32² images, 64³); the mips alone leak
    // 3.7 % at 2.
    const RenderSettings settings = withRayVisibility(smallSettings(32, 64));
    const float voxel = bench::twoRoomVoxelSize(64);
    for (float thicknessVoxels : {1.0f, 2.0f, 4.0f}) {
        const bench::LeakMeasurement leak = bench::measureLightLeak(
            gpu(), settings, bench::makeTwoRoomScene(0.0f, bench::SharedWall::TwoFaces, thicknessVoxels * voxel));
        std::printf("[ leak, rays ] two faces %.0f voxels apart: lit room %.5f, ratio %.5f\n", thicknessVoxels,
                    leak.litRoomLuminance, leak.leakRatio());
        EXPECT_GT(leak.litRoomLuminance, 0.01);
        EXPECT_LE(leak.leakRatio(), 0.01) << thicknessVoxels << " voxels thick";
    }
}

TEST_F(FailureModes, WithRayVisibilityASheetFacingTheDarkRoomLeaksUnderTwoPercent) {
    // A single double-sided sheet whose front faces the dark room: measured 0.01-1.1 % (the mips
    // alone 0.4-2.6 %).
    const RenderSettings settings = withRayVisibility(smallSettings(32, 64));
    const float voxel = bench::twoRoomVoxelSize(64);
    for (float wallX : {0.0f, voxel / 3.0f, -voxel / 2.0f}) {
        const bench::LeakMeasurement leak =
            bench::measureLightLeak(gpu(), settings, wallX, bench::SharedWall::SheetFacingDarkRoom);
        std::printf("[ leak, rays ] sheet facing the dark room at x = %+.4f m: lit room %.5f, ratio %.5f\n", wallX,
                    leak.litRoomLuminance, leak.leakRatio());
        EXPECT_GT(leak.litRoomLuminance, 0.01);
        EXPECT_LE(leak.leakRatio(), 0.02) << "wall at x = " << wallX;
    }
}

TEST_F(FailureModes, WithRayVisibilityASheetFacingTheLitRoomLeaksUnderTwoPercent) {
    // A single double-sided sheet whose lit front faces away from the dark room: measured 0.00 /
    // 0.00 / 0.55 % with the wall on a voxel boundary, a third of the way into a voxel and half way
    // (the bench's 128², `walls`: 0.2 / 0.3 / 1.2 %).
    // What is left lies where the sheet meets the floor, ceiling and walls: a voxel there holds the
    // lit face and the dark floor together, with one radiance and one normal between theirs.
    const RenderSettings settings = withRayVisibility(smallSettings(32, 64));
    const float voxel = bench::twoRoomVoxelSize(64);
    for (float wallX : {0.0f, voxel / 3.0f, -voxel / 2.0f}) {
        const bench::LeakMeasurement leak =
            bench::measureLightLeak(gpu(), settings, wallX, bench::SharedWall::SheetFacingLitRoom);
        std::printf("[ leak, rays ] sheet facing the lit room at x = %+.4f m: lit room %.5f, ratio %.5f\n", wallX,
                    leak.litRoomLuminance, leak.leakRatio());
        EXPECT_GT(leak.litRoomLuminance, 0.01);
        EXPECT_LE(leak.leakRatio(), 0.02) << "wall at x = " << wallX;
    }
}

TEST_F(FailureModes, WithRayVisibilityTheFirstBounceHoldsAcrossResolutions) {
    // The first bounce of the Cornell box at 32³-256³: measured within 3.9 % of each other, 3.8 %
    // over 64³-256³ (the mips alone 8 %): the drift came from coarse texels reaching through and
    // around surfaces.
    // Targets: 5 % over 64³-256³, 10 % over 32³-256³. (Against its path-traced truth it reads
    // 1.06-1.10, docs/experiments.md.)
    const Scene scene = loadScene("cornell");
    RenderSettings settings = withRayVisibility(smallSettings(32, 32));
    settings.image.supersample = 2;
    settings.shading.mode = RenderMode::Indirect;
    settings.resources.bounces = 1;
    const std::vector<bench::ResolutionLuminance> results =
        bench::measureResolutionDrift(gpu(), scene, settings, {32, 64, 128, 256});
    auto spreadFrom = [&](size_t first) {
        double lowest = 1e30, highest = 0.0, sum = 0.0;
        for (size_t i = first; i < results.size(); ++i) {
            lowest = std::min(lowest, results[i].meanLuminance);
            highest = std::max(highest, results[i].meanLuminance);
            sum += results[i].meanLuminance;
        }
        return (highest - lowest) / (sum / double(results.size() - first));
    };
    for (const bench::ResolutionLuminance& result : results) {
        std::printf("[ drift, rays ] %3u³: %.4f\n", result.voxelResolution, result.meanLuminance);
        EXPECT_TRUE(result.finite) << result.voxelResolution;
    }
    std::printf("[ drift, rays ] spread 32³-256³ %.3f, 64³-256³ %.3f\n", spreadFrom(0), spreadFrom(1));
    EXPECT_LE(spreadFrom(0), 0.10);
    EXPECT_LE(spreadFrom(1), 0.05);
}

TEST_F(FailureModes, ARoomInsideASunlitShellGetsTheLightOfTheRoomAlone) {
    // The sun room inside a shell 25 cm out (128², its camera, indirect light, against the sun
    // room's path-traced reference; target 0.90-1.10 of it) at `walls`: its rays stop what crosses
    // the sheets, and its surface planes what its coarse samples would see of the shell beside them.
    const std::string references = std::string(VCT_SOURCE_DIR) + "/assets/reference/sun-room-";
    const Image truth = readPfm(references + "indirect.pfm");
    const Scene shelled = bench::makeSunRoomInASunlitShell(bench::kShellGap);
    {
        // The premise: the shell lets the same sunlight in (direct light as the sun room's truth).
        RenderSettings settings = *findRenderPreset("balanced");
        settings.image.width = settings.image.height = 128;
        settings.shading.mode = RenderMode::Direct;
        Renderer renderer(gpu(), shelled, settings);
        renderer.renderFrame();
        const double direct =
            bench::meanLuminance(renderer.readImage()) / bench::meanLuminance(readPfm(references + "direct.pfm"));
        std::printf("[ shell ] direct luminance %.3f x the sun room's truth\n", direct);
        EXPECT_NEAR(direct, 1.0, 0.03);
    }
    RenderSettings settings = *findRenderPreset("walls");
    settings.image.width = settings.image.height = 128;
    const double ratio = bench::measureShelledRoomIndirect(gpu(), settings, truth);
    std::printf("[ shell ] walls: indirect luminance %.3f x the sun room's truth\n", ratio);
    EXPECT_GE(ratio, 0.90);
    EXPECT_LE(ratio, 1.10);
}

TEST_F(FailureModesGuard, AtBalancedARoomInsideASunlitShellGetsNoMoreLightThanItDid) {
    // The same at `balanced`: 2.92 × the truth, the mips letting the shell's sunlit outside in
    // through the sheets. Target 0.90-1.10, which `walls` meets (above).
    const Image truth = readPfm(std::string(VCT_SOURCE_DIR) + "/assets/reference/sun-room-indirect.pfm");
    RenderSettings settings = *findRenderPreset("balanced");
    settings.image.width = settings.image.height = 128;
    const double ratio = bench::measureShelledRoomIndirect(gpu(), settings, truth);
    std::printf("[ shell ] balanced: indirect luminance %.3f x the sun room's truth\n", ratio);
    EXPECT_GE(ratio, 0.90);
    EXPECT_LE(ratio, 3.1) << "regression guard; target 1.10";
}

TEST_F(FailureModesGuard, WithTheMipsAloneIndirectBrightnessAgreesAcrossResolutionsAndWithThePathTracer) {
    // The first bounce against its own truth (paths cut after one bounce): the later bounces repeat
    // its error, and `vct bench` measures the converged light's drift at its preset. Targets: spread
    // 0.10, which ray visibility is held to (WithRayVisibilityTheFirstBounceHoldsAcrossResolutions),
    // and each resolution 0.90-1.10 of the truth.
    const Scene scene = loadScene("cornell");
    RenderSettings settings = smallSettings(32, 32);
    settings.image.supersample = 2;
    settings.shading.mode = RenderMode::Indirect;
    settings.resources.bounces = 1;
    const std::vector<bench::ResolutionLuminance> results =
        bench::measureResolutionDrift(gpu(), scene, settings, {32, 64, 128, 256});

    pt::PathTracer tracer = pt::createPathTracer(scene);
    tracer.maxDepth = 2;  // direct light and one bounce
    pt::RenderSettings reference;
    reference.width = reference.height = 32;
    reference.samplesPerPixel = 1024;
    reference.component = pt::Component::Indirect;
    reference.threads = 1;
    reference.camera = scene.cameras.front();
    const pt::RenderResult truth = pt::render(tracer, reference);
    std::printf("[ drift ] path-traced indirect, one bounce: %.4f ± %.4f\n", truth.meanLuminance,
                truth.meanLuminanceStandardError);

    double lowest = 1e30, highest = 0.0, sum = 0.0;
    for (const bench::ResolutionLuminance& result : results) {
        std::printf("[ drift ] %3u³: %.4f (%.3f × path-traced)\n", result.voxelResolution, result.meanLuminance,
                    result.meanLuminance / truth.meanLuminance);
        EXPECT_TRUE(result.finite) << result.voxelResolution;
        lowest = std::min(lowest, result.meanLuminance);
        highest = std::max(highest, result.meanLuminance);
        sum += result.meanLuminance;
        const double ratio = result.meanLuminance / truth.meanLuminance;
        EXPECT_GE(ratio, kGuards.groundTruthRatioLow) << result.voxelResolution << "³ (regression guard; target 0.90)";
        EXPECT_LE(ratio, kGuards.groundTruthRatioHigh) << result.voxelResolution;
    }
    const double spread = (highest - lowest) / (sum / double(results.size()));
    std::printf("[ drift ] spread over resolutions: %.3f\n", spread);
    EXPECT_LE(spread, kGuards.resolutionSpread) << "regression guard; target 0.10";
}

TEST_F(FailureModesGuard, AtBalancedTheFirstBounceStaysNearItsOwnTruth) {
    // At `balanced` and the references' 128², one bounce against the path tracer's paths cut after
    // one bounce. Measured (luminance ratio, relMSE): cornell 1.023 / 0.123, terrain 1.001 / 2.17.
    // The luminance bounds lie within the target, 0.90-1.10; the relMSE bounds record today's error
    // (target: the full image's 0.05, which the bench measures; the terrain's first bounce is a few
    // bright pixels under its spheres).
    // Cornell's 1.02 is two errors that cancel: its walls let a fifth of the cones out of the
    // room, and with walls that do not (optical depth filtered in the chains, or the border
    // normalized) it reads 1.25 or 1.13. Terrain read 1.148 / 3.02 before oblique surfaces were
    // voxelized set back (voxelizationSetback): its spheres' voxels stood proud of them, and the
    // ground within a metre of them gathered 2-10x its truth, a bright band under the white one.
    struct Bound {
        const char* scene;
        double low, high, relMse;
    };
    for (const Bound bound : {Bound{"cornell", 0.95, 1.10, 0.15}, Bound{"terrain", 0.90, 1.10, 2.5}}) {
        const Scene scene = loadScene(bound.scene);
        RenderSettings settings = *findRenderPreset("balanced");
        settings.image.width = settings.image.height = 128;
        const Image truth =
            readPfm(std::string(VCT_SOURCE_DIR) + "/assets/reference/" + bound.scene + "-indirect-1bounce.pfm");
        const bench::FirstBounce first = bench::measureFirstBounce(gpu(), scene, settings, truth);
        std::printf("[ first bounce ] %s: %.3f × its truth, relMSE %.4f\n", bound.scene, first.error.luminanceRatio,
                    first.error.relMse);
        EXPECT_TRUE(first.finite) << bound.scene;
        EXPECT_GE(first.error.luminanceRatio, bound.low) << bound.scene;
        EXPECT_LE(first.error.luminanceRatio, bound.high) << bound.scene;
        EXPECT_LE(first.error.relMse, bound.relMse) << bound.scene << " (regression guard)";
    }
}

TEST_F(FailureModes, ALoneSunlitPlaneGetsNoIndirectLightFromItself) {
    // Its true indirect light is 0: no light reaches it twice. Target: 2 % of its direct light.
    for (uint32_t voxels : {32u, 64u}) {
        const bench::SelfIllumination self = bench::measureSelfIllumination(gpu(), smallSettings(32, voxels));
        std::printf("[ self ] lone plane at %u³: direct %.4f, indirect %.5f (%.2f %%)\n", voxels, self.directLuminance,
                    self.indirectLuminance, 100.0 * self.ratio());
        EXPECT_GT(self.directLuminance, 0.1);
        EXPECT_LE(self.ratio(), 0.02) << voxels;
    }
}

TEST_F(FailureModes, SmallCameraAndLightMovesChangeTheImageLittle) {
    // Target: a 1 mm step changes at most 2 % of the image (relative L1); measured 0.3-0.8 %.
    const Scene scene = loadScene("cornell");
    for (RenderMode mode : {RenderMode::Full, RenderMode::Indirect}) {
        RenderSettings settings = smallSettings(64, 64);
        settings.shading.mode = mode;
        const bench::FlickerMeasurement still = bench::measureFlicker(gpu(), scene, settings, 0.0f, 0.0f);
        EXPECT_EQ(still.cameraChange, 0.0) << "a step of zero changes nothing";
        EXPECT_EQ(still.lightChange, 0.0);
        const bench::FlickerMeasurement step = bench::measureFlicker(gpu(), scene, settings, 0.001f, 0.001f);
        std::printf("[ flicker ] %s, 1 mm steps: camera %.4f, light %.4f\n", renderModeName(mode), step.cameraChange,
                    step.lightChange);
        EXPECT_LE(step.cameraChange, 0.02) << renderModeName(mode);
        EXPECT_LE(step.lightChange, 0.02) << renderModeName(mode);
    }
}

}  // namespace
}  // namespace vct::test
