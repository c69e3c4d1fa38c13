#include "bsdf.h"

#include <algorithm>
#include <cmath>

#include "brdf.h"
#include "luminance.h"
#include "sampling.h"

namespace vct::pt {
namespace {

using glsl::luminance;

bool finitePositive(float x) { return x > 0.0f && std::isfinite(x); }

}  // namespace

float specularLobeProbability(const SurfaceMaterial& m, float NdotV) {
    const bool hasSpecular = m.metallic > 0.0f || m.specularWeight > 0.0f;
    const bool hasDiffuse = m.metallic < 1.0f && luminance(m.baseColor) > 0.0f;
    if (!hasSpecular) return 0.0f;
    if (!hasDiffuse) return 1.0f;
    // Albedo estimates with Fresnel at V·H ≈ N·V: the dielectric layer takes F, the diffuse
    // lobe the rest; the metal reflects Schlick's F(f0 = baseColor).
    const float fresnel = glsl::dielectricFresnel(NdotV, m.specularWeight);
    const float weight = glsl::schlickWeight(NdotV);
    const float metal = luminance(m.baseColor + (glm::vec3(1.0f) - m.baseColor) * weight);
    const float specular = glm::mix(fresnel, metal, m.metallic);
    const float diffuse = (1.0f - m.metallic) * luminance(m.baseColor) * (1.0f - fresnel);
    // Both lobes keep some chance, so neither is left unsampled where the estimate is poor.
    return std::clamp(specular / std::max(specular + diffuse, 1e-6f), 0.1f, 0.9f);
}

glm::vec3 evaluateBsdf(const SurfaceMaterial& m, const glm::vec3& N, const glm::vec3& V, const glm::vec3& L) {
    return glsl::evaluateBrdf(m.baseColor, m.metallic, m.roughness, m.specularWeight, N, V, L);
}

float bsdfPdf(const SurfaceMaterial& m, const glm::vec3& N, const glm::vec3& V, const glm::vec3& L) {
    const float NdotV = glm::dot(N, V), NdotL = glm::dot(N, L);
    if (NdotV <= 0.0f || NdotL <= 0.0f) return 0.0f;
    const float pSpecular = specularLobeProbability(m, NdotV);
    float pdf = (1.0f - pSpecular) * cosineHemispherePdf(NdotL);
    if (pSpecular > 0.0f) {
        const glm::vec3 H = glm::normalize(V + L);
        pdf += pSpecular * ggxVisibleNormalReflectionPdf(NdotV, glm::dot(N, H), glsl::ggxAlpha(m.roughness));
    }
    return pdf;
}

std::optional<BsdfSample> sampleBsdf(const SurfaceMaterial& m, const glm::vec3& N, const glm::vec3& V, float uLobe,
                                     float u1, float u2) {
    const Frame frame = Frame::around(N);
    const glm::vec3 viewLocal = frame.toLocal(V);
    if (viewLocal.z <= 1e-6f) return std::nullopt;
    glm::vec3 lightLocal;
    if (uLobe < specularLobeProbability(m, viewLocal.z)) {
        const glm::vec3 h = sampleGgxVisibleNormal(viewLocal, glsl::ggxAlpha(m.roughness), u1, u2);
        lightLocal = glm::reflect(-viewLocal, h);
    } else {
        lightLocal = sampleCosineHemisphere(u1, u2);
    }
    if (lightLocal.z <= 0.0f) return std::nullopt;
    const glm::vec3 L = glm::normalize(frame.toWorld(lightLocal));
    const float pdf = bsdfPdf(m, N, V, L);
    if (!finitePositive(pdf)) return std::nullopt;
    const glm::vec3 weight = evaluateBsdf(m, N, V, L) * glm::dot(N, L) / pdf;
    if (!std::isfinite(weight.x + weight.y + weight.z)) return std::nullopt;
    return BsdfSample{L, weight, pdf};
}

}  // namespace vct::pt
