#include "render/voxelize_pass.h"

#include <algorithm>
#include <numeric>

#include "error.h"
#include "gpu/commands.h"
#include "render/voxelize_reference.h"

namespace vct {
namespace {

constexpr uint64_t kAccumulationBytesPerVoxel = 4 * glsl::ACCUM_CHANNELS;

// Tiles are kept when the triangle's separation from the tile's box is at most this (grid units):
// far above float rounding (~10⁻⁵ voxel), so a voxel the GPU marks is never in a dropped tile.
constexpr double kTileSlack = 1e-3;

uint64_t cube(uint32_t resolution) { return uint64_t(resolution) * resolution * resolution; }

bool gridFits(uint64_t heapBytes, uint64_t maxBufferRange, uint32_t resolution) {
    return voxelizeMemoryBytes(resolution) <= heapBytes / 2 && cube(resolution) * 4 <= maxBufferRange;
}

}  // namespace

uint64_t voxelizeMemoryBytes(uint32_t resolution) {
    return voxelizeAccumulationBytes(resolution) +
           voxelVolumeBytes(ResourceSettings{.voxelResolution = resolution}, true);
}

uint64_t voxelizeAccumulationBytes(uint32_t resolution) { return cube(resolution) * kAccumulationBytesPerVoxel; }

void checkVoxelizeMemory(const VkPhysicalDeviceMemoryProperties& memory, const VkPhysicalDeviceLimits& limits,
                         const std::string& deviceName, uint32_t resolution) {
    uint64_t heapBytes = 0;
    for (uint32_t i = 0; i < memory.memoryHeapCount; ++i)
        if (memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            heapBytes = std::max<uint64_t>(heapBytes, memory.memoryHeaps[i].size);
    if (gridFits(heapBytes, limits.maxStorageBufferRange, resolution)) return;
    uint32_t fitting = resolution;
    while (fitting > 1 && !gridFits(heapBytes, limits.maxStorageBufferRange, fitting)) fitting /= 2;
    const std::string size = std::to_string(resolution);
    std::string message = "a " + size + "³ voxel grid needs " + std::to_string(voxelizeMemoryBytes(resolution) >> 20) +
                          " MiB of GPU memory, more than " + deviceName + " can spare (half of its " +
                          std::to_string(heapBytes >> 20) + " MiB heap, buffers of at most " +
                          std::to_string(limits.maxStorageBufferRange >> 20) + " MiB)";
    message += fitting > 1 ? "; a " + std::to_string(fitting) + "³ grid would fit" : "; no grid would fit";
    throw Error(message);
}

std::vector<uint32_t> gpuTriangleOrder(const Scene& scene, const SceneGpu& sceneGpu) {
    const uint32_t count = uint32_t(scene.triangleCount());
    if (count != sceneGpu.triangleCount)
        throw Error("the voxelizer was given a scene of " + std::to_string(count) + " triangles but the GPU holds " +
                    std::to_string(sceneGpu.triangleCount));
    std::vector<uint32_t> order(count);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return scene.triangleMaterials[a] < scene.triangleMaterials[b]; });
    uint32_t covered = 0;
    for (const SceneGpu::MaterialRange& range : sceneGpu.materialRanges)
        for (uint32_t i = range.firstIndex / 3; i < (range.firstIndex + range.indexCount) / 3; ++i, ++covered)
            if (i >= count || scene.triangleMaterials[order[i]] != range.material)
                throw Error("the voxelizer's scene and the scene on the GPU order their triangles differently");
    if (covered != count) throw Error("the scene on the GPU does not cover every triangle of the voxelizer's scene");
    return order;
}

std::vector<glm::uvec2> buildVoxelizeWorkItems(const Scene& scene, const std::vector<uint32_t>& order,
                                               const glsl::VoxelGridParams& grid) {
    const uint32_t resolution = grid.resolution.x;
    const int tile = int(glsl::VOXELIZE_TILE);
    const double halfTile = 0.5 * tile;
    std::vector<glm::uvec2> items;
    for (uint32_t position = 0; position < order.size(); ++position) {
        if (isDegenerateTriangle(scene, order[position])) continue;
        const TriangleD triangle = gridTriangle(scene, grid, order[position]);
        const VoxelRange range = triangleVoxelRange(triangle, resolution, kTileSlack);
        if (range.empty()) continue;
        const glm::ivec3 firstTile = range.first / tile, lastTile = range.last / tile;
        for (int z = firstTile.z; z <= lastTile.z; ++z)
            for (int y = firstTile.y; y <= lastTile.y; ++y)
                for (int x = firstTile.x; x <= lastTile.x; ++x) {
                    const glm::dvec3 center = glm::dvec3(x, y, z) * double(tile) + halfTile;
                    if (triangleBoxSeparation(triangle, center, halfTile) > kTileSlack) continue;
                    items.push_back({position, glsl::packCell(glm::uvec3(x, y, z))});
                }
    }
    return items;
}

VoxelizePass::VoxelizePass(GpuContext& context, const Scene& scene, const SceneGpu& sceneGpu,
                           const glsl::VoxelGridParams& grid)
    : context_(context) {
    const uint32_t resolution = grid.resolution.x;
    if (resolution == 0 || resolution % glsl::VOXELIZE_TILE != 0 || resolution > 1024 * glsl::VOXELIZE_TILE)
        throw Error("the voxelizer needs a resolution that is a multiple of 4, up to 4096, not " +
                    std::to_string(resolution));
    checkVoxelizeMemory(context.memoryProperties, context.properties.limits, context.deviceName(), resolution);

    const std::vector<glm::uvec2> items = buildVoxelizeWorkItems(scene, gpuTriangleOrder(scene, sceneGpu), grid);
    const glm::uvec2 none(0u);
    workItems =
        uploadBuffer(context, items.empty() ? &none : items.data(),
                     std::max<size_t>(items.size(), 1) * sizeof(glm::uvec2), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);

    float largestEmission = 0.0f;
    for (const Material& material : scene.materials)
        largestEmission = std::max({largestEmission, material.emission.x, material.emission.y, material.emission.z});
    params.grid = grid;
    params.grid.resolution.z = uint32_t(scene.triangleCount());
    params.grid.resolution.w = uint32_t(items.size());
    if (largestEmission > 0.0f)
        params.emission = glm::vec4(glsl::EMISSION_FIXED_MAX / largestEmission,
                                    largestEmission / glsl::EMISSION_FIXED_MAX, 0.0f, 0.0f);
    // Work items may outnumber the workgroups one dispatch row allows: fold them into rows.
    const uint32_t rowLimit = context.properties.limits.maxComputeWorkGroupCount[0];
    params.dispatch.x = std::clamp(uint32_t(items.size()), 1u, rowLimit);
    workGroupRows = (uint32_t(items.size()) + params.dispatch.x - 1) / params.dispatch.x;
    params.dispatch.y = rowLimit;

    for (Buffer& channel : accumulation)
        channel = Buffer(context, cube(resolution) * 4,
                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false);
    voxelizePipeline = createComputePipeline(context, "voxelize.comp");
    resolvePipeline = createComputePipeline(context, "voxel_resolve.comp");
}

std::vector<VkBuffer> VoxelizePass::accumulationBuffers() const {
    std::vector<VkBuffer> buffers;
    for (const Buffer& channel : accumulation) buffers.push_back(channel.buffer);
    return buffers;
}

void VoxelizePass::record(VkCommandBuffer commands, const SceneGpu& sceneGpu, VoxelVolumes& volumes) {
    const uint32_t resolution = params.grid.resolution.x;
    // The previous frame's resolve may still read the sums: wait for it before clearing.
    memoryBarrier(commands, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                  VK_ACCESS_2_NONE);
    for (Buffer& channel : accumulation) vkCmdFillBuffer(commands, channel.buffer, 0, VK_WHOLE_SIZE, 0u);
    memoryBarrier(commands, VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    // The resolve rewrites every texel of the scene voxels and the occupied list: earlier reads of
    // them (the last light passes' indirect dispatches among them) must be done. The list starts
    // empty.
    memoryBarrier(commands,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                      VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                  VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                  VK_ACCESS_2_NONE);
    const glsl::WorkListHeader none{0u, 1u, 1u, 0u};
    vkCmdUpdateBuffer(commands, volumes.occupiedDispatch.buffer, 0, sizeof(none), &none);
    memoryBarrier(commands, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);

    if (params.grid.resolution.w > 0) {
        vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, voxelizePipeline.pipeline);
        DescriptorPush()
            .buffer(0, sceneGpu.vertices.buffer)
            .buffer(1, sceneGpu.indices.buffer)
            .buffer(2, sceneGpu.triangleMaterials.buffer)
            .buffer(3, sceneGpu.materials.buffer)
            .buffer(4, workItems.buffer)
            .buffers(5, accumulationBuffers())
            .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, voxelizePipeline.layout);
        vkCmdPushConstants(commands, voxelizePipeline.layout, VK_SHADER_STAGE_ALL, 0, sizeof(params), &params);
        vkCmdDispatch(commands, params.dispatch.x, workGroupRows, 1);
        memoryBarrier(commands, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    }

    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, resolvePipeline.pipeline);
    DescriptorPush()
        .buffers(0, accumulationBuffers())
        .storageImage(1, volumes.albedoOpacity.view)
        .storageImage(2, volumes.normal.view)
        .storageImage(3, volumes.emission.view)
        .buffer(4, volumes.occupiedVoxels.buffer)
        .buffer(5, volumes.occupiedDispatch.buffer)
        .storageImages(6, volumes.lightLevelZeroViews())
        .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, resolvePipeline.layout);
    vkCmdPushConstants(commands, resolvePipeline.layout, VK_SHADER_STAGE_ALL, 0, sizeof(params), &params);
    const uint32_t groups = resolution / 4;
    vkCmdDispatch(commands, groups, groups, groups);

    memoryBarrier(commands, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                      VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                  VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                      VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
}

}  // namespace vct
