// A unit vector perpendicular to a unit vector: the start of a tangent frame, for the diffuse
// cones' ring (cone_tracing.glsl) and the rays towards an area light's disc (shadows.glsl).
#ifndef VCT_PERPENDICULAR_GLSL
#define VCT_PERPENDICULAR_GLSL

vec3 perpendicularTo(vec3 n) {
    return normalize(cross(n, abs(n.x) < 0.9f ? vec3(1.0f, 0.0f, 0.0f) : vec3(0.0f, 1.0f, 0.0f)));
}

#endif
