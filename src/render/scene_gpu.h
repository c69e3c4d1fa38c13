// The scene's geometry, materials and textures on the GPU. Built once per loaded scene.
#pragma once

#include <vector>

#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "scene/scene.h"

namespace vct {

struct SceneGpu {
    SceneGpu(GpuContext& context, const Scene& scene);
    ~SceneGpu();
    SceneGpu(const SceneGpu&) = delete;
    SceneGpu& operator=(const SceneGpu&) = delete;

    Buffer vertices;           // GpuVertex[]
    Buffer indices;            // uint32 × 3 per triangle, sorted by material (index and storage buffer)
    Buffer triangleMaterials;  // uint32 per triangle, in the sorted order
    Buffer materials;          // GpuMaterial[]
    uint32_t indexCount = 0;
    uint32_t triangleCount = 0;

    // The sorted triangles of one material: drawn with one call, the material as a push constant.
    struct MaterialRange {
        uint32_t material;
        uint32_t firstIndex;
        uint32_t indexCount;
    };
    std::vector<MaterialRange> materialRanges;

    // Base-colour textures (at least one: a white fallback) in descriptor set 1 of the G-buffer pass.
    std::vector<GpuImage> textures;
    Sampler textureSampler;
    VkDescriptorSetLayout textureSetLayout = VK_NULL_HANDLE;
    VkDescriptorPool texturePool = VK_NULL_HANDLE;
    VkDescriptorSet textureSet = VK_NULL_HANDLE;
    uint32_t textureCount() const { return uint32_t(textures.size()); }

private:
    GpuContext& context_;
};

}  // namespace vct
