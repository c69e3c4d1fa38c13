// The CPU twin of the voxelize pass, in double precision: the specification the GPU is tested against.
// The same conservative separating-axis test (see shaders_glsl/triangle_box.glsl) of the same set-back
// triangles (voxelizationSetback), the same
// degenerate-triangle rule and the same attributes, averaged exactly instead of in fixed point.
// Triangles of a material with voxelCoverage 0 touch nothing, as on the GPU. Colours are the
// materials' factors: the GPU's textures are left out (it agrees where they are white, as an
// alpha-only texture is), and the tests check the GPU's texture sampling on its own.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "voxel_grid.h"

namespace vct {

using TriangleD = std::array<glm::dvec3, 3>;

// Grid coordinates in double of a (float) world position: g = (world − origin) / voxelSize.
glm::dvec3 toGridCoordinates(const glsl::VoxelGridParams& grid, const glm::vec3& world);

// The triangle's three world positions, in grid coordinates.
TriangleD gridTriangle(const Scene& scene, const glsl::VoxelGridParams& grid, size_t triangle);

// The triangle moved back along its unit normal by voxelizationSetback (voxelize.h): the copy whose
// touching voxels the voxelizer marks. Only for a triangle that is not degenerate.
TriangleD setBackTriangle(const TriangleD& triangle);

// Zero area: the edges' cross product is exactly zero. Decided on the float world positions in
// double (where the products of float differences are exact), so the GPU's work items and the twin
// skip exactly the same triangles. Such a triangle marks no voxel.
bool isDegenerateTriangle(const Scene& scene, size_t triangle);

// Signed gap between the triangle and the closed box (centre, half side), in grid units: the
// largest over the 13 separating axes of the projections' gap along the unit axis. > 0: separated
// by at least that much; ≤ 0: touching. Axes of zero length are skipped.
double triangleBoxSeparation(const TriangleD& triangle, const glm::dvec3& boxCenter, double halfSize);

// Voxels whose box the closed triangle may touch, clipped to the grid: [first, last] per axis;
// first > last on some axis when the triangle is outside the grid. `margin` widens the range.
struct VoxelRange {
    glm::ivec3 first, last;
    bool empty() const { return glm::any(glm::greaterThan(first, last)); }
};
VoxelRange triangleVoxelRange(const TriangleD& triangle, uint32_t resolution, double margin);

struct VoxelReference {
    uint32_t resolution = 0;
    std::vector<uint32_t> count;     // triangles touching each voxel, index x + N·(y + N·z)
    std::vector<uint32_t> emitters;  // emitting triangles among them
    std::vector<glm::dvec3> albedo;  // mean linear base colour factor (0 where count = 0)
    std::vector<double> opacity;     // the largest voxelCoverage of the touching triangles (0 where none)
    // 1 where a MASK material's base colour texture touches the voxel: the GPU samples the texture
    // over the voxel for its opacity (voxelize.comp), which decides whether it touches at all. The
    // twin leaves such voxels to the tests' own expectations.
    std::vector<uint8_t> maskedByTexture;
    std::vector<glm::dvec3> normal;  // mean geometric unit normal, not renormalized
    // Where the surface lies: the mean way from the voxel's centre to the touching triangles' planes,
    // projected on the unit mean normal, in voxels (0 where the normals cancel).
    std::vector<double> surfaceOffset;
    std::vector<glm::dvec3> emission;  // mean emission of the emitting triangles
    // How close the voxel came to flipping: the smallest |separation| of any triangle tested
    // against it (infinity if none). Float and double may disagree where this is tiny.
    std::vector<double> decisionMargin;

    size_t index(uint32_t x, uint32_t y, uint32_t z) const {
        return x + size_t(resolution) * (y + size_t(resolution) * z);
    }
};

VoxelReference voxelizeReference(const Scene& scene, const glsl::VoxelGridParams& grid);

}  // namespace vct
