// Where material textures are read: the occlusion texture, the texture-coordinate set each
// textureInfo names, and KHR_texture_transform, from the file to the Scene.
#include <gtest/gtest.h>

#include "gltf_test_helpers.h"
#include "scene/load.h"
#include "scene/material_textures.h"

namespace vct {
namespace {

using test::GltfBuilder;
using test::json;
using test::TempFolder;

constexpr float kTolerance = 1e-6f;

Scene loadBuilt(GltfBuilder& gltf) {
    TempFolder folder;
    return loadGltf(gltf.writeGltf(folder, "scene").string());
}

std::string loadError(GltfBuilder& gltf) {
    try {
        loadBuilt(gltf);
    } catch (const std::exception& error) {
        return error.what();
    }
    return "";
}

// quadFacingCamera with one 8 × 1 texture for the test's material to name.
GltfBuilder texturedQuad() {
    GltfBuilder gltf = test::quadFacingCamera();
    gltf.document["images"] = json::array({{{"uri", test::halfBlackHalfWhitePngUri(8)}}});
    gltf.document["textures"] = json::array({{{"source", 0}}});
    return gltf;
}

// The quad's TEXCOORD_1: TEXCOORD_0 mirrored left to right.
void addMirroredTexCoord1(GltfBuilder& gltf) {
    gltf.document["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] =
        gltf.addVec2({{1, 1}, {0, 1}, {0, 0}, {1, 0}});
}

TEST(OcclusionTexture, IsDecodedAsLinearDataWithItsStrength) {
    GltfBuilder gltf = texturedQuad();
    gltf.document["materials"][0] = {{"occlusionTexture", {{"index", 0}, {"strength", 0.75}}}};
    const Scene scene = loadBuilt(gltf);
    const Material& material = scene.materials[0];
    ASSERT_GE(material.occlusionTexture.index, 0);
    EXPECT_FALSE(scene.textures[size_t(material.occlusionTexture.index)].srgb);
    EXPECT_EQ(material.occlusionStrength, 0.75f);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings[0];
}

TEST(OcclusionTexture, AStrengthOutsideZeroToOneIsRefused) {
    GltfBuilder gltf = texturedQuad();
    gltf.document["materials"][0] = {{"occlusionTexture", {{"index", 0}, {"strength", 1.5}}}};
    EXPECT_NE(loadError(gltf).find("materials[0].occlusionTexture.strength: 1.5 is outside [0, 1]"), std::string::npos)
        << loadError(gltf);
}

TEST(TexCoord, EachTextureReadsTheSetItsTextureInfoNames) {
    GltfBuilder gltf = texturedQuad();
    addMirroredTexCoord1(gltf);
    gltf.document["materials"][0] = {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 1}}}}},
                                     {"emissiveTexture", {{"index", 0}}},
                                     {"emissiveFactor", {1.0, 1.0, 1.0}}};
    const Scene scene = loadBuilt(gltf);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings[0];
    EXPECT_EQ(scene.materials[0].baseColorTexture.texCoord, 1u);
    EXPECT_EQ(scene.materials[0].emissiveTexture.texCoord, 0u);
    // quadFacingCamera's first corner has TEXCOORD_0 (0, 1); its TEXCOORD_1 is (1, 1).
    const Vertex& corner = scene.vertices[0];
    EXPECT_EQ(glm::vec2(corner.u, corner.v), glm::vec2(0.0f, 1.0f));
    EXPECT_EQ(corner.uv1, glm::vec2(1.0f, 1.0f));
    EXPECT_EQ(textureCoordinates(scene.materials[0].baseColorTexture, corner), glm::vec2(1.0f, 1.0f));
    EXPECT_EQ(textureCoordinates(scene.materials[0].emissiveTexture, corner), glm::vec2(0.0f, 1.0f));
}

TEST(TexCoord, APrimitiveWithoutTexCoord1ReadsTexCoord0InsteadWithOneWarning) {
    GltfBuilder gltf = texturedQuad();
    gltf.document["materials"][0] = {{"normalTexture", {{"index", 0}, {"texCoord", 1}}},
                                     {"occlusionTexture", {{"index", 0}, {"texCoord", 1}}}};
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("meshes[0].primitives[0].attributes: has no TEXCOORD_1, which materials[0]'s "
                                     "normalTexture, occlusionTexture reads; TEXCOORD_0 stands in"),
              std::string::npos)
        << scene.warnings[0];
    for (const Vertex& vertex : scene.vertices) EXPECT_EQ(vertex.uv1, glm::vec2(vertex.u, vertex.v));
}

TEST(TexCoord, ASetBeyondTheSecondIsNamedInAWarning) {
    GltfBuilder gltf = texturedQuad();
    gltf.document["materials"][0] = {{"emissiveTexture", {{"index", 0}, {"texCoord", 2}}}};
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("materials[0].emissiveTexture.texCoord: TEXCOORD_2 is not read (only "
                                     "TEXCOORD_0 and TEXCOORD_1 are); the texture is sampled with TEXCOORD_0"),
              std::string::npos)
        << scene.warnings[0];
    EXPECT_EQ(scene.materials[0].emissiveTexture.texCoord, 0u);
}

TEST(TextureTransform, IsReadFromTheExtensionWithItsTexCoordOverrideAndNoWarning) {
    GltfBuilder gltf = texturedQuad();
    addMirroredTexCoord1(gltf);
    const json transform = {{"offset", {0.5, -0.25}}, {"rotation", 1.5}, {"scale", {2, 3}}, {"texCoord", 1}};
    gltf.document["materials"][0] = {
        {"pbrMetallicRoughness",
         {{"metallicRoughnessTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}}}}};
    gltf.document["extensionsUsed"] = {"KHR_texture_transform"};
    gltf.document["extensionsRequired"] = {"KHR_texture_transform"};
    const Scene scene = loadBuilt(gltf);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings[0];
    const TextureReference& texture = scene.materials[0].metallicRoughnessTexture;
    EXPECT_EQ(texture.offset, glm::vec2(0.5f, -0.25f));
    EXPECT_EQ(texture.rotation, 1.5f);
    EXPECT_EQ(texture.scale, glm::vec2(2.0f, 3.0f));
    EXPECT_EQ(texture.texCoord, 1u);  // the extension's texCoord overrides the textureInfo's (0)
}

TEST(TextureTransform, OffsetRotationAndScaleMapTheCoordinatesAsTheExtensionSays) {
    // T(offset)·R(rotation)·S(scale)·(u, v, 1), R = [[cos, sin], [−sin, cos]], written out by hand.
    TextureReference texture;
    texture.offset = glm::vec2(0.5f, 0.25f);
    texture.rotation = 0.5235988f;  // 30°
    texture.scale = glm::vec2(2.0f, 3.0f);
    Vertex vertex;
    vertex.u = 0.2f;
    vertex.v = 0.1f;
    const float c = std::cos(0.5235988f), s = std::sin(0.5235988f);
    const glm::vec2 expected(c * 2.0f * 0.2f + s * 3.0f * 0.1f + 0.5f, -s * 2.0f * 0.2f + c * 3.0f * 0.1f + 0.25f);
    const glm::vec2 uv = textureCoordinates(texture, vertex);
    EXPECT_NEAR(uv.x, expected.x, kTolerance);
    EXPECT_NEAR(uv.y, expected.y, kTolerance);
}

TEST(TextureTransform, TheExtensionsExampleReadsTheLowerLeftQuadrant) {
    // KHR_texture_transform's example: offset (0, 1), rotation π/2, scale ½ "utilizes only the lower
    // left quadrant of the source image, rotated clockwise 90°" (v runs down the image).
    TextureReference texture;
    texture.offset = glm::vec2(0.0f, 1.0f);
    texture.rotation = 1.5707963f;
    texture.scale = glm::vec2(0.5f);
    for (const glm::vec2 corner : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)}) {
        Vertex vertex;
        vertex.u = corner.x;
        vertex.v = corner.y;
        const glm::vec2 uv = textureCoordinates(texture, vertex);
        EXPECT_GE(uv.x, -kTolerance) << corner.x << "," << corner.y;
        EXPECT_LE(uv.x, 0.5f + kTolerance) << corner.x << "," << corner.y;
        EXPECT_GE(uv.y, 0.5f - kTolerance) << corner.x << "," << corner.y;
        EXPECT_LE(uv.y, 1.0f + kTolerance) << corner.x << "," << corner.y;
    }
    // Rotated clockwise: the quad's top edge (v = 0) shows the quadrant's left edge (u = 0).
    Vertex topRight;
    topRight.u = 1.0f;
    const glm::vec2 uv = textureCoordinates(texture, topRight);
    EXPECT_NEAR(uv.x, 0.0f, kTolerance);
    EXPECT_NEAR(uv.y, 0.5f, kTolerance);
}

TEST(TextureTransform, ValuesTheLoaderCannotReadAreRefusedNamingThem) {
    const std::vector<std::pair<json, std::string>> cases = {
        {{{"offset", {1.0}}}, "KHR_texture_transform.offset: is not an array of two numbers"},
        {{{"scale", "large"}}, "KHR_texture_transform.scale: is not an array of two numbers"},
        {{{"rotation", {1.0}}}, "KHR_texture_transform.rotation: is not a number"},
        {{{"texCoord", -1}}, "KHR_texture_transform.texCoord: is not a non-negative integer"},
        {{{"texCoord", 0.5}}, "KHR_texture_transform.texCoord: is not a non-negative integer"},
    };
    for (const auto& [transform, problem] : cases) {
        GltfBuilder gltf = texturedQuad();
        gltf.document["materials"][0] = {
            {"emissiveTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}}};
        const std::string error = loadError(gltf);
        EXPECT_NE(error.find("materials[0].emissiveTexture.extensions." + problem), std::string::npos)
            << transform.dump() << ": " << error;
    }
}

}  // namespace
}  // namespace vct
