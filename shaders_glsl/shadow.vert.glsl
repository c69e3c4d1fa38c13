#version 460
// Depth of the scene as seen from one shadow view (a sun, a spot, or one cube face of a point light).
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.h"

layout(std430, set = 0, binding = VERTICES_BINDING) readonly buffer Vertices { GpuVertex vertices[]; };
layout(std430, set = 0, binding = SHADOW_VIEWS_BINDING) readonly buffer ShadowViews { ShadowView shadowViews[]; };
layout(push_constant) uniform Push { uint viewIndex; };

void main() {
    gl_Position = shadowViews[viewIndex].viewProjection * vec4(vertices[gl_VertexIndex].positionU.xyz, 1.0f);
}
