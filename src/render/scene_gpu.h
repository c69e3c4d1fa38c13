// The scene's geometry, materials and textures on the GPU. Built once per loaded scene.
#pragma once

#include <vector>

#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "scene/scene.h"

namespace vct {

// Scenes built in code skip the glTF validator, so the renderer checks what would otherwise reach
// the GPU as NaN or an out-of-range index: every vertex attribute, material factor and light value
// must be finite, light intensities and colours not negative, indices and material numbers in
// range. Throws vct::Error naming the scene (or light) and the element. Zero-length normals are
// allowed: the G-buffer falls back to the triangle's plane.
void checkSceneCanBeRendered(const Scene& scene);
void checkLightsCanBeRendered(const std::vector<Light>& lights, const std::string& sceneName);

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
        bool alphaTested = false;  // MASK or BLEND: its fragments may be discarded
        bool doubleSided = true;   // false: the camera does not see its back faces
    };
    std::vector<MaterialRange> materialRanges;
    // For the shadow pass: the triangles of opaque materials as runs of consecutive ranges, each
    // drawn with one depth-only call (one run for the whole scene when no material is alpha-tested),
    // and the ranges of MASK and BLEND materials, whose base colour's alpha must be read.
    struct IndexRun {
        uint32_t firstIndex;
        uint32_t indexCount;
    };
    std::vector<IndexRun> opaqueRuns;
    std::vector<MaterialRange> alphaTestedRanges;

    // The material textures (at least one: a white fallback), in descriptor set 1 of the G-buffer
    // pass and of the voxelizer.
    std::vector<GpuImage> textures;
    std::vector<Sampler> samplers;  // one per kind of glTF sampler the textures use (wrap, filter)
    VkDescriptorSetLayout textureSetLayout = VK_NULL_HANDLE;
    VkDescriptorPool texturePool = VK_NULL_HANDLE;
    VkDescriptorSet textureSet = VK_NULL_HANDLE;
    // The same array for the voxelizer, which reads the sRGB ones (base colour, emissive): a linear
    // texture's place holds voxelFallbackTexture, white (see the constructor for why).
    VkDescriptorSet voxelTextureSet = VK_NULL_HANDLE;
    GpuImage voxelFallbackTexture;
    uint32_t textureCount() const { return uint32_t(textures.size()); }

private:
    GpuContext& context_;
};

}  // namespace vct
