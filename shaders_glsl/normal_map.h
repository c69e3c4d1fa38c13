// glTF normal textures, the same for the renderer and the reference path tracer: the texture holds
// a tangent-space normal, +x along the tangent (the direction of increasing u), +y up the image
// (decreasing v), +z along the surface normal. The frame is MikkTSpace's where the texture
// coordinates are not skewed: the tangent ∂position/∂u made perpendicular to the normal, the
// bitangent ±cross(normal, tangent), the sign that of up the image (so mirrored coordinates, as a
// symmetric model's two halves share one texture, tilt their normals the mirrored way).
#ifndef VCT_NORMAL_MAP_H
#define VCT_NORMAL_MAP_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

// The shading normal from a normal texture's (linear) `texel`, around the unit surface `normal`;
// `alongU` and `alongV` are ∂position/∂u and ∂position/∂v. `scale` is glTF's normalTexture.scale,
// applied to x and y. Without a usable tangent the normal is left alone.
SHARED_FN vec3 normalFromTexture(vec3 normal, vec3 alongU, vec3 alongV, vec3 texel, float scale) {
    vec3 tangent = alongU - normal * dot(normal, alongU);
    float tangentLength = length(tangent);
    if (!(tangentLength > 1e-20f)) return normal;
    tangent = tangent / tangentLength;
    vec3 bitangent = cross(normal, tangent);
    if (dot(bitangent, alongV) > 0.0f) bitangent = -bitangent;  // mirrored: up the image is −∂position/∂v
    vec3 local = texel * 2.0f - 1.0f;
    vec3 mapped = tangent * (local.x * scale) + bitangent * (local.y * scale) + normal * local.z;
    float mappedLength = length(mapped);
    return mappedLength > 1e-20f ? mapped / mappedLength : normal;
}

VCT_SHARED_END

#endif
