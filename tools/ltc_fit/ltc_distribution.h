// A linearly transformed cosine (Heitz et al. 2016, §3): the clamped cosine cos⁺θ/π whose
// directions went through M. Its density at ω is D₀(M⁻¹ω/|M⁻¹ω|)·|det M⁻¹|/|M⁻¹ω|³ (eq. 2);
// sampling maps a cosine-distributed direction through M.
#pragma once

#include <cmath>

#include <glm/glm.hpp>

namespace vct::ltc {

struct Ltc {
    glm::dmat3 matrix;
    glm::dmat3 inverse;
    double inverseDeterminant;

    explicit Ltc(const glm::dmat3& m) : matrix(m), inverse(glm::inverse(m)) {
        inverseDeterminant = std::abs(glm::determinant(inverse));
    }

    double density(glm::dvec3 direction) const {
        const glm::dvec3 original = inverse * direction;
        const double length = glm::length(original);
        const double cosine = original.z / length;
        if (cosine <= 0.0) return 0.0;
        return cosine / 3.14159265358979323846 * inverseDeterminant / (length * length * length);
    }

    glm::dvec3 sample(double u, double v) const {
        const double radius = std::sqrt(u), phi = 2.0 * 3.14159265358979323846 * v;
        const glm::dvec3 original(radius * std::cos(phi), radius * std::sin(phi), std::sqrt(std::max(1.0 - u, 0.0)));
        return glm::normalize(matrix * original);
    }
};

}  // namespace vct::ltc
