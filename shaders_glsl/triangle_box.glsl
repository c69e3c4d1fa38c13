// Conservative triangle–box overlap: the separating-axis test of Akenine-Möller, "Fast 3D
// Triangle-Box Overlap Testing" (JGT 2001). A triangle and a box are disjoint iff some axis among
// the 3 box normals, the triangle normal and the 9 products (box normal × triangle edge) separates
// their projections. Both shapes are closed: touching (a projection gap of exactly 0) counts as
// overlap, so a triangle lying on a voxel face marks the voxels on both sides.
// An axis of zero length (an edge parallel to a box normal) projects everything to 0 and never
// separates, which keeps the test conservative.
#ifndef VCT_TRIANGLE_BOX_GLSL
#define VCT_TRIANGLE_BOX_GLSL

// Vertices relative to the box centre; halfSize is the box's half side.
bool separatedOnAxis(vec3 axis, vec3 v0, vec3 v1, vec3 v2, float halfSize) {
    float p0 = dot(axis, v0), p1 = dot(axis, v1), p2 = dot(axis, v2);
    float radius = halfSize * (abs(axis.x) + abs(axis.y) + abs(axis.z));
    return min(p0, min(p1, p2)) > radius || max(p0, max(p1, p2)) < -radius;
}

bool triangleTouchesBox(vec3 a, vec3 b, vec3 c, vec3 boxCenter, float halfSize) {
    vec3 v0 = a - boxCenter, v1 = b - boxCenter, v2 = c - boxCenter;
    // The box normals: the triangle's bounding box against the box.
    if (any(greaterThan(min(v0, min(v1, v2)), vec3(halfSize))) || any(lessThan(max(v0, max(v1, v2)), vec3(-halfSize))))
        return false;
    vec3 edges[3] = vec3[3](b - a, c - b, a - c);
    if (separatedOnAxis(cross(edges[0], edges[1]), v0, v1, v2, halfSize)) return false;
    for (int i = 0; i < 3; ++i) {
        vec3 e = edges[i];
        // (1,0,0) × e, (0,1,0) × e, (0,0,1) × e, written out: no rounding beyond the edge itself.
        if (separatedOnAxis(vec3(0.0f, -e.z, e.y), v0, v1, v2, halfSize)) return false;
        if (separatedOnAxis(vec3(e.z, 0.0f, -e.x), v0, v1, v2, halfSize)) return false;
        if (separatedOnAxis(vec3(-e.y, e.x, 0.0f), v0, v1, v2, halfSize)) return false;
    }
    return true;
}

#endif
