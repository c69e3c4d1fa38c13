// Light injection: direct light (with shadow-map visibility) and emission turned into the
// outgoing radiance of every occupied voxel, written to level 0 of the radiance volume.
#pragma once

#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "render/shadow_pass.h"
#include "render/voxel_volumes.h"

namespace vct {

struct InjectPass {
    explicit InjectPass(GpuContext& context);

    // Writes level 0 of volumes.radiance from the scene voxels (the light sources' light reflected
    // once), visible to the mip pass after.
    void record(VkCommandBuffer commands, VkBuffer frameConstants, VkBuffer lights, VkBuffer shadowViews,
                const ShadowPass& shadows, VoxelVolumes& volumes);
    // One more bounce: injects again, adding what each voxel's cones gather from the current
    // (mipmapped) volume, and replaces level 0 with the result. The mips must be rebuilt after.
    void recordBounce(VkCommandBuffer commands, VkBuffer frameConstants, VkBuffer lights, VkBuffer shadowViews,
                      const ShadowPass& shadows, VoxelVolumes& volumes);

    Pipeline pipeline;

private:
    void dispatch(VkCommandBuffer commands, VkBuffer frameConstants, VkBuffer lights, VkBuffer shadowViews,
                  const ShadowPass& shadows, const VoxelVolumes& volumes, VkImageView target, uint32_t gatherBounce);

    GpuContext& context_;
};

// The scale that keeps the stored radiance inside float16's range whatever the scene's units:
// 1 / an upper estimate of any voxel's radiance (a light one voxel away, the brightest emitter).
float radianceStorageScale(const std::vector<Light>& lights, const Scene& scene, float voxelSize);

}  // namespace vct
