// Sampling the renderer's BRDF (shaders_glsl/brdf.h): a mixture of a cosine-weighted diffuse
// lobe and GGX visible-normal sampling, chosen with a probability from each lobe's estimated
// albedo. The returned density is the mixture's, so one sample is weighted as by the balance
// heuristic over both lobes (Veach 1997, §9.2.4 "one-sample model").
#pragma once

#include <optional>

#include <glm/glm.hpp>

namespace vct::pt {

// A material after texturing: the inputs of glsl::evaluateBrdf.
struct SurfaceMaterial {
    glm::vec3 baseColor{1.0f};
    float metallic = 0.0f;
    float roughness = 1.0f;
    float specularWeight = 1.0f;
};

struct BsdfSample {
    glm::vec3 direction;  // L, unit, world space
    glm::vec3 weight;     // f(V, L)·(N·L) / pdf
    float pdf;            // per unit solid angle
};

// Probability of sampling the specular lobe, for a viewer at cosθ = NdotV.
float specularLobeProbability(const SurfaceMaterial& material, float NdotV);

// f(V, L) for unit N, V, L (the shared GLSL function).
glm::vec3 evaluateBsdf(const SurfaceMaterial& material, const glm::vec3& N, const glm::vec3& V, const glm::vec3& L);

// The density sampleBsdf draws L with, per unit solid angle.
float bsdfPdf(const SurfaceMaterial& material, const glm::vec3& N, const glm::vec3& V, const glm::vec3& L);

// Draws L from three uniform numbers; nothing when the sample falls below the horizon.
std::optional<BsdfSample> sampleBsdf(const SurfaceMaterial& material, const glm::vec3& N, const glm::vec3& V,
                                     float uLobe, float u1, float u2);

}  // namespace vct::pt
