// GGX reflection of a polygonal light by linearly transformed cosines (Heitz, Dupuy, Hill and
// Neubelt 2016, "Real-time polygonal-light shading with linearly transformed cosines"). For a given
// roughness and view angle, the BRDF's lobe f·cosθ (without Fresnel) is fitted by a clamped cosine
// whose directions went through a 3×3 matrix M. The lobe's integral over a polygon is then the
// cosine's over the polygon mapped back by M⁻¹: the projected solid angle of the clipped polygon,
// which area_light.h computes exactly. A table (tools/ltc_fit, src/render/ltc_ggx_table.cpp) holds
// M⁻¹ and the lobe's magnitude for 64 roughnesses × 64 view angles. Shared by the shading pass and
// the tests.
#ifndef VCT_LTC_H
#define VCT_LTC_H

#include "area_light.h"
#include "brdf.h"
#include "cpp_glsl.h"

VCT_SHARED_BEGIN

const uint LTC_TABLE_SIZE = 64u;

// One table entry: M⁻¹ in the frame (tangent towards the viewer, bitangent, normal), which has
// the form [[a 0 b] [0 1 0] [c 0 d]] after dividing by its middle element (a polygon's integral
// does not change when M⁻¹ is scaled); and the lobe's directional albedo split for Schlick's
// Fresnel (Hill and Heitz 2016): ∫ f·cosθ·F = F0·magnitude + (1 − F0)·fresnel, with
// magnitude = ∫ D·Vis·cosθ and fresnel = ∫ D·Vis·cosθ·(1 − V·H)⁵, both divided by the fitted
// cosine's share above the surface's horizon (up to a tenth of it lies below at grazing views, and
// clipping loses it), so that a light over the whole sky reflects exactly the albedo.
struct GpuLtcEntry {
    vec4 inverseMatrix;      // a, b, c, d
    vec4 magnitudeFresnel;  // x magnitude, y fresnel, zw unused
};

// Where (roughness, N·V) falls in the table, in entries: x along the view angle, parametrised by
// sqrt(1 − cosθ) (which spreads the grazing angles, where the lobe changes fastest), y along the
// perceptual roughness. Entry (x, y) is at y · LTC_TABLE_SIZE + x.
SHARED_FN vec2 ltcTableCoordinate(float roughness, float NdotV) {
    float last = float(LTC_TABLE_SIZE - 1u);
    return vec2(sqrt(1.0f - clamp(NdotV, 0.0f, 1.0f)), clamp(roughness, 0.0f, 1.0f)) * last;
}

// The view direction a table column was fitted for (x along the tangent, z the normal): the grazing
// column keeps a little height, where the lobe still has one.
SHARED_FN float ltcColumnCosine(uint column) {
    float s = float(column) / float(LTC_TABLE_SIZE - 1u);
    return max(1.0f - s * s, 1e-3f);
}

// The world-to-cosine-space matrix at a point: the table's M⁻¹ after a rotation into the frame
// (tangent towards the viewer, bitangent, normal). Straight above, any tangent does.
SHARED_FN mat3 ltcWorldToCosine(vec4 inverseMatrix, vec3 normal, vec3 toViewer) {
    vec3 tangent = toViewer - normal * dot(toViewer, normal);
    float tangentLength = length(tangent);
    tangent = tangentLength > 1e-6f
                  ? tangent / tangentLength
                  : normalize(cross(normal, abs(normal.x) < 0.9f ? vec3(1.0f, 0.0f, 0.0f) : vec3(0.0f, 1.0f, 0.0f)));
    vec3 bitangent = cross(normal, tangent);
    // Columns of a 3×3 matrix in both GLSL and GLM.
    mat3 inverseM = mat3(vec3(inverseMatrix.x, 0.0f, inverseMatrix.z), vec3(0.0f, 1.0f, 0.0f),
                         vec3(inverseMatrix.y, 0.0f, inverseMatrix.w));
    return inverseM * transpose(mat3(tangent, bitangent, normal));
}

// The fitted lobe's share that reaches the point from a triangle (corners relative to the point):
// ∫ over the triangle of the normalised lobe, 0..1. The cosine's horizon is its own (z ≥ 0 after
// the mapping), as in the paper.
SHARED_FN float ltcTriangleIntegral(mat3 worldToCosine, vec3 a, vec3 b, vec3 c) {
    return triangleIrradiance(worldToCosine * a, worldToCosine * b, worldToCosine * c, vec3(0.0f, 0.0f, 1.0f)) *
           (1.0f / PI);
}

// The lobe's directional albedo with the material's Fresnel, as brdfSpecular mixes it: the
// dielectric's f0 = 0.04 scaled by the specular weight, the metal's f0 = its base colour.
SHARED_FN vec3 ltcSpecularAlbedo(vec4 magnitudeFresnel, vec3 baseColor, float metallic, float specularWeight) {
    float magnitude = magnitudeFresnel.x, fresnel = magnitudeFresnel.y;
    float dielectric = specularWeight * (DIELECTRIC_F0 * magnitude + (1.0f - DIELECTRIC_F0) * fresnel);
    vec3 metal = baseColor * magnitude + (vec3(1.0f) - baseColor) * fresnel;
    return mix(vec3(dielectric), metal, metallic);
}

VCT_SHARED_END

#endif
