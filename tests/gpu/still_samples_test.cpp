// Samples moved within their pixel over still frames and averaged (ShadingSettings::stillSamples):
// the first frame is the unmoved image, the still image takes one frame per sample, a moved camera
// starts again from the unmoved samples, and the mean is the pixel's average over its square, as
// supersampling makes it: nearer a finely supersampled image than one sample a pixel is.
#include <cstdio>

#include "bench/metrics.h"
#include "gpu_test.h"
#include "render/renderer.h"
#include "scene/load.h"

namespace vct::test {
namespace {

RenderSettings directSettings(uint32_t stillSamples, uint32_t supersample = 1) {
    RenderSettings settings = smallRenderSettings(32, RenderMode::Direct);
    settings.image.supersample = supersample;
    settings.shading.stillSamples = stillSamples;
    return settings;
}

class StillSamples : public GpuTest {
protected:
    // Small lamps seen directly: one sample a pixel catches each lamp whole or misses it.
    Scene scene = loadScene("tile-room");
};

TEST_F(StillSamples, TheFirstFrameIsUnmovedAndTheStillImageTakesAFramePerSample) {
    Renderer unmoved(gpu(), scene, directSettings(1));
    unmoved.renderFrame();
    const Image first = unmoved.readImage();

    Renderer moving(gpu(), scene, directSettings(8));
    moving.renderFrame();
    EXPECT_TRUE(sameImages(moving.readImage(), first)) << "the first sample is the pixel's centre";
    EXPECT_EQ(1 + renderWhileSettling(moving, 19), 8u);
    const Image mean = moving.readImage();
    EXPECT_FALSE(sameImages(mean, first));
    moving.renderFrame();
    EXPECT_TRUE(sameImages(moving.readImage(), mean)) << "a complete mean stays as it is";

    // A moved camera starts again at the centre: its first frame is a fresh renderer's.
    Camera camera = scene.cameras.front();
    camera.position.x += 0.01f;
    moving.setCamera(camera);
    moving.renderFrame();
    unmoved.setCamera(camera);
    unmoved.renderFrame();
    EXPECT_TRUE(sameImages(moving.readImage(), unmoved.readImage()));
    EXPECT_TRUE(moving.settling());
}

TEST_F(StillSamples, TheMeanIsNearerThePixelsAverageThanOneSample) {
    // The pixel's average: 8×8 samples a pixel. Measured by the RMSE: the relMSE weighs the black
    // ceiling between the lamps, where a few stray samples of a lamp decide it.
    Renderer fine(gpu(), scene, directSettings(1, 8));
    fine.renderFrame();
    const Image average = fine.readImage();
    auto errorOf = [&](uint32_t stillSamples) {
        Renderer renderer(gpu(), scene, directSettings(stillSamples));
        renderer.renderSettled();
        return bench::compareImages(renderer.readImage(), average).rmse;
    };
    const double one = errorOf(1), sixteen = errorOf(16);
    std::printf("[ still samples ] RMSE against 8x8 samples a pixel: 1 sample %.4f, 16 over still frames %.4f\n", one,
                sixteen);
    EXPECT_LT(sixteen, 0.25 * one);
}

}  // namespace
}  // namespace vct::test
