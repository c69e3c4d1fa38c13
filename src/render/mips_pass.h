// The radiance volume's mip chain, built by compute downsampling level after level.
#pragma once

#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "render/voxel_volumes.h"

#include <vector>

namespace vct {

struct MipsPass {
    explicit MipsPass(GpuContext& context);

    // Reads level 0 of the radiance volume and writes every coarser level, and the six directional
    // chains of anisotropic voxels (their first level one-sided, from the scene voxels' normals);
    // visible to sampling in the fragment and compute stages after.
    // `rayVisibility`: the cones trace visibility rays (ResourceSettings::rayVisibility), and the
    // directional chains show a surface seen from behind as black and opaque; with it, the surface
    // planes too.
    void record(VkCommandBuffer commands, const VoxelVolumes& volumes, bool rayVisibility);

    Pipeline pipeline;
    Pipeline directionalFromScenePipeline;  // the directional chains' first level, one-sided
    Pipeline directionalPipeline;           // their coarser levels
    Pipeline surfacePlanesPipeline;         // the surface planes' level 0

private:
    void recordIsotropic(VkCommandBuffer commands, const GpuImage& volume);
    void recordDirectional(VkCommandBuffer commands, const VoxelVolumes& volumes, bool rayVisibility);
    // With ray visibility, the surface planes (shaders_glsl/surface_planes.h): level 0 from the
    // voxels' normals and radiance level 0, then their mip chain.
    void recordSurfacePlanes(VkCommandBuffer commands, const VoxelVolumes& volumes);
    GpuContext& context_;
};

}  // namespace vct
