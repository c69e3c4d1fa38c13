// Direct light from KHR_lights_punctual lights and area lights at a surface point.
// Requires: lights[] (GpuLight), emitterTriangles[] (GpuEmitterTriangle), frame, and shadows.glsl's bindings.
#ifndef VCT_DIRECT_LIGHT_GLSL
#define VCT_DIRECT_LIGHT_GLSL

#include "brdf.h"
#include "lights.h"
#include "shadows.glsl"
#include "area_lights.glsl"

struct SurfacePoint {
    vec3 position;
    vec3 normal;     // unit, facing the viewer
    vec3 toViewer;   // unit
    vec3 baseColor;
    float metallic;
    float roughness;
    float specularWeight;
};

// Direction to the light, and the irradiance it gives a surface facing it (before cosθ and shadows).
vec3 incidentLight(GpuLight light, vec3 position, out vec3 toLight, out float distanceToLight) {
    uint type = uint(light.radiantIntensity.w);
    if (type == LIGHT_DIRECTIONAL) {
        toLight = -light.direction.xyz;
        distanceToLight = 1e30f;
        return light.radiantIntensity.rgb;
    }
    vec3 offset = light.positionRange.xyz - position;
    float distanceSquared = max(dot(offset, offset), 1e-12f);
    distanceToLight = sqrt(distanceSquared);
    toLight = offset / distanceToLight;
    float attenuation = rangeAttenuation(distanceToLight, light.positionRange.w) / distanceSquared;
    if (type == LIGHT_SPOT)
        attenuation *= spotAttenuation(light.direction.xyz, -toLight, light.spotShadow.x, light.spotShadow.y);
    return light.radiantIntensity.rgb * attenuation;
}

// Reflected radiance towards the viewer from one area light: its exact irradiance through the
// diffuse lobe (whose Fresnel weight is taken towards the light's centre), and where the shader
// defines AREA_LIGHT_SPECULAR (the shading pass; the injection reflects diffusely only) its GGX
// highlight (areaLightSpecular).
vec3 areaLightReflected(GpuLight light, SurfacePoint surface, uint flags) {
    vec3 irradiance = areaLightIrradiance(light, surface.position, surface.normal);
    if (dot(irradiance, irradiance) <= 0.0f) return vec3(0.0f);
    vec3 toCentre = light.positionRange.xyz - surface.position;
    float distanceToLight = length(toCentre);
    float visibility = areaLightVisibility(light, surface.position, surface.normal, distanceToLight, true);
    if (visibility <= 0.0f) return vec3(0.0f);
    vec3 radiance = vec3(0.0f);
    if ((flags & SHOW_DIRECT_DIFFUSE) != 0u) {
        vec3 H = normalize(surface.toViewer + toCentre / max(distanceToLight, 1e-20f));
        radiance += brdfDiffuse(surface.baseColor, surface.metallic, surface.specularWeight,
                                max(dot(surface.toViewer, H), 0.0f)) * irradiance;
    }
#ifdef AREA_LIGHT_SPECULAR
    if (AREA_LIGHT_SPECULAR_COMPILED && (flags & SHOW_DIRECT_SPECULAR) != 0u)
        radiance += areaLightSpecular(light, surface.position, surface.normal, surface.toViewer, surface.baseColor,
                                      surface.metallic, surface.roughness, surface.specularWeight);
#endif
    return radiance * visibility;
}

// Reflected radiance towards the viewer from all lights, split by the SHOW_DIRECT_* flags. The
// punctual lights and the area lights (lights[frame.firstAreaLight..]) have loops of their own:
// lavapipe runs every branch of a loop's body for every light, so one loop ran each light through
// both kinds' code.
vec3 directLight(SurfacePoint surface, uint flags) {
    vec3 radiance = vec3(0.0f);
    float NdotV = max(dot(surface.normal, surface.toViewer), 1e-4f);
    if (AREA_LIGHTS_COMPILED && (flags & USE_AREA_LIGHTS) != 0u)
        for (uint i = frame.firstAreaLight; i < frame.lightCount; ++i)
            radiance += areaLightReflected(lights[i], surface, flags);
    for (uint i = 0u; i < frame.firstAreaLight; ++i) {
        GpuLight light = lights[i];
        vec3 toLight;
        float distanceToLight;
        vec3 irradiance = incidentLight(light, surface.position, toLight, distanceToLight);
        float NdotL = dot(surface.normal, toLight);
        if (NdotL <= 0.0f || dot(irradiance, irradiance) <= 0.0f) continue;
        float visibility = shadowVisibility(light, surface.position, surface.normal, distanceToLight, true);
        if (visibility <= 0.0f) continue;

        vec3 H = normalize(surface.toViewer + toLight);
        float NdotH = max(dot(surface.normal, H), 0.0f);
        float VdotH = max(dot(surface.toViewer, H), 0.0f);
        vec3 brdf = vec3(0.0f);
        if ((flags & SHOW_DIRECT_DIFFUSE) != 0u)
            brdf += brdfDiffuse(surface.baseColor, surface.metallic, surface.specularWeight, VdotH);
        if ((flags & SHOW_DIRECT_SPECULAR) != 0u)
            brdf += brdfSpecular(surface.baseColor, surface.metallic, surface.roughness, surface.specularWeight, NdotL,
                                 NdotV, NdotH, VdotH);
        radiance += brdf * irradiance * (NdotL * visibility);
    }
    return radiance;
}

#endif
