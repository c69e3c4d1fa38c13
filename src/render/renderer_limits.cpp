#include "render/renderer_limits.h"

#include <algorithm>
#include <cstdio>

#include "error.h"
#include "gpu_types.h"
#include "render/shadow_pass.h"
#include "render/voxel_grid_fit.h"
#include "render/voxel_volumes.h"
#include "render/voxelize_pass.h"
#include "scene/scene_limits.h"

namespace vct {
namespace {

// Bytes per texel of the formats the passes create (see each pass's constructor).
constexpr uint64_t kShadowTexel = 4;  // D32
constexpr uint64_t kSampleBytes =
    16 + 8 + 8 + 8 + 4 + 16;             // G-buffer position, normal, base colour, emissive, depth; shade
constexpr uint64_t kResolvedPixel = 16;  // RGBA32F

// The tightest of the limits a 2D render target's side must respect, with its Vulkan name.
struct SideLimit {
    uint32_t value;
    const char* name;
};
SideLimit renderTargetSideLimit(const VkPhysicalDeviceLimits& limits, bool width) {
    SideLimit tightest{limits.maxImageDimension2D, "maxImageDimension2D"};
    const SideLimit others[] = {{width ? limits.maxFramebufferWidth : limits.maxFramebufferHeight,
                                 width ? "maxFramebufferWidth" : "maxFramebufferHeight"},
                                {width ? limits.maxViewportDimensions[0] : limits.maxViewportDimensions[1],
                                 width ? "maxViewportDimensions[0]" : "maxViewportDimensions[1]"}};
    for (const SideLimit& other : others)
        if (other.value < tightest.value) tightest = other;
    return tightest;
}

uint32_t largestPowerOfTwoAtMost(uint32_t value) {
    uint32_t power = 1;
    while (power <= value / 2) power *= 2;
    return power;
}

void checkVoxelResolution(const VkPhysicalDeviceLimits& limits, const std::string& deviceName, uint32_t resolution) {
    if (resolution < kMinVoxelResolution || resolution > kMaxVoxelResolution || (resolution & (resolution - 1)) != 0)
        throw Error("the voxel resolution must be a power of two from " + std::to_string(kMinVoxelResolution) + " to " +
                    std::to_string(kMaxVoxelResolution) + ", not " + std::to_string(resolution));
    if (resolution > limits.maxImageDimension3D) {
        const uint32_t fitting = largestPowerOfTwoAtMost(limits.maxImageDimension3D);
        throw Error("a " + std::to_string(resolution) + "³ voxel grid is larger than " + deviceName +
                    "'s maxImageDimension3D of " + std::to_string(limits.maxImageDimension3D) +
                    (fitting >= kMinVoxelResolution ? "; --voxels " + std::to_string(fitting) + " fits"
                                                    : "; no voxel grid fits"));
    }
}

void checkImageSize(const VkPhysicalDeviceLimits& limits, const std::string& deviceName,
                    const RenderSettings& settings) {
    for (const bool width : {true, false}) {
        const uint64_t pixels = width ? settings.image.width : settings.image.height;
        const uint64_t samples = pixels * settings.image.supersample;
        const SideLimit limit = renderTargetSideLimit(limits, width);
        if (samples <= limit.value) continue;
        const std::string ss = std::to_string(settings.image.supersample);
        throw Error("a " + std::to_string(settings.image.width) + "×" + std::to_string(settings.image.height) +
                    " image with " + ss + "×" + ss + " supersampling renders " + std::to_string(samples) + " samples " +
                    (width ? "across" : "down") + ", more than " + deviceName + "'s " + limit.name + " of " +
                    std::to_string(limit.value) + "; at this supersampling --" + (width ? "width" : "height") + " " +
                    std::to_string(limit.value / settings.image.supersample) + " fits");
    }
}

void checkShadowMaps(const VkPhysicalDeviceLimits& limits, const std::string& deviceName, const Scene& scene,
                     const RenderSettings& settings) {
    const SideLimit side = std::min(renderTargetSideLimit(limits, true), renderTargetSideLimit(limits, false),
                                    [](const SideLimit& a, const SideLimit& b) { return a.value < b.value; });
    const struct {
        uint32_t size;
        const char* option;
        const char* what;
    } maps[] = {{settings.resources.sunShadowMapSize, "--shadow-map", "sun shadow map"},
                {settings.resources.localShadowMapSize, "--local-shadow-map", "spot and point light shadow map"},
                {settings.resources.areaShadowMapSize, "--area-shadow-map", "area light shadow map"}};
    for (const auto& map : maps)
        if (map.size > side.value)
            throw Error("a " + std::to_string(map.size) + "² " + map.what + " is larger than " + deviceName + "'s " +
                        side.name + " of " + std::to_string(side.value) + "; " + map.option + " " +
                        std::to_string(side.value) + " fits");

    const ShadowLayout layout = layoutShadows(scene.lights, findAreaLights(scene), scene.bounds(), settings);
    for (const uint32_t layers : {mostSunLayers(layout, settings), layout.localLayers, layout.areaLayers})
        if (layers > limits.maxImageArrayLayers)
            throw Error("scene '" + scene.name + "': its lights need " + std::to_string(layers) +
                        " shadow maps in one array (a point light needs six), more than " + deviceName +
                        "'s maxImageArrayLayers of " + std::to_string(limits.maxImageArrayLayers) +
                        "; remove some lights or disable shadows");
}

void checkSceneBuffers(const VkPhysicalDeviceLimits& limits, const std::string& deviceName, const Scene& scene) {
    const uint64_t range = limits.maxStorageBufferRange;
    const struct {
        uint64_t count;
        uint64_t elementBytes;
        const char* what;
    } buffers[] = {{scene.vertices.size(), sizeof(glsl::GpuVertex), "vertices"},
                   {scene.indices.size(), sizeof(uint32_t), "triangle corners (indices)"},
                   {scene.triangleMaterials.size(), sizeof(uint32_t), "triangle materials"},
                   {scene.materials.size(), sizeof(glsl::GpuMaterial), "materials"}};
    const SceneBufferLimits deviceLimits{range, deviceName};
    for (const auto& buffer : buffers)
        checkSceneBufferFits("scene '" + scene.name + "': ", buffer.count, buffer.elementBytes, buffer.what,
                             deviceLimits);
    for (size_t i = 0; i < scene.textures.size(); ++i) {
        const Texture& texture = scene.textures[i];
        if (texture.width > limits.maxImageDimension2D || texture.height > limits.maxImageDimension2D)
            throw Error("scene '" + scene.name + "': texture " + std::to_string(i) + " ('" + texture.name + "') is " +
                        std::to_string(texture.width) + "×" + std::to_string(texture.height) + ", larger than " +
                        deviceName + "'s maxImageDimension2D of " + std::to_string(limits.maxImageDimension2D));
    }
}

}  // namespace

RendererMemoryEstimate estimateRendererMemory(const Scene& scene, const RenderSettings& settings) {
    RendererMemoryEstimate estimate;
    estimate.voxels = voxelVolumeBytes(settings.resources) +
                      voxelizeAccumulationBytes(settings.resources.voxelResolution, voxelizeChannels(scene));

    const ShadowLayout layout = layoutShadows(scene.lights, findAreaLights(scene), scene.bounds(), settings);
    const uint32_t sunLayers = mostSunLayers(layout, settings);
    const uint64_t sunSide = sunLayers ? settings.resources.sunShadowMapSize : 1;
    const uint64_t localSide = layout.localLayers ? settings.resources.localShadowMapSize : 1;
    const uint64_t areaSide = layout.areaLayers ? settings.resources.areaShadowMapSize : 1;
    estimate.shadowMaps =
        (std::max(sunLayers, 1u) * sunSide * sunSide + std::max(layout.localLayers, 1u) * localSide * localSide +
         std::max(layout.areaLayers, 1u) * areaSide * areaSide) *
        kShadowTexel;

    const uint64_t samples = uint64_t(settings.image.width) * settings.image.height * settings.image.supersample *
                             settings.image.supersample;
    estimate.imageTargets =
        samples * kSampleBytes + uint64_t(settings.image.width) * settings.image.height * kResolvedPixel;

    estimate.scene = scene.vertices.size() * sizeof(glsl::GpuVertex) + scene.indices.size() * sizeof(uint32_t) +
                     scene.triangleMaterials.size() * sizeof(uint32_t) +
                     scene.materials.size() * sizeof(glsl::GpuMaterial) + 4;  // + the white fallback texture
    for (const Texture& texture : scene.textures) estimate.scene += uint64_t(texture.width) * texture.height * 4;
    return estimate;
}

uint64_t largestDeviceLocalHeap(const VkPhysicalDeviceMemoryProperties& memory) {
    uint64_t bytes = 0;
    for (uint32_t i = 0; i < memory.memoryHeapCount; ++i)
        if (memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            bytes = std::max<uint64_t>(bytes, memory.memoryHeaps[i].size);
    return bytes;
}

void checkRendererLimits(const VkPhysicalDeviceLimits& limits, const VkPhysicalDeviceMemoryProperties& memory,
                         const std::string& deviceName, const Scene& scene, const RenderSettings& settings) {
    if (settings.image.width == 0 || settings.image.height == 0 || settings.image.supersample == 0)
        throw Error("the image size and supersampling must not be zero");
    checkVoxelResolution(limits, deviceName, settings.resources.voxelResolution);
    checkVoxelizeMemory(memory, limits, deviceName, settings.resources.voxelResolution, voxelizeChannels(scene));
    checkImageSize(limits, deviceName, settings);
    checkShadowMaps(limits, deviceName, scene, settings);
    checkSceneBuffers(limits, deviceName, scene);

    const uint64_t heap = largestDeviceLocalHeap(memory);
    const RendererMemoryEstimate estimate = estimateRendererMemory(scene, settings);
    if (estimate.total() <= heap) return;
    std::string message = "rendering needs about " + bytesText(estimate.total()) + " of GPU memory (voxels " +
                          bytesText(estimate.voxels) + ", shadow maps " + bytesText(estimate.shadowMaps) +
                          ", image targets " + bytesText(estimate.imageTargets) + ", scene " +
                          bytesText(estimate.scene) + "), more than the " + bytesText(heap) + " heap of " + deviceName;
    // Suggest the setting that frees the most: a coarser voxel grid first, then smaller shadow maps.
    RenderSettings smaller = settings;
    while (smaller.resources.voxelResolution > kMinVoxelResolution &&
           estimateRendererMemory(scene, smaller).total() > heap)
        smaller.resources.voxelResolution /= 2;
    while (smaller.resources.sunShadowMapSize > 512 && estimateRendererMemory(scene, smaller).total() > heap) {
        smaller.resources.sunShadowMapSize /= 2;
        smaller.resources.localShadowMapSize = std::max(smaller.resources.localShadowMapSize / 2, 256u);
    }
    if (estimateRendererMemory(scene, smaller).total() <= heap) {
        message += "; --voxels " + std::to_string(smaller.resources.voxelResolution);
        if (smaller.resources.sunShadowMapSize != settings.resources.sunShadowMapSize)
            message += " --shadow-map " + std::to_string(smaller.resources.sunShadowMapSize) + " --local-shadow-map " +
                       std::to_string(smaller.resources.localShadowMapSize);
        message += " fits";
    } else {
        message += "; a smaller image (--width, --height, --supersample) or scene is needed";
    }
    throw Error(message);
}

}  // namespace vct
