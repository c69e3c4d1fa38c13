// Where a material texture is read, the same for the renderer and the reference path tracer: the
// texture-coordinate set its textureInfo names (TEXCOORD_0 or TEXCOORD_1), through the affine map
// of KHR_texture_transform.
#ifndef VCT_TEXTURE_TRANSFORM_H
#define VCT_TEXTURE_TRANSFORM_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

// The first two rows of the 3×3 matrix that takes (u, v, 1) to the coordinates the texture is
// sampled at, and the set it takes (u, v) from.
struct GpuTextureTransform {
    vec4 rowU;  // xyz: sampled u = dot(xyz, (u, v, 1)); w: the set, 0 or 1
    vec4 rowV;  // xyz: sampled v = dot(xyz, (u, v, 1)); w unused
};

// KHR_texture_transform: T(offset)·R(rotation)·S(scale), R = [[cos, sin], [−sin, cos]] as the
// extension's sample writes it row by row; its example (offset (0, 1), rotation π/2, scale ½
// reads "only the lower left quadrant of the image") holds with this R and not with its transpose.
SHARED_FN GpuTextureTransform textureTransform(vec2 offset, float rotation, vec2 scale, uint texCoord) {
    float c = cos(rotation);
    float s = sin(rotation);
    GpuTextureTransform transform;
    transform.rowU = vec4(c * scale.x, s * scale.y, offset.x, float(texCoord));
    transform.rowV = vec4(-s * scale.x, c * scale.y, offset.y, 0.0f);
    return transform;
}

// The coordinates a texture is sampled at, from a point's two sets.
SHARED_FN vec2 transformedTexCoord(GpuTextureTransform transform, vec2 texCoord0, vec2 texCoord1) {
    vec3 uv = vec3(transform.rowU.w > 0.5f ? texCoord1 : texCoord0, 1.0f);
    return vec2(dot(vec3(transform.rowU), uv), dot(vec3(transform.rowV), uv));
}

// How the sampled coordinates change with a point's two sets (xy TEXCOORD_0, zw TEXCOORD_1) changing
// by `texCoordsChange`: the transform's linear part applied to the change of its set.
SHARED_FN vec2 transformedTexCoordDerivative(GpuTextureTransform transform, vec4 texCoordsChange) {
    vec2 change = transform.rowU.w > 0.5f ? vec2(texCoordsChange.z, texCoordsChange.w)
                                          : vec2(texCoordsChange.x, texCoordsChange.y);
    return vec2(dot(vec2(transform.rowU), change), dot(vec2(transform.rowV), change));
}

VCT_SHARED_END

#endif
