#version 460
// One bounce of the voxels' light: each occupied voxel's diffuse cones gather the light of the
// current (mipmapped) radiance volume, and the voxel stores what it reflects of it, albedo × the
// gathered radiance, × the radiance volume's storage scale. The injection adds it to the light
// sources' light (inject.comp.glsl), so the next mip chain holds one more bounce.
// It writes its own image while the cones read the radiance volume, and it may visit only a slice
// of the occupied list (every sliceCount-th voxel from slicePhase): the viewer spreads a bounce
// over several frames, and the voxels it skips keep what they gathered before.
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.h"

layout(local_size_x = WORK_LIST_GROUP_SIZE) in;

layout(set = 0, binding = FRAME_BINDING) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = VOXEL_ALBEDO_BINDING, rgba8) uniform readonly image3D voxelAlbedo;
layout(set = 0, binding = VOXEL_NORMAL_BINDING, rgba16f) uniform readonly image3D voxelNormal;
layout(set = 0, binding = GATHERED_LIGHT_BINDING, rgba16f) uniform writeonly image3D gatheredLight;
layout(set = 0, binding = VOXEL_RADIANCE_BINDING) uniform sampler3D voxelRadiance;
layout(std430, set = 0, binding = OCCUPIED_VOXELS_BINDING) readonly buffer OccupiedVoxels { uint occupiedVoxels[]; };
layout(std430, set = 0, binding = OCCUPIED_LIST_BINDING) readonly buffer Occupied { WorkListHeader occupied; };
#include "directional_voxels.glsl"
layout(push_constant) uniform Push {
    uint sliceCount;
    uint slicePhase;
};

// Where a cone meets a surface, on which side (cone_tracing.glsl).
vec3 voxelNormalAt(ivec3 cell) { return imageLoad(voxelNormal, cell).xyz; }
#include "surface_planes.glsl"
#include "cone_tracing.glsl"

// A voxel gathers its bounce with at least this many cones, whatever the image's setting. One cone
// along its normal, the cheapest setting's, takes what lies straight ahead for its whole
// hemisphere, and the bounces feed that back into the light the next ones see: with one cone the
// sun room converged at 1.6x its path-traced indirect light. The light changes pay for the six
// (32³: 61 -> 160 ms on lavapipe); a still frame traces the image's own cones.
const uint MIN_BOUNCE_CONES = 6u;

// A voxel's cones start this many voxels out along its normal, past the voxel itself.
const float BOUNCE_CONE_START = 2.0f;

// With ray visibility, whether the voxel's cones start in the free space on its own side: where
// they start, and the way there, hold no other surface. A voxel where a sheet meets the floor of
// the room behind it has a normal halfway between theirs, and two voxels along it lie beyond the
// sheet: its cones gathered the light of the room on the sheet's lit side, and the dark room saw
// that light on its floor along the sheet (on a voxel boundary, most of what such a sheet let
// through: docs/experiments.md, 2026-12-07). Where the sheet crosses the voxel itself, the mean
// normal cannot tell the sides apart.
bool coneStartIsClear(ivec3 voxel, vec3 normal) {
    if ((frame.componentFlags & RAY_VISIBILITY) == 0u) return true;
    vec3 center = vec3(voxel) + 0.5f;
    for (float along = 1.0f; along <= BOUNCE_CONE_START; along += 0.5f) {
        ivec3 cell = ivec3(floor(center + normal * along));
        if (cell != voxel && occupiedAt(cell, 0)) return false;
    }
    return true;
}

void gatherVoxel(ivec3 voxel) {
    vec3 normalSum = imageLoad(voxelNormal, voxel).xyz;
    float normalLength = length(normalSum);
    vec3 reflected = vec3(0.0f);
    // A voxel whose triangles disagree (a thin two-sided wall, a corner) has no side to gather
    // from; it keeps the light sources' light alone.
    vec3 normal = normalSum / max(normalLength, 1e-6f);
    if (normalLength > 0.25f && coneStartIsClear(voxel, normal)) {
        vec3 center = gridToWorld(frame.grid, vec3(voxel) + 0.5f);
        float voxelSize = frame.grid.voxelSize;
        // Lambertian: albedo/π · (π Σ wᵢ Lᵢ). The ring is not turned and every beam is traced: the
        // voxels' light is gathered anew by each bounce, not averaged over frames.
        vec3 gathered = traceDiffuseConeSet(center + normal * (BOUNCE_CONE_START * voxelSize), normal, BOUNCE_CONE_START,
                                            max(frame.diffuseConeCount, MIN_BOUNCE_CONES), 0.0f, ALL_BEAMS, 0.0f)
                            .rgb;
        reflected = imageLoad(voxelAlbedo, voxel).rgb * gathered * frame.radianceScale;
    }
    imageStore(gatheredLight, voxel, vec4(reflected, 0.0f));
}

void main() {
    uint count = (occupied.count + sliceCount - 1u - slicePhase) / sliceCount;  // list items in the slice
    // The dispatch covers the slice and may be capped: each invocation strides over what it leaves.
    uint stride = gl_NumWorkGroups.x * WORK_LIST_GROUP_SIZE;
    for (uint i = gl_GlobalInvocationID.x; i < count; i += stride)
        gatherVoxel(ivec3(unpackCell(occupiedVoxels[i * sliceCount + slicePhase])));
}
