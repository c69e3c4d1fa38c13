#version 460
// One colour for the voxel grid's edges (grid_bounds.vert.glsl).
#extension GL_GOOGLE_include_directive : require
#include "present.h"

layout(push_constant) uniform Push { GridBoundsPush push; };
layout(location = 0) out vec4 color;

void main() { color = push.color; }
