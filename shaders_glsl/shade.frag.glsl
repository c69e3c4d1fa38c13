#version 460
// The full-screen lighting pass: reads the G-buffer and writes HDR radiance (scene units).
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.h"

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(std430, set = 0, binding = 1) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, set = 0, binding = 2) readonly buffer Lights { GpuLight lights[]; };
layout(std430, set = 0, binding = 3) readonly buffer ShadowViews { ShadowView shadowViews[]; };
layout(set = 0, binding = 4) uniform sampler2DArrayShadow sunShadowMaps;
layout(set = 0, binding = 5) uniform sampler2DArrayShadow localShadowMaps;
layout(set = 0, binding = 6) uniform sampler2D gPosition;
layout(set = 0, binding = 7) uniform sampler2D gNormal;
layout(set = 0, binding = 8) uniform sampler2D gBaseColor;

#include "direct_light.glsl"

layout(location = 0) out vec4 outRadiance;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 positionMaterial = texelFetch(gPosition, pixel, 0);
    if (positionMaterial.w < 0.5f) {
        outRadiance = vec4(0.0f, 0.0f, 0.0f, 1.0f);  // no environment light: nothing behind the scene
        return;
    }
    vec4 normalFront = texelFetch(gNormal, pixel, 0);
    GpuMaterial material = materials[uint(positionMaterial.w) - 1u];

    SurfacePoint surface;
    surface.position = positionMaterial.xyz;
    surface.normal = normalize(normalFront.xyz);
    surface.toViewer = normalize(frame.cameraPosition.xyz - surface.position);
    surface.baseColor = texelFetch(gBaseColor, pixel, 0).rgb;
    surface.metallic = material.metallic;
    surface.roughness = material.roughness;
    surface.specularWeight = material.specularWeight;

    uint flags = frame.counts.z;
    vec3 radiance = directLight(surface, flags);
    if ((flags & SHOW_EMISSION) != 0u && normalFront.w > 0.5f) radiance += material.emission.rgb;
    outRadiance = vec4(radiance, 1.0f);
}
