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

namespace {

bool readable(const Texture& texture) {
    const size_t texels = size_t(texture.width) * texture.height;
    return texels > 0 && texture.rgba8.size() >= texels * 4;
}

// The material's texture `reference` names, or null where there is none it could read.
const Texture* textureOf(const Scene& scene, const TextureReference& reference) {
    if (reference.index < 0 || size_t(reference.index) >= scene.textures.size()) return nullptr;
    const Texture& texture = scene.textures[size_t(reference.index)];
    return readable(texture) ? &texture : nullptr;
}

// Sub-triangles per side of a regular subdivision of the triangle with texture coordinates uv[0..2]
// that gives about two samples per texel it covers (at most 64 × 64).
int subdivisionsOver(const Texture& texture, const glm::vec2 uv[3]) {
    const glm::vec2 size(float(texture.width), float(texture.height));
    const glm::vec2 e1 = (uv[1] - uv[0]) * size, e2 = (uv[2] - uv[0]) * size;
    const float texelArea = 0.5f * std::abs(e1.x * e2.y - e1.y * e2.x);
    const float wanted = std::ceil(std::sqrt(4.0f * texelArea));  // n² sub-triangles ≈ 2 per texel
    return std::isfinite(wanted) ? std::clamp(int(wanted), 1, 64) : 64;
}

// The RGBA8 texel of `texture` at coordinates `at`, wrapped as the texture says.
const uint8_t* texelAt(const Texture& texture, glm::vec2 at) {
    const glm::vec2 texel = glm::floor(at * glm::vec2(float(texture.width), float(texture.height)));
    const uint32_t x = wrapTexel(texel.x, texture.width, texture.wrapS);
    const uint32_t y = wrapTexel(texel.y, texture.height, texture.wrapT);
    return &texture.rgba8[4 * (size_t(y) * texture.width + x)];
}

glm::dvec3 linearColor(const uint8_t* rgba) {
    return glm::dvec3(srgbToLinear(rgba[0] / 255.0f), srgbToLinear(rgba[1] / 255.0f), srgbToLinear(rgba[2] / 255.0f));
}

// The mean of `value(b1, b2)` (barycentric weights of corners 1 and 2) over the centroids of the n²
// equal sub-triangles of the triangle's regular subdivision: (i, j) upright and, but on the
// diagonal, inverted.
template <typename Value>
glm::dvec3 meanOverSubdivision(int n, const Value& value) {
    glm::dvec3 sum(0.0);
    int samples = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; i + j < n; ++j) {
            sum += value((float(i) + 1.0f / 3.0f) / float(n), (float(j) + 1.0f / 3.0f) / float(n));
            ++samples;
            if (i + j + 1 < n) {
                sum += value((float(i) + 2.0f / 3.0f) / float(n), (float(j) + 2.0f / 3.0f) / float(n));
                ++samples;
            }
        }
    return sum / double(samples);
}

glm::vec2 interpolated(const glm::vec2 uv[3], float b1, float b2) {
    return uv[0] + b1 * (uv[1] - uv[0]) + b2 * (uv[2] - uv[0]);
}

}  // namespace

float coverageOfAlpha(const Material& material, float alpha) {
    switch (material.alphaMode) {
        case AlphaMode::Opaque: return 1.0f;
        case AlphaMode::Mask: return alpha >= material.alphaCutoff ? 1.0f : 0.0f;
        case AlphaMode::Blend: break;
    }
    return std::clamp(alpha, 0.0f, 1.0f);
}

glm::vec3 meanLinearColorOverTriangle(const Texture& texture, const glm::vec2 uv[3]) {
    if (!readable(texture)) return glm::vec3(1.0f);
    return glm::vec3(meanOverSubdivision(subdivisionsOver(texture, uv), [&](float b1, float b2) {
        return linearColor(texelAt(texture, interpolated(uv, b1, b2)));
    }));
}

glm::vec3 emittedRadianceOverTriangle(const Scene& scene, const Material& material, const Vertex* const v[3]) {
    const Texture* emissive = textureOf(scene, material.emissiveTexture);
    const Texture* base =
        material.alphaMode != AlphaMode::Opaque ? textureOf(scene, material.baseColorTexture) : nullptr;
    const float factorCoverage = coverageOfAlpha(material, material.baseColorFactor.a);
    if (!emissive && !base) return material.emission * factorCoverage;
    glm::vec2 emissiveUv[3], baseUv[3];
    int n = 1;
    for (int i = 0; i < 3; ++i) {
        emissiveUv[i] = textureCoordinates(material.emissiveTexture, *v[i]);
        baseUv[i] = textureCoordinates(material.baseColorTexture, *v[i]);
    }
    if (emissive) n = std::max(n, subdivisionsOver(*emissive, emissiveUv));
    if (base) n = std::max(n, subdivisionsOver(*base, baseUv));
    const glm::dvec3 mean = meanOverSubdivision(n, [&](float b1, float b2) {
        const glm::dvec3 color =
            emissive ? linearColor(texelAt(*emissive, interpolated(emissiveUv, b1, b2))) : glm::dvec3(1.0);
        if (!base) return color * double(factorCoverage);
        // As the GPU's UNORM read, times the factor.
        const float alpha =
            float(texelAt(*base, interpolated(baseUv, b1, b2))[3]) / 255.0f * material.baseColorFactor.a;
        return color * double(coverageOfAlpha(material, alpha));
    });
    return material.emission * glm::vec3(mean);
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
    const Texture* texture = textureOf(scene, material.baseColorTexture);
    if (!texture) return coverageOfAlpha(material, factor);
    const size_t texels = size_t(texture->width) * texture->height;
    double sum = 0.0;
    for (size_t i = 0; i < texels; ++i)  // the alpha as the GPU's UNORM read, times the factor
        sum += coverageOfAlpha(material, float(texture->rgba8[4 * i + 3]) / 255.0f * factor);
    return float(sum / double(texels));
}

}  // namespace vct
