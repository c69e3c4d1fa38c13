#include "scene/material_textures.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace vct {

glsl::GpuTextureTransform textureTransform(const TextureReference& reference) {
    return glsl::textureTransform(reference.offset, reference.rotation, reference.scale, reference.texCoord);
}

glm::vec2 textureCoordinates(const TextureReference& reference, const Vertex& vertex) {
    return glsl::transformedTexCoord(textureTransform(reference), glm::vec2(vertex.u, vertex.v), vertex.uv1);
}

float srgbToLinear(float encoded) {
    return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

glm::vec3 meanLinearColor(const Texture& texture) {
    const size_t texels = size_t(texture.width) * texture.height;
    if (texels == 0 || texture.rgba8.size() < texels * 4) return glm::vec3(1.0f);
    std::array<double, 256> table;
    for (int i = 0; i < 256; ++i) table[size_t(i)] = srgbToLinear(float(i) / 255.0f);
    glm::dvec3 sum(0.0);
    for (size_t i = 0; i < texels; ++i) {
        const uint8_t* texel = &texture.rgba8[4 * i];
        sum += glm::dvec3(table[texel[0]], table[texel[1]], table[texel[2]]);
    }
    return glm::vec3(sum / double(texels));
}

uint32_t wrapTexel(double texel, uint32_t size, TextureWrap wrap) {
    if (!std::isfinite(texel) || size == 0) return 0;
    const int64_t n = int64_t(size);
    // Past ±2^52 a double holds no fraction anyway, and the wrapped result is as arbitrary.
    const int64_t i = int64_t(std::clamp(texel, -0x1p52, 0x1p52));
    switch (wrap) {
        case TextureWrap::ClampToEdge: return uint32_t(std::clamp<int64_t>(i, 0, n - 1));
        case TextureWrap::MirroredRepeat: {
            const int64_t m = ((i % (2 * n)) + 2 * n) % (2 * n);  // the period is there and back
            return uint32_t(m < n ? m : 2 * n - 1 - m);
        }
        case TextureWrap::Repeat: break;
    }
    return uint32_t(((i % n) + n) % n);
}

glm::vec3 meanLinearColorOverTriangle(const Texture& texture, const glm::vec2 uv[3]) {
    const size_t texels = size_t(texture.width) * texture.height;
    if (texels == 0 || texture.rgba8.size() < texels * 4) return glm::vec3(1.0f);
    const glm::vec2 size(float(texture.width), float(texture.height));
    const glm::vec2 e1 = (uv[1] - uv[0]) * size, e2 = (uv[2] - uv[0]) * size;
    const float texelArea = 0.5f * std::abs(e1.x * e2.y - e1.y * e2.x);
    const float wanted = std::ceil(std::sqrt(4.0f * texelArea));  // n² sub-triangles ≈ 2 per texel
    const int n = std::isfinite(wanted) ? std::clamp(int(wanted), 1, 64) : 64;
    auto texel = [&](glm::vec2 at) {
        const glm::vec2 texelAt = glm::floor(at * size);
        const uint32_t x = wrapTexel(texelAt.x, texture.width, texture.wrapS);
        const uint32_t y = wrapTexel(texelAt.y, texture.height, texture.wrapT);
        const uint8_t* rgba = &texture.rgba8[4 * (size_t(y) * texture.width + x)];
        return glm::dvec3(srgbToLinear(rgba[0] / 255.0f), srgbToLinear(rgba[1] / 255.0f),
                          srgbToLinear(rgba[2] / 255.0f));
    };
    // The n² equal sub-triangles of the subdivision: (i, j) upright and, but on the diagonal, inverted.
    glm::dvec3 sum(0.0);
    int samples = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; i + j < n; ++j) {
            const float a = (float(i) + 1.0f / 3.0f) / float(n), b = (float(j) + 1.0f / 3.0f) / float(n);
            sum += texel(uv[0] + a * (uv[1] - uv[0]) + b * (uv[2] - uv[0]));
            ++samples;
            if (i + j + 1 < n) {
                const float c = (float(i) + 2.0f / 3.0f) / float(n), d = (float(j) + 2.0f / 3.0f) / float(n);
                sum += texel(uv[0] + c * (uv[1] - uv[0]) + d * (uv[2] - uv[0]));
                ++samples;
            }
        }
    return glm::vec3(sum / double(samples));
}

glm::vec3 voxelEmission(const Scene& scene, const Material& material) {
    // Without emission the texture's mean (a pass over every texel) would only be multiplied by zero.
    const int texture = material.emissiveTexture.index;
    if (texture < 0 || size_t(texture) >= scene.textures.size() || material.emission == glm::vec3(0.0f))
        return material.emission;
    return material.emission * meanLinearColor(scene.textures[size_t(texture)]);
}

bool emitsLight(const Scene& scene, const Material& material) {
    const glm::vec3 emission = voxelEmission(scene, material);
    return emission.r > 0.0f || emission.g > 0.0f || emission.b > 0.0f;
}

bool masksVoxelsByTexture(const Scene& scene, const Material& material) {
    const int texture = material.baseColorTexture.index;
    return material.alphaMode == AlphaMode::Mask && texture >= 0 && size_t(texture) < scene.textures.size();
}

float voxelCoverage(const Scene& scene, const Material& material) {
    if (material.alphaMode == AlphaMode::Opaque) return 1.0f;
    const float factor = material.baseColorFactor.a;
    const int index = material.baseColorTexture.index;
    const Texture* texture =
        index >= 0 && size_t(index) < scene.textures.size() ? &scene.textures[size_t(index)] : nullptr;
    const size_t texels = texture ? size_t(texture->width) * texture->height : 0;
    if (texels == 0 || texture->rgba8.size() < texels * 4) {
        if (material.alphaMode == AlphaMode::Mask) return factor >= material.alphaCutoff ? 1.0f : 0.0f;
        return std::clamp(factor, 0.0f, 1.0f);
    }
    double sum = 0.0;
    for (size_t i = 0; i < texels; ++i) {
        const float alpha = float(texture->rgba8[4 * i + 3]) / 255.0f * factor;  // as the GPU's UNORM read
        sum += material.alphaMode == AlphaMode::Mask ? (alpha >= material.alphaCutoff ? 1.0 : 0.0)
                                                     : std::clamp(double(alpha), 0.0, 1.0);
    }
    return float(sum / double(texels));
}

}  // namespace vct
