// The failures users of other VCT renderers report most, measured (src/bench/failure_modes.h) and
// held to stated bounds: light leaking through thin walls, brightness that drifts with the voxel
// resolution, and flicker under small camera or light moves.
#include <cstdio>

#include "bench/failure_modes.h"
#include "gpu_test.h"
#include "path_tracer.h"
#include "render/renderer.h"
#include "scene/load.h"

namespace vct::test {
namespace {

// Bounds from the measurements (printed by each test), so that a regression shows. They record the
// renderer as it is, not what it should reach:
// - leak: 0.8 % (wall on a voxel boundary) to 1.7 % (wall half a voxel in) of the lit room's mean
//   at 64³; the ground truth is 0.
// - brightness against resolution (Cornell box, indirect, 32² × 2², anisotropic): 0.62, 0.67, 0.73,
//   0.74 × path-traced at 32³, 64³, 128³, 256³ (spread 17.5 %). The cause is the cone start offset,
//   1.5 voxels: the light of everything nearer than that is skipped, and a voxel is 8× larger at
//   32³ than at 256³. With the offset fixed in world units (1.5 voxels of 128³) the spread over
//   32³…128³ falls to 5 %, but the coarse grids then start cones inside their own surface's voxel.
// - flicker: 1 mm camera or light steps change 0.4–0.6 % of the image (relative L1).
struct FailureBounds {
    double leakRatio = 0.02;            // dark room / lit room mean luminance, ground truth 0
    double resolutionSpread = 0.20;     // (max − min) / mean of the indirect luminance, 32³…256³
    double groundTruthRatioLow = 0.55;  // indirect luminance / path-traced, each resolution
    double groundTruthRatioHigh = 1.10;
    double cameraStepChange = 0.02;  // relative L1 change after a 1 mm camera move
    double lightStepChange = 0.02;   // relative L1 change after a 1 mm light move
};
constexpr FailureBounds kBounds;

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

TEST_F(FailureModes, ThinWallLeaksAlmostNoLightIntoTheDarkRoom) {
    // The wall on a voxel boundary (x = 0 is one, the grid being centred on the scene) and inside
    // a voxel (a third of the way through one at 64³).
    const RenderSettings settings = smallSettings(32, 64);
    const float voxel = 2.0f / 62.0f;
    for (float wallX : {0.0f, voxel / 3.0f, -voxel / 2.0f}) {
        const bench::LeakMeasurement leak = bench::measureLightLeak(gpu(), settings, wallX);
        std::printf("[ leak ] wall at x = %+.4f m: lit room %.5f, dark room %.6f, ratio %.5f\n", wallX,
                    leak.litRoomLuminance, leak.darkRoomLuminance, leak.leakRatio());
        EXPECT_GT(leak.litRoomLuminance, 0.01);
        EXPECT_LE(leak.leakRatio(), kBounds.leakRatio) << "wall at x = " << wallX;
    }
}

TEST_F(FailureModes, IndirectBrightnessAgreesAcrossResolutionsAndWithThePathTracer) {
    const Scene scene = loadScene("cornell");
    RenderSettings settings = smallSettings(32, 32);
    settings.image.supersample = 2;
    settings.shading.mode = RenderMode::Indirect;
    const std::vector<bench::ResolutionLuminance> results =
        bench::measureResolutionDrift(gpu(), scene, settings, {32, 64, 128, 256});

    pt::PathTracer tracer = pt::createPathTracer(scene);
    pt::RenderSettings reference;
    reference.width = reference.height = 32;
    reference.samplesPerPixel = 1024;
    reference.component = pt::Component::Indirect;
    reference.threads = 1;
    reference.camera = scene.cameras.front();
    const pt::RenderResult truth = pt::render(tracer, reference);
    std::printf("[ drift ] path-traced indirect: %.4f ± %.4f\n", truth.meanLuminance, truth.meanLuminanceStandardError);

    double lowest = 1e30, highest = 0.0, sum = 0.0;
    for (const bench::ResolutionLuminance& result : results) {
        std::printf("[ drift ] %3u³: %.4f (%.3f × path-traced)\n", result.voxelResolution, result.meanLuminance,
                    result.meanLuminance / truth.meanLuminance);
        EXPECT_TRUE(result.finite) << result.voxelResolution;
        lowest = std::min(lowest, result.meanLuminance);
        highest = std::max(highest, result.meanLuminance);
        sum += result.meanLuminance;
        const double ratio = result.meanLuminance / truth.meanLuminance;
        EXPECT_GE(ratio, kBounds.groundTruthRatioLow) << result.voxelResolution;
        EXPECT_LE(ratio, kBounds.groundTruthRatioHigh) << result.voxelResolution;
    }
    const double spread = (highest - lowest) / (sum / double(results.size()));
    std::printf("[ drift ] spread over resolutions: %.3f\n", spread);
    EXPECT_LE(spread, kBounds.resolutionSpread);
}

TEST_F(FailureModes, SmallCameraAndLightMovesChangeTheImageLittle) {
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
        EXPECT_LE(step.cameraChange, kBounds.cameraStepChange) << renderModeName(mode);
        EXPECT_LE(step.lightChange, kBounds.lightStepChange) << renderModeName(mode);
    }
}

}  // namespace
}  // namespace vct::test
