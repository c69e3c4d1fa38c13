#version 460
// Alpha-tested shadow casters: the light passes where the G-buffer pass would discard (the same
// coverage and test, alpha_coverage.h), so a cut-out casts a cut-out shadow. A BLEND surface is
// approximated as a cut-out at coverage ½: depth maps hold no partial shadow, and the shading's
// filter counts a tap as shadowed when any of its four texels blocks (shadows.glsl), which turns a
// dithered pattern into a full shadow; the nearer of none and all is the one cast, so a surface
// lets the light through where its coverage is below ½ and stops it elsewhere. Opaque materials
// are drawn without a fragment shader (shadow.vert).
#extension GL_GOOGLE_include_directive : require
#include "alpha_coverage.h"
#include "gpu_types.h"

layout(std430, set = 0, binding = MATERIALS_BINDING) readonly buffer Materials { GpuMaterial materials[]; };
layout(push_constant) uniform Push {
    uint viewIndex;
    uint materialIndex;  // drawn one material at a time: the texture index is dynamically uniform
};
layout(constant_id = TEXTURE_COUNT_CONSTANT_ID) const uint TEXTURE_COUNT = 1;
layout(set = TEXTURES_SET, binding = COLOR_TEXTURES_BINDING) uniform sampler2D colorTextures[TEXTURE_COUNT];

layout(location = 0) in vec4 texCoords;  // xy TEXCOORD_0, zw TEXCOORD_1

void main() {
    GpuMaterial material = materials[materialIndex];
    float coverage = material.baseColorFactor.a;
    if (material.baseColorTexture >= 0) {
        // Explicit gradients, as the G-buffer pass reads its textures (lavapipe's implicit
        // derivatives of a computed coordinate went wrong along triangle edges).
        GpuTextureTransform transform = material.baseColorTransform;
        vec2 uv = transformedTexCoord(transform, texCoords.xy, texCoords.zw);
        coverage *= textureGrad(colorTextures[material.baseColorTexture], uv,
                                transformedTexCoordDerivative(transform, dFdx(texCoords)),
                                transformedTexCoordDerivative(transform, dFdy(texCoords)))
                        .a;
    }
    bool blended = material.alphaMode == ALPHA_BLEND;
    if (!coversPixel(blended ? ALPHA_MASK : material.alphaMode, blended ? 0.5f : material.alphaCutoff, coverage,
                     gl_FragCoord.xy))
        discard;
}
