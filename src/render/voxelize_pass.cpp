#include "render/voxelize_pass.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "bindings.h"
#include "error.h"
#include "gpu/commands.h"
#include "gpu/pass_uses.h"
#include "render/renderer_limits.h"
#include "render/voxelize_reference.h"
#include "scene/material_textures.h"

namespace vct {
namespace {

// Whether a scene needing `channels` keeps a whole buffer for accumulation channel `channel`.
bool keepsChannel(uint32_t channel, VoxelizeChannels channels) {
    if (channel == glsl::ACCUM_OPACITY) return channels.opacity;
    if (channel == glsl::ACCUM_EMITTERS || (channel >= glsl::ACCUM_EMISSION && channel < glsl::ACCUM_EMISSION + 3))
        return channels.emission;
    return true;
}

// Whether a MASK material reads a base colour texture (voxelize.comp samples it over each voxel).
bool hasMaskTextures(const Scene& scene) {
    return std::any_of(scene.materials.begin(), scene.materials.end(),
                       [&](const Material& material) { return masksVoxelsByTexture(scene, material); });
}

// Tiles are kept when the triangle's separation from the tile's box is at most this (grid units):
// far above float rounding (~10⁻⁵ voxel), so a voxel the GPU marks is never in a dropped tile.
constexpr double kTileSlack = 1e-3;

// The work list is held on the host and the device: at most a quarter of the device's largest heap,
// and never more than this: 2²² items, about a minute of voxelization on lavapipe with 2 cores
// (13 µs an item for large triangles; milliseconds on a GPU), where realistic scenes need far fewer
// (the Cornell box at 512³ 0.11 M, the 66 560-triangle terrain at 512³ 0.23 M). A voxelization
// longer than the GPU timeout (120 s) would fail anyway.
constexpr uint64_t kMaxWorkItemBytes = uint64_t(32) << 20;
uint64_t cube(uint32_t resolution) { return uint64_t(resolution) * resolution * resolution; }

bool gridFits(uint64_t heapBytes, uint64_t maxBufferRange, uint32_t resolution, VoxelizeChannels channels) {
    return voxelizeMemoryBytes(resolution, channels) <= heapBytes / 2 && cube(resolution) * 4 <= maxBufferRange;
}

}  // namespace

VoxelizeChannels voxelizeChannels(const Scene& scene) {
    VoxelizeChannels channels;
    channels.opacity = scene.hasAlphaMaterials();
    for (const Material& material : scene.materials)
        channels.emission = channels.emission || emitsLight(scene, material);
    return channels;
}

uint64_t voxelizeMemoryBytes(uint32_t resolution, VoxelizeChannels channels) {
    return voxelizeAccumulationBytes(resolution, channels) +
           voxelVolumeBytes(ResourceSettings{.voxelResolution = resolution}, true);
}

uint64_t voxelizeAccumulationBytes(uint32_t resolution, VoxelizeChannels channels) {
    uint64_t bytes = 0;
    for (uint32_t channel = 0; channel < glsl::ACCUM_CHANNELS; ++channel)
        bytes += keepsChannel(channel, channels) ? cube(resolution) * 4 : 4;
    return bytes;
}

void checkVoxelizeMemory(const VkPhysicalDeviceMemoryProperties& memory, const VkPhysicalDeviceLimits& limits,
                         const std::string& deviceName, uint32_t resolution, VoxelizeChannels channels) {
    const uint64_t heapBytes = largestDeviceLocalHeap(memory);
    if (gridFits(heapBytes, limits.maxStorageBufferRange, resolution, channels)) return;
    uint32_t fitting = resolution;
    while (fitting > 1 && !gridFits(heapBytes, limits.maxStorageBufferRange, fitting, channels)) fitting /= 2;
    const std::string size = std::to_string(resolution);
    std::string message =
        "a " + size + "³ voxel grid needs " + std::to_string(voxelizeMemoryBytes(resolution, channels) >> 20) +
        " MiB of GPU memory, more than " + deviceName + " can spare (half of its " + std::to_string(heapBytes >> 20) +
        " MiB heap, buffers of at most " + std::to_string(limits.maxStorageBufferRange >> 20) + " MiB)";
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

uint64_t voxelizeWorkItemLimit(const VkPhysicalDeviceMemoryProperties& memory) {
    return std::min(largestDeviceLocalHeap(memory) / 4, kMaxWorkItemBytes) / sizeof(glm::uvec2);
}

namespace {

Error tooManyWorkItems(const Scene& scene, uint32_t resolution, const std::string& howMany, uint64_t count,
                       uint64_t maxItems) {
    return Error("scene '" + scene.name + "': voxelizing its " + std::to_string(scene.triangleCount()) +
                 " triangles at " + std::to_string(resolution) + "³ takes " + howMany + " " + std::to_string(count) +
                 " work items (one per triangle and " + std::to_string(glsl::VOXELIZE_TILE) +
                 "³-voxel tile it crosses), more than the " + std::to_string(maxItems) + " (" +
                 bytesText(maxItems * sizeof(glm::uvec2)) +
                 ") the device allows (a quarter of its largest heap, at most " + bytesText(kMaxWorkItemBytes) +
                 "); a coarser --voxels or fewer large triangles would fit");
}

// At least as many work items as the scene will need: the tiles a triangle touches cover its
// projection along its normal's dominant axis, so they number at least that projection's area in
// tiles (counted for triangles inside the grid only, where clipping removes no area). It takes a
// pass over the triangles, so a scene far over the bound is refused before any tile is searched.
uint64_t fewestWorkItems(const Scene& scene, const std::vector<uint32_t>& order, const glsl::VoxelGridParams& grid) {
    const double tileArea = double(glsl::VOXELIZE_TILE) * glsl::VOXELIZE_TILE;
    double total = 0.0;
    for (uint32_t triangleIndex : order) {
        if (isDegenerateTriangle(scene, triangleIndex)) continue;
        const TriangleD triangle = gridTriangle(scene, grid, triangleIndex);
        const glm::dvec3 low = glm::min(triangle[0], glm::min(triangle[1], triangle[2]));
        const glm::dvec3 high = glm::max(triangle[0], glm::max(triangle[1], triangle[2]));
        if (glm::any(glm::lessThan(low, glm::dvec3(0.0))) ||
            glm::any(glm::greaterThan(high, glm::dvec3(grid.resolution))))
            continue;
        const glm::dvec3 normal = glm::abs(glm::cross(triangle[1] - triangle[0], triangle[2] - triangle[0]));
        total += std::floor(0.5 * std::max({normal.x, normal.y, normal.z}) / tileArea);
    }
    return uint64_t(std::min(total, 1e18));
}

}  // namespace

std::vector<glm::uvec2> buildVoxelizeWorkItems(const Scene& scene, const std::vector<uint32_t>& order,
                                               const glsl::VoxelGridParams& grid, uint64_t maxItems) {
    const uint32_t resolution = grid.resolution;
    const int tile = int(glsl::VOXELIZE_TILE);
    const double halfTile = 0.5 * tile;
    const uint64_t fewest = fewestWorkItems(scene, order, grid);
    if (fewest > maxItems) throw tooManyWorkItems(scene, resolution, "at least", fewest, maxItems);
    std::vector<glm::uvec2> items;
    for (uint32_t position = 0; position < order.size(); ++position) {
        if (isDegenerateTriangle(scene, order[position])) continue;
        // The tiles that the set-back copy the GPU marks voxels of may reach (voxelize.comp).
        const TriangleD triangle = setBackTriangle(gridTriangle(scene, grid, order[position]));
        const VoxelRange range = triangleVoxelRange(triangle, resolution, kTileSlack);
        if (range.empty()) continue;
        const glm::ivec3 firstTile = range.first / tile, lastTile = range.last / tile;
        // A large triangle's bounding box holds (N/4)³ tiles, but its plane crosses only about (N/4)²
        // of them: along the normal's dominant axis d, each column of tiles is searched only where
        // the plane can be within reach of a tile (its separation along the normal at most the slack),
        // widened by a tile against rounding. The separating-axis test then decides as before.
        const glm::dvec3 normal = glm::cross(triangle[1] - triangle[0], triangle[2] - triangle[0]);
        const glm::dvec3 magnitude = glm::abs(normal);
        const int d = magnitude.x >= magnitude.y && magnitude.x >= magnitude.z ? 0 : magnitude.y >= magnitude.z ? 1 : 2;
        const int u = (d + 1) % 3, v = (d + 2) % 3;
        const double reach = halfTile * (magnitude.x + magnitude.y + magnitude.z) + kTileSlack * glm::length(normal);
        const size_t firstItem = items.size();
        glm::ivec3 cell;
        for (cell[u] = firstTile[u]; cell[u] <= lastTile[u]; ++cell[u])
            for (cell[v] = firstTile[v]; cell[v] <= lastTile[v]; ++cell[v]) {
                // |normal · (centre − corner 0)| ≤ reach, solved for the centre's coordinate along d.
                const double rest = normal[u] * (cell[u] * tile + halfTile - triangle[0][u]) +
                                    normal[v] * (cell[v] * tile + halfTile - triangle[0][v]);
                const double a = (-reach - rest) / normal[d], b = (reach - rest) / normal[d];
                const double low = triangle[0][d] + std::min(a, b), high = triangle[0][d] + std::max(a, b);
                int first = firstTile[d], last = lastTile[d];
                if (std::isfinite(low) && std::isfinite(high)) {  // else (a normal that underflowed) all of them
                    first = std::max(first, int(std::clamp(std::floor((low - halfTile) / tile), -2.0, 2048.0)) - 1);
                    last = std::min(last, int(std::clamp(std::ceil((high - halfTile) / tile), -2.0, 2048.0)) + 1);
                }
                for (cell[d] = first; cell[d] <= last; ++cell[d]) {
                    const glm::dvec3 center = glm::dvec3(cell) * double(tile) + halfTile;
                    if (triangleBoxSeparation(triangle, center, halfTile) > kTileSlack) continue;
                    items.push_back({position, glsl::packCell(glm::uvec3(cell))});
                }
            }
        // The order a z, y, x scan gives (packCell puts z in the high bits), whatever d was.
        std::sort(items.begin() + long(firstItem), items.end(),
                  [](const glm::uvec2& a, const glm::uvec2& b) { return a.y < b.y; });
        if (items.size() > maxItems) throw tooManyWorkItems(scene, resolution, "more than", maxItems, maxItems);
    }
    return items;
}

VoxelizePass::VoxelizePass(GpuContext& context, const Scene& scene, const SceneGpu& sceneGpu,
                           const glsl::VoxelGridParams& grid, uint64_t maxChunkItems)
    : context_(context) {
    const uint32_t resolution = grid.resolution;
    if (resolution == 0 || resolution % glsl::VOXELIZE_TILE != 0 || resolution > 1024 * glsl::VOXELIZE_TILE)
        throw Error("the voxelizer needs a resolution that is a multiple of 4, up to 4096, not " +
                    std::to_string(resolution));
    const VoxelizeChannels channels = voxelizeChannels(scene);
    checkVoxelizeMemory(context.memoryProperties, context.properties.limits, context.deviceName(), resolution,
                        channels);
    params.dispatch.z = channels.opacity ? 1u : 0u;

    const std::vector<glm::uvec2> items = buildVoxelizeWorkItems(scene, gpuTriangleOrder(scene, sceneGpu), grid,
                                                                 voxelizeWorkItemLimit(context.memoryProperties));

    // The largest emission a voxel can receive: an emitting material's factor (its emissive texture,
    // sampled per voxel, is at most 1).
    float largestEmission = 0.0f;
    for (const Material& material : scene.materials) {
        if (emitsLight(scene, material))
            largestEmission =
                std::max({largestEmission, material.emission.x, material.emission.y, material.emission.z});
    }
    params.grid = grid;
    params.grid.triangleCount = uint32_t(scene.triangleCount());
    params.grid.workItems = uint32_t(items.size());
    if (largestEmission > 0.0f)
        params.emission = glm::vec4(glsl::EMISSION_FIXED_MAX / largestEmission,
                                    largestEmission / glsl::EMISSION_FIXED_MAX, 0.0f, 0.0f);
    const uint32_t rowLimit = context.properties.limits.maxComputeWorkGroupCount[0];
    params.dispatch.y = rowLimit;

    // The work items go in chunks, each in a buffer within maxStorageBufferRange and one dispatch of
    // its own, so no buffer or dispatch grows with the scene (300 000 large triangles at 128³ make
    // about 10⁹ items, which one buffer and one dispatch did not survive).
    const uint64_t chunkItems = std::min<uint64_t>(
        std::max<uint64_t>(maxChunkItems, 1), context.properties.limits.maxStorageBufferRange / sizeof(glm::uvec2));
    for (uint64_t first = 0; first < items.size(); first += chunkItems) {
        WorkChunk& chunk = workChunks.emplace_back();
        chunk.count = uint32_t(std::min<uint64_t>(chunkItems, items.size() - first));
        chunk.items = uploadBuffer(context, items.data() + first, chunk.count * sizeof(glm::uvec2),
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        // Work items may outnumber the workgroups one dispatch row allows: fold them into rows.
        chunk.groupsPerRow = std::min(chunk.count, rowLimit);
        chunk.rows = (chunk.count + chunk.groupsPerRow - 1) / chunk.groupsPerRow;
    }

    for (uint32_t channel = 0; channel < glsl::ACCUM_CHANNELS; ++channel) {
        accumulation[channel] = Buffer(context, keepsChannel(channel, channels) ? cube(resolution) * 4 : 4,
                                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false);
    }
    voxelizePipeline = createComputePipeline(
        context, "voxelize.comp", {sceneGpu.textureSetLayout},
        specializationConstants({{glsl::TEXTURE_COUNT_CONSTANT_ID, sceneGpu.textureCount()},
                                 {glsl::MASK_TEXTURES_CONSTANT_ID, hasMaskTextures(scene) ? 1u : 0u}}));
    resolvePipeline = createComputePipeline(context, "voxel_resolve.comp");
}

std::vector<VkBuffer> VoxelizePass::accumulationBuffers() const {
    std::vector<VkBuffer> buffers;
    for (const Buffer& channel : accumulation) buffers.push_back(channel.buffer);
    return buffers;
}

void VoxelizePass::record(VkCommandBuffer commands, const SceneGpu& sceneGpu, VoxelVolumes& volumes) {
    const uint32_t resolution = params.grid.resolution;
    // The sums start at zero and the occupied list empty, once whatever read them last is done.
    PassUses cleared;
    for (const Buffer& channel : accumulation) cleared.use(channel, access::transferWrite);
    cleared.use(volumes.occupiedDispatch, access::transferWrite).record(commands);
    for (Buffer& channel : accumulation) vkCmdFillBuffer(commands, channel.buffer, 0, VK_WHOLE_SIZE, 0u);
    const glsl::WorkListHeader none{0u, 1u, 1u, 0u};
    vkCmdUpdateBuffer(commands, volumes.occupiedDispatch.buffer, 0, sizeof(none), &none);

    // Chunks only add to the sums (atomics): they need no barrier between them.
    PassUses summed;
    for (const Buffer& channel : accumulation) summed.use(channel, access::computeWrite);
    summed.record(commands);
    if (!workChunks.empty()) {
        vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, voxelizePipeline.pipeline);
        vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, voxelizePipeline.layout, glsl::TEXTURES_SET,
                                1, &sceneGpu.voxelTextureSet, 0, nullptr);
    }
    for (const WorkChunk& chunk : workChunks) {
        DescriptorPush()
            .buffer(glsl::VERTICES_BINDING, sceneGpu.vertices.buffer)
            .buffer(glsl::INDICES_BINDING, sceneGpu.indices.buffer)
            .buffer(glsl::TRIANGLE_MATERIALS_BINDING, sceneGpu.triangleMaterials.buffer)
            .buffer(glsl::MATERIALS_BINDING, sceneGpu.materials.buffer)
            .buffer(glsl::VOXELIZER_WORK_ITEMS_BINDING, chunk.items.buffer)
            .buffers(glsl::VOXEL_ACCUMULATION_BINDING, accumulationBuffers())
            .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, voxelizePipeline);
        glsl::VoxelizeParams chunkParams = params;
        chunkParams.grid.workItems = chunk.count;
        chunkParams.dispatch.x = chunk.groupsPerRow;
        vkCmdPushConstants(commands, voxelizePipeline.layout, VK_SHADER_STAGE_ALL, 0, sizeof(chunkParams),
                           &chunkParams);
        vkCmdDispatch(commands, chunk.groupsPerRow, chunk.rows, 1);
    }
    // The resolve rewrites every texel of the scene voxels and lists the occupied ones.
    PassUses resolved;
    for (const Buffer& channel : accumulation) resolved.use(channel, access::computeRead);
    for (const GpuImage* written : {&volumes.albedoOpacity, &volumes.normal, &volumes.emission, &volumes.radiance})
        resolved.use(*written, access::computeWrite);
    if (volumes.gatheredLight.image != VK_NULL_HANDLE) resolved.use(volumes.gatheredLight, access::computeWrite);
    resolved.use(volumes.occupiedVoxels, access::computeWrite)
        .use(volumes.occupiedDispatch, access::computeWrite)
        .record(commands);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, resolvePipeline.pipeline);
    DescriptorPush()
        .buffers(glsl::VOXEL_ACCUMULATION_BINDING, accumulationBuffers())
        .storageImage(glsl::VOXEL_ALBEDO_BINDING, volumes.albedoOpacity.view)
        .storageImage(glsl::VOXEL_NORMAL_BINDING, volumes.normal.view)
        .storageImage(glsl::VOXEL_EMISSION_BINDING, volumes.emission.view)
        .buffer(glsl::OCCUPIED_VOXELS_BINDING, volumes.occupiedVoxels.buffer)
        .buffer(glsl::OCCUPIED_LIST_BINDING, volumes.occupiedDispatch.buffer)
        .storageImages(glsl::LIGHT_VOLUMES_BINDING, volumes.lightLevelZeroViews())
        .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, resolvePipeline);
    vkCmdPushConstants(commands, resolvePipeline.layout, VK_SHADER_STAGE_ALL, 0, sizeof(params), &params);
    const uint32_t groups = resolution / 4;
    vkCmdDispatch(commands, groups, groups, groups);
}

}  // namespace vct
