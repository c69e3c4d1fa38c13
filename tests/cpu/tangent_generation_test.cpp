// Tangents for files without TANGENT (scene/tangent_generation.h): along increasing u, handed so
// that the bitangent points up the image, smooth across the triangles that share a vertex, split
// where mirrored halves meet, and made by the loader exactly where a normal texture needs them.
#include <gtest/gtest.h>

#include "gltf_test_helpers.h"
#include "normal_map.h"
#include "scene/load.h"
#include "scene/tangent_generation.h"

namespace vct {
namespace {

using test::expectNear;
using test::GltfBuilder;
using test::json;
using test::TempFolder;

constexpr float kTolerance = 1e-5f;

Vertex vertexAt(glm::vec3 position, glm::vec2 uv, glm::vec3 normal = {0, 0, 1}) {
    Vertex vertex;
    vertex.position = position;
    vertex.u = uv.x;
    vertex.v = uv.y;
    vertex.normal = glm::normalize(normal);
    return vertex;
}

// The bitangent a vertex's tangent gives, cross(normal, tangent)·w: up the image where it is right.
glm::vec3 bitangentOf(const Vertex& vertex) {
    return glm::cross(vertex.normal, glm::vec3(vertex.tangent)) * vertex.tangent.w;
}

TEST(TangentGeneration, AQuadsTangentRunsAlongUAndItsBitangentUpTheImage) {
    // u = (x + 1)/2 and v = (1 − y)/2 (v grows down the image): tangent +x, up the image +y. With u
    // mirrored (1 − u, the second half of a symmetric model) the tangent turns to −x and up the image
    // stays +y, so the handedness turns over. The frame is the one the renderer would otherwise take
    // from each triangle's coordinates (normal_map.h's axesFromSteps).
    for (const bool mirrored : {false, true}) {
        auto u = [&](float x) { return mirrored ? 1.0f - (x + 1.0f) / 2.0f : (x + 1.0f) / 2.0f; };
        std::vector<Vertex> vertices;
        for (glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
            vertices.push_back(vertexAt({corner, 0.0f}, {u(corner.x), (1.0f - corner.y) / 2.0f}));
        std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 3};
        generateTangents(vertices, indices, 0);
        ASSERT_EQ(vertices.size(), 4u) << "one handedness: nothing to split";
        const glsl::TextureAxes axes = glsl::axesFromSteps(
            vertices[1].position - vertices[0].position, vertices[2].position - vertices[0].position,
            {vertices[1].u - vertices[0].u, vertices[1].v - vertices[0].v},
            {vertices[2].u - vertices[0].u, vertices[2].v - vertices[0].v});
        for (const Vertex& vertex : vertices) {
            expectNear(glm::vec3(vertex.tangent), {mirrored ? -1.0f : 1.0f, 0, 0});
            expectNear(glm::vec3(vertex.tangent), glm::normalize(axes.alongU));
            expectNear(bitangentOf(vertex), {0, 1, 0});
            EXPECT_LT(glm::dot(bitangentOf(vertex), axes.alongV), 0.0f) << "up the image is decreasing v";
        }
    }
}

TEST(TangentGeneration, TrianglesSharingAVertexShareOneSmoothTangent) {
    // A roof of two triangles folded along y: the left slope faces (−1, 0, 1), the right (1, 0, 1),
    // u runs across the fold. Each slope's own ∂position/∂u lies along its slope; the ridge's
    // vertices, normal +z, take their mean, +x, so the frame turns smoothly over the ridge.
    const float s = std::sqrt(0.5f);
    std::vector<Vertex> vertices = {
        vertexAt({-1, 0, 0}, {0, 1}, {-s, 0, s}),  vertexAt({0, 0, 1}, {0.5f, 1}, {0, 0, 1}),
        vertexAt({0, 1, 1}, {0.5f, 0}, {0, 0, 1}), vertexAt({1, 0, 0}, {1, 1}, {s, 0, s}),
        vertexAt({-1, 1, 0}, {0, 0}, {-s, 0, s}),  vertexAt({1, 1, 0}, {1, 0}, {s, 0, s})};
    std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 4, 1, 3, 5, 1, 5, 2};
    generateTangents(vertices, indices, 0);
    ASSERT_EQ(vertices.size(), 6u);
    expectNear(glm::vec3(vertices[1].tangent), {1, 0, 0});
    expectNear(glm::vec3(vertices[2].tangent), {1, 0, 0});
    expectNear(glm::vec3(vertices[0].tangent), glm::normalize(glm::vec3(1, 0, 1)));   // up the left slope
    expectNear(glm::vec3(vertices[3].tangent), glm::normalize(glm::vec3(1, 0, -1)));  // down the right one
    for (const Vertex& vertex : vertices) {
        EXPECT_NEAR(glm::dot(glm::vec3(vertex.tangent), vertex.normal), 0.0f, kTolerance);
        expectNear(bitangentOf(vertex), {0, 1, 0});
    }
}

TEST(TangentGeneration, AVertexWhereMirroredHalvesMeetIsSplitInTwo) {
    // Two quads side by side sharing the edge x = 0, the right one's u mirrored (u = |x|), as a
    // symmetric model's halves share one texture: their tangents point away from each other, −x and
    // +x, with opposite handedness. Averaged they would cancel on the shared edge; split, each half
    // keeps its own, and its triangles point at their own copies.
    std::vector<Vertex> vertices;
    for (float x : {-1.0f, 0.0f, 1.0f})
        for (float y : {0.0f, 1.0f}) vertices.push_back(vertexAt({x, y, 0}, {std::abs(x), 1.0f - y}));
    // Vertex 2 + i is (0, i); the left quad is 0, 2, 3, 1 and the right 2, 4, 5, 3.
    std::vector<uint32_t> indices = {0, 2, 3, 0, 3, 1, 2, 4, 5, 2, 5, 3};
    generateTangents(vertices, indices, 0);
    ASSERT_EQ(vertices.size(), 8u) << "the two shared vertices copied";
    for (size_t corner = 0; corner < indices.size(); ++corner) {
        const Vertex& vertex = vertices[indices[corner]];
        const bool right = corner >= 6;
        expectNear(glm::vec3(vertex.tangent), {right ? 1.0f : -1.0f, 0, 0});
        expectNear(bitangentOf(vertex), {0, 1, 0});
    }
    EXPECT_NE(indices[0 * 3 + 1], indices[2 * 3 + 0]) << "the left and right quads' (0, 0) are different vertices";
}

TEST(TangentGeneration, DegenerateCoordinatesLeaveTheTangentToThePixels) {
    std::vector<Vertex> vertices = {vertexAt({0, 0, 0}, {0.5f, 0.5f}), vertexAt({1, 0, 0}, {0.5f, 0.5f}),
                                    vertexAt({0, 1, 0}, {0.5f, 0.5f})};
    std::vector<uint32_t> indices = {0, 1, 2};
    generateTangents(vertices, indices, 0);
    for (const Vertex& vertex : vertices) EXPECT_EQ(vertex.tangent, glm::vec4(0.0f));
}

// The quad facing the camera with a normal texture read at `texCoord`, loaded.
Scene loadQuadWithNormalTexture(int texCoord, bool withTangents) {
    GltfBuilder gltf = test::quadFacingCamera();
    gltf.document["images"] = json::array({{{"uri", test::halfBlackHalfWhitePngUri(2)}}});
    gltf.document["textures"] = json::array({{{"source", 0}}});
    gltf.document["materials"][0]["normalTexture"] = {{"index", 0}, {"texCoord", texCoord}};
    json& attributes = gltf.document["meshes"][0]["primitives"][0]["attributes"];
    attributes["TEXCOORD_1"] = attributes["TEXCOORD_0"];
    if (withTangents) attributes["TANGENT"] = gltf.addVec4({{0, 1, 0, 1}, {0, 1, 0, 1}, {0, 1, 0, 1}, {0, 1, 0, 1}});
    TempFolder folder;
    return loadGltf(gltf.writeGltf(folder, "scene").string());
}

TEST(TangentGeneration, TheLoaderGeneratesThemWhereANormalTextureReadsTexcoord0AndTheFileHasNone) {
    for (const Vertex& vertex : loadQuadWithNormalTexture(0, false).vertices) {
        expectNear(glm::vec3(vertex.tangent), {1, 0, 0});
        expectNear(bitangentOf(vertex), {0, 1, 0});
    }
    // The file's own are kept.
    for (const Vertex& vertex : loadQuadWithNormalTexture(0, true).vertices)
        expectNear(glm::vec3(vertex.tangent), {0, 1, 0});
    // A texture read at TEXCOORD_1 takes its frame per pixel (tangents follow TEXCOORD_0), and a
    // quad without a normal texture needs none.
    for (const Vertex& vertex : loadQuadWithNormalTexture(1, false).vertices)
        EXPECT_EQ(vertex.tangent, glm::vec4(0.0f));
    GltfBuilder plain = test::quadFacingCamera();
    TempFolder folder;
    for (const Vertex& vertex : loadGltf(plain.writeGltf(folder, "plain").string()).vertices)
        EXPECT_EQ(vertex.tangent, glm::vec4(0.0f));
}

}  // namespace
}  // namespace vct
