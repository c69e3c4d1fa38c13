// The lobe the table fits: the renderer's GGX specular f·cosθ without Fresnel (brdf.h: D·Vis·cosθ),
// for a view direction in the xz plane (z the normal), and its importance sampling by the
// distribution of normals.
#pragma once

#include <cmath>

#include "brdf.h"

namespace vct::ltc {

struct LobeSample {
    double value;    // D·Vis·cosθ towards the direction, 0 below the horizon
    double density;  // of sampling that direction by `sample`, per solid angle
};

struct GgxLobe {
    glm::dvec3 view;  // unit, z ≥ 0
    float alpha;

    LobeSample evaluate(glm::dvec3 light) const {
        const glm::dvec3 half = glm::normalize(view + light);
        const float NdotH = float(std::max(half.z, 0.0));
        const double VdotH = std::max(glm::dot(view, half), 1e-12);
        const double distribution = glsl::ggxDistribution(NdotH, alpha);
        const double density = distribution * NdotH / (4.0 * VdotH);
        if (light.z <= 0.0) return {0.0, density};
        const double visibility = glsl::smithVisibility(float(light.z), float(view.z), alpha);
        return {distribution * visibility * light.z, density};
    }

    // A half vector from D·cosθh for (u, v) in [0, 1)², reflected about it.
    glm::dvec3 sample(double u, double v) const {
        const double a2 = double(alpha) * double(alpha);
        const double cos2 = (1.0 - u) / (1.0 + (a2 - 1.0) * u);
        const double cosTheta = std::sqrt(cos2), sinTheta = std::sqrt(std::max(1.0 - cos2, 0.0));
        const double phi = 2.0 * 3.14159265358979323846 * v;
        const glm::dvec3 half(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
        return 2.0 * glm::dot(view, half) * half - view;
    }
};

// The lobe's moments, by importance sampling on an n² stratified grid.
struct LobeMoments {
    double magnitude;      // ∫ D·Vis·cosθ
    double fresnel;        // ∫ D·Vis·cosθ·(1 − V·H)⁵
    glm::dvec3 direction;  // unit ∫ D·Vis·cosθ·ω, the lobe's mean direction
};

inline LobeMoments lobeMoments(const GgxLobe& lobe, int n) {
    LobeMoments moments{0.0, 0.0, glm::dvec3(0.0)};
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const glm::dvec3 light = lobe.sample((i + 0.5) / n, (j + 0.5) / n);
            const LobeSample s = lobe.evaluate(light);
            if (s.value <= 0.0) continue;
            const double weight = s.value / s.density;
            const double VdotH = glm::dot(lobe.view, glm::normalize(lobe.view + light));
            moments.magnitude += weight;
            moments.fresnel += weight * double(glsl::schlickWeight(float(VdotH)));
            moments.direction += weight * light;
        }
    const double count = double(n) * double(n);
    moments.magnitude /= count;
    moments.fresnel /= count;
    moments.direction.y = 0.0;  // symmetric about the xz plane
    moments.direction = glm::normalize(moments.direction);
    return moments;
}

}  // namespace vct::ltc
