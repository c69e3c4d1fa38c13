#version 460
// Traces given cones through a radiance volume and writes what they gather: lets the tests
// check the cone tracer on volumes with known answers, apart from voxelization and injection.
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.h"

layout(local_size_x = 64) in;
layout(set = 0, binding = FRAME_BINDING) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = VOXEL_RADIANCE_BINDING) uniform sampler3D voxelRadiance;
#include "directional_voxels.glsl"

struct ConeProbe {
    vec4 origin;     // xyz world, w 0 = one cone, 1 = the diffuse cone set around `direction`,
                     // 2 = that set leaving a surface `direction.w` voxels below the origin
    vec4 direction;  // xyz unit direction (the normal for a diffuse set), w tan(half-aperture) of one cone
};
layout(std430, set = 0, binding = CONE_PROBES_BINDING) readonly buffer Probes { ConeProbe probes[]; };
layout(std430, set = 0, binding = CONE_PROBE_RESULTS_BINDING) writeonly buffer Results { vec4 results[]; };  // radiance, occlusion
layout(push_constant) uniform Push { uint probeCount; };

// Where a cone meets a surface, on which side (cone_tracing.glsl): the probes' volumes have no
// normals, and every surface is met from the front.
vec3 voxelNormalAt(ivec3 cell) { return vec3(0.0f); }
// Nor planes: no sample is told it lies behind a surface (cone_tracing.glsl).
vec4 surfacePlaneAt(vec3 uvw, float lod) { return vec4(0.0f); }
#include "cone_tracing.glsl"

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= probeCount) return;
    ConeProbe probe = probes[index];
    if (probe.origin.w > 1.5f) {
        results[index] = traceDiffuseCones(probe.origin.xyz, probe.direction.xyz, probe.direction.w);
    } else if (probe.origin.w > 0.5f) {
        results[index] = traceDiffuseCones(probe.origin.xyz, probe.direction.xyz, NO_SURFACE);
    } else {
        ConeResult cone = traceCone(probe.origin.xyz, probe.direction.xyz, probe.direction.w, NO_SURFACE, 0.0f);
        results[index] = vec4(cone.radiance, cone.occlusion);
    }
}
