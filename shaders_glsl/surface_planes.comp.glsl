#version 460
// Level 0 of the surface planes (surface_planes.h) from the voxelizer's normals and surface offsets
// (voxel_resolve.comp) and the light of radiance level 0; one invocation per voxel, after each
// injection. The mip chain follows (mips.comp).
#extension GL_GOOGLE_include_directive : require
#include "bindings.h"
#include "surface_planes.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(set = 0, binding = VOXEL_RADIANCE_BINDING, rgba16f) uniform readonly image3D radiance;  // level 0
layout(set = 0, binding = VOXEL_NORMAL_BINDING, rgba16f) uniform readonly image3D normalSurface;
layout(set = 0, binding = SURFACE_PLANES_BINDING, rgba16f) uniform writeonly image3D planes;

void main() {
    ivec3 voxel = ivec3(gl_GlobalInvocationID);
    ivec3 size = imageSize(planes);
    if (any(greaterThanEqual(voxel, size))) return;
    vec4 normalOffset = imageLoad(normalSurface, voxel);
    float weight = surfacePlaneWeight(imageLoad(radiance, voxel).rgb);
    vec3 normal = normalOffset.xyz;
    float normalLength = length(normal);
    // The surface point: the offset is along the unit mean normal; from the grid's centre, so that
    // a half float holds the plane's offset to 1/8 voxel at 256³.
    vec3 unit = normalLength > 0.0f ? normal / normalLength : vec3(0.0f);
    vec3 surface = fromGridCentre(vec3(voxel) + 0.5f + unit * normalOffset.w, float(size.x));
    imageStore(planes, voxel, weight * vec4(normal, dot(normal, surface)));
}
