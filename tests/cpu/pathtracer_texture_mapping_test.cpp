// Where the path tracer reads material textures: the texture-coordinate set each names, through its
// KHR_texture_transform, as the renderer does; and the occlusion texture, which it ignores.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "path_tracer.h"
#include "pathtracer_test_helpers.h"
#include "scene/load.h"

namespace vct::pt {
namespace {

using namespace test;

constexpr uint32_t kSize = 32;
constexpr float kRelativeTolerance = 0.01f;

// The plane of addSunlitPlaneSeenFromAbove at pixel (x, y)'s centre: its TEXCOORD_0.
glm::vec2 planeTexCoordAtPixel(uint32_t x, uint32_t y) {
    const float worldX = -0.5f + (float(x) + 0.5f) / float(kSize), worldZ = -0.5f + (float(y) + 0.5f) / float(kSize);
    return glm::vec2(0.5f * (worldX + 1.0f), 0.5f * (worldZ + 1.0f));
}

// How far `t` lies from the nearest multiple of ½ (a half's edge in a texture, repeating).
float distanceToHalfEdge(float t) {
    const float inHalf = 2.0f * (t - std::floor(t));
    return 0.5f * std::abs(inHalf - std::round(inHalf));
}

// A sunlit Lambertian plane (E = π straight down, so radiance = base colour) with `texture` as its
// base colour texture, read as `reference` says; rendered in full light.
Image renderSunlitPlane(const Texture& texture, const TextureReference& reference,
                        const std::function<void(Scene&)>& edit = {}) {
    Scene scene;
    scene.textures.push_back(texture);
    Material material = lambertian(glm::vec3(1.0f));
    material.baseColorTexture = reference;
    addSunlitPlaneSeenFromAbove(scene, material, glm::vec3(0.0f, -1.0f, 0.0f));
    if (edit) edit(scene);
    return render(createPathTracer(scene), smallRender(scene, kSize, 4, Component::Full, 2)).image;
}

TEST(PathTracerTextureMapping, ATextureNamingTexCoord1IsReadWithTheSecondSet) {
    // TEXCOORD_1 mirrors TEXCOORD_0 left to right; the 8-texel texture is black on its left half.
    // Read with TEXCOORD_1 the plane is white on the image's left and black on its right.
    TextureReference reference;
    reference.index = 0;
    reference.texCoord = 1;
    const Image image = renderSunlitPlane(halfBlackTexture(8), reference, [](Scene& scene) {
        for (Vertex& vertex : scene.vertices) vertex.uv1 = glm::vec2(1.0f - vertex.u, vertex.v);
    });
    uint32_t checked = 0;
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
            const float u1 = 1.0f - planeTexCoordAtPixel(x, y).x;
            // Half a texel of bilinear blending, plus the pixel's own footprint (1/64 in u).
            if (std::abs(u1 - 0.5f) < 1.0f / 16.0f + 1.0f / 64.0f) continue;
            const float expected = u1 > 0.5f ? 1.0f : 0.0f;
            EXPECT_NEAR(image.pixel(x, y)[0], expected, kRelativeTolerance) << x << "," << y;
            ++checked;
        }
    EXPECT_GT(checked, kSize * kSize / 2);
}

TEST(PathTracerTextureMapping, ATransformedTextureIsReadWhereTheExtensionsFormulaSays) {
    // An 8 × 8 texture of four quadrants: red top left, green top right, blue bottom left, white
    // bottom right. With scale 2, rotation π/2 and offset ½, KHR_texture_transform reads it at
    // u' = 2v + ½, v' = −2u + ½ (worked out by hand from T·R·S). Pixels whose (u', v') lie within
    // half a texel and a pixel's footprint of a quadrant's edge see blends and are skipped.
    Texture texture;
    texture.width = texture.height = 8;
    const glm::u8vec3 quadrant[2][2] = {{{255, 0, 0}, {0, 255, 0}}, {{0, 0, 255}, {255, 255, 255}}};
    for (uint32_t y = 0; y < 8; ++y)
        for (uint32_t x = 0; x < 8; ++x) {
            const glm::u8vec3 color = quadrant[y / 4][x / 4];
            texture.rgba8.insert(texture.rgba8.end(), {color.r, color.g, color.b, 255});
        }
    TextureReference reference;
    reference.index = 0;
    reference.offset = glm::vec2(0.5f);
    reference.rotation = 1.5707963f;
    reference.scale = glm::vec2(2.0f);
    const Image image = renderSunlitPlane(texture, reference);

    const float margin = 1.0f / 16.0f + 1.0f / 32.0f;  // half a texel + a pixel (1/64 in u and v, × 2)
    uint32_t checked = 0;
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
            const glm::vec2 uv = planeTexCoordAtPixel(x, y);
            const glm::vec2 transformed(2.0f * uv.y + 0.5f, -2.0f * uv.x + 0.5f);
            if (distanceToHalfEdge(transformed.x) < margin || distanceToHalfEdge(transformed.y) < margin) continue;
            const glm::vec2 wrapped = transformed - glm::floor(transformed);
            const glm::vec3 expected = glm::vec3(quadrant[wrapped.y < 0.5f ? 0 : 1][wrapped.x < 0.5f ? 0 : 1]) / 255.0f;
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(image.pixel(x, y)[c], expected[c], kRelativeTolerance) << x << "," << y << " channel " << c;
            ++checked;
        }
    EXPECT_GT(checked, kSize * kSize / 5);
}

TEST(PathTracerTextureMapping, TheOcclusionTextureIsIgnoredBecausePathsFindOcclusionThemselves) {
    // The Cornell box's indirect light, with and without a black occlusion texture of full strength
    // on every material: the renderer would darken all of it; the path tracer, whose paths meet the
    // occluders the texture stands for, must not count them twice. Same seed, same paths.
    const Scene plain = loadScene("cornell");
    Scene occluded = plain;
    Texture black;
    black.width = black.height = 1;
    black.rgba8 = {0, 0, 0, 255};
    black.srgb = false;
    occluded.textures.push_back(black);
    for (Material& material : occluded.materials) {
        material.occlusionTexture.index = int(occluded.textures.size() - 1);
        material.occlusionStrength = 1.0f;
    }
    const Image expected = render(createPathTracer(plain), smallRender(plain, 8, 8, Component::Indirect, 5)).image;
    const Image image = render(createPathTracer(occluded), smallRender(occluded, 8, 8, Component::Indirect, 5)).image;
    double sum = 0.0;
    for (size_t i = 0; i < expected.rgb.size(); ++i) {
        EXPECT_EQ(image.rgb[i], expected.rgb[i]) << "value " << i;
        sum += expected.rgb[i];
    }
    EXPECT_GT(sum, 0.0) << "the box has indirect light for a texture to darken";
}

}  // namespace
}  // namespace vct::pt
