// What a device can hold, checked before the renderer allocates anything.
//
// A voxel grid, shadow map, image or scene the device cannot hold would otherwise surface as a
// failed vkCreateImage or vkAllocateMemory half-way through building the passes, or, for a
// storage buffer larger than maxStorageBufferRange, as wrong results. Each check names the setting,
// the device limit it exceeds (by its Vulkan name) and what would fit, e.g.
//   "a 512³ voxel grid is larger than llvmpipe's maxImageDimension3D of 256; --voxels 256 fits".
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

#include "gpu/context.h"
#include "render/settings.h"
#include "scene/scene.h"
#include "scene/scene_limits.h"

namespace vct {

// Device-local bytes the renderer's images and buffers need for `scene` and `settings`, estimated
// from their formats (the voxelizer's work list, which depends on the triangles' sizes, is left out).
struct RendererMemoryEstimate {
    uint64_t voxels = 0;        // VoxelVolumes (voxelVolumeBytes) and the voxelizer's sums
    uint64_t shadowMaps = 0;    // sun and local shadow-map arrays
    uint64_t imageTargets = 0;  // G-buffer, shading and resolve targets
    uint64_t scene = 0;         // vertex, index, material buffers and textures
    uint64_t total() const { return voxels + shadowMaps + imageTargets + scene; }
};
RendererMemoryEstimate estimateRendererMemory(const Scene& scene, const RenderSettings& settings);

// Throws vct::Error when `settings` or `scene` exceed `limits` or the largest device-local heap
// of `memory`. The limits are parameters so tests can pretend to be a smaller device.
void checkRendererLimits(const VkPhysicalDeviceLimits& limits, const VkPhysicalDeviceMemoryProperties& memory,
                         const std::string& deviceName, const Scene& scene, const RenderSettings& settings);

uint64_t largestDeviceLocalHeap(const VkPhysicalDeviceMemoryProperties& memory);

// The storage-buffer limit and the decoded-image budget a scene is loaded against (scene_limits.h).
inline SceneBufferLimits sceneBufferLimits(const GpuContext& context) {
    return {context.properties.limits.maxStorageBufferRange, context.deviceName(),
            decodedImageBudget(largestDeviceLocalHeap(context.memoryProperties))};
}

inline void checkRendererLimits(const GpuContext& context, const Scene& scene, const RenderSettings& settings) {
    checkRendererLimits(context.properties.limits, context.memoryProperties, context.deviceName(), scene, settings);
}

}  // namespace vct
