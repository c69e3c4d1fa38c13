// Irradiance from a uniformly emitting triangle, exactly (Lambert 1760; the edge form of Arvo 1995):
// for a polygon above a point's horizon, E = L/2 · Σ θᵢ (n · γᵢ), where θᵢ is the angle its edge i
// subtends at the point and γᵢ the unit normal of the plane through the point and that edge. The
// part of the triangle below the horizon is clipped off first: the edges are cut where they cross
// the horizon plane and the cut is closed along it. Shared by the renderer's area lights and the
// tests, which check it against numerical integration.
#ifndef VCT_AREA_LIGHT_H
#define VCT_AREA_LIGHT_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

// θ · (n · γ) for the edge from a to b, both relative to the point (any length).
SHARED_FN float edgeIntegral(vec3 a, vec3 b, vec3 n) {
    vec3 ua = normalize(a);
    vec3 ub = normalize(b);
    vec3 c = cross(ua, ub);
    float s = length(c);
    // atan(s, cos) keeps its precision for the tiny angles of a far or small light, where acos does not.
    return s > 1e-12f ? atan(s, dot(ua, ub)) / s * dot(c, n) : 0.0f;
}

// Where the edge a → b crosses the horizon plane (only meaningful when it does).
SHARED_FN vec3 horizonCrossing(vec3 a, vec3 b, vec3 n) {
    float da = dot(a, n);
    float db = dot(b, n);
    return a + (b - a) * (da / (da - db));
}

// The edge a → b clipped to the half-space n·v ≥ 0 (where the point can see).
SHARED_FN float clippedEdgeIntegral(vec3 a, vec3 b, vec3 n) {
    float da = dot(a, n);
    float db = dot(b, n);
    if (da >= 0.0f && db >= 0.0f) return edgeIntegral(a, b, n);
    if (da < 0.0f && db < 0.0f) return 0.0f;
    vec3 crossing = horizonCrossing(a, b, n);
    return da >= 0.0f ? edgeIntegral(a, crossing, n) : edgeIntegral(crossing, b, n);
}

// Irradiance per unit radiance at a point with unit normal n from the triangle v0 v1 v2 (corners
// relative to the point, either winding): the projected solid angle of its visible part, 0..π.
SHARED_FN float triangleIrradiance(vec3 v0, vec3 v1, vec3 v2, vec3 n) {
    float sum = clippedEdgeIntegral(v0, v1, n) + clippedEdgeIntegral(v1, v2, n) + clippedEdgeIntegral(v2, v0, n);
    // A triangle cut by the horizon leaves it on one edge and comes back on another: close the
    // boundary along the horizon from the leaving point to the returning one.
    float d0 = dot(v0, n);
    float d1 = dot(v1, n);
    float d2 = dot(v2, n);
    bool leaves01 = d0 >= 0.0f && d1 < 0.0f, leaves12 = d1 >= 0.0f && d2 < 0.0f, leaves20 = d2 >= 0.0f && d0 < 0.0f;
    bool enters01 = d0 < 0.0f && d1 >= 0.0f, enters12 = d1 < 0.0f && d2 >= 0.0f, enters20 = d2 < 0.0f && d0 >= 0.0f;
    if ((leaves01 || leaves12 || leaves20) && (enters01 || enters12 || enters20)) {
        vec3 leaving = leaves01 ? horizonCrossing(v0, v1, n)
                                : (leaves12 ? horizonCrossing(v1, v2, n) : horizonCrossing(v2, v0, n));
        vec3 entering = enters01 ? horizonCrossing(v0, v1, n)
                                 : (enters12 ? horizonCrossing(v1, v2, n) : horizonCrossing(v2, v0, n));
        sum += edgeIntegral(leaving, entering, n);
    }
    return 0.5f * abs(sum);
}

VCT_SHARED_END

#endif
