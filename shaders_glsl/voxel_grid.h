// The voxel grid: a cube around the scene, N voxels a side. Shared by C++ and GLSL.
// Grid coordinates g = (world − origin) / voxelSize, so voxel (i, j, k) spans [i, i+1] × [j, j+1] × [k, k+1].
#ifndef VCT_VOXEL_GRID_H
#define VCT_VOXEL_GRID_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

struct VoxelGridParams {
    vec4 originVoxelSize;  // xyz world position of the grid's min corner, w world size of one voxel
    uvec4 resolution;      // x voxels per side, y mip levels, z triangles, w work items (triangle tiles)
};

SHARED_FN vec3 worldToGrid(VoxelGridParams grid, vec3 world) {
    return (world - vec3(grid.originVoxelSize)) / grid.originVoxelSize.w;
}

SHARED_FN vec3 gridToWorld(VoxelGridParams grid, vec3 gridPosition) {
    return vec3(grid.originVoxelSize) + gridPosition * grid.originVoxelSize.w;
}

VCT_SHARED_END

#endif
