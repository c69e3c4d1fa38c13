// The frame: which passes run when something changed, and which are skipped when nothing did;
// and a frame is a pure function of its inputs (bit-identical, finite).
#include <algorithm>
#include <cmath>
#include <cstring>

#include "gpu/readback.h"
#include "gpu_test.h"
#include "render/renderer.h"
#include "scene/load.h"

namespace vct::test {
namespace {

RenderSettings smallSettings() {
    RenderSettings settings;
    settings.image.width = 32;
    settings.image.height = 32;
    settings.image.supersample = 1;
    settings.resources.voxelResolution = 32;
    settings.resources.sunShadowMapSize = 256;
    settings.resources.localShadowMapSize = 128;
    return settings;
}

class Frame : public GpuTest {
protected:
    Scene scene = loadScene("cornell");
};

TEST_F(Frame, FirstFrameRunsEveryPass) {
    Renderer renderer(gpu(), scene, smallSettings());
    const FrameStats stats = renderer.renderFrame();
    for (const char* pass : {"shadow", "voxelize", "inject", "mips", "gbuffer", "shade", "resolve"})
        EXPECT_TRUE(stats.ran(pass)) << pass;
    // Every pass but the second bounce, which one bounce does not run; the timings agree with the plan.
    EXPECT_EQ(stats.skipped(), std::vector<std::string>{"bounce"});
    ASSERT_EQ(stats.passes.size(), stats.plan.passes.size());
    for (size_t i = 0; i < stats.passes.size(); ++i) EXPECT_EQ(stats.passes[i].name, passName(stats.plan.passes[i]));
}

TEST_F(Frame, NothingChangedSkipsShadowsVoxelsAndInjection) {
    Renderer renderer(gpu(), scene, smallSettings());
    renderer.renderFrame();
    const FrameStats stats = renderer.renderFrame();
    for (const char* pass : {"shadow", "voxelize", "inject", "mips"}) {
        EXPECT_FALSE(stats.ran(pass)) << pass;
        const std::vector<std::string> skipped = stats.skipped();
        EXPECT_NE(std::find(skipped.begin(), skipped.end(), pass), skipped.end()) << pass;
    }
    for (const char* pass : {"gbuffer", "shade", "resolve"}) EXPECT_TRUE(stats.ran(pass)) << pass;
}

TEST_F(Frame, CameraMoveRedrawsOnlyTheImage) {
    Renderer renderer(gpu(), scene, smallSettings());
    renderer.renderFrame();
    Camera moved = renderer.camera();
    moved.position += glm::vec3(0.05f, 0.0f, 0.0f);
    renderer.setCamera(moved);
    const FrameStats stats = renderer.renderFrame();
    for (const char* pass : {"shadow", "voxelize", "inject", "mips"}) EXPECT_FALSE(stats.ran(pass)) << pass;
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
                for (const glm::vec4& voxel : readImage3D(gpu(), volume, level, VK_IMAGE_LAYOUT_GENERAL))
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

TEST_F(Frame, SecondBounceAddsLightAndRunsOnlyWithTheInjection) {
    RenderSettings settings = smallSettings();
    settings.shading.mode = RenderMode::Indirect;
    Renderer oneBounce(gpu(), scene, settings);
    oneBounce.renderFrame();
    settings.resources.bounces = 2;
    Renderer twoBounces(gpu(), scene, settings);
    EXPECT_TRUE(twoBounces.renderFrame().ran("bounce"));
    EXPECT_FALSE(twoBounces.renderFrame().ran("bounce")) << "nothing changed";
    double one = 0, two = 0;
    for (float value : oneBounce.readImage().rgb) one += value;
    for (float value : twoBounces.readImage().rgb) {
        ASSERT_TRUE(std::isfinite(value));
        two += value;
    }
    EXPECT_GT(two, one * 1.05) << "a second bounce adds light";
}

}  // namespace
}  // namespace vct::test
