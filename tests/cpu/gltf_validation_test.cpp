// What loadGltf refuses: each bad file throws one vct::Error naming the file and the problem.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>

#include "error.h"
#include "gltf_test_helpers.h"
#include "scene/load.h"

namespace vct {
namespace {

using test::GltfBuilder;
using test::json;
using test::TempFolder;

// Loads `path` and returns the message of the vct::Error it must throw ("" if none was thrown).
std::string loadError(const std::string& path, const LoadOptions& options = {}) {
    try {
        loadGltf(path, options);
    } catch (const Error& error) {
        return error.what();
    } catch (const std::exception& error) {
        return std::string("not a vct::Error: ") + error.what();
    }
    return "";
}

// Expects that loading `path` fails with a message that starts with the path and contains `problem`.
void expectRefused(const std::string& path, const std::string& problem, const LoadOptions& options = {}) {
    const std::string message = loadError(path, options);
    ASSERT_FALSE(message.empty()) << "loading " << path << " should have failed";
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << "expected '" << problem << "' in: " << message;
}

void expectRefused(GltfBuilder& gltf, const std::string& problem) {
    TempFolder folder;
    expectRefused(gltf.writeGltf(folder, "scene").string(), problem);
}

TEST(GltfValidation, MissingFileIsRefused) {
    TempFolder folder;
    expectRefused((folder.path / "nowhere.gltf").string(), "file not found");
}

TEST(GltfValidation, SceneFileThatIsADirectoryIsRefused) {
    TempFolder folder;
    std::filesystem::create_directory(folder.path / "folder.gltf");
    expectRefused((folder.path / "folder.gltf").string(), "is a directory");
}

TEST(GltfValidation, SceneFileOverTheSizeLimitIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    TempFolder folder;
    LoadOptions options;
    options.maxFileBytes = 100;
    expectRefused(gltf.writeGltf(folder, "scene").string(), "over the limit of 100 bytes", options);
}

TEST(GltfValidation, BrokenJsonReportsTheParserMessage) {
    TempFolder folder;
    const std::string path = folder.write("broken.gltf", R"({"asset": {"version": "2.0"}, "nodes": [)").string();
    expectRefused(path, "not a valid glTF file: ");
    expectRefused(path, "parse error at line 1, column 41");
}

TEST(GltfValidation, EmptyFileIsRefused) {
    TempFolder folder;
    expectRefused(folder.write("empty.gltf", "").string(), "not a valid glTF file: JSON string too short");
}

TEST(GltfValidation, AccessorRunningPastItsBufferViewIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["accessors"][0]["count"] = 1000000;
    expectRefused(gltf, "accessors[0]: 1000000 elements of 12 bytes");
}

TEST(GltfValidation, BufferViewRunningPastItsBufferIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["bufferViews"][1]["byteLength"] = 4096;
    TempFolder folder;
    expectRefused(gltf.writeGlb(folder, "scene").string(),
                  "bufferViews[1]: bytes 36 to 4132 run past the end of buffer 0");
}

TEST(GltfValidation, BufferFileShorterThanItsByteLengthIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    TempFolder folder;
    const std::string path = gltf.writeGltf(folder, "scene").string();
    folder.write("scene.bin", gltf.bin.substr(0, 20));
    expectRefused(path, "buffers[0]: 'scene.bin' holds 20 bytes, fewer than its byteLength 72");
}

TEST(GltfValidation, IndexPastTheVertexCountIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["meshes"][0]["primitives"][0]["indices"] = gltf.addIndices({0, 1, 97});
    expectRefused(gltf, "meshes[0].primitives[0].indices: index 97 is past the vertex count 3");
}

TEST(GltfValidation, AttributeNamingAMissingAccessorIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 42;
    expectRefused(gltf, "meshes[0].primitives[0].attributes.TEXCOORD_0: accessor 42 does not exist");
}

TEST(GltfValidation, AttributeOfAComponentTypeGltfForbidsIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    const int positions =
        gltf.addAccessor(std::vector<uint32_t>(9, 0), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, "VEC3", 3);
    gltf.document["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = positions;
    expectRefused(gltf, "VEC3 of UNSIGNED_INT, which glTF does not allow for POSITION");
}

TEST(GltfValidation, AttributesOfDifferentCountsAreRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = gltf.addVec2({{0, 0}});
    expectRefused(gltf, "TEXCOORD_0: has 1 elements but POSITION has 3");
}

TEST(GltfValidation, NodeCycleIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    const int first = gltf.addNode({{"children", {2}}});
    gltf.addNode({{"children", {first}}});
    expectRefused(gltf, "the node hierarchy has a cycle");
}

TEST(GltfValidation, NodeThatIsItsOwnChildIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["nodes"][0]["children"] = {0};
    expectRefused(gltf, "nodes[0]");
}

TEST(GltfValidation, NodeWithTwoParentsIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["scenes"][0]["nodes"] = {gltf.addNode({{"children", {0}}}), gltf.addNode({{"children", {0}}})};
    expectRefused(gltf, "nodes[2].children[0]: node 0 already has parent node 1");
}

TEST(GltfValidation, SceneNamingAMissingNodeIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["scenes"][0]["nodes"].push_back(9);
    expectRefused(gltf, "scenes[0].nodes[1]: node 9 does not exist");
}

TEST(GltfValidation, NodeNamingAMissingMeshIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["nodes"][0]["mesh"] = 3;
    expectRefused(gltf, "nodes[0].mesh: mesh 3 does not exist");
}

TEST(GltfValidation, NanPositionIsRefused) {
    GltfBuilder gltf;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const int positions = gltf.addVec3({{0, 0, 0}, {1, 0, 0}, {0, nan, 0}});
    gltf.setScene({gltf.addNode({{"mesh", gltf.addMesh({{"POSITION", positions}})}})});
    expectRefused(gltf, "meshes[0].primitives[0].attributes.POSITION: element 2 holds nan");
}

TEST(GltfValidation, InfinitePositionIsRefused) {
    GltfBuilder gltf;
    const float infinity = std::numeric_limits<float>::infinity();
    const int positions = gltf.addVec3({{infinity, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    gltf.setScene({gltf.addNode({{"mesh", gltf.addMesh({{"POSITION", positions}})}})});
    expectRefused(gltf, "element 0 holds inf, not a finite number");
}

TEST(GltfValidation, NanNormalAndInfiniteTexcoordAreRefused) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float infinity = std::numeric_limits<float>::infinity();
    {
        GltfBuilder gltf;
        const int positions = gltf.addVec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
        const int normals = gltf.addVec3({{0, 0, 1}, {nan, 0, 1}, {0, 0, 1}});
        gltf.setScene({gltf.addNode({{"mesh", gltf.addMesh({{"POSITION", positions}, {"NORMAL", normals}})}})});
        expectRefused(gltf, "attributes.NORMAL: element 1 holds nan");
    }
    {
        GltfBuilder gltf;
        const int positions = gltf.addVec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
        const int normals = gltf.addVec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
        const int tangents = gltf.addVec4({{1, 0, 0, 1}, {1, 0, 0, 1}, {1, 0, 0, nan}});
        gltf.setScene({gltf.addNode(
            {{"mesh", gltf.addMesh({{"POSITION", positions}, {"NORMAL", normals}, {"TANGENT", tangents}})}})});
        expectRefused(gltf, "attributes.TANGENT: element 2 holds nan");
    }
    GltfBuilder gltf;
    const int positions = gltf.addVec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int uvs = gltf.addVec2({{0, 0}, {1, 0}, {0, -infinity}});
    gltf.setScene({gltf.addNode({{"mesh", gltf.addMesh({{"POSITION", positions}, {"TEXCOORD_0", uvs}})}})});
    expectRefused(gltf, "attributes.TEXCOORD_0: element 2 holds -inf");
}

TEST(GltfValidation, ZeroLengthNormalsLoadAsTheyAre) {
    // Not an error: the renderer's G-buffer falls back to the triangle's plane (tests/gpu/stress_test.cpp).
    GltfBuilder gltf;
    const int positions = gltf.addVec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int normals = gltf.addVec3({{0, 0, 0}, {0, 0, 0}, {0, 0, 0}});
    gltf.setScene({gltf.addNode({{"mesh", gltf.addMesh({{"POSITION", positions}, {"NORMAL", normals}})}})});
    test::TempFolder folder;
    const Scene scene = loadGltf(gltf.writeGltf(folder, "scene").string());
    ASSERT_EQ(scene.vertices.size(), 3u);
    for (const Vertex& vertex : scene.vertices) {
        EXPECT_TRUE(std::isfinite(vertex.normal.x) && std::isfinite(vertex.normal.y) && std::isfinite(vertex.normal.z));
    }
}

TEST(GltfValidation, MalformedNodeTransformIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["nodes"][0]["matrix"] = {1, 0, 0, 1};
    expectRefused(gltf, "nodes[0].matrix: has 4 numbers, expected 16");
    gltf.document["nodes"][0].erase("matrix");
    gltf.document["nodes"][0]["rotation"] = {0, 0, 0, 0};
    expectRefused(gltf, "nodes[0].rotation: is not a unit quaternion");
}

TEST(GltfValidation, CameraFieldOfViewOutsideZeroToPiIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["cameras"] =
        json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 4.0}, {"znear", 0.1}}}}});
    gltf.document["nodes"][0]["camera"] = 0;
    expectRefused(gltf, "cameras[0].perspective.yfov: 4 is not an angle in (0, π)");
}

TEST(GltfValidation, CameraWithZeroNearPlaneIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["cameras"] =
        json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.0}}}}});
    expectRefused(gltf, "cameras[0].perspective.znear");
}

TEST(GltfValidation, NegativeLightIntensityIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["extensions"] = {
        {"KHR_lights_punctual", {{"lights", json::array({{{"type", "point"}, {"intensity", -5.0}}})}}}};
    expectRefused(gltf, "extensions.KHR_lights_punctual.lights[0].intensity: -5 is negative");
}

TEST(GltfValidation, SpotConeWiderThanAHemisphereIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["extensions"] = {
        {"KHR_lights_punctual", {{"lights", json::array({{{"type", "spot"}, {"spot", {{"outerConeAngle", 2.0}}}}})}}}};
    expectRefused(gltf, "lights[0].spot.outerConeAngle");
}

TEST(GltfValidation, NodeNamingAMissingLightIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", 5}}}};
    expectRefused(gltf, "nodes[0].extensions.KHR_lights_punctual.light: light 5 does not exist");
}

TEST(GltfValidation, LightOrEmissionBrighterThanFloatsCarryIsRefused) {
    // Accepted, a light of 1e38 rendered NaN and infinite pixels with exit status 0.
    GltfBuilder light = test::triangleScene();
    light.document["extensions"] = {
        {"KHR_lights_punctual", {{"lights", json::array({{{"type", "point"}, {"intensity", 1e38}}})}}}};
    expectRefused(light,
                  "extensions.KHR_lights_punctual.lights[0].intensity: 1e+38 times its colour is 1e+38, "
                  "brighter than this renderer represents (1e+20)");
    GltfBuilder colour = test::triangleScene();
    colour.document["extensions"] = {
        {"KHR_lights_punctual",
         {{"lights", json::array({{{"type", "point"}, {"intensity", 10.0}, {"color", {1.0, 1e38, 1.0}}}})}}}};
    expectRefused(colour, "times its colour is 1e+39");
    GltfBuilder emission = test::triangleScene();
    emission.document["materials"] =
        json::array({{{"emissiveFactor", {1.0, 1.0, 1.0}},
                      {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 1e30}}}}}}});
    emission.document["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    expectRefused(emission, "materials[0].emissiveFactor: with its strength, an emission of 1e+30");
}

TEST(GltfValidation, MaterialFactorOutOfRangeIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["materials"] = json::array({{{"pbrMetallicRoughness", {{"roughnessFactor", 7.0}}}}});
    expectRefused(gltf, "materials[0].pbrMetallicRoughness.roughnessFactor: 7 is outside [0, 1]");
}

TEST(GltfValidation, NegativeAlphaCutoffIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["materials"] = json::array({{{"alphaMode", "MASK"}, {"alphaCutoff", -0.5}}});
    expectRefused(gltf, "materials[0].alphaCutoff: -0.5 is negative");
}

TEST(GltfValidation, PrimitiveNamingAMissingMaterialIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["meshes"][0]["primitives"][0]["material"] = 2;
    expectRefused(gltf, "meshes[0].primitives[0].material: material 2 does not exist");
}

TEST(GltfValidation, UnsupportedRequiredExtensionIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    gltf.document["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    expectRefused(gltf, "requires extension KHR_draco_mesh_compression");
}

TEST(GltfValidation, HugeAccessorWithoutBufferViewIsRefusedBeforeAllocating) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["accessors"].push_back({{"componentType", 5126}, {"count", 4000000000u}, {"type", "VEC3"}});
    expectRefused(gltf, "accessors[2].count: 4000000000 is more than this loader accepts");
}

TEST(GltfValidation, MeshOfMoreVerticesThanABufferTakesIsRefusedFromItsCounts) {
    // 2²⁸ positions of zeros, with no buffer view (so the file is a few hundred bytes), as the
    // mesh's only attribute: without normals every triangle gets vertices of its own, 3 × ⌊2²⁸/3⌋.
    // Read, they would take about 35 GB; the counts alone refuse them, at once. The sentence gives
    // the file's count first, then the one the loader would build.
    for (bool sparse : {false, true}) {
        GltfBuilder gltf = test::triangleScene();
        json huge = {{"componentType", 5126}, {"count", 1u << 28}, {"type", "VEC3"}};
        if (sparse) {
            const std::vector<uint8_t> which = {0};
            const std::vector<float> moved = {0, 5, 0};
            huge["sparse"] = {{"count", 1},
                              {"indices",
                               {{"bufferView", gltf.addBufferView(which.data(), which.size())},
                                {"componentType", TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE}}},
                              {"values", {{"bufferView", gltf.addBufferView(moved.data(), moved.size() * 4)}}}};
        }
        gltf.document["accessors"].push_back(huge);
        gltf.document["meshes"][0]["primitives"][0]["attributes"] = {{"POSITION", 2}};
        expectRefused(gltf,
                      "its 268435456 vertices (268435455 once each triangle has its own) need 16384 MiB in one "
                      "storage buffer, more than a typical GPU's "
                      "maxStorageBufferRange of 2048 MiB; at most 33554432 vertices fit");
    }
}

TEST(GltfValidation, SceneOverTheDevicesBufferLimitIsRefusedWithTheRenderersSentence) {
    GltfBuilder gltf = test::triangleScene();  // 3 vertices of 64 bytes
    TempFolder folder;
    const std::string path = gltf.writeGltf(folder, "scene").string();
    LoadOptions options;
    options.bufferLimits = {128, "a small device"};
    expectRefused(path,
                  "its 3 vertices need 192 bytes in one storage buffer, more than a small device's "
                  "maxStorageBufferRange of 128 bytes; at most 2 vertices fit",
                  options);
    options.bufferLimits.maxBufferBytes = 192;
    EXPECT_EQ(loadError(path, options), "");
}

TEST(GltfValidation, DeeplyNestedJsonIsRefusedBeforeParsing) {
    // Nested arrays in the root's `extras`: 20 000 levels overflowed the stack inside the parser.
    const auto nested = [](size_t depth) {
        GltfBuilder gltf = test::triangleScene();
        TempFolder folder;
        folder.write("scene.bin", gltf.bin);
        gltf.document["buffers"] = json::array({{{"uri", "scene.bin"}, {"byteLength", gltf.bin.size()}}});
        const std::string document = gltf.document.dump();
        const std::string text =
            "{\"extras\": " + std::string(depth, '[') + std::string(depth, ']') + ", " + document.substr(1);
        return loadError(folder.write("scene.gltf", text).string());
    };
    EXPECT_NE(nested(20000).find("the JSON nests more than 1000 levels deep"), std::string::npos) << nested(20000);
    EXPECT_EQ(nested(900), "") << "the root object and 900 arrays are 901 levels";
}

TEST(GltfValidation, IndexBeyondThirtyTwoBitsIsReportedAsWritten) {
    // tinygltf reads indices into an int: 2³¹ wrapped to −2³¹ and was reported so.
    GltfBuilder gltf = test::triangleScene();
    gltf.document["nodes"][0]["mesh"] = 2147483648u;
    expectRefused(gltf, "nodes[0].mesh is 2147483648, outside the 32-bit range");
    gltf = test::triangleScene();
    gltf.document["scenes"][0]["nodes"] = {-3000000000LL};
    expectRefused(gltf, "scenes[0].nodes[0] is -3000000000, outside the 32-bit range");
    gltf = test::triangleScene();
    gltf.document["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 4294967297u;
    expectRefused(gltf, "meshes[0].primitives[0].attributes.NORMAL is 4294967297, outside the 32-bit range");
    // Numbers that are not indices may be any integer: the user's own data, a position.
    gltf = test::triangleScene();
    gltf.document["extras"] = {{"serial", 9000000000u}};
    gltf.document["nodes"][0]["translation"] = {3000000000u, 0, 0};
    TempFolder folder;
    EXPECT_EQ(loadError(gltf.writeGltf(folder, "scene").string()), "");
}

TEST(GltfValidation, GlbOfAVersionOtherThanTwoIsRefused) {
    for (uint32_t version : {1u, 3u}) {
        GltfBuilder gltf = test::triangleScene();
        TempFolder folder;
        const std::filesystem::path path = gltf.writeGlb(folder, "scene");
        std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(4);
        file.write(reinterpret_cast<const char*>(&version), 4);
        file.close();
        expectRefused(path.string(),
                      "a binary glTF (GLB) of version " + std::to_string(version) + "; only version 2 is supported");
    }
}

// tinygltf counts the BIN chunk's length without its 8-byte header and would copy past the file's end.
TEST(GltfValidation, GlbWhoseBinChunkRunsPastTheEndIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    TempFolder folder;
    const std::filesystem::path path = gltf.writeGlb(folder, "scene");
    std::vector<char> bytes(std::filesystem::file_size(path));
    std::ifstream(path, std::ios::binary).read(bytes.data(), std::streamsize(bytes.size()));
    for (const uint32_t missing : {4u, 8u}) {
        const uint32_t length = uint32_t(bytes.size()) - missing;  // the BIN chunk keeps its length
        std::ofstream file(path, std::ios::binary | std::ios::trunc);
        file.write(bytes.data(), 8);
        file.write(reinterpret_cast<const char*>(&length), 4);
        file.write(bytes.data() + 12, std::streamsize(length) - 12);
        file.close();
        expectRefused(path.string(), "the GLB's BIN chunk says it holds");
    }
}

TEST(GltfValidation, SparseIndexPastTheCountIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    const std::vector<uint8_t> which = {200};
    const std::vector<float> moved = {0, 5, 0};
    const int indexView = gltf.addBufferView(which.data(), which.size());
    const int valueView = gltf.addBufferView(moved.data(), moved.size() * sizeof(float));
    gltf.document["accessors"][0]["sparse"] = {
        {"count", 1},
        {"indices", {{"bufferView", indexView}, {"componentType", TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE}}},
        {"values", {{"bufferView", valueView}}}};
    expectRefused(gltf, "attributes.POSITION: sparse index 200 is past the count");
}

TEST(GltfValidation, GlbImageBufferViewPastItsBufferIsRefused) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 16}, {"byteLength", 1 << 20}});
    gltf.document["images"] = json::array({{{"bufferView", 2}, {"mimeType", "image/png"}}});
    TempFolder folder;
    expectRefused(gltf.writeGlb(folder, "scene").string(), "images[0].bufferView");
}

// ---- The file policy: buffer and image URIs stay inside the scene's folder.

// The triangle scene whose buffer URI is `uri` (the .bin is written as scene.bin all the same).
std::string sceneWithBufferUri(const TempFolder& folder, const std::string& uri, const std::string& subfolder = "") {
    GltfBuilder gltf = test::triangleScene();
    folder.write(subfolder + "scene.bin", gltf.bin);
    gltf.document["buffers"] = json::array({{{"uri", uri}, {"byteLength", gltf.bin.size()}}});
    return folder.write(subfolder + "scene.gltf", gltf.document.dump()).string();
}

TEST(GltfFilePolicy, AbsoluteUriIsRefused) {
    TempFolder folder;
    expectRefused(sceneWithBufferUri(folder, "/etc/hostname"), "buffers[0].uri: '/etc/hostname' is an absolute path");
}

TEST(GltfFilePolicy, UriEscapingTheFolderIsRefused) {
    TempFolder folder;
    folder.write("x.bin", std::string(64, '\0'));  // the target exists: the refusal is not "file not found"
    expectRefused(sceneWithBufferUri(folder, "../../x.bin", "a/b/"), "'../../x.bin' leaves the allowed folder");
    expectRefused(sceneWithBufferUri(folder, "%2E%2E/%2E%2E/x.bin", "a/b/"), "leaves the allowed folder");
}

TEST(GltfFilePolicy, SymlinkEscapingTheFolderIsRefused) {
    TempFolder folder;
    folder.write("outside/secret.bin", std::string(64, '\0'));
    const std::string path = sceneWithBufferUri(folder, "link.bin", "scene/");
    std::filesystem::create_symlink(folder.path / "outside/secret.bin", folder.path / "scene/link.bin");
    expectRefused(path, "through a symbolic link");
}

TEST(GltfFilePolicy, UriNamingADirectoryIsRefused) {
    TempFolder folder;
    std::filesystem::create_directory(folder.path / "data");
    expectRefused(sceneWithBufferUri(folder, "data"), "is a directory");
}

TEST(GltfFilePolicy, UriNamingAFifoIsRefusedWithoutBlocking) {
    TempFolder folder;
    ASSERT_EQ(mkfifo((folder.path / "pipe.bin").c_str(), 0600), 0);
    expectRefused(sceneWithBufferUri(folder, "pipe.bin"), "is not a regular file");
}

TEST(GltfFilePolicy, UriWithAnotherSchemeIsRefused) {
    TempFolder folder;
    expectRefused(sceneWithBufferUri(folder, "file:///etc/hostname"), "is not a relative path or a data: URI");
}

TEST(GltfFilePolicy, BufferOverTheSizeLimitIsRefused) {
    TempFolder folder;
    const std::string path = sceneWithBufferUri(folder, "scene.bin");
    LoadOptions options;
    options.maxFileBytes = 16 * 1024;
    folder.write("scene.bin", std::string(options.maxFileBytes + 1, '\0'));
    expectRefused(path, "over the limit of 16384 bytes", options);
}

TEST(GltfFilePolicy, AllowedRootCanWidenTheFolder) {
    TempFolder folder;
    GltfBuilder gltf = test::triangleScene();
    folder.write("shared/mesh.bin", gltf.bin);
    gltf.document["buffers"] = json::array({{{"uri", "../shared/mesh.bin"}, {"byteLength", gltf.bin.size()}}});
    const std::string path = folder.write("scenes/scene.gltf", gltf.document.dump()).string();
    expectRefused(path, "leaves the allowed folder");
    LoadOptions options;
    options.allowedRoot = folder.path.string();
    EXPECT_EQ(loadGltf(path, options).triangleCount(), 1u);
}

TEST(GltfFilePolicy, ImageOutsideTheFolderIsNotReadButWarned) {
    GltfBuilder gltf = test::triangleScene();
    gltf.document["images"] = json::array({{{"uri", "/etc/hostname"}}});
    gltf.document["textures"] = json::array({{{"source", 0}}});
    gltf.document["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
    gltf.document["meshes"][0]["primitives"][0]["material"] = 0;
    TempFolder folder;
    const Scene scene = loadGltf(gltf.writeGltf(folder, "scene").string());
    EXPECT_TRUE(scene.textures.empty());
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("'/etc/hostname' is an absolute path"), std::string::npos) << scene.warnings[0];
}

// ---- Public corpora (the Khronos glTF-Validator's test assets, tinygltf's past regressions), which CI
// places beside the checkout and names in VCT_CORPORA_DIR. Many of these files are deliberately broken.

std::vector<std::string> corpusFiles(const std::string& subfolder) {
    std::vector<std::string> files;
    const char* corpora = std::getenv("VCT_CORPORA_DIR");
    if (!corpora || !std::filesystem::is_directory(std::filesystem::path(corpora) / subfolder)) return files;
    for (const auto& entry :
         std::filesystem::recursive_directory_iterator(std::filesystem::path(corpora) / subfolder)) {
        const std::string extension = entry.path().extension().string();
        if (entry.is_regular_file() && (extension == ".gltf" || extension == ".glb"))
            files.push_back(entry.path().string());
    }
    return files;
}

TEST(GltfCorpora, EveryFileLoadsOrFailsWithAnErrorNamingIt) {
    const std::vector<std::string> files = corpusFiles("gltf-validator");
    if (files.empty())
        GTEST_SKIP() << "needs the public glTF corpora: set VCT_CORPORA_DIR to a folder holding gltf-validator/ "
                        "(.ci/run passes ../shared/corpora)";
    size_t refused = 0;
    for (const std::string& path : files) {
        const std::string message = loadError(path);
        if (message.empty()) continue;
        ++refused;
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
    }
    EXPECT_GT(refused, 0u) << "the corpus holds invalid files; some must be refused";
    EXPECT_LT(refused, files.size()) << "the corpus holds valid files; some must load";
}

TEST(GltfCorpora, TinygltfRegressionInputsAreRefused) {
    const std::vector<std::string> files = corpusFiles("tinygltf-regressions");
    if (files.empty())
        GTEST_SKIP() << "needs the public glTF corpora: set VCT_CORPORA_DIR to a folder holding "
                        "tinygltf-regressions/ (.ci/run passes ../shared/corpora)";
    for (const std::string& path : files) {
        const std::string message = loadError(path);
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << path << " must be refused, got: '" << message << "'";
    }
}

}  // namespace
}  // namespace vct
