// What the camera sees of glTF materials beyond the base colour, and of a file without lights.
#include <cmath>

#include "../cpu/gltf_test_helpers.h"
#include "bench/metrics.h"
#include "gpu_test.h"
#include "path_traced_reference.h"
#include "render/renderer.h"
#include "scene/default_light.h"
#include "scene/load.h"
#include "scene/material_textures.h"

namespace vct::test {
namespace {

constexpr uint32_t kSize = 32;
constexpr float kRelativeTolerance = 0.01f;

RenderSettings directSettings() { return smallRenderSettings(kSize, RenderMode::Direct); }

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

// An 8-texel normal texture whose left half tilts the normal 30° along +u (the texel (tilt, 128,
// up)) and right half 30° up the image ((128, tilt, up)), on the quad's material.
const uint8_t kTilt = uint8_t(std::lround((0.5 + 0.5 * std::sin(0.5235988)) * 255.0));
const uint8_t kUp = uint8_t(std::lround((0.5 + 0.5 * std::cos(0.5235988)) * 255.0));
const glm::vec3 kAlongU = glm::vec3(kTilt, 128, kUp) / 255.0f, kUpImage = glm::vec3(128, kTilt, kUp) / 255.0f;

void useHalfTiltedNormalTexture(GltfBuilder& gltf) {
    std::vector<uint16_t> texels;
    for (uint32_t x = 0; x < 8; ++x)
        texels.insert(texels.end(), {uint16_t(x < 4 ? kTilt : 128), uint16_t(x < 4 ? 128 : kTilt), kUp, 255});
    gltf.document["images"] =
        json::array({{{"uri", "data:image/png;base64," + base64(encodePng(8, 1, 4, 8, texels))}}});
    gltf.document["textures"] = json::array({{{"source", 0}}});
    gltf.document["materials"][0]["normalTexture"] = {{"index", 0}};
}

// The light the default sun gives the quad (albedo 0.8, facing +z) where the normal `texel` is read
// in the frame (tangent, bitangent): L = E·max(n'·l, 0)·albedo/π.
float tiltedNormalLight(glm::vec3 texel, glm::vec3 tangent, glm::vec3 bitangent) {
    const glm::vec3 local = glm::normalize(texel * 2.0f - 1.0f);  // tangent x, bitangent y, normal z
    const glm::vec3 normal = local.x * tangent + local.y * bitangent + local.z * glm::vec3(0, 0, 1);
    const float cosine = std::max(glm::dot(normal, -glm::normalize(kDefaultSunTravel)), 0.0f);
    return kDefaultSunIlluminance * cosine * 0.8f / 3.14159265f;
}

// Every pixel of the image's left third is `left`, of its right third `right`.
void expectHalves(const Image& image, float left, float right, const std::string& what) {
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x <= 10; ++x)
            EXPECT_NEAR(image.pixel(x, y)[0], left, kRelativeTolerance * left) << x << "," << y << " " << what;
        for (uint32_t x = 21; x < kSize; ++x)
            EXPECT_NEAR(image.pixel(x, y)[0], right, kRelativeTolerance * right) << x << "," << y << " " << what;
    }
}

TEST_F(MaterialTextures, NormalTextureTiltsTheShadingNormalAlongUAndUpTheImage) {
    // A Lambertian quad whose 8-texel normal texture tilts the normal 30° along +u (towards +x, the
    // tangent) on its left half and 30° up the image (+y, the bitangent) on its right, under the
    // default sun: L = E·max(n'·l, 0)·albedo/π with n' the tilted normal, which a wrong sign on
    // either axis would tilt the other way. Mirrored (u = 1 − u, as the second half of a symmetric
    // model), the halves swap sides, +u tilts towards −x and up the image stays +y.
    for (const bool mirrored : {false, true}) {
        GltfBuilder gltf = quadFacingCamera();
        if (mirrored) {
            const int uvs = gltf.addVec2({{1, 1}, {0, 1}, {0, 0}, {1, 0}});
            gltf.document["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = uvs;
        }
        useHalfTiltedNormalTexture(gltf);
        const Image image = renderLitQuad(gltf, {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}}, {"metallicFactor", 0.0}});

        const glm::vec3 alongPlusU = mirrored ? glm::vec3(-1, 0, 0) : glm::vec3(1, 0, 0), upTheImage(0, 1, 0);
        const float alongU = tiltedNormalLight(kAlongU, alongPlusU, upTheImage);
        const float upImage = tiltedNormalLight(kUpImage, alongPlusU, upTheImage);
        // Tilts the other way would give other light.
        const glm::vec3 againstU = glm::vec3(255 - kTilt, 128, kUp) / 255.0f;
        const glm::vec3 downImage = glm::vec3(128, 255 - kTilt, kUp) / 255.0f;
        ASSERT_GT(std::abs(alongU - tiltedNormalLight(againstU, alongPlusU, upTheImage)), 0.2f * alongU);
        ASSERT_GT(std::abs(upImage - tiltedNormalLight(downImage, alongPlusU, upTheImage)), 0.2f * upImage);
        expectHalves(image, mirrored ? upImage : alongU, mirrored ? alongU : upImage,
                     mirrored ? "mirrored" : "not mirrored");
    }
}

TEST_F(MaterialTextures, ANormalTextureFollowsTheFilesTangents) {
    // The quad and texture above, with a TANGENT along +y (handedness +1), a quarter turn from the
    // direction u increases in (+x): +u tilts towards +y, and up the image, the bitangent
    // cross(+z, +y) = -x, towards -x. Taken from the triangles' coordinates, the tilts were +x and +y.
    GltfBuilder gltf = quadFacingCamera();
    const int tangents = gltf.addVec4({{0, 1, 0, 1}, {0, 1, 0, 1}, {0, 1, 0, 1}, {0, 1, 0, 1}});
    gltf.document["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] = tangents;
    useHalfTiltedNormalTexture(gltf);
    const Image image = renderLitQuad(gltf, {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}}, {"metallicFactor", 0.0}});

    const float left = tiltedNormalLight(kAlongU, {0, 1, 0}, {-1, 0, 0});
    const float right = tiltedNormalLight(kUpImage, {0, 1, 0}, {-1, 0, 0});
    // The frame from the coordinates would give other light.
    ASSERT_GT(std::abs(left - tiltedNormalLight(kAlongU, {1, 0, 0}, {0, 1, 0})), 0.1f * left);
    ASSERT_GT(std::abs(right - tiltedNormalLight(kUpImage, {1, 0, 0}, {0, 1, 0})), 0.1f * right);
    expectHalves(image, left, right, "with the file's tangents");
}

TEST_F(MaterialTextures, ATexturedWallBleedsItsTexturesColourIntoTheIndirectLight) {
    // A white floor (the quad) beside a wall both lit by a sun. The wall is red once through its
    // base colour factor and once through a red texture under a white factor, as glTF models are
    // coloured: the indirect light on the floor must be the same red in both, so the voxels carry
    // the texture's colour (with the factor alone they bounced white light).
    const glm::u8vec3 red(200, 40, 40);  // sRGB
    auto render = [&](bool textured) {
        GltfBuilder gltf = quadFacingCamera();
        gltf.document["materials"][0] = {
            {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}}, {"metallicFactor", 0.0}}}};
        // The wall: x = 1, y ∈ [−1, 1], z ∈ [0, 2], facing the floor (−x).
        const int positions = gltf.addVec3({{1, -1, 0}, {1, -1, 2}, {1, 1, 2}, {1, 1, 0}});
        const int normals = gltf.addVec3({{-1, 0, 0}, {-1, 0, 0}, {-1, 0, 0}, {-1, 0, 0}});
        const int uvs = gltf.addVec2({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
        const int wall = gltf.addMesh({{"POSITION", positions}, {"NORMAL", normals}, {"TEXCOORD_0", uvs}},
                                      gltf.addIndices({0, 1, 2, 0, 2, 3}), /*material=*/1);
        gltf.document["scenes"][0]["nodes"].push_back(gltf.addNode({{"mesh", wall}}));
        json pbr = {{"metallicFactor", 0.0}};
        if (textured) {
            std::vector<uint16_t> texels;
            for (int i = 0; i < 16; ++i) texels.insert(texels.end(), {red.r, red.g, red.b, 255});
            gltf.document["images"] =
                json::array({{{"uri", "data:image/png;base64," + base64(encodePng(4, 4, 4, 8, texels))}}});
            gltf.document["textures"] = json::array({{{"source", 0}}});
            pbr["baseColorTexture"] = {{"index", 0}};
        } else {
            pbr["baseColorFactor"] = {srgbToLinear(red.r / 255.0f), srgbToLinear(red.g / 255.0f),
                                      srgbToLinear(red.b / 255.0f), 1.0};
        }
        gltf.document["materials"].push_back({{"pbrMetallicRoughness", pbr}});
        Scene scene = loadBuilt(gltf);
        Light sun;
        sun.type = LightType::Directional;
        sun.direction = glm::normalize(glm::vec3(1.0f, 0.0f, -1.0f));  // onto the floor and the wall's face
        sun.intensity = 3.0f;
        scene.lights.push_back(sun);
        RenderSettings settings = directSettings();
        settings.shading.mode = RenderMode::Indirect;
        Renderer renderer(gpu(), scene, settings);
        renderer.renderFrame();
        return renderer.readImage();
    };
    const Image textured = render(true), coloured = render(false);
    // The floor's half beside the wall (x > 0 in the image's right half).
    glm::dvec3 texturedSum(0.0), colouredSum(0.0);
    for (uint32_t y = 4; y < kSize - 4; ++y)
        for (uint32_t x = kSize / 2; x < kSize - 4; ++x) {
            texturedSum += glm::dvec3(textured.pixel(x, y)[0], textured.pixel(x, y)[1], textured.pixel(x, y)[2]);
            colouredSum += glm::dvec3(coloured.pixel(x, y)[0], coloured.pixel(x, y)[1], coloured.pixel(x, y)[2]);
        }
    std::printf(
        "indirect light beside the wall, red through the factor: (%.4f %.4f %.4f), through a texture: "
        "(%.4f %.4f %.4f)\n",
        colouredSum.r, colouredSum.g, colouredSum.b, texturedSum.r, texturedSum.g, texturedSum.b);
    ASSERT_GT(colouredSum.r, 2.0 * colouredSum.g) << "the red wall tints the floor's indirect light";
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(texturedSum[c], colouredSum[c], 0.01 * colouredSum[c]) << "channel " << c;
}

TEST_F(MaterialTextures, ATexturedQuadsDirectLightMatchesThePathTracer) {
    // The quad under the default sun with a 4 × 4 checker of base colours and a metallic-roughness
    // texture whose rows alternate polished metal and rough paint: the renderer's direct light (one
    // sample a pixel, the textures through their mip chains) against the path tracer's (256 samples
    // a pixel, bilinear), which shares the loader and the material model but not one line of shading.
    GltfBuilder gltf = quadFacingCamera();
    std::vector<uint16_t> checker, metalRough;
    const uint16_t colours[4][3] = {{230, 60, 40}, {60, 200, 90}, {50, 80, 220}, {240, 240, 230}};
    for (uint32_t y = 0; y < 4; ++y)
        for (uint32_t x = 0; x < 4; ++x) {
            const uint16_t* colour = colours[(x + 2 * y) % 4];
            checker.insert(checker.end(), {colour[0], colour[1], colour[2], 255});
            // glTF: green = roughness, blue = metallic.
            metalRough.insert(metalRough.end(), y % 2 ? std::initializer_list<uint16_t>{0, 60, 255, 255}
                                                      : std::initializer_list<uint16_t>{0, 220, 0, 255});
        }
    gltf.document["images"] =
        json::array({{{"uri", "data:image/png;base64," + base64(encodePng(4, 4, 4, 8, checker))}},
                     {{"uri", "data:image/png;base64," + base64(encodePng(4, 4, 4, 8, metalRough))}}});
    gltf.document["samplers"] = json::array({{{"magFilter", 9728}}});  // nearest: sharp cells in both
    gltf.document["textures"] = json::array({{{"source", 0}, {"sampler", 0}}, {{"source", 1}, {"sampler", 0}}});
    gltf.document["materials"][0] = {
        {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicRoughnessTexture", {{"index", 1}}}}}};
    Scene scene = loadBuilt(gltf);
    ASSERT_TRUE(addDefaultSunAndSkyIfUnlit(scene));
    Renderer renderer(gpu(), scene, directSettings());
    renderer.renderFrame();
    const Image image = renderer.readImage();

    const Image truth = pathTracedDirectLight(scene, kSize);
    const bench::ImageError error = bench::compareImages(image, truth);
    std::printf("[ textures ] direct light against the path tracer: luminance %.4f of it, relMSE %.4f\n",
                error.luminanceRatio, error.relMse);
    EXPECT_NEAR(error.luminanceRatio, 1.0, 0.02);
    EXPECT_LT(error.relMse, 0.02);
}

}  // namespace
}  // namespace vct::test
