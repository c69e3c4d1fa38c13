// The suns' shadow cascades (src/render/sun_cascades.h) on the GPU: the landscape's direct light,
// whose houses one scene-fitted map cannot shadow, against its path-traced reference; a moved
// camera redraws the cascades alone and shades as a fresh renderer; a small scene gets none.
#include "bench/metrics.h"
#include "gpu_test.h"
#include "render/presets.h"
#include "render/renderer.h"
#include "scene/load.h"

namespace vct::test {
namespace {

const std::string kLandscape = std::string(VCT_SOURCE_DIR) + "/assets/scenes/landscape.gltf";

RenderSettings directAt128(uint32_t sunCascades) {
    RenderSettings settings = *findRenderPreset("quality");
    settings.image.width = settings.image.height = 128;  // the reference's size
    settings.shading.mode = RenderMode::Direct;
    settings.resources.sunCascades = sunCascades;
    return settings;
}

class SunCascadesOnGpu : public GpuTest {};

TEST_F(SunCascadesOnGpu, TheLandscapesDirectLightMatchesThePathTracer) {
    // One 4096² map over 1 km has texels of a third of a metre: the houses' walls and door frames
    // cast blobs (relMSE 7.1, lavapipe, 2026-12-07). Target: direct light as in the small scenes.
    const Scene scene = loadScene(kLandscape);
    const Image reference = readPfm(std::string(VCT_SOURCE_DIR) + "/assets/reference/landscape-direct.pfm");
    double errors[2] = {0.0, 0.0};
    for (uint32_t cascades : {0u, 4u}) {
        Renderer renderer(gpu(), scene, directAt128(cascades));
        renderer.renderSettled();
        errors[cascades ? 1 : 0] = bench::compareImages(renderer.readImage(), reference).relMse;
    }
    std::printf("[ cascades ] landscape direct relMSE: %.4f with cascades, %.4f without\n", errors[1], errors[0]);
    EXPECT_LE(errors[1], 0.01) << "target: the direct light of the small scenes";
    EXPECT_GT(errors[0], 1.0) << "the scene no longer needs cascades: it tests nothing";
}

TEST_F(SunCascadesOnGpu, AMovedCameraRedrawsTheCascadesAloneAndShadesAsAFreshRenderer) {
    Scene scene = loadScene(kLandscape);
    ASSERT_FALSE(scene.cameras.empty());
    RenderSettings settings = *findRenderPreset("balanced");
    settings.image.width = settings.image.height = 64;
    settings.shading.stillSamples = 1;
    settings.image.diffuseDownscale = 1;  // no diffuse light reused from the frame before the move
    settings.resources.voxelResolution = 32;
    settings.resources.sunShadowMapSize = 1024;
    settings.resources.bounces = 1;
    Camera moved = scene.cameras.front();
    moved.position += glm::vec3(0.3f, 0.0f, 0.2f);

    Renderer moving(gpu(), scene, settings);
    moving.renderFrame();
    moving.setCamera(moved);
    const FrameStats after = moving.renderFrame();
    EXPECT_TRUE(after.ran("shadow")) << "the cascades follow the camera";
    EXPECT_FALSE(after.ran("inject")) << "the voxels' light keeps the scene-fitted map";
    const Image kept = moving.readImage();

    scene.cameras.front() = moved;
    Renderer fresh(gpu(), scene, settings);
    fresh.renderFrame();
    EXPECT_LE(largestDifference(kept, fresh.readImage()), 1e-5)
        << "the frame after moving the camera differs from a fresh renderer's";
}

TEST_F(SunCascadesOnGpu, TheDebugViewShowsTheFinestCascadeNearAndCoarserOnesBeyond) {
    // The landscape's door is a few metres away and the hills beyond it hundreds: the finest
    // cascade's red holds the near ground, and some other map (green, blue, yellow or grey) the rest.
    RenderSettings settings = directAt128(4);
    settings.shading.stillSamples = 1;
    settings.shading.debugView = DebugView::SunCascades;
    Renderer renderer(gpu(), loadScene(kLandscape), settings);
    renderer.renderFrame();
    const Image image = renderer.readImage();
    size_t finest = 0, others = 0;
    for (size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
        const float r = image.rgb[i], g = image.rgb[i + 1], b = image.rgb[i + 2];
        if (r + g + b <= 0.0f) continue;  // the sky
        (r > 2.0f * g && r > 2.0f * b ? finest : others) += 1;
    }
    std::printf("[ cascades ] debug view: %zu pixels in the finest cascade, %zu in the others\n", finest, others);
    EXPECT_GT(finest, image.rgb.size() / 3 / 20) << "the near ground in the finest cascade";
    EXPECT_GT(others, image.rgb.size() / 3 / 20) << "the far ground in coarser maps";
}

TEST_F(SunCascadesOnGpu, ASmallSceneSeenFromOutsideGetsNone) {
    // The Cornell box lit by the sun, its camera 0.8 m in front: its map's texels are finer than
    // the pixels everywhere the camera sees, so cascades would only cost.
    const Scene scene = loadScene("cornell-sun");
    Image images[2];
    for (uint32_t cascades : {0u, 4u}) {
        RenderSettings settings = directAt128(cascades);
        settings.shading.stillSamples = 1;
        Renderer renderer(gpu(), scene, settings);
        renderer.renderFrame();
        images[cascades ? 1 : 0] = renderer.readImage();
    }
    EXPECT_TRUE(sameImages(images[0], images[1]));
}

}  // namespace
}  // namespace vct::test
