// glTF doubleSided on screen: a single-sided surface is culled where the camera sees its back, a
// double-sided one is seen from both sides; the shadow maps see both sides of every surface.
#include <cmath>

#include "../cpu/alpha_test_scenes.h"
#include "gpu_test.h"
#include "render/renderer.h"

namespace vct::test {
namespace {

constexpr uint32_t kSize = 32;
constexpr float kTolerance = 0.05f;  // of the lit radiance, 1

// The direct light where the camera's rays cross both the occluder and, behind it, the wall within
// ±0.9 of their middle (the wall's points, farther away, fill more of the view).
std::vector<glm::vec3> occluderPixels(const Scene& scene) {
    RenderSettings settings = smallRenderSettings(kSize, RenderMode::Direct);
    settings.resources.bounces = 1;
    settings.resources.sunShadowMapSize = 512;
    Renderer renderer(gpu(), scene, settings);
    renderer.renderFrame();
    const Image image = renderer.readImage();
    std::vector<glm::vec3> pixels;
    const float halfExtent = 2.0f * std::tan(0.5f * kCameraFov);  // of the view at the wall, z = 0
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
            const glm::vec2 seen = halfExtent * glm::vec2(2.0f * (float(x) + 0.5f) / float(kSize) - 1.0f,
                                                          1.0f - 2.0f * (float(y) + 0.5f) / float(kSize));
            if (std::abs(seen.x) < 0.9f && std::abs(seen.y) < 0.9f)
                pixels.push_back(glm::vec3(image.pixel(x, y)[0], image.pixel(x, y)[1], image.pixel(x, y)[2]));
        }
    return pixels;
}

class DoubleSided : public GpuTest {};

TEST_F(DoubleSided, ASingleSidedSurfaceIsNotSeenFromBehindButStillCastsItsShadow) {
    const std::vector<glm::vec3> front = occluderPixels(occluderBeforeWall(AlphaMode::Opaque, false));
    const std::vector<glm::vec3> singleSided = occluderPixels(occluderSeenFromBehind(false));
    const std::vector<glm::vec3> doubleSided = occluderPixels(occluderSeenFromBehind(true));
    ASSERT_GT(front.size(), 100u);
    Scene singleSidedFront = occluderBeforeWall(AlphaMode::Opaque, false);
    singleSidedFront.materials[1].doubleSided = false;
    const std::vector<glm::vec3> frontSingleSided = occluderPixels(singleSidedFront);
    for (size_t i = 0; i < front.size(); ++i) {
        // Its front, and a double-sided back: the lit red occluder, radiance (1, 0, 0).
        for (const glm::vec3& seen : {front[i], frontSingleSided[i], doubleSided[i]}) {
            EXPECT_NEAR(seen.r, 1.0f, kTolerance) << "pixel " << i;
            EXPECT_NEAR(seen.g, 0.0f, kTolerance) << "pixel " << i;
        }
        // A single-sided back: the white wall behind, in the occluder's shadow.
        EXPECT_NEAR(singleSided[i].r, 0.0f, kTolerance) << "pixel " << i;
        EXPECT_NEAR(singleSided[i].g, 0.0f, kTolerance) << "pixel " << i;
    }
}

}  // namespace
}  // namespace vct::test
