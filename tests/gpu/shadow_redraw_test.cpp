// A light change redraws only the shadow maps whose views moved (src/render/shadow_pass.h): the
// sun's, not the area lights' cubes, which depend on the geometry alone. The maps it keeps must
// still be right: the frame equals a fresh renderer's.
#include "gpu_test.h"
#include "render/presets.h"
#include "render/renderer.h"
#include "render/shadow_pass.h"
#include "scene/area_lights.h"
#include "scene/load.h"

namespace vct::test {
namespace {

Light sunFrom(glm::vec3 direction) {
    Light sun;
    sun.name = "sun";
    sun.type = LightType::Directional;
    sun.intensity = 2.0f;
    sun.direction = glm::normalize(direction);
    return sun;
}

// cornell-emissive (its lamp is an area light) with a sun shining in through the open front.
Scene lampRoomWithSun(glm::vec3 sunDirection) {
    Scene scene = loadScene("cornell-emissive");
    scene.lights.push_back(sunFrom(sunDirection));
    return scene;
}

RenderSettings smallBalanced() {
    RenderSettings settings = *findRenderPreset("balanced");
    settings.image.width = settings.image.height = 64;
    settings.resources.voxelResolution = 32;
    settings.resources.sunShadowMapSize = 512;
    settings.resources.areaShadowMapSize = 128;
    settings.resources.bounces = 1;
    return settings;
}

TEST(ShadowRedraw, MovingTheSunChangesOnlyTheSunsMaps) {
    const glm::vec3 before(0.3f, -0.5f, -1.0f), after(-0.3f, -0.6f, -1.0f);
    const Scene scene = lampRoomWithSun(before);
    const std::vector<AreaLight> areaLights = findAreaLights(scene);
    ASSERT_FALSE(areaLights.empty());
    const RenderSettings settings = smallBalanced();
    const ShadowLayout first = layoutShadows(scene.lights, areaLights, scene.bounds(), settings);
    std::vector<Light> moved = scene.lights;
    moved.back() = sunFrom(after);
    const ShadowLayout second = layoutShadows(moved, areaLights, scene.bounds(), settings);
    EXPECT_EQ(changedShadowArrays(first, second), shadowArrayBit(ShadowArray::Sun));
    EXPECT_EQ(changedShadowArrays(first, first), 0u);

    std::vector<Light> brighter = scene.lights;
    brighter.back().intensity *= 2.0f;
    EXPECT_EQ(changedShadowArrays(first, layoutShadows(brighter, areaLights, scene.bounds(), settings)), 0u)
        << "a shadow map does not depend on a light's intensity";
}

TEST(ShadowRedraw, MovingTheCameraChangesOnlyTheSunsCascades) {
    const Scene scene = loadScene(std::string(VCT_SOURCE_DIR) + "/assets/scenes/landscape.gltf");
    ASSERT_FALSE(scene.cameras.empty());
    const RenderSettings settings = *findRenderPreset("quality");
    CascadeView view;
    view.camera = scene.cameras.front();
    view.imageHeight = 540;
    view.nearestGeometry = 0.5f;
    const ShadowLayout first = layoutShadows(scene.lights, {}, scene.bounds(), settings, &view);
    ASSERT_GT(first.sunCascadeLayers, 1u);
    view.camera.position.x += 0.05f;
    const ShadowArraySet changed =
        changedShadowArrays(first, layoutShadows(scene.lights, {}, scene.bounds(), settings, &view));
    EXPECT_NE(changed & sunCascadeBit(0), 0u) << "the finest cascade, of millimetre texels, moved";
    EXPECT_EQ(changed & ~kSunCascadeLayers, 0u) << "the scene-fitted map stays";
}

class ShadowRedrawOnGpu : public GpuTest {};

TEST_F(ShadowRedrawOnGpu, TheAreaLightsKeptMapsShadeAsFreshOnesDo) {
    const RenderSettings settings = smallBalanced();
    Renderer moving(gpu(), lampRoomWithSun({0.3f, -0.5f, -1.0f}), settings);
    moving.renderFrame();
    const Scene target = lampRoomWithSun({-0.3f, -0.6f, -1.0f});
    moving.setLights(target.lights);
    moving.renderFrame();
    const Image kept = moving.readImage();

    Renderer fresh(gpu(), target, settings);
    fresh.renderFrame();
    const Image redrawn = fresh.readImage();
    ASSERT_EQ(kept.rgb.size(), redrawn.rgb.size());
    double largest = 0.0, total = 0.0;
    for (size_t i = 0; i < kept.rgb.size(); ++i) {
        largest = std::max(largest, double(std::abs(kept.rgb[i] - redrawn.rgb[i])));
        total += redrawn.rgb[i];
    }
    EXPECT_GT(total, 0.0);
    EXPECT_LE(largest, 1e-5) << "the frame after moving the sun differs from a fresh renderer's";
}

}  // namespace
}  // namespace vct::test
