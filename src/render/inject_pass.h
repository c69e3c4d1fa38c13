// Light injection: direct light (with shadow-map visibility) and emission turned into the
// outgoing radiance of every occupied voxel, written to level 0 of the radiance volume.
#pragma once

#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "render/shadow_pass.h"
#include "render/voxelize_pass.h"

namespace vct {

struct InjectPass {
    InjectPass(GpuContext& context, uint32_t resolution, bool anisotropic, uint32_t bounces);

    // Writes level 0 of `radiance`. Leaves it in GENERAL, visible to the mip pass.
    void record(VkCommandBuffer commands, VkBuffer frameConstants, VkBuffer lights, VkBuffer shadowViews,
                const ShadowPass& shadows, const VoxelizePass& voxels);
    // The second bounce: injects again, adding what each voxel's cones gather from the current
    // (first-bounce, mipmapped) volume, and replaces level 0 with the result. The mips must be
    // rebuilt afterwards.
    void recordBounce(VkCommandBuffer commands, VkBuffer frameConstants, VkBuffer lights, VkBuffer shadowViews,
                      const ShadowPass& shadows, const VoxelizePass& voxels);

    // Puts the volumes in GENERAL (from UNDEFINED the first time) after earlier reads.
    void prepareLayouts(VkCommandBuffer commands);

    uint32_t resolution;
    // RGBA16F with the full mip chain: radiance × scale premultiplied by opacity, and opacity.
    GpuImage radiance;
    // Anisotropic voxels: six chains for rays along +x, −x, +y, −y, +z, −z, from the grid's level 1
    // down (level 0 is shared); empty when the voxels are isotropic.
    std::vector<GpuImage> directional;
    GpuImage bounceTarget;  // level 0 of the second bounce (only with bounces = 2)
    Sampler volumeSampler;
    Pipeline pipeline;

    // The six views of the directional array binding (the isotropic volume stands in when the
    // voxels are isotropic; the shaders then never sample it).
    std::vector<VkImageView> directionalViews() const {
        std::vector<VkImageView> views(6, radiance.view);
        for (size_t direction = 0; direction < directional.size(); ++direction) views[direction] = directional[direction].view;
        return views;
    }
    bool initialized = false;

private:
    void dispatch(VkCommandBuffer commands, VkBuffer frameConstants, VkBuffer lights, VkBuffer shadowViews,
                  const ShadowPass& shadows, const VoxelizePass& voxels, VkImageView target, uint32_t gatherBounce);

    GpuContext& context_;
};

// The scale that keeps the stored radiance inside float16's range whatever the scene's units:
// 1 / an upper estimate of any voxel's radiance (a light one voxel away, the brightest emitter).
float radianceStorageScale(const std::vector<Light>& lights, const Scene& scene, float voxelSize);

}  // namespace vct
