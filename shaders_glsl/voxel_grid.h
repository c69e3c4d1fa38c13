// The voxel grid: a cube around the scene, N voxels a side. Shared by C++ and GLSL.
// Grid coordinates g = (world − origin) / voxelSize, so voxel (i, j, k) spans [i, i+1] × [j, j+1] × [k, k+1].
#ifndef VCT_VOXEL_GRID_H
#define VCT_VOXEL_GRID_H

#include "cpp_glsl.h"
#include "work_list.h"

VCT_SHARED_BEGIN

struct VoxelGridParams {
    vec3 origin;         // world position of the grid's min corner
    float voxelSize;     // world size of one voxel
    uint resolution;     // voxels per side
    uint mipLevels;      // of the radiance volume
    uint triangleCount;  // the voxelizer's: the scene's triangles (0 elsewhere)
    uint workItems;      // the voxelizer's: the triangle tiles its dispatch covers (0 elsewhere)
};

SHARED_FN vec3 worldToGrid(VoxelGridParams grid, vec3 world) {
    return (world - grid.origin) / grid.voxelSize;
}

SHARED_FN vec3 gridToWorld(VoxelGridParams grid, vec3 gridPosition) {
    return grid.origin + gridPosition * grid.voxelSize;
}

// A cell of the grid (a voxel, or a tile of voxels) packed 10 bits per axis: up to 1024 cells a side.
SHARED_FN uint packCell(uvec3 cell) { return cell.x | (cell.y << 10u) | (cell.z << 20u); }
SHARED_FN uvec3 unpackCell(uint packed) { return uvec3(packed & 1023u, (packed >> 10u) & 1023u, packed >> 20u); }

// The occupied voxels are a work list (work_list.h) the voxelizer writes, packCell each, in no
// particular order, so that the passes over the scene's surfaces (light injection, bounces) run one
// invocation per occupied voxel rather than per voxel of the grid: a room's walls fill a few
// percent of its grid, and a 4³ block of invocations cut by a wall would otherwise run its empty
// lanes alongside the occupied ones.

VCT_SHARED_END

#endif
