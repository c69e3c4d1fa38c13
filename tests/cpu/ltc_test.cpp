// The area lights' GGX highlights by linearly transformed cosines (shaders_glsl/ltc.h and the table
// of src/render/ltc_table.h) against numerical integration of the renderer's own brdfSpecular·cosθ
// over the light, and against the limits the fit must reach.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "brdf.h"
#include "ltc.h"
#include "render/ltc_table.h"

namespace {

using glm::vec3;
constexpr double kPi = 3.14159265358979323846;

struct Triangle {
    vec3 a, b, c;  // relative to the shading point, front face (cross(b − a, c − a)) towards it
};

// A rectangle centred at `centre` with half-extents along `u` and `v`, facing the origin.
std::vector<Triangle> rectangle(vec3 centre, vec3 u, vec3 v) {
    const vec3 p0 = centre - u - v, p1 = centre + u - v, p2 = centre + u + v, p3 = centre - u + v;
    std::vector<Triangle> triangles = {{p0, p1, p2}, {p0, p2, p3}};
    for (Triangle& t : triangles)
        if (glm::dot(glm::cross(t.b - t.a, t.c - t.a), -t.a) < 0.0f) std::swap(t.b, t.c);
    return triangles;
}

// Where the ray from the origin along `direction` meets the triangle, if it does.
bool hits(const Triangle& t, glm::dvec3 direction) {
    const glm::dvec3 a(t.a), e1 = glm::dvec3(t.b) - a, e2 = glm::dvec3(t.c) - a;
    const glm::dvec3 p = glm::cross(direction, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-14) return false;
    const glm::dvec3 s = -a;
    const double u = glm::dot(s, p) / det;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(direction, q) / det;
    const double distance = glm::dot(e2, q) / det;
    return u >= 0.0 && v >= 0.0 && u + v <= 1.0 && distance > 0.0;
}

struct Surface {
    vec3 baseColor;
    float metallic, roughness, specularWeight;
};

// ∫ over the light of brdfSpecular·cosθ (radiance 1), normal +z, by importance sampling the GGX
// distribution of normals on an n² stratified grid: the truth, Fresnel on V·H direction by direction.
double integratedSpecular(const std::vector<Triangle>& light, const Surface& s, glm::dvec3 view, int n = 700) {
    const double alpha = vct::glsl::ggxAlpha(s.roughness), a2 = alpha * alpha;
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double u = (i + 0.5) / n, w = (j + 0.5) / n;
            const double cos2 = (1.0 - u) / (1.0 + (a2 - 1.0) * u);
            const double sinTheta = std::sqrt(std::max(1.0 - cos2, 0.0)), phi = 2.0 * kPi * w;
            const glm::dvec3 half(sinTheta * std::cos(phi), sinTheta * std::sin(phi), std::sqrt(cos2));
            const double VdotH = glm::dot(view, half);
            if (VdotH <= 0.0) continue;
            const glm::dvec3 l = 2.0 * VdotH * half - view;
            if (l.z <= 0.0) continue;
            bool lit = false;
            for (const Triangle& t : light) lit = lit || hits(t, l);
            if (!lit) continue;
            const double density = vct::glsl::ggxDistribution(float(half.z), float(alpha)) * half.z / (4.0 * VdotH);
            const vec3 f = vct::glsl::brdfSpecular(s.baseColor, s.metallic, s.roughness, s.specularWeight, float(l.z),
                                                   float(view.z), float(half.z), float(VdotH));
            sum += double(f.g) * l.z / density;
        }
    return sum / (double(n) * double(n));
}

// The same by the table, as the shader computes it (area_lights.glsl's areaLightSpecular).
double ltcSpecular(const std::vector<Triangle>& light, const Surface& s, glm::dvec3 view) {
    static const std::vector<vct::glsl::GpuLtcEntry> table = vct::ltcGgxTable();
    const vec3 normal(0.0f, 0.0f, 1.0f), toViewer(view);
    const vct::glsl::GpuLtcEntry entry = vct::lookupLtcGgx(table, s.roughness, toViewer.z);
    const vec3 albedo = vct::glsl::ltcSpecularAlbedo(entry.magnitudeFresnel, s.baseColor, s.metallic, s.specularWeight);
    const glm::mat3 worldToCosine = vct::glsl::ltcWorldToCosine(entry.inverseMatrix, normal, toViewer);
    double sum = 0.0;
    for (const Triangle& t : light) sum += vct::glsl::ltcTriangleIntegral(worldToCosine, t.a, t.b, t.c);
    return double(albedo.g) * sum;
}

// A light over the whole sky (to a millionth of a radian above the horizon): a fan of four triangles
// around the zenith, so that no edge joins two nearly opposite directions, where a triangle's edge
// integral loses float precision.
std::vector<Triangle> sky() {
    const float s = 1e4f;
    const vec3 zenith(0.0f, 0.0f, 0.01f), corners[4] = {{-s, -s, 0.01f}, {s, -s, 0.01f}, {s, s, 0.01f}, {-s, s, 0.01f}};
    std::vector<Triangle> triangles;
    for (int i = 0; i < 4; ++i) triangles.push_back({zenith, corners[(i + 1) % 4], corners[i]});
    return triangles;
}

glm::dvec3 viewAt(double degrees) {
    const double theta = degrees * kPi / 180.0;
    return {std::sin(theta), 0.0, std::cos(theta)};
}

// Errors over a set of cases: relative to the truth, or to a twentieth of the lobe's albedo where the
// light catches only the lobe's tail; and against the albedo itself.
struct ErrorSummary {
    double squares = 0.0, worst = 0.0, worstOfAlbedo = 0.0;
    int count = 0;
    void add(double ltc, double truth, double albedo) {
        const double error = std::abs(ltc - truth) / std::max(truth, 0.05 * albedo);
        squares += error * error;
        worst = std::max(worst, error);
        worstOfAlbedo = std::max(worstOfAlbedo, std::abs(ltc - truth) / albedo);
        ++count;
    }
    double rms() const { return std::sqrt(squares / count); }
};

TEST(Ltc, AreaLightHighlightsMatchNumericalIntegrationOfTheBrdf) {
    // A 1 m square above the point, a panel near the mirror direction of oblique views, a small
    // lamp off to the side and a strip standing across the horizon; roughness 0.1 to 1, views from
    // the normal to 80°; a metal (f0 = 0.9) and a dielectric (f0 = 0.04).
    const std::vector<std::vector<Triangle>> lights = {
        rectangle(vec3(0.0f, 0.0f, 1.5f), vec3(0.5f, 0, 0), vec3(0, 0.5f, 0)),
        rectangle(vec3(-1.2f, 0.1f, 1.0f), vec3(0.4f, 0, 0), vec3(0, 0.3f, 0)),
        rectangle(vec3(0.8f, -0.6f, 0.7f), vec3(0.15f, 0, 0), vec3(0, 0.15f, 0)),
        rectangle(vec3(-1.5f, 0.0f, 0.1f), vec3(0, 0, 0.4f), vec3(0, 1.0f, 0))};
    ErrorSummary metals, dielectrics;
    for (float roughness : {0.1f, 0.25f, 0.5f, 0.75f, 1.0f})
        for (double degrees : {0.0, 30.0, 60.0, 80.0})
            for (const Surface& material :
                 {Surface{vec3(0.9f), 1.0f, 0.0f, 1.0f}, Surface{vec3(0.5f), 0.0f, 0.0f, 1.0f}}) {
                Surface surface = material;
                surface.roughness = roughness;
                const glm::dvec3 view = viewAt(degrees);
                const double albedo = integratedSpecular(sky(), surface, view, 300);
                for (const std::vector<Triangle>& light : lights) {
                    const double truth = integratedSpecular(light, surface, view);
                    const double ltc = ltcSpecular(light, surface, view);
                    (surface.metallic > 0.5f ? metals : dielectrics).add(ltc, truth, albedo);
                }
            }
    std::printf(
        "[ ltc ] metal: RMS relative error %.3f, worst %.3f (%.3f of the albedo); dielectric: %.3f, "
        "worst %.3f (%.3f of the albedo), %d cases each\n",
        metals.rms(), metals.worst, metals.worstOfAlbedo, dielectrics.rms(), dielectrics.worst,
        dielectrics.worstOfAlbedo, metals.count);
    // The metal's error is the fit's (measured RMS 0.067, worst 0.29; 0.11 of the albedo for a lamp
    // at the horizon in the mirror direction of an 80° view, roughness 0.25, 15 % too bright). The
    // dielectric's adds Schlick's Fresnel taken as the whole lobe's mean (Hill and Heitz 2016): at
    // grazing views it overstates the light reflected far from the mirror direction and understates
    // it near there, where Fresnel is strongest (measured RMS 0.27, worst 0.91, 0.31 of the albedo).
    EXPECT_LT(metals.rms(), 0.09);
    EXPECT_LT(metals.worst, 0.4);
    EXPECT_LT(metals.worstOfAlbedo, 0.15);
    EXPECT_LT(dielectrics.rms(), 0.35);
    EXPECT_LT(dielectrics.worstOfAlbedo, 0.4);
}

TEST(Ltc, ALightOverTheWholeSkyReflectsTheIntegratedDirectionalAlbedo) {
    // Where a light covers the whole sky the reflection is the lobe's directional albedo, F0 = 1
    // (the table's magnitude) and F0 = 0 (its Fresnel part), between the table's entries too. The
    // table's magnitudes make up for the fitted cosine's share below the horizon, which clipping
    // loses (up to a tenth at grazing views).
    for (float roughness : {0.05f, 0.2f, 0.45f, 0.7f, 1.0f})
        for (double degrees : {0.0, 25.0, 50.0, 70.0, 85.0}) {
            const glm::dvec3 view = viewAt(degrees);
            const Surface mirrorMetal{vec3(1.0f), 1.0f, roughness, 1.0f}, blackMetal{vec3(0.0f), 1.0f, roughness, 1.0f};
            const double magnitude = integratedSpecular(sky(), mirrorMetal, view, 400);
            const double fresnel = integratedSpecular(sky(), blackMetal, view, 400);
            EXPECT_NEAR(ltcSpecular(sky(), mirrorMetal, view), magnitude, 0.01 * magnitude)
                << "roughness " << roughness << ", view " << degrees << "°";
            EXPECT_NEAR(ltcSpecular(sky(), blackMetal, view), fresnel, 0.01 * magnitude)
                << "roughness " << roughness << ", view " << degrees << "°";
        }
}

TEST(Ltc, TheRoughestLobeSeenFromAboveIsARotationallySymmetricCosine) {
    // At roughness 1 and normal incidence GGX·cosθ is rotationally symmetric and a little wider than
    // a cosine (∝ cosθ/(1 + cosθ) there): M⁻¹ a uniform scale in the tangent plane without skew,
    // and a light's reflection close to its irradiance/π times the albedo.
    const std::vector<vct::glsl::GpuLtcEntry> table = vct::ltcGgxTable();
    const vct::glsl::GpuLtcEntry entry = vct::lookupLtcGgx(table, 1.0f, 1.0f);
    const glm::vec4 m = entry.inverseMatrix;
    EXPECT_NEAR(m.x, 1.0f, 1e-4f);  // the middle element is 1
    EXPECT_NEAR(m.y, 0.0f, 1e-4f);
    EXPECT_NEAR(m.z, 0.0f, 1e-4f);
    EXPECT_GT(m.w, 1.0f);  // wider than the cosine: M⁻¹ stretches the normal's component
    EXPECT_LT(m.w, 1.3f);
    const Surface rough{vec3(1.0f), 1.0f, 1.0f, 1.0f};
    for (const std::vector<Triangle>& light :
         {rectangle(vec3(0.0f, 0.0f, 1.0f), vec3(0.5f, 0, 0), vec3(0, 0.5f, 0)),
          rectangle(vec3(1.0f, 0.5f, 0.5f), vec3(0.3f, 0, 0), vec3(0, 0.2f, 0.1f))}) {
        double irradiance = 0.0;
        for (const Triangle& t : light) irradiance += vct::glsl::triangleIrradiance(t.a, t.b, t.c, vec3(0, 0, 1));
        const double lambertLike = entry.magnitudeFresnel.x * irradiance / kPi;
        EXPECT_NEAR(ltcSpecular(light, rough, viewAt(0.0)), lambertLike, 0.2 * lambertLike);
        EXPECT_NEAR(ltcSpecular(light, rough, viewAt(0.0)), integratedSpecular(light, rough, viewAt(0.0)),
                    0.03 * lambertLike);
    }
}

TEST(Ltc, ASmallLampReflectsLikeAPointLight) {
    // A lamp of 2 cm at 2 m: its reflection tends to brdfSpecular·cosθ·solid angle, the punctual
    // lights' formula, where it sits in the body of a lobe that is wide against it (measured within
    // 21 %). Out in the tail of a lobe seen at a grazing angle, the fit's density is off more.
    for (float roughness : {0.4f, 0.7f, 1.0f})
        for (double degrees : {0.0, 40.0})
            for (vec3 direction : {glm::normalize(vec3(-0.5f, 0.0f, 1.0f)), glm::normalize(vec3(0.3f, 0.4f, 1.0f))}) {
                const vec3 centre = 2.0f * direction;
                const vec3 u = 0.01f * glm::normalize(glm::cross(direction, vec3(0, 1, 0)));
                const vec3 v = glm::cross(direction, u);
                const std::vector<Triangle> lamp = rectangle(centre, u, v);
                const double solidAngle = 4.0 * glm::length(u) * glm::length(v) / 4.0;
                const glm::dvec3 view = viewAt(degrees);
                const Surface metal{vec3(1.0f), 1.0f, roughness, 1.0f};
                const vec3 toViewer(view), half = glm::normalize(toViewer + direction);
                const double point = vct::glsl::brdfSpecular(metal.baseColor, 1.0f, roughness, 1.0f, direction.z,
                                                             toViewer.z, half.z, glm::dot(toViewer, half))
                                         .g *
                                     direction.z * solidAngle;
                EXPECT_NEAR(ltcSpecular(lamp, metal, view), point, 0.25 * point)
                    << "roughness " << roughness << ", view " << degrees << "°";
            }
}

}  // namespace
