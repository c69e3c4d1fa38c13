#version 460
// G-buffer: vertices are pulled from the scene's storage buffer (already in world space).
#extension GL_GOOGLE_include_directive : require
#include "gpu_types.h"

layout(set = 0, binding = FRAME_BINDING) uniform Frame { FrameConstants frame; };
layout(std430, set = 0, binding = VERTICES_BINDING) readonly buffer Vertices { GpuVertex vertices[]; };

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec4 texCoords;  // xy TEXCOORD_0, zw TEXCOORD_1
layout(location = 3) out vec4 worldTangent;  // the file's TANGENT, 0 without one

void main() {
    GpuVertex vertex = vertices[gl_VertexIndex];
    worldPosition = vertex.positionU.xyz;
    worldNormal = vertex.normalV.xyz;
    texCoords = vec4(vertex.positionU.w, vertex.normalV.w, vertex.texCoord1.xy);
    worldTangent = vertex.tangent;
    gl_Position = frame.viewProjection * vec4(worldPosition, 1.0f);
}
