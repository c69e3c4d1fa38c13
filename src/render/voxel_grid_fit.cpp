#include "render/voxel_grid_fit.h"

#include <algorithm>
#include <bit>

#include "error.h"

namespace vct {

glsl::VoxelGridParams fitVoxelGrid(const Bounds& sceneBounds, uint32_t resolution) {
    if (resolution < kMinVoxelResolution || resolution > kMaxVoxelResolution || !std::has_single_bit(resolution))
        throw Error("the voxel resolution must be a power of two from " + std::to_string(kMinVoxelResolution) + " to " +
                    std::to_string(kMaxVoxelResolution) + ", not " + std::to_string(resolution));
    const glm::vec3 extent = sceneBounds.extent();
    float side = std::max({extent.x, extent.y, extent.z});
    if (!(side > 0.0f)) side = 1.0f;
    // One voxel of margin on each side: side' = side · N / (N − 2).
    side *= float(resolution) / float(resolution - 2);
    glsl::VoxelGridParams grid{};
    const float voxelSize = side / float(resolution);
    grid.originVoxelSize = glm::vec4(sceneBounds.center() - glm::vec3(0.5f * side), voxelSize);
    grid.resolution = glm::uvec4(resolution, voxelMipCount(resolution), 0u, 0u);
    return grid;
}

uint32_t voxelMipCount(uint32_t resolution) { return uint32_t(std::bit_width(resolution)); }

}  // namespace vct
