// The surface model of the renderer and of the reference path tracer: glTF 2.0
// metallic-roughness (glTF spec, Appendix B) with KHR_materials_specular's weight.
//
//   f = mix(dielectric, metal, metallic)
//   dielectric = baseColor/π · (1 − w·F(f0 = 0.04)) + w·F(f0 = 0.04)·D·Vis
//   metal      = F(f0 = baseColor)·D·Vis
//
// with GGX D, height-correlated Smith Vis (Heitz 2014), Schlick's Fresnel on V·H, α = roughness²
// and w the specular weight (1 by default, 0 for a pure Lambertian surface).
#ifndef VCT_BRDF_H
#define VCT_BRDF_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

const float PI = 3.14159265358979f;
// Perceptual roughness below this makes GGX a near-delta that neither the cones nor
// float precision can represent; both renderers clamp the same way.
const float MIN_ROUGHNESS = 0.045f;
const float DIELECTRIC_F0 = 0.04f;

SHARED_FN float ggxAlpha(float roughness) {
    float r = clamp(roughness, MIN_ROUGHNESS, 1.0f);
    return r * r;
}

SHARED_FN float ggxDistribution(float NdotH, float alpha) {
    float a2 = alpha * alpha;
    float d = NdotH * NdotH * (a2 - 1.0f) + 1.0f;
    return a2 / (PI * d * d);
}

// G2 / (4 NdotL NdotV), height-correlated Smith for GGX.
SHARED_FN float smithVisibility(float NdotL, float NdotV, float alpha) {
    float a2 = alpha * alpha;
    float lambdaV = NdotL * sqrt(NdotV * NdotV * (1.0f - a2) + a2);
    float lambdaL = NdotV * sqrt(NdotL * NdotL * (1.0f - a2) + a2);
    return 0.5f / max(lambdaV + lambdaL, 1e-7f);
}

SHARED_FN float schlickWeight(float cosTheta) {
    float m = clamp(1.0f - cosTheta, 0.0f, 1.0f);
    float m2 = m * m;
    return m2 * m2 * m;
}

// Fresnel of the dielectric layer, scaled by the specular weight: the share of light the
// specular lobe takes from the diffuse one.
SHARED_FN float dielectricFresnel(float VdotH, float specularWeight) {
    return specularWeight * (DIELECTRIC_F0 + (1.0f - DIELECTRIC_F0) * schlickWeight(VdotH));
}

// The diffuse part of f (zero for metals), for the direct-diffuse toggle.
SHARED_FN vec3 brdfDiffuse(vec3 baseColor, float metallic, float specularWeight, float VdotH) {
    return (1.0f - metallic) * baseColor * (1.0f / PI) * (1.0f - dielectricFresnel(VdotH, specularWeight));
}

// The specular part of f, for the direct-specular toggle.
SHARED_FN vec3 brdfSpecular(vec3 baseColor, float metallic, float roughness, float specularWeight,
                            float NdotL, float NdotV, float NdotH, float VdotH) {
    float alpha = ggxAlpha(roughness);
    float lobe = ggxDistribution(NdotH, alpha) * smithVisibility(NdotL, NdotV, alpha);
    vec3 metalFresnel = baseColor + (vec3(1.0f) - baseColor) * schlickWeight(VdotH);
    return lobe * mix(vec3(dielectricFresnel(VdotH, specularWeight)), metalFresnel, metallic);
}

// f(V, L) for unit vectors N, V, L; zero below either horizon.
SHARED_FN vec3 evaluateBrdf(vec3 baseColor, float metallic, float roughness, float specularWeight, vec3 N,
                            vec3 V, vec3 L) {
    float NdotL = dot(N, L);
    float NdotV = dot(N, V);
    if (NdotL <= 0.0f || NdotV <= 0.0f) return vec3(0.0f);
    vec3 H = normalize(V + L);
    float NdotH = max(dot(N, H), 0.0f);
    float VdotH = max(dot(V, H), 0.0f);
    return brdfDiffuse(baseColor, metallic, specularWeight, VdotH) +
           brdfSpecular(baseColor, metallic, roughness, specularWeight, NdotL, NdotV, NdotH, VdotH);
}

VCT_SHARED_END

#endif
