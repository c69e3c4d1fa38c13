// How much light reaches a point from a KHR_lights_punctual light, shared by the renderer
// and the path tracer. Irradiance at a surface facing the light: point I/d², spot
// I/d² · the spec's smooth cone falloff, directional E. Multiply by cosθ at the surface.
#ifndef VCT_LIGHTS_H
#define VCT_LIGHTS_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

const uint LIGHT_DIRECTIONAL = 0u;
const uint LIGHT_POINT = 1u;
const uint LIGHT_SPOT = 2u;
// An emissive surface (src/scene/area_lights.h): its GpuLight holds the mean radiance, the shadow
// cube's eye and the light's radius, its front normal and area, and its range of emitter triangles.
const uint LIGHT_AREA = 3u;

// KHR_lights_punctual's recommended range falloff: smooth to zero at `range` (0 = none).
SHARED_FN float rangeAttenuation(float distance, float range) {
    if (range <= 0.0f) return 1.0f;
    float ratio = distance / range;
    float ratio4 = ratio * ratio * ratio * ratio;
    return clamp(1.0f - ratio4, 0.0f, 1.0f);
}

// The spec's spot falloff: smoothstep-like ramp between the outer and inner cone, written as
// the spec's reference implementation (lightAngleScale/Offset) and squared.
SHARED_FN float spotAttenuation(vec3 lightDirection, vec3 toSurface, float innerConeAngle, float outerConeAngle) {
    float cosOuter = cos(outerConeAngle);
    float cosInner = cos(innerConeAngle);
    float scale = 1.0f / max(cosInner - cosOuter, 0.001f);
    float offset = -cosOuter * scale;
    float cd = dot(lightDirection, toSurface);
    float attenuation = clamp(cd * scale + offset, 0.0f, 1.0f);
    return attenuation * attenuation;
}

VCT_SHARED_END

#endif
