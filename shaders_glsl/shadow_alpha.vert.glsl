#version 460
// Depth of an alpha-tested material (MASK or BLEND) seen from one shadow view: shadow.vert plus the
// texture coordinates its fragment shader reads the base colour's alpha at.
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.h"

layout(std430, set = 0, binding = VERTICES_BINDING) readonly buffer Vertices { GpuVertex vertices[]; };
layout(std430, set = 0, binding = SHADOW_VIEWS_BINDING) readonly buffer ShadowViews { ShadowView shadowViews[]; };
layout(push_constant) uniform Push {
    uint viewIndex;
    uint materialIndex;
};

layout(location = 0) out vec4 texCoords;  // xy TEXCOORD_0, zw TEXCOORD_1

void main() {
    GpuVertex vertex = vertices[gl_VertexIndex];
    texCoords = vec4(vertex.positionU.w, vertex.normalV.w, vertex.texCoord1.xy);
    gl_Position = shadowViews[viewIndex].viewProjection * vec4(vertex.positionU.xyz, 1.0f);
}
