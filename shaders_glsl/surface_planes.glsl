// The surface planes (surface_planes.h) as the passes that trace cones read them: cone_tracing.glsl
// calls surfacePlaneAt, which the cone probes (no planes) define as vec4(0).
#ifndef VCT_SURFACE_PLANES_GLSL
#define VCT_SURFACE_PLANES_GLSL

#include "surface_planes.h"

layout(set = 0, binding = SURFACE_PLANES_BINDING) uniform sampler3D surfacePlanes;

vec4 surfacePlaneAt(vec3 uvw, float lod) { return textureLod(surfacePlanes, uvw, lod); }

#endif
