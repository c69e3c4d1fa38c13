#version 460
// The full-screen lighting pass: reads the G-buffer and writes HDR radiance (scene units).
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.h"
#include "gbuffer_packing.h"

layout(set = 0, binding = FRAME_BINDING) uniform Frame { FrameConstants frame; };
layout(std430, set = 0, binding = MATERIALS_BINDING) readonly buffer Materials { GpuMaterial materials[]; };
layout(std430, set = 0, binding = LIGHTS_BINDING) readonly buffer Lights { GpuLight lights[]; };
layout(std430, set = 0, binding = SHADOW_VIEWS_BINDING) readonly buffer ShadowViews { ShadowView shadowViews[]; };
layout(set = 0, binding = SUN_SHADOW_MAPS_BINDING) uniform sampler2DArrayShadow sunShadowMaps;
layout(set = 0, binding = LOCAL_SHADOW_MAPS_BINDING) uniform sampler2DArrayShadow localShadowMaps;
layout(set = 0, binding = G_POSITION_BINDING) uniform sampler2D gPosition;
layout(set = 0, binding = G_NORMAL_BINDING) uniform sampler2D gNormal;  // xyz, w = gbufferSideOcclusion
layout(set = 0, binding = G_BASE_COLOR_BINDING) uniform sampler2D gBaseColor;  // rgb, metallic
layout(set = 0, binding = VOXEL_RADIANCE_BINDING) uniform sampler3D voxelRadiance;
layout(set = 0, binding = VOXEL_ALBEDO_BINDING) uniform sampler3D voxelAlbedo;
layout(set = 0, binding = VOXEL_NORMAL_BINDING) uniform sampler3D voxelNormal;
#include "directional_voxels.glsl"
// The reduced diffuse cones' result per sample, where TRACES_DIFFUSE_CONES is false.
layout(set = 0, binding = DIFFUSE_SAMPLES_BINDING) uniform sampler2D reducedDiffuse;
// The shadow maps' depths, for the PCF kernel's blocker search (shadows.glsl).
layout(set = 0, binding = SUN_SHADOW_DEPTHS_BINDING) uniform sampler2DArray sunShadowDepths;
layout(set = 0, binding = LOCAL_SHADOW_DEPTHS_BINDING) uniform sampler2DArray localShadowDepths;
layout(set = 0, binding = G_EMISSIVE_BINDING) uniform sampler2D gEmissive;  // the emissive texture's colour, roughness
layout(std430, set = 0, binding = EMITTER_TRIANGLES_BINDING) readonly buffer EmitterTriangles { GpuEmitterTriangle emitterTriangles[]; };
layout(set = 0, binding = AREA_SHADOW_MAPS_BINDING) uniform sampler2DArrayShadow areaShadowMaps;
layout(set = 0, binding = AREA_SHADOW_DEPTHS_BINDING) uniform sampler2DArray areaShadowDepths;
#include "ltc.h"
// The area lights' GGX table of linearly transformed cosines (src/render/ltc_table.h).
layout(std430, set = 0, binding = LTC_TABLE_BINDING) readonly buffer LtcTable { GpuLtcEntry ltcTable[]; };
#define AREA_LIGHT_SPECULAR
#define SHADOW_BLOCKER_SEARCH
// Whether the scene has area lights (with the component on): without them their code, which
// costs lavapipe even where it never runs (a 1280×720 frame's shading took 6× longer), is left out.
layout(constant_id = WITH_AREA_LIGHTS_CONSTANT_ID) const bool WITH_AREA_LIGHTS = true;
#define AREA_LIGHTS_COMPILED WITH_AREA_LIGHTS
// Whether some sun, and some spot or point light, casts shadows: the maps of a kind the scene
// lacks are not read (lavapipe would read them at every PCF tap).
layout(constant_id = WITH_SUN_SHADOWS_CONSTANT_ID) const bool WITH_SUN_SHADOWS = true;
layout(constant_id = WITH_LOCAL_SHADOWS_CONSTANT_ID) const bool WITH_LOCAL_SHADOWS = true;
#define SUN_SHADOWS_COMPILED WITH_SUN_SHADOWS
#define LOCAL_SHADOWS_COMPILED WITH_LOCAL_SHADOWS
// Whether some material reflects specularly: the area lights' GGX highlights are left out of a
// scene of Lambertian surfaces, where they are zero (tile-room's shading 62 -> 52 ms at 128²).
layout(constant_id = WITH_AREA_LIGHT_SPECULAR_CONSTANT_ID) const bool WITH_AREA_LIGHT_SPECULAR = true;
#define AREA_LIGHT_SPECULAR_COMPILED WITH_AREA_LIGHT_SPECULAR

// Where a cone meets a surface, on which side (cone_tracing.glsl).
vec3 voxelNormalAt(ivec3 cell) { return texelFetch(voxelNormal, cell, 0).xyz; }
#include "surface_planes.glsl"
#include "cone_tracing.glsl"
#include "reduced_diffuse.glsl"
#include "direct_light.glsl"
#include "debug_views.glsl"

layout(location = 0) out vec4 outRadiance;

// What this pipeline can run (ShadePass builds one per combination a frame asks for). Code that a
// frame skips still costs lavapipe: every inlined cone loop widens the SIMD fragment program, and
// the still frame of a 1280×720 image took 340 ms with all of it against 115 ms with none.
layout(constant_id = WITH_DEBUG_VIEWS_CONSTANT_ID) const bool WITH_DEBUG_VIEWS = true;
layout(constant_id = TRACES_DIFFUSE_CONES_CONSTANT_ID) const bool TRACES_DIFFUSE_CONES = true;  // false: reads reducedDiffuse
layout(constant_id = TRACES_SPECULAR_CONE_CONSTANT_ID) const bool TRACES_SPECULAR_CONE = true;

// Indirect light gathered by cones, split like the direct light into diffuse and specular parts.
// The split of reflected energy between the two lobes uses the GGX directional albedo.
vec3 indirectLight(SurfacePoint surface, ivec2 pixel, uint flags) {
    bool wantDiffuse = (flags & SHOW_INDIRECT_DIFFUSE) != 0u;
    bool wantAmbient = (flags & SHOW_AMBIENT_OCCLUSION) != 0u && frame.ambientFactor > 0.0f;
    bool wantSpecular = (flags & SHOW_INDIRECT_SPECULAR) != 0u;
    if (!wantDiffuse && !wantAmbient && !wantSpecular) return vec3(0.0f);

    float NdotV = max(dot(surface.normal, surface.toViewer), 1e-4f);
    vec2 lobe = environmentBrdf(clamp(surface.roughness, MIN_ROUGHNESS, 1.0f), NdotV);
    float dielectricSpecular = surface.specularWeight * (DIELECTRIC_F0 * lobe.x + lobe.y);
    vec3 specularAlbedo = mix(vec3(dielectricSpecular), surface.baseColor * lobe.x + lobe.y, surface.metallic);
    vec3 diffuseAlbedo = (1.0f - surface.metallic) * surface.baseColor * (1.0f - dielectricSpecular);

    vec3 radiance = vec3(0.0f);
    bool reflects = wantSpecular && max(specularAlbedo.r, max(specularAlbedo.g, specularAlbedo.b)) > 1e-3f;
    float tanHalf = specularConeTanHalfAperture(ggxAlpha(surface.roughness));
    // A lobe at least as wide as the widest specular cone (90°: roughness ≥ 0.64) takes the light
    // the diffuse cones gathered, already at hand, instead of a cone of its own: six cones estimate
    // so wide a lobe better (FlightHelmet, 128², against the path tracer: full relMSE 0.182 -> 0.167),
    // and its pixels trace nothing more.
    bool reflectsDiffuseLight = reflects && (wantDiffuse || wantAmbient) && tanHalf >= frame.specularConeMaxTan;
    if (wantDiffuse || wantAmbient) {
        vec4 gathered = TRACES_DIFFUSE_CONES ? gatherDiffuse(surface.position, surface.normal)
                                             : texelFetch(reducedDiffuse, pixel, 0);
        if (wantDiffuse) radiance += diffuseAlbedo * gathered.rgb;  // albedo/π · (π Σ wᵢ Lᵢ)
        if (wantAmbient) radiance += frame.ambientFactor * diffuseAlbedo * (1.0f - gathered.a);
        if (reflectsDiffuseLight) radiance += specularAlbedo * gathered.rgb;
    }
    // Skip the specular cone where the material reflects (almost) nothing specularly.
    if (TRACES_SPECULAR_CONE && reflects && !reflectsDiffuseLight) {
        // Like the diffuse cones, it starts a little off the surface, clear of its own voxels.
        vec3 origin = surface.position + surface.normal * (frame.coneStartOffset * frame.grid.voxelSize);
        vec3 reflected = reflect(-surface.toViewer, surface.normal);
        vec4 across = surfaceAcrossTheGap(surface.position, surface.normal);
        radiance += specularAlbedo * (across.a > 0.0f ? across.rgb
                                                      : traceCone(origin, reflected, tanHalf, frame.coneStartOffset,
                                                                  dot(reflected, surface.normal)).radiance);
    }
    return radiance;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 positionMaterial = texelFetch(gPosition, pixel, 0);
    if (WITH_DEBUG_VIEWS && frame.debugView != DEBUG_NONE) {
        outRadiance = vec4(debugView(pixel, positionMaterial), 1.0f);
        return;
    }
    if (positionMaterial.w < 0.5f) {
        // Nothing in front of the camera: it sees the sky, direct light as a lamp seen is.
        vec4 far = frame.inverseViewProjection * vec4(gl_FragCoord.xy * frame.inverseRenderSize * 2.0f - 1.0f, 1.0f, 1.0f);
        vec3 sky = skyRadiance(normalize(far.xyz / far.w - frame.cameraPosition), 0.0f);
        outRadiance = vec4((frame.componentFlags & SHOW_SKY) != 0u ? sky : vec3(0.0f), 1.0f);
        return;
    }
    vec4 normalSide = texelFetch(gNormal, pixel, 0);
    GpuMaterial material = materials[uint(positionMaterial.w) - 1u];

    SurfacePoint surface;
    surface.position = positionMaterial.xyz;
    surface.normal = normalize(normalSide.xyz);
    surface.toViewer = normalize(frame.cameraPosition - surface.position);
    vec4 baseColorMetallic = texelFetch(gBaseColor, pixel, 0);
    vec4 emissiveRoughness = texelFetch(gEmissive, pixel, 0);
    surface.baseColor = baseColorMetallic.rgb;
    surface.metallic = baseColorMetallic.a;
    surface.roughness = emissiveRoughness.a;
    surface.specularWeight = material.specularWeight;

    uint flags = frame.componentFlags;
    vec3 radiance = directLight(surface, flags);
    if ((flags & SHOW_EMISSION) != 0u && gbufferFrontFace(normalSide.w))
        radiance += material.emission.rgb * emissiveRoughness.rgb;
    // The occlusion texture scales the indirect light, diffuse and specular, and the ambient term.
    radiance += gbufferOcclusion(normalSide.w) * indirectLight(surface, pixel, flags);
    outRadiance = vec4(radiance, 1.0f);
}
