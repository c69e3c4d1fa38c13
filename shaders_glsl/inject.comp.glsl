#version 460
// Light injection: the outgoing radiance of every occupied voxel, from the direct light it
// receives (with shadow-map visibility) reflected diffusely: from the punctual lights and from the
// area lights. Emission itself stays out of the voxels: the area lights carry it, exactly, to the
// pixels and to the voxels, and a cone that met it again would count it twice. With the area lights
// off (USE_AREA_LIGHTS) the voxels emit it instead, for the cones to gather. Written to
// level 0 of the radiance volume as radiance × scale premultiplied by opacity. One invocation per
// voxel of the voxelizer's occupied list (voxel_grid.h); the empty voxels stay zero.
// With addGathered = 1 each voxel also reflects the light its cones last gathered
// (bounce_gather.comp.glsl): the light sources' light plus one more bounce.
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.h"

layout(local_size_x = WORK_LIST_GROUP_SIZE) in;

layout(set = 0, binding = FRAME_BINDING) uniform Frame { FrameConstants frame; };
layout(std430, set = 0, binding = LIGHTS_BINDING) readonly buffer Lights { GpuLight lights[]; };
layout(std430, set = 0, binding = SHADOW_VIEWS_BINDING) readonly buffer ShadowViews { ShadowView shadowViews[]; };
layout(set = 0, binding = SUN_SHADOW_MAPS_BINDING) uniform sampler2DArrayShadow sunShadowMaps;
layout(set = 0, binding = LOCAL_SHADOW_MAPS_BINDING) uniform sampler2DArrayShadow localShadowMaps;
layout(set = 0, binding = VOXEL_ALBEDO_BINDING, rgba8) uniform readonly image3D voxelAlbedo;
layout(set = 0, binding = VOXEL_NORMAL_BINDING, rgba16f) uniform readonly image3D voxelNormal;
layout(std430, set = 0, binding = EMITTER_TRIANGLES_BINDING) readonly buffer EmitterTriangles { GpuEmitterTriangle emitterTriangles[]; };
layout(set = 0, binding = VOXEL_RADIANCE_BINDING, rgba16f) uniform writeonly image3D radiance;
layout(set = 0, binding = GATHERED_LIGHT_BINDING, rgba16f) uniform readonly image3D gatheredLight;
layout(std430, set = 0, binding = OCCUPIED_VOXELS_BINDING) readonly buffer OccupiedVoxels { uint occupiedVoxels[]; };
layout(std430, set = 0, binding = OCCUPIED_LIST_BINDING) readonly buffer Occupied { WorkListHeader occupied; };
layout(set = 0, binding = VOXEL_EMISSION_BINDING, rgba16f) uniform readonly image3D voxelEmission;
layout(set = 0, binding = AREA_SHADOW_MAPS_BINDING) uniform sampler2DArrayShadow areaShadowMaps;
// The area lights' irradiance at each listed voxel (three floats an item), kept between injections:
// it changes only with the voxels, the area lights' maps or the components shown, and it is most of
// an injection's cost where there are area lights. A pipeline of its own reads it (lavapipe would
// run the area lights' code beside the read); this one writes it.
layout(std430, set = 0, binding = AREA_LIGHT_CACHE_BINDING) buffer AreaLightCache { float keptAreaLight[]; };
layout(constant_id = AREA_LIGHTS_CACHED_CONSTANT_ID) const bool AREA_LIGHTS_CACHED = false;
layout(push_constant) uniform Push { uint addGathered; };

#include "voxel_grid.h"
#include "direct_light.glsl"

// Where a voxel takes its light: on its surface, which may lie up to √3/2 voxel from its centre (a
// ceiling's voxels 10 cm above a point light, their centres half a voxel nearer to it, were lit
// 1/d² brighter, the coarser the grid the more). The shadow maps' own normal offset keeps the
// lookup clear of the surface's texels. A voxel whose triangles disagree (a thin two-sided wall)
// has no side and no surface to speak of: its centre stands in, its shadow looked up half a voxel
// towards the light.
struct VoxelSurface {
    vec3 point;
    vec3 normalSum;  // the mean of its triangles' unit normals (voxel_resolve.comp)
    float normalLength;
    bool sided;
};

VoxelSurface voxelSurface(ivec3 voxel) {
    vec4 normalOffset = imageLoad(voxelNormal, voxel);
    VoxelSurface surface;
    surface.normalSum = normalOffset.xyz;
    surface.normalLength = length(surface.normalSum);
    surface.sided = surface.normalLength > 0.25f;
    surface.point = gridToWorld(frame.grid, vec3(voxel) + 0.5f);
    if (surface.sided)
        surface.point += surface.normalSum * (normalOffset.w * frame.grid.voxelSize / surface.normalLength);
    return surface;
}

// The cosine of a light arriving along `toLight` over the voxel's triangles: the mean of theirs, by
// the mean normal unnormalized (where they all face the light, exact: the cosine is linear in the
// normal). Renormalized, the edge where a ceiling meets a wall faced the light at 45° and took 1.4×
// the light of its two faces (the Cornell box's first bounce spread over 32³-256³ 8.1 % with it,
// 6.1 % without). Without a side, an average orientation (1/2) rather than none.
float meanCosine(VoxelSurface surface, vec3 toLight) {
    return surface.sided ? max(dot(surface.normalSum, toLight), 0.0f) : 0.5f;
}

// The normal a voxel's shadow is looked up along: its surface's, or without a side the way to the
// light.
vec3 facingNormal(VoxelSurface surface, vec3 toLight) {
    return surface.sided ? surface.normalSum / surface.normalLength : toLight;
}

vec3 shadowLookupPoint(VoxelSurface surface, vec3 normal) {
    return surface.sided ? surface.point : surface.point + normal * (0.5f * frame.grid.voxelSize);
}

// An area light's irradiance at a voxel. Linear in the normal too, where the light is above the
// horizon: the unit normal's, scaled by the mean normal's length.
vec3 areaLightOnVoxel(GpuLight light, VoxelSurface surface) {
    vec3 normal = facingNormal(surface, normalize(light.positionRange.xyz - surface.point));
    vec3 lookup = shadowLookupPoint(surface, normal);
    vec3 irradiance = areaLightIrradiance(light, lookup, normal) * meanCosine(surface, normal);
    if (dot(irradiance, irradiance) <= 0.0f) return vec3(0.0f);
    return irradiance * areaLightVisibility(light, lookup, normal, distance(light.positionRange.xyz, lookup), false);
}

void injectVoxel(uint item, ivec3 voxel) {
    vec4 albedoOpacity = imageLoad(voxelAlbedo, voxel);
    VoxelSurface surface = voxelSurface(voxel);

    bool areaLights = (frame.componentFlags & USE_AREA_LIGHTS) != 0u;
    vec3 irradiance = vec3(0.0f);
    // Area lights and punctual ones in loops of their own (as in direct_light.glsl's directLight).
    if (areaLights && frame.firstAreaLight < frame.lightCount) {
        if (AREA_LIGHTS_CACHED) {
            irradiance = vec3(keptAreaLight[3u * item], keptAreaLight[3u * item + 1u],
                              keptAreaLight[3u * item + 2u]);
        } else {
            for (uint i = frame.firstAreaLight; i < frame.lightCount; ++i)
                irradiance += areaLightOnVoxel(lights[i], surface);
            for (uint c = 0u; c < 3u; ++c) keptAreaLight[3u * item + c] = irradiance[c];
        }
    }
    for (uint i = 0u; i < frame.firstAreaLight; ++i) {
        GpuLight light = lights[i];
        vec3 toLight;
        float distanceToLight;
        vec3 incident = incidentLight(light, surface.point, toLight, distanceToLight);
        float cosine = meanCosine(surface, toLight);
        if (cosine <= 0.0f) continue;
        vec3 normal = facingNormal(surface, toLight);
        vec3 lookup = shadowLookupPoint(surface, normal);
        float visibility = shadowVisibility(light, lookup, normal, distanceToLight, false);
        irradiance += incident * cosine * visibility;
    }
    vec3 outgoing = albedoOpacity.rgb * (1.0f / PI) * irradiance;
    if (!areaLights) outgoing += imageLoad(voxelEmission, voxel).rgb;
    vec3 scaled = outgoing * frame.radianceScale;
    if (addGathered != 0u) scaled += imageLoad(gatheredLight, voxel).rgb;  // already scaled
    float opacity = albedoOpacity.a;
    imageStore(radiance, voxel, vec4(scaled * opacity, opacity));
}

void main() {
    // The dispatch may be capped below ⌈count / group size⌉: each invocation strides over the rest.
    uint stride = gl_NumWorkGroups.x * WORK_LIST_GROUP_SIZE;
    for (uint i = gl_GlobalInvocationID.x; i < occupied.count; i += stride)
        injectVoxel(i, ivec3(unpackCell(occupiedVoxels[i])));
}
