// glTF normal textures, the same for the renderer and the reference path tracer: the texture holds
// a tangent-space normal, +x along the tangent (the direction of increasing u), +y up the image
// (decreasing v), +z along the surface normal. The frame is MikkTSpace's where the texture
// coordinates are not skewed: the tangent ∂position/∂u made perpendicular to the normal, the
// bitangent ±cross(normal, tangent), the sign that of up the image (so mirrored coordinates, as a
// symmetric model's two halves share one texture, tilt their normals the mirrored way). ∂position/∂u
// and ∂v come from the vertex tangent where there is one (the file's TANGENT, or generated on loading:
// src/scene/tangent_generation.h), else from each triangle's coordinates.
#ifndef VCT_NORMAL_MAP_H
#define VCT_NORMAL_MAP_H

#include "cpp_glsl.h"
#include "texture_transform.h"

VCT_SHARED_BEGIN

// ∂position/∂u and ∂position/∂v, u and v the normal texture's own coordinates (after its transform).
struct TextureAxes {
    vec3 alongU;
    vec3 alongV;
};

// The axes from two steps across the surface, `step1` and `step2` (positions), over which the
// texture's coordinates change by `change1` and `change2`: the 2 × 2 system inverted. Zero (the
// normal left alone) where the coordinates' changes are degenerate. The G-buffer takes its steps
// from screen-space derivatives, the path tracer from the triangle's edges.
SHARED_FN TextureAxes axesFromSteps(vec3 step1, vec3 step2, vec2 change1, vec2 change2) {
    float determinant = change1.x * change2.y - change2.x * change1.y;
    TextureAxes axes;
    axes.alongU = vec3(0.0f);
    axes.alongV = vec3(0.0f);
    if (!(abs(determinant) > 1e-20f)) return axes;
    axes.alongU = (change2.y * step1 - change1.y * step2) / determinant;
    axes.alongV = (change1.x * step2 - change2.x * step1) / determinant;
    return axes;
}

// The axes of a glTF TANGENT (xyz unit, along increasing u of TEXCOORD_0; the bitangent
// cross(normal, xyz)·w points up the image, towards decreasing v) through the linear part A of the
// normal texture's KHR_texture_transform, (u', v') = A (u, v): unit steps along ∂p/∂u and ∂p/∂v change
// (u', v') by A's columns. The file
// gives directions only, so u and v are taken to advance alike along the surface (exact without a
// rotation or an unequal scale). Zero (the normal left alone) where the transform is singular.
// Vertex tangents are smooth across a mesh's triangles, where the axes from each triangle's own
// texture coordinates turn at its edges (a low-polygon sphere's normal-mapped light shows its facets).
SHARED_FN TextureAxes axesOfTangent(vec3 normal, vec4 tangent, GpuTextureTransform transform) {
    vec3 alongU = vec3(tangent.x, tangent.y, tangent.z);
    vec3 alongV = -cross(normal, alongU) * (tangent.w < 0.0f ? -1.0f : 1.0f);
    return axesFromSteps(alongU, alongV, vec2(transform.rowU.x, transform.rowV.x),
                         vec2(transform.rowU.y, transform.rowV.y));
}

// Whether a point's interpolated TANGENT frame serves the normal texture: the file has one (not
// zero) and the texture reads TEXCOORD_0, the set the tangents follow.
SHARED_FN bool tangentServes(vec4 tangent, GpuTextureTransform transform) {
    return dot(vec3(tangent.x, tangent.y, tangent.z), vec3(tangent.x, tangent.y, tangent.z)) > 1e-12f &&
           transform.rowU.w < 0.5f;
}

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
