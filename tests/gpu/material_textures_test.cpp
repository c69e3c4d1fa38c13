// What the camera sees of glTF materials beyond the base colour, and of a file without lights.
#include <cmath>

#include "../cpu/gltf_test_helpers.h"
#include "gpu_test.h"
#include "render/renderer.h"
#include "scene/default_light.h"
#include "scene/load.h"

namespace vct::test {
namespace {

constexpr uint32_t kSize = 32;
constexpr float kRelativeTolerance = 0.01f;

RenderSettings directSettings() {
    RenderSettings settings;
    settings.image.width = kSize;
    settings.image.height = kSize;
    settings.image.supersample = 1;
    settings.resources.voxelResolution = 32;
    settings.resources.sunShadowMapSize = 256;
    settings.resources.localShadowMapSize = 128;
    settings.shading.mode = RenderMode::Direct;
    return settings;
}

Scene loadBuilt(GltfBuilder& gltf) {
    TempFolder folder;
    return loadGltf(gltf.writeGltf(folder, "scene").string());
}

class MaterialTextures : public GpuTest {
protected:
    // The quad with this pbrMetallicRoughness (and no dielectric specular: a Lambertian
    // dielectric), lit by the default sun alone, in direct light.
    Image renderLitQuad(GltfBuilder& gltf, const json& pbr) {
        json& material = gltf.document["materials"][0];  // keeps what the test set (a normal texture)
        material["pbrMetallicRoughness"] = pbr;
        material["extensions"] = {{"KHR_materials_specular", {{"specularFactor", 0.0}}}};
        gltf.document["extensionsUsed"] = {"KHR_materials_specular"};
        Scene scene = loadBuilt(gltf);
        EXPECT_TRUE(addDefaultSunAndSkyIfUnlit(scene));
        Renderer renderer(gpu(), scene, directSettings());
        renderer.renderFrame();
        return renderer.readImage();
    }
};

TEST_F(MaterialTextures, EmissiveTextureHalfBlackLightsHalfTheQuad) {
    // quadFacingCamera: the camera sees u ∈ [0.23, 0.77]; the 8-texel texture is black up to
    // u = 0.5 and bilinear filtering blends only within half a texel (1/16) of that edge, so
    // columns 0–10 see black texels only and columns 21–31 white ones only.
    GltfBuilder gltf = quadFacingCamera();
    gltf.document["images"] = json::array({{{"uri", halfBlackHalfWhitePngUri(8)}}});
    gltf.document["textures"] = json::array({{{"source", 0}}});
    gltf.document["materials"][0] = {{"emissiveFactor", {2.0, 1.0, 0.5}}, {"emissiveTexture", {{"index", 0}}}};
    const Scene scene = loadBuilt(gltf);
    Renderer renderer(gpu(), scene, directSettings());
    renderer.renderFrame();
    const Image image = renderer.readImage();
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x <= 10; ++x) EXPECT_LT(image.pixel(x, y)[0], 1e-3f) << x << "," << y;
        for (uint32_t x = 21; x < kSize; ++x) {
            EXPECT_NEAR(image.pixel(x, y)[0], 2.0f, kRelativeTolerance * 2.0f) << x << "," << y;
            EXPECT_NEAR(image.pixel(x, y)[1], 1.0f, kRelativeTolerance * 1.0f) << x << "," << y;
            EXPECT_NEAR(image.pixel(x, y)[2], 0.5f, kRelativeTolerance * 0.5f) << x << "," << y;
        }
    }
}

TEST_F(MaterialTextures, FileWithoutLightsIsLitByTheDefaultSun) {
    // A grey Lambertian quad and nothing else: the default sun gives it L = E·cosθ·albedo/π.
    GltfBuilder gltf = quadFacingCamera();
    const Image image = renderLitQuad(gltf, {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}}, {"metallicFactor", 0.0}});
    const float cosine = -glm::normalize(kDefaultSunTravel).z;
    const float expected = kDefaultSunIlluminance * cosine * 0.8f / 3.14159265f;
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x)
            EXPECT_NEAR(image.pixel(x, y)[0], expected, kRelativeTolerance * expected) << x << "," << y;
}

TEST_F(MaterialTextures, MetallicRoughnessTextureScalesTheFactorsPerTexel) {
    // Factors metallic 1, roughness 1; the 8-texel texture (linear: blue = metallic, green =
    // roughness) is a rough dielectric on its left half and metal of roughness 128/255 on its right
    // (columns 0-10 and 21-31 see one half each, as in EmissiveTextureHalfBlackLightsHalfTheQuad).
    // Lit by the default sun: the left half is Lambertian, L = E·cosθ·albedo/π; the right half is
    // what a metal of that roughness gives from its factors alone. Read as sRGB, 128 would be a
    // roughness of 0.22.
    std::vector<uint16_t> texels;
    for (uint32_t x = 0; x < 8; ++x)
        texels.insert(texels.end(), {0, uint16_t(x < 4 ? 255 : 128), uint16_t(x < 4 ? 0 : 255), 255});
    const json white = {0.8, 0.8, 0.8, 1.0};
    GltfBuilder textured = quadFacingCamera();
    textured.document["images"] =
        json::array({{{"uri", "data:image/png;base64," + base64(encodePng(8, 1, 4, 8, texels))}}});
    textured.document["textures"] = json::array({{{"source", 0}}});
    const Image image =
        renderLitQuad(textured, {{"baseColorFactor", white}, {"metallicRoughnessTexture", {{"index", 0}}}});
    GltfBuilder plain = quadFacingCamera();
    const Image metal =
        renderLitQuad(plain, {{"baseColorFactor", white}, {"metallicFactor", 1.0}, {"roughnessFactor", 128.0 / 255.0}});

    const float cosine = -glm::normalize(kDefaultSunTravel).z;
    const float lambertian = kDefaultSunIlluminance * cosine * 0.8f / 3.14159265f;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x <= 10; ++x)
            EXPECT_NEAR(image.pixel(x, y)[0], lambertian, kRelativeTolerance * lambertian) << x << "," << y;
        for (uint32_t x = 21; x < kSize; ++x) {
            const float expected = metal.pixel(x, y)[0];
            EXPECT_GT(expected, 0.0f) << "the metal reflects the sun here";
            EXPECT_NEAR(image.pixel(x, y)[0], expected, kRelativeTolerance * expected) << x << "," << y;
        }
    }
}

TEST_F(MaterialTextures, NormalTextureTiltsTheShadingNormalAlongUAndUpTheImage) {
    // A Lambertian quad whose 8-texel normal texture tilts the normal 30° along +u (towards +x, the
    // tangent) on its left half and 30° up the image (+y, the bitangent) on its right, under the
    // default sun: L = E·max(n'·l, 0)·albedo/π with n' the tilted normal, which a wrong sign on
    // either axis would tilt the other way.
    const uint8_t tilt = uint8_t(std::lround((0.5 + 0.5 * std::sin(0.5235988)) * 255.0));
    const uint8_t up = uint8_t(std::lround((0.5 + 0.5 * std::cos(0.5235988)) * 255.0));
    std::vector<uint16_t> texels;
    for (uint32_t x = 0; x < 8; ++x)
        texels.insert(texels.end(), {uint16_t(x < 4 ? tilt : 128), uint16_t(x < 4 ? 128 : tilt), up, 255});
    GltfBuilder gltf = quadFacingCamera();
    gltf.document["images"] =
        json::array({{{"uri", "data:image/png;base64," + base64(encodePng(8, 1, 4, 8, texels))}}});
    gltf.document["textures"] = json::array({{{"source", 0}}});
    gltf.document["materials"][0]["normalTexture"] = {{"index", 0}};
    const Image image = renderLitQuad(gltf, {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}}, {"metallicFactor", 0.0}});

    auto expected = [&](glm::vec3 texel) {
        const glm::vec3 normal = glm::normalize(texel * 2.0f - 1.0f);  // tangent x, bitangent y, normal z
        const float cosine = std::max(glm::dot(normal, -glm::normalize(kDefaultSunTravel)), 0.0f);
        return kDefaultSunIlluminance * cosine * 0.8f / 3.14159265f;
    };
    const float alongU = expected(glm::vec3(tilt, 128, up) / 255.0f);
    const float upImage = expected(glm::vec3(128, tilt, up) / 255.0f);
    // Tilts the other way would give other light.
    ASSERT_GT(std::abs(alongU - expected(glm::vec3(255 - tilt, 128, up) / 255.0f)), 0.2f * alongU);
    ASSERT_GT(std::abs(upImage - expected(glm::vec3(128, 255 - tilt, up) / 255.0f)), 0.2f * upImage);
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x <= 10; ++x)
            EXPECT_NEAR(image.pixel(x, y)[0], alongU, kRelativeTolerance * alongU) << x << "," << y;
        for (uint32_t x = 21; x < kSize; ++x)
            EXPECT_NEAR(image.pixel(x, y)[0], upImage, kRelativeTolerance * upImage) << x << "," << y;
    }
}

}  // namespace
}  // namespace vct::test
