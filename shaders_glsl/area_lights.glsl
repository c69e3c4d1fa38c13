// Direct light from area lights (LIGHT_AREA, src/scene/area_lights.h): the exact unshadowed
// irradiance of each emitting triangle (area_light.h), times one shadow-map visibility for the
// light, whose penumbra widens with the light's size (shadows.glsl). With AREA_LIGHT_SPECULAR
// defined, also their GGX reflection, exact up to a fitted table (linearly transformed cosines, ltc.h).
// Requires: emitterTriangles[] (GpuEmitterTriangle), what direct_light.glsl requires, and with
// AREA_LIGHT_SPECULAR ltcTable[] (GpuLtcEntry, the table of src/render/ltc_table.h).
#ifndef VCT_AREA_LIGHTS_GLSL
#define VCT_AREA_LIGHTS_GLSL

#include "area_light.h"

// Irradiance at `position` (unit `normal`) from the light's triangles whose front faces it.
vec3 areaLightIrradiance(GpuLight light, vec3 position, vec3 normal) {
    uint first = uint(light.spotShadow.x);
    uint count = uint(light.spotShadow.y);
    vec3 irradiance = vec3(0.0f);
    for (uint i = first; i < first + count; ++i) {
        GpuEmitterTriangle triangle = emitterTriangles[i];
        vec3 a = triangle.a.xyz - position;
        vec3 b = triangle.b.xyz - position;
        vec3 c = triangle.c.xyz - position;
        // Emission leaves the front face only: the point must lie in front of the triangle's plane.
        if (dot(cross(b - a, c - a), -a) <= 0.0f) continue;
        irradiance += vec3(triangle.a.w, triangle.b.w, triangle.c.w) * triangleIrradiance(a, b, c, normal);
    }
    return irradiance;
}

#ifdef AREA_LIGHT_SPECULAR
#include "ltc.h"

// The GGX table's entry for (roughness, N·V), blended between its four neighbours (the CPU twin is
// lookupLtcGgx in src/render/ltc_table.cpp).
GpuLtcEntry ltcLookup(float roughness, float NdotV) {
    vec2 coordinate = ltcTableCoordinate(roughness, NdotV);
    uvec2 low = min(uvec2(coordinate), uvec2(LTC_TABLE_SIZE - 2u));
    vec2 t = coordinate - vec2(low);
    uint index = low.y * LTC_TABLE_SIZE + low.x;
    GpuLtcEntry e00 = ltcTable[index], e10 = ltcTable[index + 1u];
    GpuLtcEntry e01 = ltcTable[index + LTC_TABLE_SIZE], e11 = ltcTable[index + LTC_TABLE_SIZE + 1u];
    GpuLtcEntry entry;
    entry.inverseMatrix = mix(mix(e00.inverseMatrix, e10.inverseMatrix, t.x),
                              mix(e01.inverseMatrix, e11.inverseMatrix, t.x), t.y);
    entry.magnitudeFresnel = mix(mix(e00.magnitudeFresnel, e10.magnitudeFresnel, t.x),
                                 mix(e01.magnitudeFresnel, e11.magnitudeFresnel, t.x), t.y);
    return entry;
}

// The light's GGX reflection by linearly transformed cosines (ltc.h): each triangle whose front
// faces the point, mapped into the space where the pixel's lobe is a clamped cosine, clipped to that
// cosine's horizon and integrated exactly; exact up to the table's fit (a few percent).
vec3 areaLightSpecular(GpuLight light, vec3 position, vec3 normal, vec3 toViewer, vec3 baseColor, float metallic,
                       float roughness, float specularWeight) {
    float NdotV = max(dot(normal, toViewer), 1e-4f);
    GpuLtcEntry entry = ltcLookup(roughness, NdotV);
    vec3 albedo = ltcSpecularAlbedo(entry.magnitudeFresnel, baseColor, metallic, specularWeight);
    if (max(albedo.r, max(albedo.g, albedo.b)) <= 0.0f) return vec3(0.0f);
    mat3 worldToCosine = ltcWorldToCosine(entry.inverseMatrix, normal, toViewer);
    uint first = uint(light.spotShadow.x);
    uint count = uint(light.spotShadow.y);
    vec3 reflected = vec3(0.0f);
    for (uint i = first; i < first + count; ++i) {
        GpuEmitterTriangle triangle = emitterTriangles[i];
        vec3 a = triangle.a.xyz - position;
        vec3 b = triangle.b.xyz - position;
        vec3 c = triangle.c.xyz - position;
        if (dot(cross(b - a, c - a), -a) <= 0.0f) continue;  // front faces only, as for the irradiance
        reflected += vec3(triangle.a.w, triangle.b.w, triangle.c.w) * ltcTriangleIntegral(worldToCosine, a, b, c);
    }
    return albedo * reflected;
}
#endif

#endif
