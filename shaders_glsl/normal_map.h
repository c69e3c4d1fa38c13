// glTF normal textures, the same for the renderer and the reference path tracer: the texture holds
// a tangent-space normal, +x along the tangent (the direction of increasing u), +y along
// cross(normal, tangent) (up the image), +z along the surface normal.
#ifndef VCT_NORMAL_MAP_H
#define VCT_NORMAL_MAP_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

// The shading normal from a normal texture's (linear) `texel`, around the unit surface `normal`;
// `alongU` is ∂position/∂u, made perpendicular to the normal here. `scale` is glTF's
// normalTexture.scale, applied to x and y. Without a usable tangent the normal is left alone.
SHARED_FN vec3 normalFromTexture(vec3 normal, vec3 alongU, vec3 texel, float scale) {
    vec3 tangent = alongU - normal * dot(normal, alongU);
    float tangentLength = length(tangent);
    if (!(tangentLength > 1e-20f)) return normal;
    tangent = tangent / tangentLength;
    vec3 bitangent = cross(normal, tangent);
    vec3 local = texel * 2.0f - 1.0f;
    vec3 mapped = tangent * (local.x * scale) + bitangent * (local.y * scale) + normal * local.z;
    float mappedLength = length(mapped);
    return mappedLength > 1e-20f ? mapped / mappedLength : normal;
}

VCT_SHARED_END

#endif
