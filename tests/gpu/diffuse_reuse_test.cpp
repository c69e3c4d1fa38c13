// The reduced diffuse cones' light reused across frames (shaders_glsl/reduced_diffuse.glsl): a
// still view keeps its image and traces a quarter of the blocks and edge samples; a moving view stays as close to
// the truth as a fresh render, surfaces it uncovers included; light that converged anew is traced
// anew.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "bench/metrics.h"
#include "gpu_test.h"
#include "io/image_io.h"
#include "render/renderer.h"
#include "scene/load.h"

namespace vct::test {
namespace {

RenderSettings reducedSettings() {
    RenderSettings settings;
    settings.image = {.width = 128, .height = 128, .supersample = 1, .diffuseDownscale = 4};
    settings.resources.voxelResolution = 64;
    settings.resources.sunShadowMapSize = 512;
    settings.resources.localShadowMapSize = 256;
    settings.shading.mode = RenderMode::Indirect;
    return settings;
}

// The camera turned about the vertical axis through `pivot`.
Camera orbited(Camera camera, glm::vec3 pivot, float degrees) {
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0.0f, 1.0f, 0.0f));
    camera.position = pivot + glm::vec3(turn * glm::vec4(camera.position - pivot, 0.0f));
    camera.forward = glm::vec3(turn * glm::vec4(camera.forward, 0.0f));
    camera.up = glm::vec3(turn * glm::vec4(camera.up, 0.0f));
    return camera;
}

class DiffuseReuse : public GpuTest {
protected:
    Scene scene = loadScene("cornell");
};

TEST_F(DiffuseReuse, AStillViewKeepsItsImageAndTracesAQuarterOfTheBlocks) {
    Renderer renderer(gpu(), scene, reducedSettings());
    const FrameStats first = renderer.renderFrame();
    const Image traced = renderer.readImage();
    EXPECT_GT(first.diffuseBlocksTraced, 32u * 32u * 3u / 4u) << "the first frame traces every block on a surface";
    for (int frame = 1; frame <= 8; ++frame) {
        const FrameStats stats = renderer.renderFrame();
        const double difference = largestDifference(renderer.readImage(), traced);
        std::printf(
            "[ reuse ] still frame %d: %u blocks and %u samples traced (first frame %u, %u), largest "
            "difference %.2g\n",
            frame, stats.diffuseBlocksTraced, stats.diffuseSamplesTraced, first.diffuseBlocksTraced,
            first.diffuseSamplesTraced, difference);
        // A quarter of each, by a 2×2 pattern that the surfaces and their edges fill unevenly.
        EXPECT_LT(stats.diffuseBlocksTraced, 0.3 * first.diffuseBlocksTraced) << frame;
        EXPECT_LT(stats.diffuseSamplesTraced, 0.35 * first.diffuseSamplesTraced) << frame;
        EXPECT_LT(difference, 1e-4) << frame;
    }
}

TEST_F(DiffuseReuse, AViewThatMovedAndCameBackIsAsCloseToTheTruthAsAFreshRender) {
    // The camera turns 1° a frame about the room's centre, 6° away and back: the blocks' edges sweep
    // over the walls and the floor, uncovering surfaces the last frame did not see, and the light
    // of every block is carried from frame to frame for up to four frames. The representatives of
    // a moved view sample the voxels' pattern elsewhere than a fresh render's (about 1 % relMSE
    // between the two 6° away), so the measure is the distance from the path-traced truth.
    const glm::vec3 pivot = scene.bounds().center();
    Renderer moving(gpu(), scene, reducedSettings());
    moving.renderFrame();
    Camera camera = moving.camera();
    uint32_t blocks = 0, samples = 0;
    const int frames = 12;
    for (int frame = 1; frame <= frames; ++frame) {
        camera = orbited(camera, pivot, frame <= frames / 2 ? 1.0f : -1.0f);
        moving.setCamera(camera);
        const FrameStats stats = moving.renderFrame();
        blocks += stats.diffuseBlocksTraced;
        samples += stats.diffuseSamplesTraced;
    }
    Renderer fresh(gpu(), scene, reducedSettings());
    fresh.setCamera(camera);
    const FrameStats freshStats = fresh.renderFrame();
    const Image truth = readPfm(std::string(VCT_SOURCE_DIR) + "/assets/reference/cornell-indirect.pfm");
    const Image image = moving.readImage(), freshImage = fresh.readImage();
    const double movingError = bench::compareImages(image, truth).relMse;
    const double freshError = bench::compareImages(freshImage, truth).relMse;
    const double brightness = bench::compareImages(image, freshImage).luminanceRatio;
    std::printf(
        "[ reuse ] after 6° away and back: relMSE %.4f (fresh render %.4f), luminance %.4f of the fresh "
        "render's; %.0f blocks and %.0f samples traced a frame (fresh: %u, %u)\n",
        movingError, freshError, brightness, double(blocks) / frames, double(samples) / frames,
        freshStats.diffuseBlocksTraced, freshStats.diffuseSamplesTraced);
    EXPECT_LT(movingError, 1.02 * freshError);
    EXPECT_NEAR(brightness, 1.0, 0.01);
    EXPECT_LT(blocks, frames * freshStats.diffuseBlocksTraced / 2) << "most blocks reuse the last frame's light";
    EXPECT_LT(samples, frames * freshStats.diffuseSamplesTraced / 2) << "most edge samples reuse theirs";
}

TEST_F(DiffuseReuse, AViewThatStopsSettlesInFourFramesOnAFreshRendersImage) {
    // The viewer draws while the renderer is settling: after the view stops, every block and edge
    // sample traces anew within four frames, and the image is then a fresh render's.
    Renderer renderer(gpu(), scene, reducedSettings());
    renderer.renderFrame();
    EXPECT_FALSE(renderer.settling()) << "a first frame traces everything";
    const Camera stopped = orbited(renderer.camera(), scene.bounds().center(), 5.0f);
    renderer.setCamera(stopped);
    EXPECT_EQ(1 + renderer.renderSettled(10).settleFrames, 4u) << "frames until settled";
    Renderer fresh(gpu(), scene, reducedSettings());
    fresh.setCamera(stopped);
    fresh.renderFrame();
    EXPECT_LT(largestDifference(renderer.readImage(), fresh.readImage()), 1e-4);
}

TEST_F(DiffuseReuse, LightThatConvergesAnewIsTracedAnew) {
    // A light moved with converged bounces is a new solution: no block keeps the old light.
    Renderer renderer(gpu(), scene, reducedSettings());
    renderer.renderFrame();
    const FrameStats first = renderer.renderFrame();
    std::vector<Light> lights = renderer.lights();
    lights.front().position.x += 0.3f;
    lights.front().intensity *= 2.0f;
    renderer.setLights(lights);
    const FrameStats moved = renderer.renderFrame();
    EXPECT_GT(moved.diffuseBlocksTraced, 3u * first.diffuseBlocksTraced);

    Scene relit = scene;
    relit.lights = lights;
    Renderer fresh(gpu(), relit, reducedSettings());
    fresh.renderFrame();
    EXPECT_LT(largestDifference(renderer.readImage(), fresh.readImage()), 1e-4);
}

}  // namespace
}  // namespace vct::test
