// Where a cone starts. Cones leave a surface frame.coneStartOffset voxels out along its normal,
// clear of its own voxels. Where another surface lies closer than that and faces back (the floor
// under a sphere resting on it: within 6 cm of the contact a 1.5-voxel offset puts the origin
// inside the sphere), the cones would start past it, and since one-sided voxels seen from behind
// are empty, they would see through it into the lit room (a bright band under the sphere of
// cornell-metal). Requires: frame (FrameConstants), voxelNormal (level-0 mean normals, see
// voxel_resolve.comp) and voxelRadiance.
#ifndef VCT_CONE_START_GLSL
#define VCT_CONE_START_GLSL

#include "voxel_grid.h"

// A voxel's surface faces back towards a cone's surface when their normals are more than 120°
// apart (a resting sphere's underside within 6 cm of its contact: 156-180°; a wall meeting the
// floor: 90°, not across the gap).
const float FACING_BACK = -0.5f;

// The light of the first surface facing back across the gap between `position` and the cones'
// origin, premultiplied by its opacity (a = 1), in scene units; or vec4(0) where the gap is clear.
// The gap is probed every half voxel from one voxel out.
vec4 surfaceAcrossTheGap(vec3 position, vec3 normal) {
    VoxelGridParams grid = frame.grid;
    ivec3 last = ivec3(grid.resolution) - 1;
    vec3 start = worldToGrid(grid, position);
    // How far from a plane through `position` a voxel's centre can lie and the plane still touch it.
    float ownReach = 0.5f * (abs(normal.x) + abs(normal.y) + abs(normal.z));
    for (float gap = 1.0f; gap <= frame.coneStartOffset; gap += 0.5f) {
        ivec3 voxel = ivec3(floor(start + gap * normal));
        if (any(lessThan(voxel, ivec3(0))) || any(greaterThan(voxel, last))) break;
        // A voxel that the surface's own plane may touch is its own, whatever its normal says:
        // seen from the back of its triangles (surfaces reflect on both sides) a surface's voxels
        // face back at it.
        if (dot(vec3(voxel) + 0.5f - start, normal) <= ownReach) continue;
        vec3 facing = texelFetch(voxelNormal, voxel, 0).xyz;  // not renormalized: 0 where empty
        if (dot(facing, normal) < FACING_BACK * length(facing))
            return vec4(texelFetch(voxelRadiance, voxel, 0).rgb / frame.radianceScale, 1.0f);
    }
    return vec4(0.0f);
}

#endif
