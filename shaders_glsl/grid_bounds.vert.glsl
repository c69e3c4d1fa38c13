#version 460
// The voxel grid's 12 edges as a line list of 24 vertices; no vertex buffer. Corner c of the box
// takes bit 0 of c from x, bit 1 from y, bit 2 from z (0 = min, 1 = max).
#extension GL_GOOGLE_include_directive : require
#include "present.h"

layout(push_constant) uniform Push { GridBoundsPush push; };

const uint kEdgeEnds[24] = uint[](0, 1, 2, 3, 4, 5, 6, 7,   // along x
                                  0, 2, 1, 3, 4, 6, 5, 7,   // along y
                                  0, 4, 1, 5, 2, 6, 3, 7);  // along z

void main() {
    const uint corner = kEdgeEnds[gl_VertexIndex];
    const vec3 pick = vec3(corner & 1u, (corner >> 1u) & 1u, (corner >> 2u) & 1u);
    gl_Position = push.viewProjection * vec4(mix(push.boxMin.xyz, push.boxMax.xyz, pick), 1.0f);
}
