// The radiance volume's mip chain, built by compute downsampling level after level.
#pragma once

#include "gpu/pipelines.h"
#include "gpu/resources.h"

#include <vector>

namespace vct {

struct MipsPass {
    explicit MipsPass(GpuContext& context);

    // Reads level 0 of `volume` (GENERAL) and writes every coarser level; leaves the volume in
    // GENERAL, visible to sampling in the fragment and compute stages.
    void record(VkCommandBuffer commands, const GpuImage& volume);
    // Builds the six directional chains from level 0 of `volume` (anisotropic voxels).
    void recordDirectional(VkCommandBuffer commands, const GpuImage& volume, const std::vector<GpuImage>& directional);

    Pipeline pipeline;
    Pipeline directionalPipeline;

private:
    GpuContext& context_;
};

}  // namespace vct
