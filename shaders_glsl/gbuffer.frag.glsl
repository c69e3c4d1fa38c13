#version 460
// G-buffer: world position + material index, shading normal + front-face flag and occlusion, base
// colour + metallic, and the emissive texture's colour (the shading pass multiplies it with the
// material's emission) + roughness. Four targets, the most Vulkan guarantees (maxColorAttachments ≥ 4):
// metallic and roughness ride in the alpha channels of the two colour targets, the front-face flag
// and the occlusion texture's value share the normal's (gbufferSideOcclusion). Fragments the
// material's alpha leaves uncovered are discarded (alpha_coverage.h).
#extension GL_GOOGLE_include_directive : require
#include "alpha_coverage.h"
#include "gpu_types.h"
#include "normal_map.h"
#include "gbuffer_packing.h"

layout(set = 0, binding = FRAME_BINDING) uniform Frame { FrameConstants frame; };
layout(std430, set = 0, binding = MATERIALS_BINDING) readonly buffer Materials { GpuMaterial materials[]; };
// Triangles are drawn one material at a time, so the texture index is dynamically uniform
// (no descriptor-indexing feature needed: lavapipe has none).
layout(push_constant) uniform Push { uint materialIndex; };
layout(constant_id = TEXTURE_COUNT_CONSTANT_ID) const uint TEXTURE_COUNT = 1;
// True in the pipeline that draws MASK and BLEND materials: only it may discard, so the opaque
// materials' pipeline keeps its early depth test.
layout(constant_id = ALPHA_TESTED_CONSTANT_ID) const bool ALPHA_TESTED = false;
// Base colour and emissive (sRGB), metallic-roughness (linear): the image's format decodes each.
layout(set = TEXTURES_SET, binding = COLOR_TEXTURES_BINDING) uniform sampler2D colorTextures[TEXTURE_COUNT];

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec4 texCoords;  // xy TEXCOORD_0, zw TEXCOORD_1
layout(location = 3) in vec4 worldTangent;  // the file's TANGENT, 0 without one

layout(location = 0) out vec4 outPosition;   // xyz, w = material index + 1 (0 = nothing)
layout(location = 1) out vec4 outNormal;     // xyz facing the camera, w = gbufferSideOcclusion
layout(location = 2) out vec4 outBaseColor;  // linear rgb, metallic
layout(location = 3) out vec4 outEmissive;   // linear rgb of the emissive texture (1 without one), roughness

// Where a texture is read: its set of texture coordinates through its transform.
vec2 uvOf(GpuTextureTransform transform) { return transformedTexCoord(transform, texCoords.xy, texCoords.zw); }

// A material texture, filtered over the pixel's footprint (trilinear, through the mip chain). The
// footprint comes from the derivatives of the interpolated coordinate sets, through the transform:
// lavapipe's implicit derivatives of a computed value went wrong along the triangles' edges, where
// they would pick too coarse a level.
vec4 materialTexture(int index, GpuTextureTransform transform) {
    return textureGrad(colorTextures[index], uvOf(transform), transformedTexCoordDerivative(transform, dFdx(texCoords)),
                       transformedTexCoordDerivative(transform, dFdy(texCoords)));
}

void main() {
    GpuMaterial material = materials[materialIndex];
    vec4 baseColor = material.baseColorFactor;
    if (material.baseColorTexture >= 0)
        baseColor *= materialTexture(material.baseColorTexture, material.baseColorTransform);
    vec3 emissive = vec3(1.0f);
    if (material.emissiveTexture >= 0)
        emissive = materialTexture(material.emissiveTexture, material.emissiveTransform).rgb;
    vec2 metallicRoughness = vec2(material.metallic, material.roughness);
    if (material.metallicRoughnessTexture >= 0)
        metallicRoughness *=
            materialTexture(material.metallicRoughnessTexture, material.metallicRoughnessTransform).bg;
    metallicRoughness = clamp(metallicRoughness, 0.0f, 1.0f);
    // glTF 2.0 §3.9.3: the occlusion texture's red channel, blended towards 1 by 1 − strength,
    // scales the indirect light only.
    float occlusion = 1.0f;
    if (material.occlusionTexture >= 0) {
        float red = materialTexture(material.occlusionTexture, material.occlusionTransform).r;
        occlusion = clamp(1.0f + material.occlusionStrength * (red - 1.0f), 0.0f, 1.0f);
    }

    // Surfaces reflect on both sides (as in the reference path tracer); emission leaves the front only.
    vec3 normal = worldNormal;
    float lengthSquared = dot(normal, normal);
    if (!(lengthSquared > 1e-20f)) {
        // A zero-length vertex normal (or normals that cancel): the triangle's own plane.
        normal = cross(dFdx(worldPosition), dFdy(worldPosition));
        lengthSquared = dot(normal, normal);
    }
    normal = lengthSquared > 0.0f ? normal * inversesqrt(lengthSquared) : vec3(0.0f, 1.0f, 0.0f);
    vec3 toCamera = frame.cameraPosition - worldPosition;
    // The side is the interpolated normal's; a normal texture tilts the normal of that side.
    bool frontFace = dot(normal, toCamera) >= 0.0f;
    if (material.normalTexture >= 0) {
        // ∂position/∂u and ∂v: the file's tangent frame where it has one for this texture; else
        // from screen-space derivatives, u, v the normal texture's own (after its transform), the
        // frame the path tracer takes from the triangle's edges (the ratio is the same whichever way
        // the screen's y runs). The coordinates' derivatives are the interpolated sets' through the
        // transform: lavapipe's derivatives of a computed value went wrong along the triangles'
        // edges. All derivatives are taken before the choice, by the whole quad.
        GpuTextureTransform transform = material.normalTransform;
        vec2 uvX = transformedTexCoordDerivative(transform, dFdx(texCoords));
        vec2 uvY = transformedTexCoordDerivative(transform, dFdy(texCoords));
        vec3 positionX = dFdx(worldPosition), positionY = dFdy(worldPosition);
        vec3 texel = materialTexture(material.normalTexture, transform).rgb;
        TextureAxes axes = tangentServes(worldTangent, transform)
                               ? axesOfTangent(normal, worldTangent, transform)
                               : axesFromSteps(positionX, positionY, uvX, uvY);
        normal = normalFromTexture(normal, axes.alongU, axes.alongV, texel, material.normalScale);
    }
    if (!frontFace) normal = -normal;

    // glTF alphaMode: a cut-out (MASK) or a stochastic share of the pixels (BLEND), alpha_coverage.h.
    // Discarded only here, after every derivative above was taken with the whole quad.
    if (ALPHA_TESTED && !coversPixel(material.alphaMode, material.alphaCutoff, baseColor.a, gl_FragCoord.xy))
        discard;

    outPosition = vec4(worldPosition, float(materialIndex + 1u));
    outNormal = vec4(normal, gbufferSideOcclusion(frontFace, occlusion));
    outBaseColor = vec4(baseColor.rgb, metallicRoughness.x);
    outEmissive = vec4(emissive, metallicRoughness.y);
}
