// The screen's ring of diffuse cones turned over still frames and averaged
// (ShadingSettings::diffuseConeTurns): the first frame is the fixed ring's image, each turn is one
// more still frame, the mean holds every turn whichever it starts at, and any change starts it
// anew. On the sun room, whose small sunlit patch six fixed sharp cones drew as streaks, the mean
// is nearer the path tracer.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bench/metrics.h"
#include "gpu_test.h"
#include "io/image_io.h"
#include "render/presets.h"
#include "render/renderer.h"
#include "scene/load.h"

namespace vct::test {
namespace {

constexpr uint32_t kTurns = 3;

RenderSettings turnedSettings(uint32_t turns) {
    RenderSettings settings = smallRenderSettings(32, RenderMode::Indirect);
    settings.image.diffuseDownscale = 4;  // the reduced cones' reused light must not mix turns
    settings.shading.diffuseConeTurns = turns;
    return settings;
}

class TurnedCones : public GpuTest {
protected:
    Scene scene = loadScene("cornell");
};
class TurnedConesGuard : public GpuTest {};

TEST_F(TurnedCones, TheFirstFrameIsTheFixedRingsAndEachTurnIsOneMoreStillFrame) {
    Renderer fixed(gpu(), scene, turnedSettings(1));
    fixed.renderFrame();
    EXPECT_FALSE(fixed.settling());
    const Image fixedImage = fixed.readImage();

    Renderer turned(gpu(), scene, turnedSettings(kTurns));
    turned.renderFrame();
    EXPECT_TRUE(sameImages(turned.readImage(), fixedImage)) << "the first turn is the fixed ring";
    EXPECT_EQ(1 + renderWhileSettling(turned, 9), kTurns);
    const Image mean = turned.readImage();
    const double change = largestDifference(mean, fixedImage);
    std::printf("[ turns ] the mean of %u turns differs from the fixed ring's image by up to %.3f of its mean\n",
                kTurns, change);
    EXPECT_GT(change, 0.01) << "the other turns' cones saw other light";
    for (float value : mean.rgb) ASSERT_TRUE(std::isfinite(value) && value >= 0.0f);
    // A settled mean stays as it is.
    turned.renderFrame();
    EXPECT_TRUE(sameImages(turned.readImage(), mean));
}

TEST_F(TurnedCones, TheMeanHoldsEveryTurnWhicheverItStartsAt) {
    Renderer renderer(gpu(), scene, turnedSettings(kTurns));
    renderer.renderSettled();
    const Image mean = renderer.readImage();
    // A step away and back: the mean starts anew, at the turn the last one ended on.
    const Camera start = renderer.camera();
    Camera moved = start;
    moved.position.x += 0.05f;
    renderer.setCamera(moved);
    renderer.renderFrame();
    EXPECT_TRUE(renderer.settling());
    renderer.setCamera(start);
    renderer.renderSettled();
    EXPECT_FALSE(renderer.settling());
    // The same turns summed in another order: equal to float rounding.
    EXPECT_LT(largestDifference(renderer.readImage(), mean), 1e-4);
}

TEST_F(TurnedCones, NewShadingStartsTheMeanAnew) {
    Renderer renderer(gpu(), scene, turnedSettings(kTurns));
    renderer.renderSettled();
    ShadingSettings shading = renderer.settings().shading;
    shading.diffuseConeAperture = 50.0f;
    renderer.setShading(shading);
    renderer.renderFrame();
    EXPECT_TRUE(renderer.settling());
    // Turned on in a renderer that had no resolve pass, and back off.
    Renderer fixed(gpu(), scene, turnedSettings(1));
    fixed.renderFrame();
    const Image fixedImage = fixed.readImage();
    shading = fixed.settings().shading;
    shading.diffuseConeTurns = kTurns;
    fixed.setShading(shading);
    const FrameStats stats = fixed.renderSettled();
    EXPECT_TRUE(stats.ran("resolve"));
    EXPECT_FALSE(sameImages(fixed.readImage(), fixedImage));
    shading.diffuseConeTurns = 1;
    fixed.setShading(shading);
    fixed.renderSettled();
    EXPECT_TRUE(sameImages(fixed.readImage(), fixedImage)) << "the fixed ring's image again";
}

TEST_F(TurnedConesGuard, TheSunRoomsStreaksAverageOut) {
    // The sun room at `walls` (128², indirect light, against its path-traced reference): six fixed
    // 60° cones with rays drew the small sunlit patch on the floor as streaks on the back wall
    // (indirect relMSE 0.165 in the bench's full image); its ring turned over four still frames
    // halves that: 0.201 -> 0.106 here. The bound on the turned ring is a regression guard at today's
    // figure (target: the bench's full relMSE <= 0.05).
    const std::string references = std::string(VCT_SOURCE_DIR) + "/assets/reference/sun-room-";
    const Image truth = readPfm(references + "indirect.pfm");
    const Scene sunRoom = loadScene("sun-room");
    RenderSettings settings = *findRenderPreset("walls");
    settings.image.width = settings.image.height = 128;
    settings.shading.mode = RenderMode::Indirect;
    ASSERT_GT(settings.shading.diffuseConeTurns, 1u);
    double error[2];
    for (int turned = 0; turned < 2; ++turned) {
        RenderSettings run = settings;
        if (!turned) run.shading.diffuseConeTurns = 1;
        Renderer renderer(gpu(), sunRoom, run);
        renderer.renderSettled();
        error[turned] = bench::compareImages(renderer.readImage(), truth).relMse;
        std::printf("[ turns ] sun room, %u turn(s): indirect relMSE %.4f\n", run.shading.diffuseConeTurns,
                    error[turned]);
    }
    EXPECT_LT(error[1], 0.7 * error[0]);
    EXPECT_LT(error[1], 0.12) << "regression guard; target: the bench's full relMSE 0.05";
}

}  // namespace
}  // namespace vct::test
