// What loadGltf makes of valid glTF files: geometry in world space, materials, cameras, lights.
#include <gtest/gtest.h>

#include <cmath>

#include "error.h"
#include "gltf_test_helpers.h"
#include "scene/load.h"

namespace vct {
namespace {

using test::expectNear;
using test::GltfBuilder;
using test::json;
using test::TempFolder;

constexpr float kTolerance = 1e-5f;
constexpr float kPi = 3.14159265358979f;

glm::vec3 cornerOf(const Scene& scene, size_t triangle, int corner) {
    return scene.vertices[scene.indices[3 * triangle + size_t(corner)]].position;
}

// The normal implied by the winding (counter-clockwise = front, glTF §3.7.2.1).
glm::vec3 windingNormal(const Scene& scene, size_t triangle) {
    return glm::normalize(glm::cross(cornerOf(scene, triangle, 1) - cornerOf(scene, triangle, 0),
                                     cornerOf(scene, triangle, 2) - cornerOf(scene, triangle, 0)));
}

Scene loadBuilt(GltfBuilder& gltf, const LoadOptions& options = {}) {
    TempFolder folder;
    return loadGltf(gltf.writeGltf(folder, "scene").string(), options);
}

// A unit quad (two triangles) with indices of the given component type.
void expectQuadLoadsWithIndexType(int componentType) {
    GltfBuilder gltf;
    const int positions = gltf.addVec3({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    const int indices = gltf.addIndices({0, 1, 2, 0, 2, 3}, componentType);
    gltf.setScene({gltf.addNode({{"mesh", gltf.addMesh({{"POSITION", positions}}, indices)}})});
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.triangleCount(), 2u);
    expectNear(cornerOf(scene, 0, 2), {1, 1, 0});
    expectNear(cornerOf(scene, 1, 2), {0, 1, 0});
    EXPECT_EQ(scene.triangleMaterials.size(), 2u);
}

TEST(GltfLoader, ReadsUnsignedByteIndices) { expectQuadLoadsWithIndexType(TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE); }
TEST(GltfLoader, ReadsUnsignedShortIndices) { expectQuadLoadsWithIndexType(TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT); }
TEST(GltfLoader, ReadsUnsignedIntIndices) { expectQuadLoadsWithIndexType(TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT); }

TEST(GltfLoader, NonIndexedPrimitiveUsesVerticesInOrder) {
    GltfBuilder gltf = test::triangleScene();
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.triangleCount(), 1u);
    expectNear(cornerOf(scene, 0, 0), {0, 0, 0});
    expectNear(cornerOf(scene, 0, 1), {1, 0, 0});
    expectNear(cornerOf(scene, 0, 2), {0, 1, 0});
    expectNear(scene.vertices[scene.indices[0]].normal, {0, 0, 1});
}

TEST(GltfLoader, SceneNameIsThePath) {
    GltfBuilder gltf = test::triangleScene();
    TempFolder folder;
    const std::string path = gltf.writeGltf(folder, "named").string();
    EXPECT_EQ(loadGltf(path).name, path);
}

TEST(GltfLoader, AppliesNodeHierarchyTransforms) {
    GltfBuilder gltf = test::triangleScene();
    // Parent: translate (10,0,0) · rotate 90° about +Y · scale 2. Child: a matrix translating (0,1,0).
    const float half = std::sqrt(0.5f);
    gltf.document["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 1};
    const int parent = gltf.addNode(
        {{"translation", {10, 0, 0}}, {"rotation", {0, half, 0, half}}, {"scale", {2, 2, 2}}, {"children", {0}}});
    gltf.setScene({parent});
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.triangleCount(), 1u);
    // Local (1,0,0) → child (1,1,0) → scaled (2,2,0) → rotated about Y (0,2,−2) → translated (10,2,−2).
    expectNear(cornerOf(scene, 0, 0), {10, 2, 0});
    expectNear(cornerOf(scene, 0, 1), {10, 2, -2});
    expectNear(cornerOf(scene, 0, 2), {10, 4, 0});
    expectNear(scene.vertices[scene.indices[0]].normal, {1, 0, 0});  // +Z rotated 90° about Y
}

TEST(GltfLoader, TransformsNormalsByTheInverseTranspose) {
    GltfBuilder gltf;
    const int positions = gltf.addVec3({{0, 0, 0}, {1, -1, 0}, {0, 0, 1}});
    const glm::vec3 slanted = glm::normalize(glm::vec3(1, 1, 0));
    const int normals = gltf.addVec3({slanted, slanted, slanted});
    const int mesh = gltf.addMesh({{"POSITION", positions}, {"NORMAL", normals}});
    gltf.setScene({gltf.addNode({{"mesh", mesh}, {"scale", {2, 1, 1}}})});
    const Scene scene = loadBuilt(gltf);
    // Stretching x by 2 tilts the surface towards x, so its normal tilts away: (1/2, 1, 0) normalised.
    expectNear(scene.vertices[scene.indices[0]].normal, glm::normalize(glm::vec3(0.5f, 1, 0)));
}

TEST(GltfLoader, NegativeScaleFlipsWindingSoFrontFacesStayFront) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["nodes"][0]["scale"] = {-1, 1, 1};
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.triangleCount(), 1u);
    const glm::vec3 normal = scene.vertices[scene.indices[0]].normal;
    expectNear(normal, {0, 0, 1});  // the inverse transpose of a mirror in x leaves +Z alone
    expectNear(windingNormal(scene, 0), normal);
}

TEST(GltfLoader, TangentsTurnWithTheNodeAndAMirrorTurnsTheirHandednessOver) {
    // A tangent along +x (handedness +1) under a node turned 90° about z: along +y. Mirrored in x
    // first (glTF scales before it rotates): along -y, and its handedness turned over, so that the
    // bitangent cross(normal, tangent)·w is still the transformed file's, R·S·(+y) = -x.
    for (const bool mirrored : {false, true}) {
        GltfBuilder gltf;
        const int positions = gltf.addVec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
        const int normals = gltf.addVec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
        const int tangents = gltf.addVec4({{2, 0, 0, 1}, {1, 0, 0, 1}, {1, 0, 0, 1}});  // not unit: normalized
        const int mesh = gltf.addMesh({{"POSITION", positions}, {"NORMAL", normals}, {"TANGENT", tangents}});
        json node = {{"mesh", mesh}, {"rotation", {0, 0, std::sqrt(0.5), std::sqrt(0.5)}}};  // 90° about z
        if (mirrored) node["scale"] = {-1, 1, 1};
        gltf.setScene({gltf.addNode(node)});
        const Scene scene = loadBuilt(gltf);
        ASSERT_EQ(scene.vertices.size(), 3u);
        for (const Vertex& vertex : scene.vertices) {
            expectNear(glm::vec3(vertex.tangent), {0, mirrored ? -1.0f : 1.0f, 0});
            EXPECT_EQ(vertex.tangent.w, mirrored ? -1.0f : 1.0f);
            expectNear(vertex.normal, {0, 0, 1});
            expectNear(glm::cross(vertex.normal, glm::vec3(vertex.tangent)) * vertex.tangent.w, {-1, 0, 0});
        }
    }
}

TEST(GltfLoader, TangentsWithoutNormalsAreIgnored) {
    // glTF 2.0 §3.7.2.1: flat normals are generated, and the tangents the file gives are not used.
    GltfBuilder gltf;
    const int positions = gltf.addVec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int tangents = gltf.addVec4({{1, 0, 0, 1}, {1, 0, 0, 1}, {1, 0, 0, 1}});
    gltf.setScene({gltf.addNode({{"mesh", gltf.addMesh({{"POSITION", positions}, {"TANGENT", tangents}})}})});
    const Scene scene = loadBuilt(gltf);
    for (const Vertex& vertex : scene.vertices) EXPECT_EQ(vertex.tangent, glm::vec4(0.0f));
}

TEST(GltfLoader, GeneratesFlatNormalsWhenNormalsAreMissing) {
    GltfBuilder gltf;
    // Two triangles folded along the x axis: one in the floor (y = 0), one in the wall (z = 0).
    const int positions = gltf.addVec3({{0, 0, 0}, {1, 0, 0}, {0, 0, -1}, {0, 1, 0}});
    const int indices = gltf.addIndices({0, 1, 2, 0, 3, 1});
    gltf.setScene({gltf.addNode({{"mesh", gltf.addMesh({{"POSITION", positions}}, indices)}})});
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.triangleCount(), 2u);
    EXPECT_EQ(scene.vertices.size(), 6u) << "flat shading needs unshared vertices";
    for (size_t corner = 0; corner < 3; ++corner) {
        expectNear(scene.vertices[scene.indices[corner]].normal, {0, 1, 0});
        expectNear(scene.vertices[scene.indices[3 + corner]].normal, {0, 0, -1});
    }
    expectNear(windingNormal(scene, 0), {0, 1, 0});
}

TEST(GltfLoader, ReadsNormalizedIntegerTexcoords) {
    GltfBuilder gltf = test::triangleScene();
    const std::vector<uint8_t> bytes = {0, 255, 255, 0, 51, 102};
    const int uv8 = gltf.addAccessor(bytes, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, "VEC2", 3, true);
    gltf.document["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = uv8;
    Scene scene = loadBuilt(gltf);
    EXPECT_NEAR(scene.vertices[0].u, 0.0f, kTolerance);
    EXPECT_NEAR(scene.vertices[0].v, 1.0f, kTolerance);
    EXPECT_NEAR(scene.vertices[2].u, 0.2f, kTolerance);
    EXPECT_NEAR(scene.vertices[2].v, 0.4f, kTolerance);

    const std::vector<uint16_t> shorts = {65535, 0, 0, 65535, 13107, 26214};
    const int uv16 = gltf.addAccessor(shorts, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, "VEC2", 3, true);
    gltf.document["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = uv16;
    scene = loadBuilt(gltf);
    EXPECT_NEAR(scene.vertices[0].u, 1.0f, kTolerance);
    EXPECT_NEAR(scene.vertices[2].v, 0.4f, kTolerance);
}

TEST(GltfLoader, ReadsInterleavedAttributesThroughByteStride) {
    GltfBuilder gltf;
    // position xyz + uv per vertex, 20 bytes apart.
    const std::vector<float> interleaved = {0, 0, 0, 0.1f, 0.2f, 1, 0, 0, 0.3f, 0.4f, 0, 1, 0, 0.5f, 0.6f};
    const int view = gltf.addBufferView(interleaved.data(), interleaved.size() * sizeof(float), 20);
    const int positions =
        gltf.append("accessors", {{"bufferView", view}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
    const int uvs = gltf.append(
        "accessors",
        {{"bufferView", view}, {"byteOffset", 12}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}});
    gltf.setScene({gltf.addNode({{"mesh", gltf.addMesh({{"POSITION", positions}, {"TEXCOORD_0", uvs}})}})});
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.triangleCount(), 1u);
    const Vertex& last = scene.vertices[scene.indices[2]];
    expectNear(last.position, {0, 1, 0});
    EXPECT_NEAR(last.u, 0.5f, kTolerance);
    EXPECT_NEAR(last.v, 0.6f, kTolerance);
}

TEST(GltfLoader, SparseAccessorReplacesListedElements) {
    GltfBuilder gltf = test::triangleScene();
    const std::vector<uint8_t> which = {2};
    const std::vector<float> moved = {0, 5, 0};
    const int indexView = gltf.addBufferView(which.data(), which.size());
    const int valueView = gltf.addBufferView(moved.data(), moved.size() * sizeof(float));
    gltf.document["accessors"][0]["sparse"] = {
        {"count", 1},
        {"indices", {{"bufferView", indexView}, {"componentType", TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE}}},
        {"values", {{"bufferView", valueView}}}};
    const Scene scene = loadBuilt(gltf);
    expectNear(cornerOf(scene, 0, 1), {1, 0, 0});
    expectNear(cornerOf(scene, 0, 2), {0, 5, 0});
}

TEST(GltfLoader, ConvertsTriangleStripsAndFans) {
    GltfBuilder gltf;
    const int positions = gltf.addVec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
    const int strip = gltf.addMesh({{"POSITION", positions}}, -1, -1, TINYGLTF_MODE_TRIANGLE_STRIP);
    const int fan = gltf.addMesh({{"POSITION", positions}}, -1, -1, TINYGLTF_MODE_TRIANGLE_FAN);
    gltf.setScene({gltf.addNode({{"mesh", strip}}), gltf.addNode({{"mesh", fan}})});
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.triangleCount(), 4u);
    // Both strip triangles and the first fan triangle (v1, v2, v0) face +Z, as the vertices were listed.
    for (size_t triangle = 0; triangle < 3; ++triangle) expectNear(windingNormal(scene, triangle), {0, 0, 1});
}

TEST(GltfLoader, SkipsPointsAndLinesWithAWarning) {
    GltfBuilder gltf = test::triangleScene();
    const int points = gltf.addMesh({{"POSITION", 0}}, -1, -1, TINYGLTF_MODE_POINTS);
    gltf.document["scenes"][0]["nodes"].push_back(gltf.addNode({{"mesh", points}}));
    const Scene scene = loadBuilt(gltf);
    EXPECT_EQ(scene.triangleCount(), 1u);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("meshes[1].primitives[0].mode"), std::string::npos) << scene.warnings[0];
}

TEST(GltfLoader, SkipsPrimitivesWithoutPositionWithAWarning) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["meshes"][0]["primitives"][0]["attributes"].erase("POSITION");
    const Scene scene = loadBuilt(gltf);
    EXPECT_EQ(scene.triangleCount(), 0u);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("meshes[0].primitives[0].attributes: has no POSITION"), std::string::npos)
        << scene.warnings[0];
}

TEST(GltfLoader, LoadsOnlyTheDefaultScene) {
    GltfBuilder gltf = test::triangleScene();
    const int moved = gltf.addNode({{"mesh", 0}, {"translation", {0, 0, 7}}});
    gltf.document["scenes"].push_back({{"nodes", {moved}}});
    gltf.document["scene"] = 1;
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.triangleCount(), 1u);
    EXPECT_NEAR(cornerOf(scene, 0, 0).z, 7.0f, kTolerance);
}

TEST(GltfLoader, WithoutScenesLoadsEveryRootNode) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document.erase("scenes");
    gltf.document.erase("scene");
    const int child = gltf.addNode({{"mesh", 0}});
    gltf.addNode({{"mesh", 0}, {"children", {child}}});
    EXPECT_EQ(loadBuilt(gltf).triangleCount(), 3u);  // node 0, node 2 and its child
}

TEST(GltfLoader, ConvertsMaterialFactorsAndExtensions) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["materials"] = json::array(
        {{{"name", "glowing"},
          {"pbrMetallicRoughness",
           {{"baseColorFactor", {0.5, 0.25, 0.125, 1.0}}, {"metallicFactor", 0.3}, {"roughnessFactor", 0.7}}},
          {"emissiveFactor", {1.0, 0.5, 0.0}},
          {"doubleSided", true},
          {"extensions",
           {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}},
            {"KHR_materials_specular", {{"specularFactor", 0.0}}}}}}});
    gltf.document["meshes"][0]["primitives"][0]["material"] = 0;
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.materials.size(), 1u);
    const Material& material = scene.materials[0];
    EXPECT_EQ(material.name, "glowing");
    EXPECT_FLOAT_EQ(material.baseColorFactor.g, 0.25f);
    EXPECT_FLOAT_EQ(material.baseColorFactor.b, 0.125f);
    EXPECT_FLOAT_EQ(material.metallic, 0.3f);
    EXPECT_FLOAT_EQ(material.roughness, 0.7f);
    expectNear(material.emission, {4.0f, 2.0f, 0.0f});
    EXPECT_FLOAT_EQ(material.specularWeight, 0.0f);
    EXPECT_TRUE(material.doubleSided);
    EXPECT_EQ(material.baseColorTexture.index, -1);
    EXPECT_EQ(scene.triangleMaterials[0], 0u);
}

TEST(GltfLoader, PrimitivesWithoutMaterialGetTheDefaultMaterial) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["materials"] = json::array({{{"name", "unused"}}});
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.triangleMaterials[0], 1u);
    const Material& fallback = scene.materials[1];
    EXPECT_EQ(fallback.baseColorFactor, glm::vec4(1.0f));
    EXPECT_EQ(fallback.metallic, 1.0f);
    EXPECT_EQ(fallback.roughness, 1.0f);
}

TEST(GltfLoader, MaterialsAreNeverEmpty) {
    GltfBuilder gltf;
    gltf.setScene({gltf.addNode({{"name", "empty"}})});
    const Scene scene = loadBuilt(gltf);
    EXPECT_EQ(scene.triangleCount(), 0u);
    EXPECT_EQ(scene.materials.size(), 1u);
}

TEST(GltfLoader, PlacesPerspectiveCameraInWorldSpace) {
    GltfBuilder gltf;
    gltf.document["cameras"] =
        json::array({{{"type", "perspective"}, {"name", "main"}, {"perspective", {{"yfov", 0.6}, {"znear", 0.05}}}},
                     {{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}, {"zfar", 100.0}}}}});
    const float half = std::sqrt(0.5f);
    // Turned 90° about +Y: local −Z (forward) becomes world −X.
    const int first = gltf.addNode({{"camera", 0}, {"translation", {1, 2, 3}}, {"rotation", {0, half, 0, half}}});
    const int second = gltf.addNode({{"camera", 1}, {"scale", {1, 3, 1}}});
    gltf.setScene({first, second});
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.cameras.size(), 2u);
    const Camera& camera = scene.cameras[0];
    EXPECT_EQ(camera.name, "main");
    expectNear(camera.position, {1, 2, 3});
    expectNear(camera.forward, {-1, 0, 0});
    expectNear(camera.up, {0, 1, 0});
    EXPECT_FLOAT_EQ(camera.yfov, 0.6f);
    EXPECT_FLOAT_EQ(camera.znear, 0.05f);
    EXPECT_EQ(camera.zfar, 0.0f) << "an absent zfar means an infinite projection";
    expectNear(scene.cameras[1].up, {0, 1, 0});  // a scaled axis is normalised
    EXPECT_FLOAT_EQ(scene.cameras[1].zfar, 100.0f);
}

TEST(GltfLoader, SkipsOrthographicCamerasWithAWarning) {
    GltfBuilder gltf;
    gltf.document["cameras"] = json::array(
        {{{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}}});
    gltf.setScene({gltf.addNode({{"camera", 0}})});
    const Scene scene = loadBuilt(gltf);
    EXPECT_TRUE(scene.cameras.empty());
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("orthographic"), std::string::npos);
}

// One light of the given JSON on a node turned 90° about +X (local −Z → world +Y) at (4,5,6).
Scene sceneWithLight(const json& light) {
    GltfBuilder gltf;
    gltf.document["extensionsUsed"] = {"KHR_lights_punctual"};
    gltf.document["extensions"] = {{"KHR_lights_punctual", {{"lights", json::array({light})}}}};
    const float half = std::sqrt(0.5f);
    gltf.setScene({gltf.addNode({{"translation", {4, 5, 6}},
                                 {"rotation", {half, 0, 0, half}},
                                 {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}})});
    return loadBuilt(gltf);
}

TEST(GltfLoader, PlacesDirectionalLightAlongNodeMinusZ) {
    const Scene scene =
        sceneWithLight({{"type", "directional"}, {"color", {1.0, 0.9, 0.8}}, {"intensity", 3.5}, {"name", "sun"}});
    ASSERT_EQ(scene.lights.size(), 1u);
    const Light& light = scene.lights[0];
    EXPECT_EQ(light.type, LightType::Directional);
    EXPECT_EQ(light.name, "sun");
    EXPECT_FLOAT_EQ(light.intensity, 3.5f) << "lux, as KHR_lights_punctual defines it";
    expectNear(light.color, {1.0f, 0.9f, 0.8f});
    expectNear(light.direction, {0, 1, 0});
}

TEST(GltfLoader, PlacesPointLightAtNodeTranslation) {
    const Scene scene = sceneWithLight({{"type", "point"}, {"intensity", 20.0}, {"range", 8.0}});
    ASSERT_EQ(scene.lights.size(), 1u);
    const Light& light = scene.lights[0];
    EXPECT_EQ(light.type, LightType::Point);
    EXPECT_FLOAT_EQ(light.intensity, 20.0f) << "candela";
    EXPECT_FLOAT_EQ(light.range, 8.0f);
    expectNear(light.position, {4, 5, 6});
    expectNear(light.color, {1, 1, 1});  // the glTF default
}

TEST(GltfLoader, PlacesSpotLightWithConeAngles) {
    const Scene scene = sceneWithLight(
        {{"type", "spot"}, {"intensity", 100.0}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}});
    ASSERT_EQ(scene.lights.size(), 1u);
    const Light& light = scene.lights[0];
    EXPECT_EQ(light.type, LightType::Spot);
    expectNear(light.position, {4, 5, 6});
    expectNear(light.direction, {0, 1, 0});
    EXPECT_FLOAT_EQ(light.innerConeAngle, 0.2f);
    EXPECT_FLOAT_EQ(light.outerConeAngle, 0.5f);
    EXPECT_FLOAT_EQ(sceneWithLight({{"type", "spot"}, {"spot", json::object()}}).lights[0].outerConeAngle, kPi / 4)
        << "the glTF default outer cone";
}

TEST(GltfLoader, LoadsBinaryGlb) {
    GltfBuilder gltf = test::triangleScene();
    TempFolder folder;
    const Scene scene = loadGltf(gltf.writeGlb(folder, "scene").string());
    ASSERT_EQ(scene.triangleCount(), 1u);
    expectNear(cornerOf(scene, 0, 1), {1, 0, 0});
}

TEST(GltfLoader, LoadsBuffersFromDataUris) {
    GltfBuilder gltf = test::triangleScene();
    TempFolder folder;
    const Scene scene = loadGltf(gltf.writeGltf(folder, "scene", GltfBuilder::BufferStorage::DataUri).string());
    ASSERT_EQ(scene.triangleCount(), 1u);
    expectNear(cornerOf(scene, 0, 2), {0, 1, 0});
    EXPECT_FALSE(std::filesystem::exists(folder.path / "scene.bin"));
}

TEST(GltfLoader, DecodesPercentEncodedUris) {
    GltfBuilder gltf = test::triangleScene();
    TempFolder folder;
    folder.write("my mesh+data.bin", gltf.bin);
    gltf.document["buffers"] = json::array({{{"uri", "my%20mesh%2Bdata.bin"}, {"byteLength", gltf.bin.size()}}});
    const std::string path = folder.write("scene.gltf", gltf.document.dump()).string();
    EXPECT_EQ(loadGltf(path).triangleCount(), 1u);
}

// The triangle with material 0 whose base colour texture is image `uri`.
GltfBuilder texturedTriangle(const std::string& uri) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["images"] = json::array({{{"uri", uri}}});
    gltf.document["textures"] = json::array({{{"source", 0}}});
    gltf.document["materials"] = json::array(
        {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"baseColorFactor", {1, 0, 0, 1}}}}}});
    gltf.document["meshes"][0]["primitives"][0]["material"] = 0;
    return gltf;
}

TEST(GltfLoader, DecodesEightBitPngBaseColorTexture) {
    GltfBuilder gltf = texturedTriangle("albedo.png");
    TempFolder folder;
    folder.write("albedo.png", test::encodePng(2, 1, 4, 8, {255, 0, 0, 255, 10, 20, 30, 40}));
    const Scene scene = loadGltf(gltf.writeGltf(folder, "scene").string());
    ASSERT_EQ(scene.textures.size(), 1u);
    ASSERT_EQ(scene.materials[0].baseColorTexture.index, 0);
    const Texture& texture = scene.textures[0];
    EXPECT_EQ(texture.width, 2u);
    EXPECT_EQ(texture.height, 1u);
    EXPECT_EQ(texture.rgba8, (std::vector<uint8_t>{255, 0, 0, 255, 10, 20, 30, 40}));
    EXPECT_TRUE(scene.warnings.empty());
}

TEST(GltfLoader, ReducesSixteenBitPngTo8BitRgba) {
    GltfBuilder gltf = texturedTriangle("deep.png");
    TempFolder folder;
    folder.write("deep.png", test::encodePng(1, 1, 3, 16, {0xFFFF, 0x8080, 0x0000}));
    const Scene scene = loadGltf(gltf.writeGltf(folder, "scene").string());
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.textures[0].rgba8, (std::vector<uint8_t>{255, 128, 0, 255}));
}

TEST(GltfLoader, DecodesTextureEmbeddedInGlb) {
    GltfBuilder gltf = texturedTriangle("unused");
    const std::string png = test::encodePng(1, 1, 4, 8, {1, 2, 3, 4});
    gltf.document["images"][0] = {{"bufferView", gltf.addBufferView(png.data(), png.size())},
                                  {"mimeType", "image/png"}};
    TempFolder folder;
    const Scene scene = loadGltf(gltf.writeGlb(folder, "scene").string());
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.materials[0].baseColorTexture.index, 0);
    EXPECT_EQ(scene.textures[0].rgba8, (std::vector<uint8_t>{1, 2, 3, 4}));
}

// ---- Decompression bombs: decoded bytes are budgeted from the headers, and each image decoded once.

// `count` materials, each with a base colour texture of its own naming image `uris[i % uris.size()]`.
GltfBuilder manyTexturedMaterials(size_t count, const std::vector<std::string>& uris) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["images"] = json::array();
    gltf.document["textures"] = json::array();
    gltf.document["materials"] = json::array();
    for (size_t i = 0; i < count; ++i) {
        gltf.document["images"].push_back({{"uri", uris[i % uris.size()]}});
        gltf.document["textures"].push_back({{"source", i}});
        gltf.document["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", i}}}}}});
    }
    return gltf;
}

// A PNG whose header claims width × height but which holds one pixel: what its header says is all
// a budget check before decoding may see, and decoding it would fail. Its header's CRC is right.
std::string pngClaiming(uint32_t width, uint32_t height) {
    std::string png = test::encodePng(1, 1, 4, 8, {1, 2, 3, 4});
    // The header chunk after the signature: 4 + 4 + 13 + 4 bytes, its last 5 data bytes kept.
    const std::string header = test::bigEndian32(width) + test::bigEndian32(height) + png.substr(24, 5);
    return png.replace(8, 25, test::pngChunk("IHDR", header));
}

TEST(GltfLoader, ImageNamedByManyEntriesIsDecodedOnce) {
    // 64 entries name one 64×64 PNG (16 KiB decoded), under a budget of 20 KiB: decoded 64 times
    // they would need 1 MiB. A data URI named twice and a GLB buffer view named twice likewise.
    TempFolder folder;
    std::vector<uint16_t> samples(64 * 64 * 4, 200);
    const std::string png = test::encodePng(64, 64, 4, 8, samples);
    folder.write("same.png", png);
    LoadOptions options;
    options.bufferLimits.maxDecodedImageBytes = 20 << 10;
    for (const std::string& uri : {std::string("same.png"), "data:image/png;base64," + test::base64(png)}) {
        GltfBuilder gltf = manyTexturedMaterials(64, {uri});
        const Scene scene = loadGltf(gltf.writeGltf(folder, "scene").string(), options);
        ASSERT_EQ(scene.textures.size(), 1u);
        EXPECT_EQ(scene.textures[0].rgba8.size(), 64u * 64 * 4);
        ASSERT_GE(scene.materials.size(), 64u);  // and the default material of the untextured triangle
        for (size_t i = 0; i < 64; ++i) EXPECT_EQ(scene.materials[i].baseColorTexture.index, 0);
        EXPECT_TRUE(scene.warnings.empty());
    }
    GltfBuilder gltf = manyTexturedMaterials(8, {"unused"});
    const int view = gltf.addBufferView(png.data(), png.size());
    for (json& image : gltf.document["images"]) image = {{"bufferView", view}, {"mimeType", "image/png"}};
    const Scene scene = loadGltf(gltf.writeGlb(folder, "scene").string(), options);
    EXPECT_EQ(scene.textures.size(), 1u);
}

TEST(GltfLoader, APngWhoseChunkRunsPastItsEndIsACorruptImageNotAnAllocation) {
    // A valid 2×2 PNG whose image-data chunk header then claims 1.5 GB: stb_image grew its buffer to
    // that before finding the bytes missing (the fuzzer's find); libpng reads the chunk as it comes.
    // The texture is dropped with a warning saying so, as an image it cannot decode is.
    TempFolder folder;
    std::string png = test::encodePng(2, 2, 4, 8, std::vector<uint16_t>(16, 200));
    const size_t idat = png.find("IDAT");
    ASSERT_NE(idat, std::string::npos);
    png.replace(idat - 4, 4, std::string("\x5d\x00\x00\x11", 4));
    GltfBuilder gltf = manyTexturedMaterials(1, {"data:image/png;base64," + test::base64(png)});
    const Scene scene = loadGltf(gltf.writeGltf(folder, "scene").string());
    EXPECT_TRUE(scene.textures.empty());
    ASSERT_FALSE(scene.warnings.empty());
    EXPECT_NE(scene.warnings[0].find("corrupt PNG: the data ends inside the image"), std::string::npos)
        << scene.warnings[0];
}

TEST(GltfLoader, DecodedImagesOverTheBudgetAreRefusedFromTheirHeaders) {
    // Five files of a few dozen bytes whose headers claim 8192² pixels, 256 MiB each decoded: the
    // fifth would bring the scene's images past the default budget of 1 GiB, and the header says so
    // before anything is decoded.
    TempFolder folder;
    std::vector<std::string> uris;
    for (int i = 0; i < 5; ++i) {
        uris.push_back("bomb" + std::to_string(i) + ".png");
        folder.write(uris.back(), pngClaiming(8192, 8192));
    }
    GltfBuilder gltf = manyTexturedMaterials(5, uris);
    const std::string path = gltf.writeGltf(folder, "scene").string();
    try {
        loadGltf(path);
        FAIL() << "expected vct::Error";
    } catch (const Error& error) {
        EXPECT_EQ(std::string(error.what()),
                  path +
                      ": images[4] ('bomb4.png', 8192×8192) would bring the decoded images to 1280 MiB, over the "
                      "budget of 1024 MiB for one scene's images");
    }
    // Real pixels under a small budget: the second distinct 64×64 image (16 KiB each) is one too many.
    const std::vector<uint16_t> samples(64 * 64 * 4, 100);
    folder.write("a.png", test::encodePng(64, 64, 4, 8, samples));
    folder.write("b.png", test::encodePng(64, 64, 4, 8, std::vector<uint16_t>(64 * 64 * 4, 50)));
    LoadOptions options;
    options.bufferLimits.maxDecodedImageBytes = 20 << 10;
    GltfBuilder two = manyTexturedMaterials(2, {"a.png", "b.png"});
    try {
        loadGltf(two.writeGltf(folder, "two").string(), options);
        FAIL() << "expected vct::Error";
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what())
                      .find("images[1] ('b.png', 64×64) would bring the decoded images to 32 KiB, "
                            "over the budget of 20 KiB"),
                  std::string::npos)
            << error.what();
    }
}

TEST(GltfLoader, DecodedImageBudgetScalesWithTheDevicesMemory) {
    EXPECT_EQ(decodedImageBudget(uint64_t(2) << 30), uint64_t(512) << 20);  // a 2 GiB GPU: a quarter
    EXPECT_EQ(decodedImageBudget(uint64_t(64) << 30), uint64_t(1) << 30);   // at most 1 GiB
}

TEST(GltfLoader, MissingTextureWarnsAndFallsBackToTheFactor) {
    GltfBuilder gltf = texturedTriangle("missing.png");
    TempFolder folder;
    const std::string path = gltf.writeGltf(folder, "scene").string();
    const Scene scene = loadGltf(path);
    EXPECT_EQ(scene.materials[0].baseColorTexture.index, -1);
    EXPECT_EQ(scene.materials[0].baseColorFactor, glm::vec4(1, 0, 0, 1));
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find(path), std::string::npos) << scene.warnings[0];
    EXPECT_NE(scene.warnings[0].find("missing.png"), std::string::npos) << scene.warnings[0];
}

TEST(GltfLoader, CorruptTextureWarnsAndFallsBackToTheFactor) {
    GltfBuilder gltf = texturedTriangle("corrupt.png");
    TempFolder folder;
    folder.write("corrupt.png", "\x89PNG but not really");
    const Scene scene = loadGltf(gltf.writeGltf(folder, "scene").string());
    EXPECT_EQ(scene.materials[0].baseColorTexture.index, -1);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("corrupt.png"), std::string::npos) << scene.warnings[0];
}

TEST(GltfLoader, StrictLoadingTurnsAMissingTextureIntoAnError) {
    GltfBuilder gltf = texturedTriangle("missing.png");
    TempFolder folder;
    const std::string path = gltf.writeGltf(folder, "scene").string();
    LoadOptions strict;
    strict.strict = true;
    try {
        loadGltf(path, strict);
        FAIL() << "expected vct::Error";
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find("missing.png"), std::string::npos) << error.what();
        EXPECT_EQ(std::string(error.what()).rfind(path, 0), 0u) << error.what();
    }
}

TEST(GltfLoader, WarnsAboutIgnoredExtensions) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["extensionsUsed"] = {"KHR_materials_clearcoat", "KHR_materials_specular"};
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("KHR_materials_clearcoat"), std::string::npos);
}

}  // namespace
}  // namespace vct
