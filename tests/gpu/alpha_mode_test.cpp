// glTF alphaMode on screen and in the shadow maps: a checkerboard cut-out (MASK) shows the wall
// behind it through its holes and lets the sun through them; a half-transparent BLEND surface
// covers about half the pixels, and casts a shadow from half alpha up.
#include <cmath>
#include <cstdio>

#include <glm/gtc/type_ptr.hpp>

#include "../cpu/alpha_test_scenes.h"
#include "gpu_test.h"
#include "render/renderer.h"

namespace vct::test {
namespace {

constexpr uint32_t kSize = 64;
constexpr float kRadianceTolerance = 0.05f;  // of the lit radiance, 1
// Pixels this close to an edge of the checkerboard (world units) may see either side: a pixel
// spans 0.027 on the occluder; the shadow's PCF kernel and the texture filter a little more.
constexpr float kOccluderEdgeMargin = 0.03f;
constexpr float kShadowEdgeMargin = 0.06f;

RenderSettings directLightSettings() {
    RenderSettings settings = smallRenderSettings(kSize, RenderMode::Direct);
    settings.resources.bounces = 1;
    settings.resources.sunShadowMapSize = 512;
    return settings;
}

// Where the camera's ray through pixel (x, y)'s centre crosses the plane z.
glm::vec2 pointSeenAt(uint32_t x, uint32_t y, float z) {
    const float halfExtent = (2.0f - z) * std::tan(0.5f * kCameraFov);
    return halfExtent *
           glm::vec2(2.0f * (float(x) + 0.5f) / float(kSize) - 1.0f, 1.0f - 2.0f * (float(y) + 0.5f) / float(kSize));
}

Image renderDirectLight(const Scene& scene) {
    Renderer renderer(gpu(), scene, directLightSettings());
    renderer.renderFrame();
    return renderer.readImage();
}

// The lit red occluder: radiance (1, 0, 0).
bool showsLitOccluder(const glm::vec3& pixel) {
    return std::abs(pixel.r - 1.0f) < kRadianceTolerance && pixel.g < kRadianceTolerance;
}

class AlphaMaterial : public GpuTest {};

TEST_F(AlphaMaterial, AMaskShowsTheWallThroughItsHolesLitThroughTheHolesOfItsShadow) {
    const Image image = renderDirectLight(occluderBeforeWall(AlphaMode::Mask, true));
    uint32_t occluderPixels = 0, litWallPixels = 0, shadowedWallPixels = 0, wrong = 0;
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
            const glm::vec2 onOccluder = pointSeenAt(x, y, kOccluderZ), onWall = pointSeenAt(x, y, 0.0f);
            if (distanceToCheckerEdge(onOccluder) < kOccluderEdgeMargin) continue;
            const glm::vec3 pixel = glm::make_vec3(image.pixel(x, y));
            if (checkerOpaqueAt(onOccluder)) {
                ++occluderPixels;
                if (!showsLitOccluder(pixel) && wrong++ < 5) {
                    ADD_FAILURE() << "pixel " << x << "," << y << " should show the red quad, shows " << pixel.r << ","
                                  << pixel.g << "," << pixel.b;
                }
                continue;
            }
            // Through a hole: the white wall, lit where the sun (straight down −Z) passes a hole too.
            if (distanceToCheckerEdge(onWall) < kShadowEdgeMargin) continue;
            const bool lit = !checkerOpaqueAt(onWall);
            ++(lit ? litWallPixels : shadowedWallPixels);
            const float expected = lit ? 1.0f : 0.0f;
            if ((std::abs(pixel.r - expected) > kRadianceTolerance ||
                 std::abs(pixel.g - expected) > kRadianceTolerance) &&
                wrong++ < 5)
                ADD_FAILURE() << "pixel " << x << "," << y << " should show the " << (lit ? "lit" : "shadowed")
                              << " wall, shows " << pixel.r << "," << pixel.g << "," << pixel.b;
        }
    std::printf("MASK: %u quad, %u lit wall, %u shadowed wall pixels checked, %u wrong\n", occluderPixels,
                litWallPixels, shadowedWallPixels, wrong);
    EXPECT_EQ(wrong, 0u);
    EXPECT_GT(occluderPixels, kSize * kSize / 4);
    EXPECT_GT(litWallPixels, kSize * kSize / 50);
    EXPECT_GT(shadowedWallPixels, kSize * kSize / 50);
}

// The share of the pixels showing the lit red quad, and the mean radiance of those showing the
// white wall (lit or not) behind the quad, where its shadow may fall (the camera also sees the
// wall a little beyond it); every pixel must be one or the other.
struct BlendImage {
    double occluderShare = 0.0, meanWall = 0.0;
};

BlendImage classifyPixels(const Image& image) {
    uint32_t occluderPixels = 0, wallPixels = 0, other = 0;
    double wallRadiance = 0.0;
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
            const glm::vec3 pixel = glm::make_vec3(image.pixel(x, y));
            if (showsLitOccluder(pixel)) {
                ++occluderPixels;
            } else if (std::abs(pixel.r - pixel.g) < kRadianceTolerance) {  // white: the wall
                const glm::vec2 onWall = pointSeenAt(x, y, 0.0f);
                if (std::max(std::abs(onWall.x), std::abs(onWall.y)) > 1.0f - kShadowEdgeMargin) continue;
                ++wallPixels;
                wallRadiance += pixel.g;
            } else {
                ++other;
            }
        }
    EXPECT_EQ(other, 0u) << "pixels that are neither the red quad nor the white wall";
    return {double(occluderPixels) / double(kSize * kSize), wallPixels > 0 ? wallRadiance / double(wallPixels) : 0.0};
}

TEST_F(AlphaMaterial, BlendAtHalfAlphaCoversAboutHalfThePixels) {
    const BlendImage half = classifyPixels(renderDirectLight(occluderBeforeWall(AlphaMode::Blend, false, 0.5f)));
    const BlendImage quarter = classifyPixels(renderDirectLight(occluderBeforeWall(AlphaMode::Blend, false, 0.25f)));
    std::printf("BLEND: alpha 0.5 covers %.3f of the pixels, alpha 0.25 %.3f\n", half.occluderShare,
                quarter.occluderShare);
    EXPECT_NEAR(half.occluderShare, 0.5, 0.03);
    EXPECT_NEAR(quarter.occluderShare, 0.25, 0.03);
}

TEST_F(AlphaMaterial, BlendCastsAShadowFromHalfAlphaUp) {
    // The documented approximation (shadow_alpha.frag): alpha 0.4 lets the sun through, 0.6 stops it.
    const BlendImage clear = classifyPixels(renderDirectLight(occluderBeforeWall(AlphaMode::Blend, false, 0.4f)));
    const BlendImage dark = classifyPixels(renderDirectLight(occluderBeforeWall(AlphaMode::Blend, false, 0.6f)));
    std::printf("BLEND: the wall seen through alpha 0.4 has mean radiance %.3f, through 0.6 %.3f (lit: 1)\n",
                clear.meanWall, dark.meanWall);
    EXPECT_NEAR(clear.meanWall, 1.0, kRadianceTolerance);
    EXPECT_NEAR(dark.meanWall, 0.0, kRadianceTolerance);
}

}  // namespace
}  // namespace vct::test
