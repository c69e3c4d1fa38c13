// The frame: which passes run when something changed, and which are skipped when nothing did;
// and a frame is a pure function of its inputs (bit-identical, finite).
#include <algorithm>
#include <cmath>
#include <cstring>

#include "bench/metrics.h"
#include "gpu/readback.h"
#include "gpu_test.h"
#include "render/renderer.h"
#include "scene/load.h"

namespace vct::test {
namespace {

RenderSettings smallSettings() { return smallRenderSettings(32, RenderMode::Full); }

class Frame : public GpuTest {
protected:
    Scene scene = loadScene("cornell");
};

TEST_F(Frame, FirstFrameRunsEveryPass) {
    RenderSettings settings = smallSettings();
    settings.image.diffuseDownscale = 2;  // the diffuse cones in a pass of their own
    settings.image.supersample = 2;       // and samples for the resolve to average
    Renderer renderer(gpu(), scene, settings);
    const FrameStats stats = renderer.renderFrame();
    for (const char* pass :
         {"shadow", "voxelize", "inject", "mips", "bounce", "gbuffer", "diffuse-cones", "shade", "resolve"})
        EXPECT_TRUE(stats.ran(pass)) << pass;
    EXPECT_TRUE(stats.skipped().empty());
    // The timings agree with the plan, in pipeline order.
    ASSERT_EQ(stats.passes.size(), stats.plan.passes.size());
    for (size_t i = 0; i < stats.passes.size(); ++i) EXPECT_EQ(stats.passes[i].name, passName(stats.plan.passes[i]));
}

TEST_F(Frame, NothingChangedSkipsShadowsVoxelsInjectionAndTheGBuffer) {
    Renderer renderer(gpu(), scene, smallSettings());
    renderer.renderFrame();
    const Image first = renderer.readImage();
    const FrameStats stats = renderer.renderFrame();
    const Image second = renderer.readImage();
    ASSERT_EQ(first.rgb.size(), second.rgb.size());
    EXPECT_EQ(std::memcmp(first.rgb.data(), second.rgb.data(), first.rgb.size() * sizeof(float)), 0)
        << "the last frame's G-buffer shades the same image";
    for (const char* pass : {"shadow", "voxelize", "inject", "mips", "gbuffer"}) {
        EXPECT_FALSE(stats.ran(pass)) << pass;
        const std::vector<std::string> skipped = stats.skipped();
        EXPECT_NE(std::find(skipped.begin(), skipped.end(), pass), skipped.end()) << pass;
    }
    EXPECT_TRUE(stats.ran("shade"));
    EXPECT_FALSE(stats.ran("resolve")) << "one sample per pixel: the shading pass's image is the output";
}

TEST_F(Frame, CameraMoveRedrawsOnlyTheImage) {
    Renderer renderer(gpu(), scene, smallSettings());
    renderer.renderFrame();
    Camera moved = renderer.camera();
    moved.position += glm::vec3(0.05f, 0.0f, 0.0f);
    renderer.setCamera(moved);
    const FrameStats stats = renderer.renderFrame();
    for (const char* pass : {"shadow", "voxelize", "inject", "mips"}) EXPECT_FALSE(stats.ran(pass)) << pass;
    EXPECT_TRUE(stats.ran("gbuffer"));
}

TEST_F(Frame, LightMoveReinjectsWithoutRevoxelizing) {
    Renderer renderer(gpu(), scene, smallSettings());
    renderer.renderFrame();
    std::vector<Light> lights = renderer.lights();
    lights[0].position.x += 0.05f;
    renderer.setLights(lights);
    const FrameStats stats = renderer.renderFrame();
    for (const char* pass : {"shadow", "inject", "mips"}) EXPECT_TRUE(stats.ran(pass)) << pass;
    EXPECT_FALSE(stats.ran("voxelize"));
    EXPECT_FALSE(stats.ran("gbuffer")) << "the view did not move";
}

TEST_F(Frame, TheSameLightsAgainChangeNothingAndARelightConvergesAgain) {
    // The bench and the viewer hand the renderer its lights every frame: the same ones again are no
    // change. Asked to, it converges the light again from its sources (a scene lit by emissive
    // surfaces alone has no light to move: the bench times that).
    Renderer renderer(gpu(), scene, smallSettings());
    renderer.renderFrame();
    renderer.setLights(renderer.lights());
    const FrameStats same = renderer.renderFrame();
    for (const char* pass : {"shadow", "inject", "mips"}) EXPECT_FALSE(same.ran(pass)) << pass;
    renderer.relight();
    const FrameStats relit = renderer.renderFrame();
    for (const char* pass : {"shadow", "inject", "mips"}) EXPECT_TRUE(relit.ran(pass)) << pass;
    EXPECT_FALSE(relit.ran("voxelize"));
}

TEST_F(Frame, GeometryMoveRevoxelizesAndRedrawsShadows) {
    Renderer renderer(gpu(), scene, smallSettings());
    renderer.renderFrame();
    Scene moved = scene;
    for (Vertex& vertex : moved.vertices) vertex.position.y += 0.01f;
    renderer.setGeometry(moved);
    const FrameStats stats = renderer.renderFrame();
    for (const char* pass : {"shadow", "voxelize", "inject", "mips"}) EXPECT_TRUE(stats.ran(pass)) << pass;
}

TEST_F(Frame, SwitchingShadowsOrAreaLightsRelightsTheVoxels) {
    // The voxels' light depends on both (and the area lights' part of it is kept between
    // injections): switched off and on again, the indirect light is a fresh render's each time.
    const Scene emissive = loadScene("cornell-emissive");
    RenderSettings on = smallSettings();
    on.shading.mode = RenderMode::Indirect;
    const auto freshImage = [&](const RenderSettings& settings) {
        Renderer fresh(gpu(), emissive, settings);
        fresh.renderFrame();
        return fresh.readImage();
    };
    const Image expectedOn = freshImage(on);
    for (bool Components::*component : {&Components::shadows, &Components::areaLights}) {
        RenderSettings off = on;
        off.shading.components.*component = false;
        const Image expectedOff = freshImage(off);
        EXPECT_FALSE(sameImages(expectedOn, expectedOff)) << "the component made no difference";
        Renderer toggled(gpu(), emissive, on);
        toggled.renderFrame();
        toggled.setShading(off.shading);
        toggled.renderFrame();
        EXPECT_TRUE(sameImages(toggled.readImage(), expectedOff));
        toggled.setShading(on.shading);
        toggled.renderFrame();
        EXPECT_TRUE(sameImages(toggled.readImage(), expectedOn));
    }
}

TEST_F(Frame, RemovedGeometryLeavesNoLightBehind) {
    // The light passes visit only the occupied voxels, so the voxelizer must clear the light of
    // voxels that became empty: the frame after the tall block is removed equals a fresh render
    // of the room without it. (Its vertices stay, unused, so the grid does not move.)
    Scene withoutTallBlock = scene;
    const size_t kept = scene.triangleCount() - 10;  // the tall block: the last five quads
    withoutTallBlock.indices.resize(kept * 3);
    withoutTallBlock.triangleMaterials.resize(kept);
    RenderSettings settings = smallSettings();
    settings.shading.mode = RenderMode::Indirect;
    Renderer changed(gpu(), scene, settings);
    changed.renderFrame();
    const Image before = changed.readImage();
    changed.setGeometry(withoutTallBlock);
    changed.renderFrame();
    const Image after = changed.readImage();
    Renderer fresh(gpu(), withoutTallBlock, settings);
    fresh.renderFrame();
    const Image expected = fresh.readImage();
    const size_t bytes = expected.rgb.size() * sizeof(float);
    ASSERT_EQ(after.rgb.size(), expected.rgb.size());
    EXPECT_NE(std::memcmp(before.rgb.data(), expected.rgb.data(), bytes), 0) << "the block made no difference";
    EXPECT_EQ(std::memcmp(after.rgb.data(), expected.rgb.data(), bytes), 0) << "light was left where the block stood";
}

TEST_F(Frame, ShadingPipelinesFollowWhatTheFrameShows) {
    // The shading pass has one pipeline per variant (debug views, diffuse cones traced or read,
    // specular cone): switching between them changes what they should and nothing else.
    const Scene metal = loadScene("cornell-metal");  // its gold sphere needs the specular cone
    RenderSettings settings = smallSettings();
    settings.shading.mode = RenderMode::Indirect;
    Renderer renderer(gpu(), metal, settings);
    renderer.renderFrame();
    const Image lit = renderer.readImage();
    ShadingSettings shading = settings.shading;
    shading.components.indirectSpecular = false;
    renderer.setShading(shading);
    renderer.renderFrame();
    EXPECT_FALSE(sameImages(renderer.readImage(), lit)) << "the sphere reflected nothing";
    shading.components.indirectSpecular = true;
    shading.debugView = DebugView::Normal;
    renderer.setShading(shading);
    renderer.renderFrame();
    EXPECT_FALSE(sameImages(renderer.readImage(), lit)) << "the debug view showed the lit image";
    shading.debugView = DebugView::None;
    renderer.setShading(shading);
    renderer.renderFrame();
    EXPECT_TRUE(sameImages(renderer.readImage(), lit)) << "back from the debug view, the lit image changed";
}

TEST_F(Frame, TheDepthViewSpansTheSceneFromNearToFar) {
    // The Cornell box from its camera outside the box: the depth view grows from the near walls'
    // edges to the back wall, and neither saturates (it was over 0.9 nearly everywhere when it
    // divided by the grid's side).
    RenderSettings settings = smallSettings();
    settings.shading.debugView = DebugView::Depth;
    Renderer renderer(gpu(), scene, settings);
    renderer.renderFrame();
    const Image depth = renderer.readImage();
    float lowest = 1.0f, highest = 0.0f;
    size_t white = 0, pixels = depth.rgb.size() / 3;
    for (size_t i = 0; i < pixels; ++i) {
        const float value = depth.rgb[i * 3];
        if (value <= 0.0f) continue;  // background
        lowest = std::min(lowest, value);
        highest = std::max(highest, value);
        white += value > 0.95f;
    }
    EXPECT_LT(lowest, 0.35f);
    EXPECT_GT(highest, 0.5f);
    EXPECT_LT(highest, 1.0f);
    EXPECT_LT(white, pixels / 100) << "the depth view saturates";
}

TEST_F(Frame, TheVoxelAlbedoViewShowsTheBackWallInOneColour) {
    // The Cornell box's back wall above the blocks, seen through its voxels: one albedo under one
    // face shade. A march in fixed steps, filtered, met the wall at a depth set by where its steps
    // fell and drew concentric rings over it (its albedo blended with the empty voxels in front).
    RenderSettings settings = smallSettings();
    settings.image.width = settings.image.height = 64;
    settings.shading.debugView = DebugView::VoxelAlbedo;
    Renderer renderer(gpu(), scene, settings);
    renderer.renderFrame();
    const Image image = renderer.readImage();
    float lowest = 1e9f, highest = 0.0f;
    for (uint32_t y = 17; y < 26; ++y) {      // 26-40 % down: between the ceiling and the blocks
        for (uint32_t x = 19; x < 45; ++x) {  // 30-70 % across
            lowest = std::min(lowest, image.pixel(x, y)[0]);
            highest = std::max(highest, image.pixel(x, y)[0]);
        }
    }
    EXPECT_GT(lowest, 0.0f) << "a ray passed through the wall";
    EXPECT_LT(highest - lowest, 0.01f * highest) << "the wall's voxels show more than one colour";
}

TEST_F(Frame, DirectLightNeedsNoVoxels) {
    RenderSettings settings = smallSettings();
    settings.shading.mode = RenderMode::Direct;
    Renderer renderer(gpu(), scene, settings);
    const FrameStats stats = renderer.renderFrame();
    for (const char* pass : {"voxelize", "inject", "mips"}) EXPECT_FALSE(stats.ran(pass)) << pass;
    EXPECT_TRUE(stats.ran("shadow"));
}

TEST_F(Frame, SwitchingIndirectLightOnBuildsTheVoxelsThen) {
    RenderSettings settings = smallSettings();
    settings.shading.mode = RenderMode::Direct;
    Renderer renderer(gpu(), scene, settings);
    renderer.renderFrame();
    settings.shading.mode = RenderMode::Full;
    renderer.setShading(settings.shading);
    const FrameStats stats = renderer.renderFrame();
    for (const char* pass : {"voxelize", "inject", "mips"}) EXPECT_TRUE(stats.ran(pass)) << pass;
    EXPECT_FALSE(stats.ran("shadow"));
}

TEST_F(Frame, TwoRendersOfTheSameFrameAreBitIdenticalAndFinite) {
    for (const char* name : {"cornell", "cornell-emissive"}) {
        const Scene source = loadScene(name);
        std::vector<float> first;
        for (int run = 0; run < 2; ++run) {
            Renderer renderer(gpu(), source, smallSettings());
            renderer.renderFrame();
            const Image image = renderer.readImage();
            for (float value : image.rgb) ASSERT_TRUE(std::isfinite(value) && value >= 0.0f) << name;
            if (run == 0) {
                first = image.rgb;
            } else {
                ASSERT_EQ(std::memcmp(first.data(), image.rgb.data(), first.size() * sizeof(float)), 0)
                    << name << ": two renders differ";
            }
            // Every voxel of every level is finite (the volume is in GENERAL after a frame).
            const GpuImage& volume = renderer.volumes().radiance;
            for (uint32_t level = 0; level < volume.desc.mipLevels; ++level)
                for (const glm::vec4& voxel : readImage3D(gpu(), volume, level))
                    for (int c = 0; c < 4; ++c) ASSERT_TRUE(std::isfinite(voxel[c])) << name << " level " << level;
        }
    }
}

TEST_F(Frame, ColourBleedsFromTheRedAndGreenWalls) {
    // In the indirect light alone, the left of the picture (the red wall's side) is much redder
    // than the right (the green wall's side).
    RenderSettings settings = smallSettings();
    settings.image.width = settings.image.height = 64;
    settings.shading.mode = RenderMode::Indirect;
    settings.resources.voxelResolution = 64;
    Renderer renderer(gpu(), scene, settings);
    renderer.renderFrame();
    const Image image = renderer.readImage();
    double leftRed = 0, leftGreen = 0, rightRed = 0, rightGreen = 0;
    for (uint32_t y = 20; y < 44; ++y)
        for (uint32_t x = 0; x < 64; ++x) {
            const float* p = image.pixel(x, y);
            if (x < 21) leftRed += p[0], leftGreen += p[1];
            if (x >= 43) rightRed += p[0], rightGreen += p[1];
        }
    EXPECT_GT(leftRed / leftGreen, 2.0 * (rightRed / rightGreen));
    EXPECT_GT(leftRed + leftGreen + rightRed + rightGreen, 0.0);
}

double imageSum(const Image& image) {
    double sum = 0.0;
    for (float value : image.rgb) sum += value;
    return sum;
}

TEST_F(Frame, ReducedDiffuseConesAreNoFurtherFromTheTruth) {
    // Diffuse cones for one sample in 2×2 or 4×4, upsampled along the surfaces: the Cornell box's
    // indirect light is as close to the path-traced reference as tracing every sample (what the
    // upsampling smooths is the voxels' own pattern; bleeding across edges would show here), and
    // no brighter or darker.
    RenderSettings settings = smallSettings();
    settings.image.width = settings.image.height = 128;
    settings.resources.voxelResolution = 64;
    settings.shading.mode = RenderMode::Indirect;
    const Image reference = readPfm(std::string(VCT_SOURCE_DIR) + "/assets/reference/cornell-indirect.pfm");
    Renderer everySample(gpu(), scene, settings);
    everySample.renderFrame();
    EXPECT_FALSE(everySample.renderFrame().ran("diffuse-cones"));
    const Image full = everySample.readImage();
    const bench::ImageError fullError = bench::compareImages(full, reference);
    for (uint32_t downscale : {2u, 4u}) {
        settings.image.diffuseDownscale = downscale;
        Renderer reduced(gpu(), scene, settings);
        reduced.renderFrame();
        EXPECT_TRUE(reduced.renderFrame().ran("diffuse-cones")) << downscale;
        const Image image = reduced.readImage();
        const bench::ImageError error = bench::compareImages(image, reference);
        const double brightness = bench::compareImages(image, full).luminanceRatio;
        std::printf("[ diffuse ] 1/%u: relMSE %.4f (every sample %.4f), luminance %.4f of every sample's\n", downscale,
                    error.relMse, fullError.relMse, brightness);
        EXPECT_LT(error.relMse, 1.05 * fullError.relMse) << "diffuse downscale " << downscale;
        EXPECT_NEAR(brightness, 1.0, 0.01) << "diffuse downscale " << downscale;
    }
}

TEST_F(Frame, EachBounceAddsLessLightThanTheOneBefore) {
    // The bounce series of a closed room: every bounce adds light, each less than the last (the
    // walls reflect less than all), and converging stops once a bounce adds under 1 %.
    RenderSettings settings = smallSettings();
    settings.shading.mode = RenderMode::Indirect;
    std::vector<double> sums;
    for (uint32_t bounces : {1u, 2u, 3u}) {
        settings.resources.bounces = bounces;
        Renderer renderer(gpu(), scene, settings);
        const FrameStats stats = renderer.renderFrame();
        EXPECT_EQ(stats.bounces, bounces);
        EXPECT_EQ(stats.ran("bounce"), bounces > 1);
        EXPECT_FALSE(renderer.renderFrame().ran("bounce")) << "nothing changed";
        sums.push_back(imageSum(renderer.readImage()));
    }
    EXPECT_GT(sums[1], sums[0] * 1.05) << "a second bounce adds light";
    EXPECT_GT(sums[2], sums[1]);
    EXPECT_LT(sums[2] - sums[1], sums[1] - sums[0]) << "the third adds less than the second";

    settings.resources.bounces = kConvergedBounces;
    Renderer converged(gpu(), scene, settings);
    const FrameStats stats = converged.renderFrame();
    std::printf("[ bounces ] Cornell box at 32³: converged after %u bounces\n", stats.bounces);
    EXPECT_TRUE(stats.bouncesConverged);
    EXPECT_GT(stats.bounces, 3u);
    EXPECT_LT(stats.bounces, kMaxBouncesPerFrame);
    const double all = imageSum(converged.readImage());
    EXPECT_GT(all, sums[2]);
    // What the bounces still to come would add, at most: the last bounce's share over (1 − ratio).
    EXPECT_LT(all, 2.0 * sums[0] + 2.0 * (sums[2] - sums[0]));
}

TEST_F(Frame, VoxelBouncesGatherWithSixConesWhenTheImageTracesOne) {
    // The voxels' converged light, seen through the voxel radiance view: the same whether the image
    // traces one diffuse cone or six of the same aperture, since a bounce gathers with at least six
    // (bounce_gather.comp). With one, the Cornell box's voxels converged to a different light.
    RenderSettings settings = smallSettings();
    settings.shading.debugView = DebugView::VoxelRadiance;
    std::vector<Image> images;
    for (uint32_t cones : {1u, 6u}) {
        settings.shading.diffuseConeCount = cones;
        Renderer renderer(gpu(), scene, settings);
        EXPECT_TRUE(renderer.renderFrame().bouncesConverged) << cones;
        images.push_back(renderer.readImage());
    }
    ASSERT_EQ(images[0].rgb.size(), images[1].rgb.size());
    EXPECT_GT(imageSum(images[1]), 0.0);
    EXPECT_EQ(std::memcmp(images[0].rgb.data(), images[1].rgb.data(), images[0].rgb.size() * sizeof(float)), 0);
}

TEST_F(Frame, ConvergedLightIsTheSameForTheSameInputs) {
    // Re-lighting starts again from the light sources, so the image does not creep towards the
    // fixed point frame after frame.
    Renderer renderer(gpu(), scene, smallSettings());
    renderer.renderFrame();
    const Image first = renderer.readImage();
    renderer.relight();
    EXPECT_TRUE(renderer.renderFrame().ran("inject"));
    const Image second = renderer.readImage();
    ASSERT_EQ(first.rgb.size(), second.rgb.size());
    EXPECT_EQ(std::memcmp(first.rgb.data(), second.rgb.data(), first.rgb.size() * sizeof(float)), 0);
}

// Renders progressive frames until the light settles, checking on the way that it only grows;
// returns how many frames that took. `image` is left holding the settled light.
static uint32_t framesToSettle(Renderer& progressive, Image& image) {
    uint32_t frames = 0;
    double previous = 0.0;
    for (FrameStats stats; frames < 96; ++frames) {
        stats = progressive.renderFrame();
        if (!stats.ran("inject")) break;  // no bounce: settled
        EXPECT_EQ(stats.bounces, 1u) << "frame " << frames;
        const double now = imageSum(progressive.readImage());
        EXPECT_GE(now, previous * 0.999) << "the light grows towards its fixed point, it does not pump";
        previous = now;
    }
    image = progressive.readImage();
    return frames;
}

TEST_F(Frame, ProgressiveBouncesReachTheConvergedLightOneBouncePerFrame) {
    RenderSettings settings = smallSettings();
    settings.shading.mode = RenderMode::Indirect;
    Renderer allAtOnce(gpu(), scene, settings);
    allAtOnce.renderFrame();
    const double target = imageSum(allAtOnce.readImage());

    settings.shading.progressiveBounces = true;
    settings.shading.progressiveSlices = 1;
    Renderer progressive(gpu(), scene, settings);
    Image settled;
    const uint32_t frames = framesToSettle(progressive, settled);
    std::printf("[ bounces ] progressive: settled after %u frames\n", frames);
    EXPECT_LT(frames, 32u);
    EXPECT_NEAR(imageSum(settled), target, 0.03 * target);
}

TEST_F(Frame, ProgressiveBouncesSpreadOverSlicesReachTheSameLight) {
    // Each frame gathers for a third of the voxels only: the light takes about three times as many
    // frames to settle, and settles where a whole bounce per frame does.
    RenderSettings settings = smallSettings();
    settings.shading.mode = RenderMode::Indirect;
    settings.shading.progressiveBounces = true;
    settings.shading.progressiveSlices = 1;
    Renderer whole(gpu(), scene, settings);
    Image wholeImage;
    const uint32_t wholeFrames = framesToSettle(whole, wholeImage);

    settings.shading.progressiveSlices = 3;
    Renderer sliced(gpu(), scene, settings);
    Image slicedImage;
    const uint32_t slicedFrames = framesToSettle(sliced, slicedImage);
    std::printf("[ bounces ] settled after %u frames whole, %u in thirds\n", wholeFrames, slicedFrames);
    EXPECT_GE(slicedFrames, 2 * wholeFrames);
    EXPECT_LT(slicedFrames, 96u);
    const double target = imageSum(wholeImage);
    EXPECT_NEAR(imageSum(slicedImage), target, 0.02 * target);
}

}  // namespace
}  // namespace vct::test
