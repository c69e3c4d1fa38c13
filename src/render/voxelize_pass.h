// Voxelizes the scene's triangles into a 3D grid: albedo and opacity, mean normal, emission.
// Conservative (every voxel a triangle touches) and order-independent (integer sums); see
// shaders_glsl/voxelize.h for the work split and the fixed-point scales, and voxelize_reference.h
// for the CPU twin that specifies the result.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "render/scene_gpu.h"
#include "render/voxel_volumes.h"
#include "scene/scene.h"
#include "voxelize.h"

namespace vct {

// The accumulation channels a scene needs beyond those every voxel has (voxelize.h): opacity for
// MASK or BLEND materials, emission for emitting ones. Those it does not need are one word each, so
// that a scene pays only for what it has (an opaque scene without emitters fits a 256³ grid in
// lavapipe's share of its heap).
struct VoxelizeChannels {
    bool opacity = false;
    bool emission = false;
};
VoxelizeChannels voxelizeChannels(const Scene& scene);

// Bytes a grid of resolution³ voxels needs on the GPU: the scene voxels (VoxelVolumes) and the
// accumulation buffers; and the accumulation buffers alone.
uint64_t voxelizeMemoryBytes(uint32_t resolution, VoxelizeChannels channels = {});
uint64_t voxelizeAccumulationBytes(uint32_t resolution, VoxelizeChannels channels = {});

// Throws a vct::Error naming the largest resolution that would fit when the grid needs more than
// half of the device's largest device-local heap (the rest is left to the scene, the frame's
// images and the radiance volume), or an accumulation buffer exceeds maxStorageBufferRange.
void checkVoxelizeMemory(const VkPhysicalDeviceMemoryProperties& memory, const VkPhysicalDeviceLimits& limits,
                         const std::string& deviceName, uint32_t resolution, VoxelizeChannels channels = {});

// The order SceneGpu stores the triangles in (stable by material), checked against its material ranges.
std::vector<uint32_t> gpuTriangleOrder(const Scene& scene, const SceneGpu& sceneGpu);

// The most work items a scene may need on a device (a quarter of its largest heap, at most 32 MiB,
// 2²² items).
uint64_t voxelizeWorkItemLimit(const VkPhysicalDeviceMemoryProperties& memory);

// The (triangle, packed tile) work items: for every non-degenerate triangle, the tiles of its voxel
// bounding box (clipped to the grid) that the triangle may touch, in z, y, x order. `order[i]` is the
// scene triangle stored at position i on the GPU; work items name positions. Throws vct::Error
// naming the scene and the bound when the list would hold more than `maxItems`: at once when the
// triangles' areas already say so, else as soon as the list grows past it.
std::vector<glm::uvec2> buildVoxelizeWorkItems(const Scene& scene, const std::vector<uint32_t>& order,
                                               const glsl::VoxelGridParams& grid, uint64_t maxItems = UINT32_MAX);

struct VoxelizePass {
    // `scene` is the CPU copy of what `sceneGpu` holds: the work items are built from it, once, and
    // split into chunks of at most `maxChunkItems` (kMaxChunkItems; tests pass fewer).
    static constexpr uint64_t kMaxChunkItems = uint64_t(1) << 22;  // 32 MiB a buffer
    VoxelizePass(GpuContext& context, const Scene& scene, const SceneGpu& sceneGpu, const glsl::VoxelGridParams& grid,
                 uint64_t maxChunkItems = kMaxChunkItems);

    // Clears the sums, voxelizes, resolves into the scene voxels of `volumes` (albedo and opacity,
    // normal, emission), visible to later compute and fragment shader reads (sampled or storage).
    void record(VkCommandBuffer commands, const SceneGpu& sceneGpu, VoxelVolumes& volumes);

    glsl::VoxelizeParams params{};                          // its grid with triangleCount and workItems
    std::array<Buffer, glsl::ACCUM_CHANNELS> accumulation;  // uint per voxel each, cleared every record
    // The work items, uvec2 (triangle, packed tile), in chunks of one buffer and one dispatch each.
    struct WorkChunk {
        Buffer items;
        uint32_t count = 0;
        uint32_t groupsPerRow = 0, rows = 0;  // the chunk's dispatch is groupsPerRow × rows
    };
    std::vector<WorkChunk> workChunks;
    Pipeline voxelizePipeline;
    Pipeline resolvePipeline;

private:
    std::vector<VkBuffer> accumulationBuffers() const;
    GpuContext& context_;
};

}  // namespace vct
