// Voxelization: the work split, the fixed-point accumulation and the pass parameters. Shared by C++ and GLSL.
//
// Work split. A large triangle touches thousands of voxels; one invocation per triangle would run
// them one after another while the rest of the GPU idles. So the CPU (once, when the geometry is
// uploaded) cuts each triangle's voxel bounding box into tiles of VOXELIZE_TILE³ voxels, keeps the
// tiles the triangle's plane and edges can reach (the same separating-axis test against the tile's
// box, with a margin), and writes one work item (triangle, tile) per kept tile. The GPU runs one
// workgroup per work item and one invocation per voxel of the tile, so the work is spread evenly
// whatever the triangle sizes.
//
// Emission is averaged over the emitting triangles only: a lamp just under a ceiling shares its
// voxels with the ceiling, and averaging over both would halve its light in the voxels. Opacity and
// albedo come from every triangle.
//
// Where the surface lies. A triangle touches the voxel anywhere within it, and a voxel's light is
// the light falling on its surface, not on its centre: each triangle adds the way from the centre to
// the nearest point of its plane, n·(n·(a − centre)), the same for either side of a thin wall.
//
// Coverage (glTF alphaMode). A triangle covers a voxel by the share of its surface there: a
// material's voxelCoverage (material_textures.h, GpuMaterial::voxelEmission.w) without a base colour
// texture, with one the voxel's footprint on it (voxelize.comp: BLEND its mean alpha, MASK the share
// of it whose alpha reaches the cutoff). A voxel's opacity is the largest coverage of the triangles
// touching it (a surface cut into many triangles covers a voxel no more than one of them does; an
// opaque one makes it opaque), and a triangle of coverage 0 touches nothing. Albedo, normal and
// emission stay plain means over the triangles that touch.
//
// Order-independent averaging. Each touching triangle adds its attributes to integer sums with
// atomicAdd; integer addition is associative, so the sums (and the images) do not depend on the
// order the GPU happens to run the work items in. Float atomics would round differently per order.
// Fixed-point scales, with N contributions to one voxel (sums wrap modulo 2³², so only the final
// sum has to fit):
//   albedo in [0, 1] × 2^15, unsigned: N · 2^15 < 2^32 for N ≤ 131071; step 3·10⁻⁵ (UNORM8 needs 4·10⁻³).
//   normal in [−1, 1] × 2^14, two's complement: |N · 2^14| < 2^31 for N ≤ 131071; step 6·10⁻⁵
//       (the half-float output has 5·10⁻⁴ near 1).
//   emission in [0, max] scaled so the largest emission component of an emitting material (its factor:
//       the emissive texture it is sampled through is at most 1) is 2^15, unsigned: the same
//       bound as albedo; each contribution is rounded to max · 2^−16, far below half-float precision
//       for the brightest emitter (dimmer emitters in the same scene get the same absolute step).
#ifndef VCT_VOXELIZE_H
#define VCT_VOXELIZE_H

#include "cpp_glsl.h"
#include "voxel_grid.h"

VCT_SHARED_BEGIN

const uint VOXELIZE_TILE = 4u;  // a work item covers VOXELIZE_TILE³ voxels

// The accumulation buffers, one uint per voxel each, index x + N·(y + N·z).
const uint ACCUM_COUNT = 0u;     // triangles touching the voxel
const uint ACCUM_ALBEDO = 1u;    // 3 channels, rgb × ALBEDO_FIXED_SCALE
const uint ACCUM_NORMAL = 4u;    // 3 channels, xyz × NORMAL_FIXED_SCALE (two's complement)
// Emission, kept only for a scene with emitters (VoxelizeParams.emission.x > 0), else one word each:
const uint ACCUM_EMISSION = 7u;   // 3 channels, rgb × VoxelizeParams.emission.x, emitting triangles only
const uint ACCUM_EMITTERS = 10u;  // emitting triangles touching the voxel
// The largest coverage × OPACITY_FIXED_SCALE of the touching triangles; kept only for a scene with
// MASK or BLEND materials (VoxelizeParams.dispatch.z = 1), else one word, never read: opacity is 1.
const uint ACCUM_OPACITY = 11u;
// 3 channels, xyz × SURFACE_FIXED_SCALE (two's complement): the way from the voxel's centre to the
// nearest point of each touching triangle's plane, in voxels (at most √3 − 1/2 long: a voxel's
// centre lies within √3/2 of the set-back plane it touches, which is set back at most (√3 − 1)/2).
const uint ACCUM_SURFACE = 12u;
const uint ACCUM_CHANNELS = 15u;

const float ALBEDO_FIXED_SCALE = 32768.0f;
const float NORMAL_FIXED_SCALE = 16384.0f;
const float SURFACE_FIXED_SCALE = 8192.0f;  // |offset| < 2: the sum fits for N ≤ 131071; step 1.2·10⁻⁴
// A mean normal shorter than this (the faces of a thin wall cancelling) gives the surface no
// direction to lie along: its offset is 0. Far above the fixed point's rounding (2^-14).
const float SURFACE_NORMAL_MIN = 1.0f / 64.0f;
const float OPACITY_FIXED_SCALE = 32768.0f;  // coverage in [0, 1]; atomicMax, so no sum to overflow
const float EMISSION_FIXED_MAX = 32768.0f;     // the scene's largest emission component maps here
const uint MAX_EXACT_CONTRIBUTIONS = 131071u;  // triangles per voxel before a sum could overflow
const float HALF_FLOAT_MAX = 65504.0f;

// How far the voxelizer sets a triangle back, against its unit normal n, before it marks the voxels
// the triangle touches: ½(|nx| + |ny| + |nz| − 1) voxels. The voxels a plane touches have their
// centres within ½(|nx| + |ny| + |nz|) of it: half a voxel on either side for a wall along the grid,
// but up to 0.87 in front of an oblique surface, whose voxels then stand proud of it and, seen from
// its front as one-sided voxels are, make it look up to a third of a voxel nearer. Set back, every
// surface's voxels reach at most half a voxel in front of it, as a wall's along the grid do (those
// are not moved at all), and the surplus lies behind it, where cones leaving it do not look. The
// terrain's spheres (0.7 m, 2.2 voxels at 64³) had looked fat: the ground around them gathered
// 2-10x its light within a metre of them, a bright band under the white one, and the terrain's
// indirect light was 1.13x the path tracer's (0.98 set back; the rooms, built along the grid,
// moved by under 1 %).
SHARED_FN float voxelizationSetback(vec3 unitNormal) {
    return 0.5f * max(abs(unitNormal.x) + abs(unitNormal.y) + abs(unitNormal.z) - 1.0f, 0.0f);
}

struct VoxelizeParams {
    VoxelGridParams grid;  // with its triangleCount and workItems
    vec4 emission;         // x fixed-point scale (EMISSION_FIXED_MAX / largest component, 0 without emitters), y its inverse
    uvec4 dispatch;        // x workgroups per row of the voxelize dispatch (work item = group.y · x + group.x),
                           // y the most workgroups the occupied-voxel dispatch may have,
                           // z 1 = the scene has MASK or BLEND materials: ACCUM_OPACITY is kept
};

VCT_SHARED_END

#endif
