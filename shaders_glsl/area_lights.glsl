// Direct light from area lights (LIGHT_AREA, src/scene/area_lights.h): the exact unshadowed
// irradiance of each emitting triangle (area_light.h), times one shadow-map visibility for the
// light, whose penumbra widens with the light's size (shadows.glsl).
// Requires: emitterTriangles[] (GpuEmitterTriangle) and what direct_light.glsl requires.
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

// The light's specular reflection, approximated: GGX evaluated towards the point of the light
// nearest the mirror direction (the light's disc in its plane), the lobe widened by the disc's
// angular radius and renormalised (Karis 2013, "representative point"). Diffuse light is exact.
vec3 areaLightSpecular(GpuLight light, vec3 position, vec3 normal, vec3 toViewer, vec3 baseColor, float metallic,
                       float roughness, float specularWeight) {
    vec3 centre = light.positionRange.xyz;
    vec3 front = light.direction.xyz;
    float lightRadius = light.positionRange.w;
    vec3 reflected = reflect(-toViewer, normal);
    vec3 nearest = centre;
    float approach = dot(reflected, front);
    if (approach < -1e-4f) {
        float along = dot(centre - position, front) / approach;
        if (along > 0.0f) nearest = position + reflected * along;
    }
    vec3 offset = nearest - centre;
    offset -= front * dot(offset, front);
    float offsetLength = length(offset);
    if (offsetLength > lightRadius) offset *= lightRadius / offsetLength;
    vec3 toLight = centre + offset - position;
    float distanceToLight = length(toLight);
    toLight /= max(distanceToLight, 1e-20f);
    float NdotL = dot(normal, toLight);
    float cosLight = -dot(front, toLight);
    if (NdotL <= 0.0f || cosLight <= 0.0f) return vec3(0.0f);

    float alpha = ggxAlpha(roughness);
    float widened = min(alpha + 0.5f * lightRadius / max(distanceToLight, 1e-20f), 1.0f);
    float normalisation = (alpha * alpha) / (widened * widened);
    float solidAngle = min(light.direction.w * cosLight / (distanceToLight * distanceToLight), 2.0f * PI);
    vec3 H = normalize(toViewer + toLight);
    float NdotV = max(dot(normal, toViewer), 1e-4f);
    vec3 f = brdfSpecular(baseColor, metallic, roughness, specularWeight, NdotL, NdotV, max(dot(normal, H), 0.0f),
                          max(dot(toViewer, H), 0.0f));
    return f * light.radiantIntensity.rgb * (solidAngle * NdotL * normalisation);
}

#endif
