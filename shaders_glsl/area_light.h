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

// Where the edge a → b, whose ends lie at heights da and db over the horizon plane, crosses it
// (only meaningful when it does; a finite point when it does not).
SHARED_FN vec3 horizonCrossing(vec3 a, vec3 b, float da, float db) {
    float gap = da - db;
    return a + (b - a) * (da / (gap != 0.0f ? gap : 1.0f));
}

// The part of the edge a → b on the side n·v ≥ 0 (where the point can see), `crossing` where the
// edge crosses the horizon: one edge integral between the visible part's ends, whichever way the
// edge is cut. (A GPU that runs both sides of every branch, as lavapipe does, pays for each
// edgeIntegral written: this way four a triangle, not ten.)
SHARED_FN float clippedEdgeIntegral(vec3 a, vec3 b, float da, float db, vec3 crossing, vec3 n) {
    vec3 from = da >= 0.0f ? a : crossing;
    vec3 to = db >= 0.0f ? b : crossing;
    return da >= 0.0f || db >= 0.0f ? edgeIntegral(from, to, n) : 0.0f;
}

// Irradiance per unit radiance at a point with unit normal n from the triangle v0 v1 v2 (corners
// relative to the point, either winding): the projected solid angle of its visible part, 0..π.
SHARED_FN float triangleIrradiance(vec3 v0, vec3 v1, vec3 v2, vec3 n) {
    float d0 = dot(v0, n);
    float d1 = dot(v1, n);
    float d2 = dot(v2, n);
    vec3 c01 = horizonCrossing(v0, v1, d0, d1);
    vec3 c12 = horizonCrossing(v1, v2, d1, d2);
    vec3 c20 = horizonCrossing(v2, v0, d2, d0);
    float sum = clippedEdgeIntegral(v0, v1, d0, d1, c01, n) + clippedEdgeIntegral(v1, v2, d1, d2, c12, n) +
                clippedEdgeIntegral(v2, v0, d2, d0, c20, n);
    // A triangle cut by the horizon leaves it on one edge and comes back on another: close the
    // boundary along the horizon from the leaving point to the returning one.
    bool leaves01 = d0 >= 0.0f && d1 < 0.0f, leaves12 = d1 >= 0.0f && d2 < 0.0f, leaves20 = d2 >= 0.0f && d0 < 0.0f;
    bool enters01 = d0 < 0.0f && d1 >= 0.0f, enters12 = d1 < 0.0f && d2 >= 0.0f, enters20 = d2 < 0.0f && d0 >= 0.0f;
    vec3 leaving = leaves01 ? c01 : (leaves12 ? c12 : c20);
    vec3 entering = enters01 ? c01 : (enters12 ? c12 : c20);
    if ((leaves01 || leaves12 || leaves20) && (enters01 || enters12 || enters20))
        sum += edgeIntegral(leaving, entering, n);
    return 0.5f * abs(sum);
}

VCT_SHARED_END

#endif
