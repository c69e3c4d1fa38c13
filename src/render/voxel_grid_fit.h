// Fitting the voxel grid to a scene.
#pragma once

#include <cstdint>

#include "scene/scene.h"
#include "voxel_grid.h"

namespace vct {

constexpr uint32_t kMinVoxelResolution = 32;
constexpr uint32_t kMaxVoxelResolution = 512;

// A cube centred on the scene's bounds, its side the largest extent plus a margin of one voxel
// on each side (so geometry on the bounds is not cut by the grid's edge). A scene flat along an
// axis still gets a cube; an empty or point-like scene gets a unit cube.
glsl::VoxelGridParams fitVoxelGrid(const Bounds& sceneBounds, uint32_t resolution);

// Mip levels down to 1³.
uint32_t voxelMipCount(uint32_t resolution);

}  // namespace vct
