// The voxelize pass against its CPU twin (render/voxelize_reference.h), voxel for voxel, and the
// properties the twin cannot show by itself: closed shells, averaging, order independence, no NaN.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <iostream>
#include <numeric>
#include <random>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>

#include "error.h"
#include "gpu/commands.h"
#include "gpu/readback.h"
#include "gpu/timing.h"
#include "gpu_test.h"
#include "render/scene_gpu.h"
#include "render/voxel_grid_fit.h"
#include "render/voxelize_pass.h"
#include "render/voxelize_reference.h"
#include "scene/load.h"
#include "scene/material_textures.h"

namespace vct {
namespace {

// Tolerances of the GPU against the exact averages of the twin.
constexpr float kAlbedoTolerance = 0.6f / 255.0f;  // UNORM8 rounding plus the 2^-15 fixed point
constexpr float kNormalTolerance = 2e-3f;          // half float (2^-11 relative) plus 2^-14 fixed point
constexpr float kEmissionTolerance = 2e-3f;        // relative to the scene's largest emission
// Half float of an offset below 1, plus the 2^-14 fixed point of the normal and of the way to the
// planes, the more for a short mean normal (the offset is along its direction).
float surfaceOffsetTolerance(const glm::dvec3& normal) { return 1e-3f + 2e-4f / float(glm::length(normal)); }
// Voxels whose decision margin in double is below this (grid units) may legitimately differ
// between float and double; they are counted, and must stay a tiny fraction.
constexpr double kAmbiguousMargin = 1e-5;
constexpr double kMaxAmbiguousFraction = 1e-3;

using TriangleF = std::array<glm::vec3, 3>;

struct TestMaterial {
    glm::vec3 albedo{0.8f};
    glm::vec3 emission{0.0f};
};

Scene makeScene(const std::vector<TriangleF>& triangles, const std::vector<uint32_t>& materialOfTriangle = {},
                const std::vector<TestMaterial>& materials = {TestMaterial{}}) {
    Scene scene;
    scene.name = "voxelize test";
    for (size_t t = 0; t < triangles.size(); ++t) {
        for (const glm::vec3& corner : triangles[t]) {
            scene.indices.push_back(uint32_t(scene.vertices.size()));
            Vertex vertex;
            vertex.position = corner;
            scene.vertices.push_back(vertex);
        }
        scene.triangleMaterials.push_back(materialOfTriangle.empty() ? 0u : materialOfTriangle[t]);
    }
    for (const TestMaterial& test : materials) {
        Material material;
        material.baseColorFactor = glm::vec4(test.albedo, 1.0f);
        material.emission = test.emission;
        scene.materials.push_back(material);
    }
    return scene;
}

// Origin 0 and a power-of-two voxel size: grid coordinates are exact in float.
glsl::VoxelGridParams exactGrid(uint32_t resolution, float voxelSize = 1.0f) {
    glsl::VoxelGridParams grid{};
    grid.origin = glm::vec3(0.0f, 0.0f, 0.0f);
    grid.voxelSize = voxelSize;
    grid.resolution = resolution;
    grid.mipLevels = 1u;
    return grid;
}

struct VoxelImages {
    std::vector<glm::vec4> albedoOpacity, normal, emission;
    std::vector<uint32_t> occupied;  // the occupied-voxel list, packed cells
    glsl::WorkListHeader occupiedDispatch{};
    size_t workItems = 0;
    size_t chunks = 0;  // buffers and dispatches the work items were split into
    std::vector<PassTime> times;
};

VoxelImages voxelizeOnGpu(const Scene& scene, const glsl::VoxelGridParams& grid, int timedRuns = 0,
                          uint64_t maxChunkItems = VoxelizePass::kMaxChunkItems) {
    GpuContext& context = test::gpu();
    SceneGpu sceneGpu(context, scene);
    VoxelizePass pass(context, scene, sceneGpu, grid, maxChunkItems);
    VoxelVolumes volumes(context, ResourceSettings{.voxelResolution = grid.resolution, .anisotropicVoxels = false});
    GpuTimer timer(context);
    for (int run = 0; run <= timedRuns; ++run)  // run 0 warms up, the last one is timed
        submitAndWait(context, [&](VkCommandBuffer commands) {
            timer.reset(commands);
            timer.begin(commands, "voxelize");
            pass.record(commands, sceneGpu, volumes);
            timer.end(commands);
        });
    VoxelImages images;
    images.albedoOpacity = readImage3D(context, volumes.albedoOpacity, 0);
    images.normal = readImage3D(context, volumes.normal, 0);
    images.emission = readImage3D(context, volumes.emission, 0);
    const std::vector<uint32_t> header = readBufferWords(context, volumes.occupiedDispatch, 4);
    std::memcpy(&images.occupiedDispatch, header.data(), sizeof(images.occupiedDispatch));
    images.occupied = readBufferWords(context, volumes.occupiedVoxels, images.occupiedDispatch.count);
    images.workItems = pass.params.grid.workItems;
    images.chunks = pass.workChunks.size();
    images.times = timer.results();
    return images;
}

std::string voxelName(const VoxelReference& reference, size_t i) {
    const size_t n = reference.resolution;
    std::ostringstream name;
    name << "voxel (" << i % n << ", " << (i / n) % n << ", " << i / (n * n) << ")";
    return name.str();
}

struct Comparison {
    size_t occupied = 0, ambiguous = 0, masked = 0, mismatches = 0;
    std::string firstMismatch;
};

// Occupancy, count and averaged attributes of every voxel, except those within `ambiguousMargin`
// of flipping in double precision and those a MASK texture decides (VoxelReference::maskedByTexture).
Comparison compareWithTwin(const VoxelImages& gpu, const VoxelReference& twin, double ambiguousMargin,
                           float largestEmission = 1.0f) {
    Comparison result;
    for (size_t i = 0; i < twin.count.size(); ++i) {
        if (twin.count[i] > 0) ++result.occupied;
        if (twin.decisionMargin[i] < ambiguousMargin) {
            ++result.ambiguous;
            continue;
        }
        if (twin.maskedByTexture[i]) {
            ++result.masked;
            continue;
        }
        std::ostringstream problem;
        const glm::vec4 albedo = gpu.albedoOpacity[i], normal = gpu.normal[i], emission = gpu.emission[i];
        // UNORM8, at least 1/255 where occupied (voxel_resolve.comp).
        const float opacity = twin.count[i] > 0 ? std::max(float(twin.opacity[i]), 1.0f / 255.0f) : 0.0f;
        if (std::abs(albedo.a - opacity) > kAlbedoTolerance || (albedo.a > 0.0f) != (twin.count[i] > 0))
            problem << "opacity " << albedo.a << ", the twin says " << opacity;
        else if (std::abs(normal.w - float(twin.surfaceOffset[i])) > surfaceOffsetTolerance(twin.normal[i]))
            problem << "surface offset " << normal.w << ", the twin says " << twin.surfaceOffset[i];
        for (int c = 0; c < 3 && problem.str().empty(); ++c) {
            if (std::abs(albedo[c] - float(twin.albedo[i][c])) > kAlbedoTolerance)
                problem << "albedo[" << c << "] " << albedo[c] << ", the twin says " << twin.albedo[i][c];
            else if (std::abs(normal[c] - float(twin.normal[i][c])) > kNormalTolerance)
                problem << "normal[" << c << "] " << normal[c] << ", the twin says " << twin.normal[i][c];
            else if (std::abs(emission[c] - float(twin.emission[i][c])) > kEmissionTolerance * largestEmission)
                problem << "emission[" << c << "] " << emission[c] << ", the twin says " << twin.emission[i][c];
        }
        if (problem.str().empty()) continue;
        if (result.mismatches++ == 0) result.firstMismatch = voxelName(twin, i) + ": " + problem.str();
    }
    return result;
}

// The occupied list names each voxel of opacity 1 once and nothing else, and its dispatch covers it.
void expectOccupiedListMatchesTheImages(const VoxelImages& gpu, uint32_t resolution) {
    std::vector<uint8_t> listed(gpu.albedoOpacity.size(), 0);
    size_t outside = 0, repeated = 0;
    for (uint32_t packed : gpu.occupied) {
        const glm::uvec3 voxel = glsl::unpackCell(packed);
        if (glm::any(glm::greaterThanEqual(voxel, glm::uvec3(resolution)))) {
            ++outside;
            continue;
        }
        const size_t index = voxel.x + resolution * (voxel.y + size_t(resolution) * voxel.z);
        if (listed[index]++ > 0) ++repeated;
    }
    EXPECT_EQ(outside, 0u) << "listed voxels outside the grid";
    EXPECT_EQ(repeated, 0u) << "voxels listed twice";
    size_t unlisted = 0, wronglyListed = 0;
    for (size_t i = 0; i < listed.size(); ++i) {
        const bool occupied = gpu.albedoOpacity[i].a > 0.0f;
        if (occupied && !listed[i]) ++unlisted;
        if (!occupied && listed[i]) ++wronglyListed;
    }
    EXPECT_EQ(unlisted, 0u) << "occupied voxels missing from the list";
    EXPECT_EQ(wronglyListed, 0u) << "empty voxels in the list";
    const glsl::WorkListHeader& dispatch = gpu.occupiedDispatch;
    EXPECT_EQ(dispatch.groupsX, (dispatch.count + glsl::WORK_LIST_GROUP_SIZE - 1) / glsl::WORK_LIST_GROUP_SIZE);
    EXPECT_EQ(dispatch.groupsY, 1u);
    EXPECT_EQ(dispatch.groupsZ, 1u);
}

void expectMatchesTwin(const Scene& scene, const glsl::VoxelGridParams& grid, double ambiguousMargin,
                       float largestEmission = 1.0f) {
    const VoxelImages gpu = voxelizeOnGpu(scene, grid);
    const VoxelReference twin = voxelizeReference(scene, grid);
    const Comparison comparison = compareWithTwin(gpu, twin, ambiguousMargin, largestEmission);
    expectOccupiedListMatchesTheImages(gpu, grid.resolution);
    EXPECT_GT(comparison.occupied, 0u);
    EXPECT_EQ(comparison.mismatches, 0u) << comparison.firstMismatch;
    EXPECT_LE(double(comparison.ambiguous), kMaxAmbiguousFraction * double(comparison.occupied))
        << comparison.ambiguous << " ambiguous voxels of " << comparison.occupied << " occupied";
}

// An independent check of conservativeness: the voxel holding any point of the triangle, set back
// as the voxelizer marks it (voxelizationSetback), is marked.
void expectSampledPointsMarked(const Scene& scene, const glsl::VoxelGridParams& grid, const VoxelImages& gpu) {
    const int n = int(grid.resolution);
    size_t missed = 0;
    for (size_t t = 0; t < scene.triangleCount(); ++t) {
        if (isDegenerateTriangle(scene, t)) continue;
        const TriangleD triangle = setBackTriangle(gridTriangle(scene, grid, t));
        const int steps = 64;
        for (int a = 0; a <= steps; ++a)
            for (int b = 0; a + b <= steps; ++b) {
                const double u = double(a) / steps, v = double(b) / steps;
                const glm::dvec3 p = triangle[0] + u * (triangle[1] - triangle[0]) + v * (triangle[2] - triangle[0]);
                const glm::ivec3 voxel(glm::floor(p));
                if (glm::any(glm::lessThan(voxel, glm::ivec3(0))) ||
                    glm::any(glm::greaterThanEqual(voxel, glm::ivec3(n))))
                    continue;
                if (gpu.albedoOpacity[size_t(voxel.x) + size_t(n) * (size_t(voxel.y) + size_t(n) * size_t(voxel.z))]
                        .a != 1.0f)
                    ++missed;
            }
    }
    EXPECT_EQ(missed, 0u) << "points of a triangle lie in voxels the GPU left empty";
}

// The opacity of voxel (x, y, z) of a 32³ grid.
float opacityAt(const VoxelImages& gpu, int x, int y, int z) {
    return gpu.albedoOpacity[size_t(x) + 32 * (size_t(y) + 32 * size_t(z))].a;
}

glm::vec3 randomUnitVector(std::mt19937& random) {
    std::normal_distribution<float> normal;
    return glm::normalize(glm::vec3(normal(random), normal(random), normal(random)));
}

class Voxelize : public test::GpuTest {};

TEST_F(Voxelize, RandomTrianglesMatchTheCpuTwinVoxelForVoxel) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> position(-0.5f, 3.7f), size(0.02f, 1.5f);
    std::vector<TriangleF> triangles;
    std::vector<uint32_t> materials;
    for (int t = 0; t < 300; ++t) {
        const glm::vec3 center(position(random), position(random), position(random));
        const float extent = size(random);
        triangles.push_back({center + extent * randomUnitVector(random), center + extent * randomUnitVector(random),
                             center + extent * randomUnitVector(random)});
        materials.push_back(uint32_t(t % 3));
    }
    const Scene scene =
        makeScene(triangles, materials,
                  {{{0.9f, 0.1f, 0.1f}, {}}, {{0.1f, 0.9f, 0.2f}, {2.0f, 1.0f, 0.0f}}, {glm::vec3(0.5f), {}}});
    // A grid whose origin and voxel size are not exact in float: conversion rounds differently.
    glsl::VoxelGridParams grid{};
    grid.origin = glm::vec3(-0.3f, -0.2f, -0.1f);
    grid.voxelSize = 0.11f;
    grid.resolution = 32;
    grid.mipLevels = 1;
    expectMatchesTwin(scene, grid, kAmbiguousMargin, 2.0f);
    expectSampledPointsMarked(scene, grid, voxelizeOnGpu(scene, grid));
}

TEST_F(Voxelize, SliverTriangleMarksEveryTouchedVoxel) {
    std::mt19937 random(11);
    std::uniform_real_distribution<float> position(6.0f, 26.0f), width(1e-4f, 5e-2f);
    std::vector<TriangleF> triangles;
    for (int t = 0; t < 40; ++t) {
        const glm::vec3 start(position(random), position(random), position(random));
        const glm::vec3 end(position(random), position(random), position(random));
        const glm::vec3 across = glm::normalize(glm::cross(end - start, randomUnitVector(random)));
        triangles.push_back({start, end, glm::mix(start, end, 0.37f) + width(random) * across});
    }
    const Scene scene = makeScene(triangles);
    expectMatchesTwin(scene, exactGrid(32), kAmbiguousMargin);
    expectSampledPointsMarked(scene, exactGrid(32), voxelizeOnGpu(scene, exactGrid(32)));
}

TEST_F(Voxelize, TriangleOnVoxelFaceMarksTheVoxelsOnBothSides) {
    // In the plane x = 8, with corners on voxel corners: exact, so no voxel is excused.
    const Scene scene = makeScene({{glm::vec3(8, 2, 3), glm::vec3(8, 12, 3), glm::vec3(8, 2, 13)}});
    expectMatchesTwin(scene, exactGrid(32), 0.0);
    const VoxelImages gpu = voxelizeOnGpu(scene, exactGrid(32));
    for (int x : {7, 8}) {
        EXPECT_EQ(opacityAt(gpu, x, 2, 3), 1.0f) << x;
        EXPECT_EQ(opacityAt(gpu, x, 6, 6), 1.0f) << x;
        EXPECT_EQ(opacityAt(gpu, x, 1, 2), 1.0f) << x << ": the corner (8, 2, 3) touches this voxel";
    }
    for (int x : {6, 9}) EXPECT_EQ(opacityAt(gpu, x, 6, 6), 0.0f) << x;
}

TEST_F(Voxelize, TriangleOnVoxelEdgesMarksEveryVoxelAroundTheEdge) {
    // In the plane y = 9 (along the grid, so not set back), its edge on the voxel edge z = 22.
    const Scene scene = makeScene({{glm::vec3(4, 9, 22), glm::vec3(16, 9, 22), glm::vec3(4, 9, 28)}});
    expectMatchesTwin(scene, exactGrid(32), 0.0);
    const VoxelImages gpu = voxelizeOnGpu(scene, exactGrid(32));
    // Voxels y 8 and 9, z 21 and 22.
    for (int y : {8, 9})
        for (int z : {21, 22}) EXPECT_EQ(opacityAt(gpu, 10, y, z), 1.0f) << y << " " << z;
    EXPECT_EQ(opacityAt(gpu, 10, 9, 20), 0.0f);
}

TEST_F(Voxelize, AnObliquePlaneMarksTheVoxelsItCrossesAndThoseBehindItNotThoseInFront) {
    // The plane x = y, facing +x −y, holds the voxel edges {x = y = i}: the boxes it touches, |i − j|
    // ≤ 1, reach a whole voxel in front of it. Set back by (√2 − 1)/2 it touches i − j = 0 (the
    // voxels it runs through, their centres on it) and −1 (behind it), not +1: its voxels' centres
    // lie at most half a voxel in front of it, as a wall's along the grid do.
    const Scene scene = makeScene({{glm::vec3(2, 2, 1), glm::vec3(20, 20, 1), glm::vec3(2, 2, 19)}});
    expectMatchesTwin(scene, exactGrid(32), 0.0);
    const VoxelImages gpu = voxelizeOnGpu(scene, exactGrid(32));
    for (int z : {3, 9}) {
        EXPECT_EQ(opacityAt(gpu, 5, 5, z), 1.0f) << z;
        EXPECT_EQ(opacityAt(gpu, 4, 5, z), 1.0f) << z << ": behind the plane";
        EXPECT_EQ(opacityAt(gpu, 5, 4, z), 0.0f) << z << ": in front of the plane";
        EXPECT_EQ(opacityAt(gpu, 3, 5, z), 0.0f) << z;
    }
}

TEST_F(Voxelize, TriangleLargerThanTheGridIsClippedToIt) {
    const Scene scene = makeScene(
        {{glm::vec3(-200.0f, -150.0f, -90.0f), glm::vec3(250.0f, 40.0f, 30.0f), glm::vec3(-60.0f, 230.0f, 120.0f)}});
    const VoxelImages gpu = voxelizeOnGpu(scene, exactGrid(32));
    // Only tiles the plane crosses inside the grid: far fewer than the 8³ tiles of the grid.
    EXPECT_GT(gpu.workItems, 0u);
    EXPECT_LT(gpu.workItems, 8u * 8u * 8u / 2u);
    expectMatchesTwin(scene, exactGrid(32), kAmbiguousMargin);
}

// The work items as the specification states them: every tile of the set-back triangle's voxel
// range that the separating-axis test keeps, scanned z, y, x (the builder searches only near the plane).
std::vector<glm::uvec2> everyTouchedTile(const Scene& scene, const glsl::VoxelGridParams& grid) {
    std::vector<glm::uvec2> items;
    for (uint32_t t = 0; t < scene.triangleCount(); ++t) {
        if (isDegenerateTriangle(scene, t)) continue;
        const TriangleD triangle = setBackTriangle(gridTriangle(scene, grid, t));
        const VoxelRange range = triangleVoxelRange(triangle, grid.resolution, 1e-3);
        if (range.empty()) continue;
        const glm::ivec3 first = range.first / 4, last = range.last / 4;
        for (int z = first.z; z <= last.z; ++z)
            for (int y = first.y; y <= last.y; ++y)
                for (int x = first.x; x <= last.x; ++x)
                    if (triangleBoxSeparation(triangle, glm::dvec3(x, y, z) * 4.0 + 2.0, 2.0) <= 1e-3)
                        items.push_back({t, glsl::packCell(glm::uvec3(x, y, z))});
    }
    return items;
}

TEST(VoxelizeWorkItems, AreEveryTileTheTriangleTouchesFoundNearItsPlaneOnly) {
    // Random triangles of every size and orientation, large ones past the grid, and axis-aligned ones
    // (whose plane lies on tile faces).
    std::mt19937 random(11);
    std::uniform_real_distribution<float> position(-10.0f, 74.0f), size(0.1f, 60.0f);
    std::vector<TriangleF> triangles;
    for (int t = 0; t < 400; ++t) {
        const glm::vec3 center(position(random), position(random), position(random));
        const float extent = size(random);
        triangles.push_back({center + extent * randomUnitVector(random), center + extent * randomUnitVector(random),
                             center + extent * randomUnitVector(random)});
    }
    triangles.push_back({glm::vec3(1, 1, 8), glm::vec3(60, 1, 8), glm::vec3(1, 60, 8)});
    triangles.push_back({glm::vec3(12, -5, -5), glm::vec3(12, 70, -5), glm::vec3(12, -5, 70)});
    const Scene scene = makeScene(triangles);
    std::vector<uint32_t> order(scene.triangleCount());
    std::iota(order.begin(), order.end(), 0u);
    EXPECT_EQ(buildVoxelizeWorkItems(scene, order, exactGrid(64)), everyTouchedTile(scene, exactGrid(64)));
}

TEST(VoxelizeWorkItems, MoreThanTheBoundAreRefusedNamingTheSceneAndTheBound) {
    // 100 triangles across a 64³ grid: each crosses hundreds of tiles.
    std::vector<TriangleF> triangles(100, {glm::vec3(0, 0, 0), glm::vec3(64, 0, 64), glm::vec3(0, 64, 32)});
    Scene scene = makeScene(triangles);
    scene.name = "many-walls.gltf";
    std::vector<uint32_t> order(scene.triangleCount());
    std::iota(order.begin(), order.end(), 0u);
    const size_t needed = buildVoxelizeWorkItems(scene, order, exactGrid(64)).size();
    EXPECT_GT(needed, 10000u);
    // Far over the bound: refused from the triangles' areas (each covers 128 tiles in projection),
    // before any tile is searched; just over it: refused as the list passes it.
    const std::string prefix = "scene 'many-walls.gltf': voxelizing its 100 triangles at 64³ takes ";
    for (const auto& [bound, howMany] : {std::pair<uint64_t, std::string>{10000, "at least 12800 work items"},
                                         std::pair<uint64_t, std::string>{12800, "more than 12800 work items"}}) {
        try {
            buildVoxelizeWorkItems(scene, order, exactGrid(64), bound);
            ADD_FAILURE() << "expected vct::Error for a bound of " << bound;
        } catch (const Error& error) {
            EXPECT_EQ(std::string(error.what())
                          .rfind(prefix + howMany +
                                     " (one per triangle and 4³-voxel tile it "
                                     "crosses), more than the " +
                                     std::to_string(bound),
                                 0),
                      0u)
                << error.what();
        }
    }
    EXPECT_EQ(buildVoxelizeWorkItems(scene, order, exactGrid(64), needed).size(), needed);
    VkPhysicalDeviceMemoryProperties memory{};
    memory.memoryHeapCount = 1;
    memory.memoryHeaps[0] = {VkDeviceSize(1) << 30, VK_MEMORY_HEAP_DEVICE_LOCAL_BIT};
    EXPECT_EQ(voxelizeWorkItemLimit(memory), (uint64_t(32) << 20) / 8) << "at most 32 MiB";
    memory.memoryHeaps[0].size = VkDeviceSize(64) << 20;
    EXPECT_EQ(voxelizeWorkItemLimit(memory), (uint64_t(16) << 20) / 8) << "a quarter of a 64 MiB heap";
}

TEST_F(Voxelize, WorkItemsSplitIntoChunksGiveTheSameImages) {
    // Each chunk is a buffer and a dispatch of its own; the sums do not care how the items are split.
    const Scene scene = loadScene("cornell");
    const glsl::VoxelGridParams grid = fitVoxelGrid(scene.bounds(), 64);
    const VoxelImages whole = voxelizeOnGpu(scene, grid);
    const VoxelImages chunked = voxelizeOnGpu(scene, grid, 0, 97);
    EXPECT_EQ(whole.chunks, 1u);
    EXPECT_EQ(chunked.chunks, (whole.workItems + 96) / 97);
    EXPECT_EQ(chunked.workItems, whole.workItems);
    EXPECT_EQ(chunked.albedoOpacity, whole.albedoOpacity);
    EXPECT_EQ(chunked.normal, whole.normal);
    EXPECT_EQ(chunked.emission, whole.emission);
}

// 6-connected flood fill through empty voxels from the grid's corner; returns the reached mask.
std::vector<bool> floodFromOutside(const std::vector<glm::vec4>& albedoOpacity, int n) {
    std::vector<bool> reached(albedoOpacity.size(), false);
    std::vector<glm::ivec3> stack = {glm::ivec3(0)};
    reached[0] = true;
    const glm::ivec3 steps[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    while (!stack.empty()) {
        const glm::ivec3 voxel = stack.back();
        stack.pop_back();
        for (const glm::ivec3& step : steps) {
            const glm::ivec3 next = voxel + step;
            if (glm::any(glm::lessThan(next, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(next, glm::ivec3(n))))
                continue;
            const size_t i = size_t(next.x) + size_t(n) * (size_t(next.y) + size_t(n) * size_t(next.z));
            if (reached[i] || albedoOpacity[i].a > 0.0f) continue;
            reached[i] = true;
            stack.push_back(next);
        }
    }
    return reached;
}

std::vector<TriangleF> icosphere(glm::vec3 center, float radius, int subdivisions) {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<glm::vec3> v = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                                {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    std::vector<std::array<glm::vec3, 3>> faces;
    const int f[20][3] = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                          {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                          {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (const auto& face : f)
        faces.push_back({glm::normalize(v[face[0]]), glm::normalize(v[face[1]]), glm::normalize(v[face[2]])});
    for (int s = 0; s < subdivisions; ++s) {
        std::vector<std::array<glm::vec3, 3>> finer;
        for (const auto& [a, b, c] : faces) {
            // Midpoints computed the same way on both sides of an edge, so neighbours share vertices exactly.
            const auto mid = [](glm::vec3 p, glm::vec3 q) {
                return glm::normalize(glm::all(glm::lessThan(p, q)) ? p + q : q + p);
            };
            const glm::vec3 ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
        }
        faces = finer;
    }
    std::vector<TriangleF> triangles;
    for (const auto& [a, b, c] : faces)
        triangles.push_back({center + radius * a, center + radius * b, center + radius * c});
    return triangles;
}

TEST_F(Voxelize, ClosedSphereGivesAShellWithoutHoles) {
    const Scene scene = makeScene(icosphere(glm::vec3(16.1f, 15.7f, 16.3f), 11.3f, 3));
    const VoxelImages gpu = voxelizeOnGpu(scene, exactGrid(32));
    const std::vector<bool> outside = floodFromOutside(gpu.albedoOpacity, 32);
    EXPECT_FALSE(outside[16 + 32 * (16 + 32 * 16)]) << "the flood from outside reached the sphere's centre";
    expectMatchesTwin(scene, exactGrid(32), kAmbiguousMargin);
}

TEST_F(Voxelize, ClosedRotatedCubeGivesAShellWithoutHoles) {
    // Turned about an oblique axis, so that no face lies along the grid. (A basis of rational
    // entries, 0.36 0.48 -0.8 and the like, with its rational set-backs put a few voxel corners
    // within 10⁻⁶ of its faces' edges, where the GPU's rounding decides.)
    const glm::mat3 rotation = glm::mat3(glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1, 2, 3))));
    std::vector<TriangleF> triangles;
    const auto corner = [&](int i) {
        return glm::vec3(16.2f, 15.9f, 16.05f) +
               rotation * (9.0f * glm::vec3((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1));
    };
    const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& q : quads) {
        triangles.push_back({corner(q[0]), corner(q[1]), corner(q[2])});
        triangles.push_back({corner(q[0]), corner(q[2]), corner(q[3])});
    }
    const Scene scene = makeScene(triangles);
    const VoxelImages gpu = voxelizeOnGpu(scene, exactGrid(32));
    EXPECT_FALSE(floodFromOutside(gpu.albedoOpacity, 32)[16 + 32 * (16 + 32 * 16)]);
    expectMatchesTwin(scene, exactGrid(32), kAmbiguousMargin);
}

TEST_F(Voxelize, TrianglesSharingAVoxelAverageTheirAttributes) {
    // Two small triangles inside voxel (5, 5, 5), red facing +z and blue facing +x, different
    // emission; the red one's plane 0.2 voxel in front of the centre, the blue one's 0.1 behind it.
    const Scene scene =
        makeScene({{glm::vec3(5.25f, 5.25f, 5.7f), glm::vec3(5.75f, 5.25f, 5.7f), glm::vec3(5.25f, 5.75f, 5.7f)},
                   {glm::vec3(5.4f, 5.25f, 5.25f), glm::vec3(5.4f, 5.75f, 5.25f), glm::vec3(5.4f, 5.25f, 5.75f)}},
                  {0, 1}, {{{1.0f, 0.0f, 0.0f}, {4.0f, 0.0f, 0.0f}}, {{0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 2.0f}}});
    const VoxelImages gpu = voxelizeOnGpu(scene, exactGrid(32));
    const size_t voxel = 5 + 32 * (5 + 32 * 5);
    EXPECT_NEAR(gpu.albedoOpacity[voxel].r, 0.5f, kAlbedoTolerance);
    EXPECT_NEAR(gpu.albedoOpacity[voxel].b, 0.5f, kAlbedoTolerance);
    EXPECT_EQ(gpu.albedoOpacity[voxel].a, 1.0f);
    EXPECT_NEAR(gpu.normal[voxel].x, 0.5f, kNormalTolerance);
    EXPECT_NEAR(gpu.normal[voxel].z, 0.5f, kNormalTolerance);
    // The mean way to their planes, (-0.1, 0, 0.2) / 2, along the unit mean normal (1, 0, 1) / √2.
    EXPECT_NEAR(gpu.normal[voxel].w, 0.05f * std::sqrt(0.5f), 1e-3f);
    EXPECT_NEAR(gpu.emission[voxel].r, 2.0f, kEmissionTolerance * 4.0f);
    EXPECT_NEAR(gpu.emission[voxel].b, 1.0f, kEmissionTolerance * 4.0f);
}

TEST_F(Voxelize, ThinTwoSidedWallAveragesItsNormalsToNearZero) {
    const glm::vec3 a(3.8f, 3.25f, 3.25f), b(3.8f, 3.75f, 3.25f), c(3.8f, 3.25f, 3.75f);
    const VoxelImages gpu = voxelizeOnGpu(makeScene({{a, b, c}, {a, c, b}}), exactGrid(32));
    const glm::vec4 normal = gpu.normal[3 + 32 * (3 + 32 * 3)];
    EXPECT_EQ(normal.w, 0.0f) << "without a side, no direction for the surface to lie along";
    EXPECT_LT(glm::length(glm::vec3(normal)), kNormalTolerance) << "opposite faces in one voxel cancel";
}

TEST_F(Voxelize, ImagesDoNotDependOnTriangleOrder) {
    std::mt19937 random(3);
    std::uniform_real_distribution<float> position(0.0f, 32.0f);
    std::vector<TriangleF> triangles;
    std::vector<uint32_t> materials;
    for (int t = 0; t < 400; ++t) {
        const glm::vec3 center(position(random), position(random), position(random));
        triangles.push_back({center + 3.0f * randomUnitVector(random), center + 3.0f * randomUnitVector(random),
                             center + 3.0f * randomUnitVector(random)});
        materials.push_back(uint32_t(t % 4));
    }
    const std::vector<TestMaterial> palette = {{{0.9f, 0.3f, 0.1f}, {1.0f, 3.0f, 0.5f}},
                                               {{0.2f, 0.7f, 0.33f}, {}},
                                               {{0.123f, 0.456f, 0.789f}, {7.0f, 0.0f, 0.1f}},
                                               {glm::vec3(1.0f), {}}};
    const VoxelImages first = voxelizeOnGpu(makeScene(triangles, materials, palette), exactGrid(32));
    std::vector<size_t> order(triangles.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::shuffle(order.begin(), order.end(), random);
    std::vector<TriangleF> shuffledTriangles;
    std::vector<uint32_t> shuffledMaterials;
    for (size_t i : order) {
        shuffledTriangles.push_back(triangles[i]);
        shuffledMaterials.push_back(materials[i]);
    }
    const VoxelImages second = voxelizeOnGpu(makeScene(shuffledTriangles, shuffledMaterials, palette), exactGrid(32));
    const auto identical = [](const std::vector<glm::vec4>& x, const std::vector<glm::vec4>& y) {
        return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(glm::vec4)) == 0;
    };
    EXPECT_TRUE(identical(first.albedoOpacity, second.albedoOpacity));
    EXPECT_TRUE(identical(first.normal, second.normal));
    EXPECT_TRUE(identical(first.emission, second.emission));
}

TEST_F(Voxelize, DegenerateTrianglesMarkNothingAndNothingIsNaN) {
    // Coincident corners, collinear corners, a huge emitter and a tiny (but not degenerate) triangle.
    const Scene scene = makeScene({{glm::vec3(4, 4, 4), glm::vec3(4, 4, 4), glm::vec3(4, 4, 4)},
                                   {glm::vec3(1, 1, 1), glm::vec3(9, 9, 9), glm::vec3(5, 5, 5)},
                                   {glm::vec3(20.3f, 20.1f, 20.2f), glm::vec3(20.3f + 1e-6f, 20.1f, 20.2f),
                                    glm::vec3(20.3f, 20.1f + 1e-6f, 20.2f)}},
                                  {}, {{{2.0f, -1.0f, 0.5f}, {1e9f, 0.0f, 1.0f}}});
    const VoxelImages gpu = voxelizeOnGpu(scene, exactGrid(32));
    size_t occupied = 0;
    for (const auto* image : {&gpu.albedoOpacity, &gpu.normal, &gpu.emission})
        for (const glm::vec4& texel : *image)
            ASSERT_TRUE(std::isfinite(texel.x) && std::isfinite(texel.y) && std::isfinite(texel.z) &&
                        std::isfinite(texel.w));
    for (const glm::vec4& texel : gpu.albedoOpacity) occupied += texel.a > 0.0f;
    EXPECT_EQ(occupied, 1u) << "only the tiny triangle marks a voxel";
    expectOccupiedListMatchesTheImages(gpu, 32);
    EXPECT_EQ(gpu.albedoOpacity[20 + 32 * (20 + 32 * 20)].a, 1.0f);
    const VoxelReference twin = voxelizeReference(scene, exactGrid(32));
    EXPECT_EQ(std::count_if(twin.count.begin(), twin.count.end(), [](uint32_t c) { return c > 0; }), 1);
}

TEST_F(Voxelize, EmptySceneGivesAnEmptyGrid) {
    const VoxelImages gpu = voxelizeOnGpu(makeScene({}), exactGrid(32));
    EXPECT_EQ(gpu.workItems, 0u);
    EXPECT_EQ(gpu.occupiedDispatch.count, 0u);
    expectOccupiedListMatchesTheImages(gpu, 32);
    for (const auto* image : {&gpu.albedoOpacity, &gpu.normal, &gpu.emission})
        for (const glm::vec4& texel : *image) ASSERT_EQ(texel, glm::vec4(0.0f));
}

TEST_F(Voxelize, EmissionIsTheMeanOfTheEmittingTrianglesOnly) {
    // A lamp 1 mm under a ceiling, both in voxel (5, 5, 5): the voxel keeps the lamp's whole emission
    // (averaged with the ceiling it would keep half), while its albedo and opacity count both.
    const Scene scene =
        makeScene({{glm::vec3(5.25f, 5.5f, 5.25f), glm::vec3(5.25f, 5.5f, 5.75f), glm::vec3(5.75f, 5.5f, 5.25f)},
                   {glm::vec3(5.1f, 5.501f, 5.1f), glm::vec3(5.1f, 5.501f, 5.9f), glm::vec3(5.9f, 5.501f, 5.1f)}},
                  {0, 1}, {{{1.0f, 1.0f, 1.0f}, {3.0f, 2.0f, 1.0f}}, {{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}}});
    const VoxelImages gpu = voxelizeOnGpu(scene, exactGrid(32));
    const size_t voxel = 5 + 32 * (5 + 32 * 5);
    EXPECT_NEAR(gpu.emission[voxel].r, 3.0f, kEmissionTolerance * 3.0f);
    EXPECT_NEAR(gpu.emission[voxel].g, 2.0f, kEmissionTolerance * 3.0f);
    EXPECT_NEAR(gpu.emission[voxel].b, 1.0f, kEmissionTolerance * 3.0f);
    EXPECT_NEAR(gpu.albedoOpacity[voxel].r, 0.5f, kAlbedoTolerance);
    EXPECT_EQ(gpu.albedoOpacity[voxel].a, 1.0f);
    expectMatchesTwin(scene, exactGrid(32), kAmbiguousMargin);
}

// A rectangle of two textured triangles in the plane z = `z` over voxels x ∈ [2, 9], y ∈ [2, 5]
// (its edges clear of the voxels' faces), mapped u = (x − 2)/8, v = (y − 2)/4: with a texture 8
// texels wide, voxel column x reads texel column x − 2 at its centre.
void addTexturedRectangle(Scene& scene, float z, uint32_t material) {
    const float x0 = 2.2f, x1 = 9.8f, y0 = 2.2f, y1 = 5.8f;
    auto corner = [&](float x, float y) {
        Vertex vertex;
        vertex.position = glm::vec3(x, y, z);
        vertex.u = (x - 2.0f) / 8.0f;
        vertex.v = (y - 2.0f) / 4.0f;
        vertex.uv1 = glm::vec2(vertex.u, vertex.v);
        return vertex;
    };
    const uint32_t first = uint32_t(scene.vertices.size());
    for (const Vertex& vertex : {corner(x0, y0), corner(x1, y0), corner(x1, y1), corner(x0, y1)})
        scene.vertices.push_back(vertex);
    for (uint32_t index : {0u, 1u, 2u, 0u, 2u, 3u}) scene.indices.push_back(first + index);
    scene.triangleMaterials.insert(scene.triangleMaterials.end(), {material, material});
}

Texture texture(uint32_t width, uint32_t height, const std::function<glm::u8vec3(uint32_t, uint32_t)>& texel) {
    Texture result;
    result.width = width;
    result.height = height;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            const glm::u8vec3 rgb = texel(x, y);
            result.rgba8.insert(result.rgba8.end(), {rgb.r, rgb.g, rgb.b, 255});
        }
    return result;
}

TEST_F(Voxelize, TexturesGiveEachVoxelTheColourOfTheSurfaceThere) {
    // The light the voxels bounce must have the colour the surface has there: a glTF model's
    // baseColorFactor is mostly white, its colour in the texture. Layer 3: base colour factor ½
    // through a texture red in its left half and green in its right. Layer 6: emission (3, 2, 1)
    // through an emissive texture black in its left half. Layer 9: a red and green checkerboard of
    // two texels per voxel, which a voxel sees as its mean, (½, ½, 0) in linear light, through the
    // texture's mip chain (one texel read would be red or green).
    Scene scene;
    scene.name = "textured voxels";
    auto halves = [](glm::u8vec3 left, glm::u8vec3 right) {
        return texture(8, 1, [=](uint32_t x, uint32_t) { return x < 4 ? left : right; });
    };
    scene.textures.push_back(halves({255, 0, 0}, {0, 255, 0}));
    scene.textures.push_back(halves({0, 0, 0}, {255, 255, 255}));
    scene.textures.push_back(texture(
        16, 8, [](uint32_t x, uint32_t y) { return (x + y) % 2 ? glm::u8vec3(255, 0, 0) : glm::u8vec3(0, 255, 0); }));
    Material halfColoured;
    halfColoured.baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    halfColoured.baseColorTexture.index = 0;
    Material halfGlowing;
    halfGlowing.emission = glm::vec3(3.0f, 2.0f, 1.0f);
    halfGlowing.emissiveTexture.index = 1;
    Material checkered;
    checkered.baseColorTexture.index = 2;
    scene.materials = {halfColoured, halfGlowing, checkered};
    addTexturedRectangle(scene, 3.5f, 0);
    addTexturedRectangle(scene, 6.5f, 1);
    addTexturedRectangle(scene, 9.5f, 2);

    const VoxelImages gpu = voxelizeOnGpu(scene, exactGrid(16));
    auto at = [&](const std::vector<glm::vec4>& image, uint32_t x, uint32_t y, uint32_t z) {
        return glm::vec3(image[x + 16 * (y + 16 * z)]);
    };
    auto expectNear = [](glm::vec3 actual, glm::vec3 expected, float tolerance, const std::string& where) {
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], tolerance) << where << " channel " << c;
    };
    // A voxel beside the colour edge (columns 5 and 6) that the rectangle's diagonal also crosses
    // averages two triangles' reads, one of them at the corner where the other triangle meets it,
    // on the edge: it lies between the two colours.
    auto expectBetween = [](glm::vec3 actual, glm::vec3 left, glm::vec3 right, float tolerance,
                            const std::string& where) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(actual[c], std::min(left[c], right[c]) - tolerance) << where << " channel " << c;
            EXPECT_LE(actual[c], std::max(left[c], right[c]) + tolerance) << where << " channel " << c;
        }
    };
    const glm::vec3 red(0.5f, 0.0f, 0.0f), green(0.0f, 0.5f, 0.0f), dark(0.0f), glowing(3.0f, 2.0f, 1.0f);
    for (uint32_t y = 2; y <= 5; ++y)
        for (uint32_t x = 2; x <= 9; ++x) {
            const std::string where = "voxel column " + std::to_string(x) + ", row " + std::to_string(y);
            const glm::vec3 albedo = at(gpu.albedoOpacity, x, y, 3), emission = at(gpu.emission, x, y, 6);
            if (x == 5 || x == 6) {
                expectBetween(albedo, red, green, kAlbedoTolerance, where + " of the half-coloured layer");
                expectBetween(emission, dark, glowing, kEmissionTolerance * 3.0f, where + " of the half-glowing layer");
            } else {
                expectNear(albedo, x < 6 ? red : green, kAlbedoTolerance, where + " of the half-coloured layer");
                expectNear(emission, x < 6 ? dark : glowing, kEmissionTolerance * 3.0f,
                           where + " of the half-glowing layer");
            }
            // sRGB 255 and 0 averaged in linear light, then stored as UNORM8.
            expectNear(at(gpu.albedoOpacity, x, y, 9), glm::vec3(0.5f, 0.5f, 0.0f), 1.0f / 255.0f,
                       where + " of the checkered layer");
        }
}

TEST_F(Voxelize, ABlendSurfaceIsAsOpaqueAsItsAlphaWhereItIs) {
    // BLEND through a texture opaque in its left half and clear in its right (factor alpha 1): the
    // voxels take the alpha of their own footprint, 1 on the left and none on the right, where the
    // texture's mean, 1/2, would make every voxel half opaque (an atlas's other parts counted).
    Scene scene;
    scene.name = "half-clear BLEND";
    Texture halfClear;
    halfClear.width = 8;
    halfClear.height = 1;
    for (uint32_t x = 0; x < 8; ++x)
        halfClear.rgba8.insert(halfClear.rgba8.end(), {255, 255, 255, uint8_t(x < 4 ? 255 : 0)});
    scene.textures.push_back(halfClear);
    Material blend;
    blend.alphaMode = AlphaMode::Blend;
    blend.baseColorTexture.index = 0;
    scene.materials = {blend};
    addTexturedRectangle(scene, 3.5f, 0);
    EXPECT_EQ(voxelCoverage(scene, scene.materials[0]), 0.5f);
    const VoxelImages gpu = voxelizeOnGpu(scene, exactGrid(16));
    for (uint32_t y = 2; y <= 5; ++y)
        for (uint32_t x = 2; x <= 9; ++x) {
            const float opacity = gpu.albedoOpacity[x + 16 * (y + 16 * 3)].a;
            if (x < 5) {
                EXPECT_EQ(opacity, 1.0f) << "voxel column " << x << ", row " << y;
            } else if (x > 6) {
                EXPECT_EQ(opacity, 0.0f) << "voxel column " << x << ", row " << y;
            }
        }
}

// A rectangle of two triangles in the plane z = `z` (a voxel centre plane: it touches that layer
// of voxels only) over voxels x, y ∈ [2, 5], its edges and diagonal clear of the voxels' corners.
std::vector<TriangleF> squareAt(float z) {
    const glm::vec3 a(2.3f, 2.2f, z), b(5.8f, 2.2f, z), c(5.8f, 5.7f, z), d(2.3f, 5.7f, z);
    return {{a, b, c}, {a, c, d}};
}

TEST_F(Voxelize, AlphaMaterialsMakeVoxelsAsOpaqueAsTheShareOfTheSurfaceThatIsThere) {
    // Layer 2: MASK through a texture of alphas 255, 200, 128, 128, 128, 127, 0, 0 (cutoff 0.5:
    // 128/255 passes, 127/255 does not), u running across the square's four voxel columns, two
    // texels a column: columns 2 and 3 are whole, column 4 half there, column 5 a hole (no voxel).
    // Layer 5: BLEND of alpha 0.5 (factor) → 1/2. Layer 8: MASK with a factor of alpha 0.3 below
    // its cutoff → no voxel. Layer 11: opaque and the mask sharing the voxels → 1, the largest.
    std::vector<TriangleF> triangles;
    std::vector<uint32_t> materials;
    for (auto [z, material] : {std::pair{2.5f, 1u}, {5.5f, 2u}, {8.5f, 3u}, {11.5f, 0u}, {11.5f, 1u}}) {
        for (const TriangleF& triangle : squareAt(z)) triangles.push_back(triangle);
        materials.insert(materials.end(), {material, material});
    }
    Scene scene = makeScene(triangles, materials, {{}, {}, {}, {}});
    for (Vertex& vertex : scene.vertices) vertex.u = vertex.uv1.x = (vertex.position.x - 2.0f) / 4.0f;
    Texture texture;
    texture.width = 8;
    texture.height = 1;
    for (uint8_t alpha : {255, 200, 128, 128, 128, 127, 0, 0})
        texture.rgba8.insert(texture.rgba8.end(), {255, 255, 255, alpha});
    scene.textures.push_back(texture);
    scene.materials[1].alphaMode = AlphaMode::Mask;
    scene.materials[1].baseColorTexture.index = 0;
    scene.materials[2].alphaMode = AlphaMode::Blend;
    scene.materials[2].baseColorFactor.a = 0.5f;
    scene.materials[3].alphaMode = AlphaMode::Mask;
    scene.materials[3].baseColorFactor.a = 0.3f;

    const VoxelImages gpu = voxelizeOnGpu(scene, exactGrid(16));
    // The opacity of voxel column x of layer z, the same in every row.
    auto opacityOfColumn = [&](uint32_t x, uint32_t z) {
        const float first = gpu.albedoOpacity[x + 16 * (2 + 16 * z)].a;
        for (uint32_t y = 3; y < 6; ++y)
            EXPECT_EQ(gpu.albedoOpacity[x + 16 * (y + 16 * z)].a, first) << "column " << x << " of layer " << z;
        return first;
    };
    std::printf(
        "voxel opacity: MASK columns %.4f %.4f %.4f %.4f, BLEND 1/2 %.4f, MASK below cutoff %.4f, "
        "with an opaque one %.4f\n",
        opacityOfColumn(2, 2), opacityOfColumn(3, 2), opacityOfColumn(4, 2), opacityOfColumn(5, 2),
        opacityOfColumn(3, 5), opacityOfColumn(3, 8), opacityOfColumn(5, 11));
    EXPECT_EQ(opacityOfColumn(2, 2), 1.0f);
    EXPECT_EQ(opacityOfColumn(3, 2), 1.0f);
    EXPECT_NEAR(opacityOfColumn(4, 2), 0.5f, kAlbedoTolerance);
    EXPECT_EQ(opacityOfColumn(5, 2), 0.0f) << "the hole";
    for (uint32_t x = 2; x < 6; ++x) {
        EXPECT_NEAR(opacityOfColumn(x, 5), 0.5f, kAlbedoTolerance);
        EXPECT_EQ(opacityOfColumn(x, 8), 0.0f);
        EXPECT_EQ(opacityOfColumn(x, 11), 1.0f);
    }
    expectMatchesTwin(scene, exactGrid(16), kAmbiguousMargin);
}

TEST_F(Voxelize, SixtyFiveThousandTrianglesInOneVoxelDoNotOverflow) {
    // The largest values each sum can receive, 70 000 times over (more than the 65 535 promised).
    const TriangleF triangle = {glm::vec3(5.1f, 5.1f, 5.9f), glm::vec3(5.9f, 5.1f, 5.9f), glm::vec3(5.1f, 5.9f, 5.9f)};
    const std::vector<TriangleF> triangles(70000, triangle);
    const VoxelImages gpu =
        voxelizeOnGpu(makeScene(triangles, {}, {{glm::vec3(1.0f), {3.0f, 3.0f, 3.0f}}}), exactGrid(32));
    const size_t voxel = 5 + 32 * (5 + 32 * 5);
    EXPECT_EQ(gpu.albedoOpacity[voxel], glm::vec4(1.0f));
    EXPECT_NEAR(gpu.normal[voxel].z, 1.0f, kNormalTolerance);
    EXPECT_NEAR(gpu.normal[voxel].w, 0.4f, 1e-3f) << "the plane 0.4 voxel in front of the centre";
    EXPECT_NEAR(gpu.emission[voxel].g, 3.0f, kEmissionTolerance * 3.0f);
}

TEST_F(Voxelize, CornellBoxMatchesTheCpuTwin) {
    const Scene scene = loadScene("cornell");
    for (uint32_t resolution : {64u, 128u}) {
        // The fitted grid puts the walls exactly on voxel faces (one voxel of margin), where float
        // rounding of the grid coordinates decides: those voxels are ambiguous by construction.
        // Shifted by a fraction of a voxel, the walls leave the faces and nearly nothing is ambiguous.
        glsl::VoxelGridParams grid = fitVoxelGrid(scene.bounds(), resolution);
        const VoxelImages fitted = voxelizeOnGpu(scene, grid, 2);
        for (const PassTime& time : fitted.times)
            std::cout << "cornell " << resolution << "³: " << time.name << " " << time.milliseconds << " ms on "
                      << test::gpu().deviceName() << ", " << fitted.workItems << " work items\n";
        const Comparison onFaces = compareWithTwin(fitted, voxelizeReference(scene, grid), kAmbiguousMargin);
        EXPECT_EQ(onFaces.mismatches, 0u) << resolution << ": " << onFaces.firstMismatch;
        // Voxelized three times: each run lists the voxels afresh.
        expectOccupiedListMatchesTheImages(fitted, resolution);
        std::cout << "cornell " << resolution << "³: " << fitted.occupied.size() << " occupied voxels ("
                  << 100.0 * double(fitted.occupied.size()) / double(fitted.albedoOpacity.size())
                  << " % of the grid)\n";

        grid.origin -= glm::vec3(0.37f * grid.voxelSize);
        const Comparison shifted =
            compareWithTwin(voxelizeOnGpu(scene, grid), voxelizeReference(scene, grid), kAmbiguousMargin);
        EXPECT_EQ(shifted.mismatches, 0u) << resolution << ": " << shifted.firstMismatch;
        EXPECT_LE(double(shifted.ambiguous), kMaxAmbiguousFraction * double(shifted.occupied))
            << shifted.ambiguous << " ambiguous voxels of " << shifted.occupied << " occupied";
    }
}

TEST(VoxelizeMemory, GridTooLargeForTheHeapNamesAResolutionThatFits) {
    VkPhysicalDeviceMemoryProperties memory{};
    memory.memoryHeapCount = 1;
    memory.memoryHeaps[0] = {VkDeviceSize(1) << 30, VK_MEMORY_HEAP_DEVICE_LOCAL_BIT};  // 1 GiB
    VkPhysicalDeviceLimits limits{};
    limits.maxStorageBufferRange = 0xFFFFFFFFu;
    EXPECT_NO_THROW(checkVoxelizeMemory(memory, limits, "a small GPU", 128));
    try {
        checkVoxelizeMemory(memory, limits, "a small GPU", 512);
        FAIL() << "a 512³ grid cannot fit in half a gigabyte";
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find("a small GPU"), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find("a 128³ grid would fit"), std::string::npos) << error.what();
    }
}

TEST(VoxelizeMemory, AScenePaysOnlyForTheChannelsItNeeds) {
    // Opacity (MASK, BLEND) is one channel, emission four; unneeded, each is one word.
    const uint64_t channel = uint64_t(64) * 64 * 64 * 4 - 4;
    EXPECT_EQ(voxelizeAccumulationBytes(64, {.opacity = true}) - voxelizeAccumulationBytes(64), channel);
    EXPECT_EQ(voxelizeAccumulationBytes(64, {.emission = true}) - voxelizeAccumulationBytes(64), 4 * channel);
    // lavapipe's heap is 2 GiB, of which the voxelizer may take half.
    EXPECT_LE(voxelizeMemoryBytes(256), uint64_t(1) << 30) << "an opaque scene without emitters at 256³";
}

}  // namespace
}  // namespace vct
