// Random numbers and the sample warps of the path tracer, with their densities.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "brdf.h"

namespace vct::pt {

constexpr float kPi = 3.14159265358979f;

// splitmix64's finaliser (Steele, Lea and Flood 2014): a good 64-bit hash for seeding.
inline uint64_t mixBits(uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// PCG32 (O'Neill 2014, pcg32_random_r): 64-bit LCG state, xorshift-high + random-rotation output.
struct Rng {
    uint64_t state = 0;
    uint64_t increment = 1;  // odd; selects the stream

    // One independent stream per (seed, pixel, sample): an image does not depend on how its
    // work was split between threads or passes.
    static Rng forSample(uint64_t seed, uint64_t pixel, uint64_t sample) {
        const uint64_t key = mixBits(mixBits(mixBits(seed) ^ pixel) ^ sample);
        Rng rng;
        rng.increment = (mixBits(key ^ 0xda942042e4dd58b5ull) << 1) | 1u;
        rng.state = key + rng.increment;  // as pcg32_srandom_r
        rng.nextUint();
        return rng;
    }

    uint32_t nextUint() {
        const uint64_t old = state;
        state = old * 6364136223846793005ull + increment;
        const uint32_t xorShifted = uint32_t(((old >> 18u) ^ old) >> 27u);
        const uint32_t rotation = uint32_t(old >> 59u);
        return (xorShifted >> rotation) | (xorShifted << ((32u - rotation) & 31u));
    }

    // Uniform in [0, 1): the top 24 bits, so the result is exactly representable and never 1.
    float uniform() { return float(nextUint() >> 8) * 0x1p-24f; }
};

// An orthonormal basis around a unit normal (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited", JCGT 6(1)); local z is the normal.
struct Frame {
    glm::vec3 tangent, bitangent, normal;

    static Frame around(const glm::vec3& n) {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float b = n.x * n.y * a;
        return {glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x), glm::vec3(b, sign + n.y * n.y * a, -n.y),
                n};
    }
    glm::vec3 toLocal(const glm::vec3& v) const {
        return {glm::dot(v, tangent), glm::dot(v, bitangent), glm::dot(v, normal)};
    }
    glm::vec3 toWorld(const glm::vec3& v) const { return v.x * tangent + v.y * bitangent + v.z * normal; }
};

// Shirley and Chiu's concentric map of the square to the unit disk (PBRT-v3 §13.6.2).
inline glm::vec2 concentricDisk(float u1, float u2) {
    const float x = 2.0f * u1 - 1.0f, y = 2.0f * u2 - 1.0f;
    if (x == 0.0f && y == 0.0f) return glm::vec2(0.0f);
    const bool xMajor = std::abs(x) > std::abs(y);
    const float r = xMajor ? x : y;
    const float theta = xMajor ? (kPi / 4.0f) * (y / x) : (kPi / 2.0f) - (kPi / 4.0f) * (x / y);
    return r * glm::vec2(std::cos(theta), std::sin(theta));
}

// The entry a uniform `u` in [0, 1) picks from a cumulative distribution (ascending, non-empty, its
// last entry 1): the first whose cumulative probability passes u, so entry i with probability
// cdf[i] − cdf[i − 1] and never one of probability 0.
inline size_t pickFromCdf(const std::vector<float>& cdf, float u) {
    return std::min(size_t(std::upper_bound(cdf.begin(), cdf.end(), u) - cdf.begin()), cdf.size() - 1);
}

// Malley's method: cosine-weighted direction about local +z, pdf cosθ/π (PBRT-v3 §13.6.3).
inline glm::vec3 sampleCosineHemisphere(float u1, float u2) {
    const glm::vec2 d = concentricDisk(u1, u2);
    return glm::vec3(d, std::sqrt(std::max(0.0f, 1.0f - glm::dot(d, d))));
}

inline float cosineHemispherePdf(float cosTheta) { return cosTheta > 0.0f ? cosTheta / kPi : 0.0f; }

// Smith's masking G1 for GGX (Heitz 2014, "Understanding the Masking-Shadowing Function", eq. 34
// with GGX's Λ): 2·cosθ / (cosθ + sqrt(α² + (1 − α²)·cos²θ)).
inline float smithG1(float cosTheta, float alpha) {
    const float a2 = alpha * alpha;
    return 2.0f * cosTheta / (cosTheta + std::sqrt(a2 + (1.0f - a2) * cosTheta * cosTheta));
}

// A GGX microfacet normal from the distribution of normals visible from `viewLocal` (unit, local
// z up, z > 0): Heitz 2018, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4), listing 1.
inline glm::vec3 sampleGgxVisibleNormal(const glm::vec3& viewLocal, float alpha, float u1, float u2) {
    const glm::vec3 vh = glm::normalize(glm::vec3(alpha * viewLocal.x, alpha * viewLocal.y, viewLocal.z));
    const float lengthSquared = vh.x * vh.x + vh.y * vh.y;
    const glm::vec3 t1 =
        lengthSquared > 0.0f ? glm::vec3(-vh.y, vh.x, 0.0f) / std::sqrt(lengthSquared) : glm::vec3(1, 0, 0);
    const glm::vec3 t2 = glm::cross(vh, t1);
    const float r = std::sqrt(u1), phi = 2.0f * kPi * u2;
    const float p1 = r * std::cos(phi);
    const float s = 0.5f * (1.0f + vh.z);
    const float p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * r * std::sin(phi);
    const glm::vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
    return glm::normalize(glm::vec3(alpha * nh.x, alpha * nh.y, std::max(1e-6f, nh.z)));
}

// Density of L = reflect(−V, H) with H drawn by sampleGgxVisibleNormal, per unit solid angle:
// D_V(H) / (4 V·H) with D_V(H) = G1(V)·(V·H)·D(H) / (N·V) (Heitz 2018, eqs. 1 and 17).
inline float ggxVisibleNormalReflectionPdf(float NdotV, float NdotH, float alpha) {
    if (NdotV <= 0.0f || NdotH <= 0.0f) return 0.0f;
    return smithG1(NdotV, alpha) * glsl::ggxDistribution(NdotH, alpha) / (4.0f * NdotV);
}

// Multiple importance sampling weight, power heuristic with β = 2 (Veach 1997, §9.2.4).
inline float powerHeuristic(float pdf, float otherPdf) {
    const float a = pdf * pdf, b = otherPdf * otherPdf;
    return a + b > 0.0f ? a / (a + b) : 0.0f;
}

}  // namespace vct::pt
