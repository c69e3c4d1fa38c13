#include "scene/material_textures.h"

#include <array>
#include <cmath>

namespace vct {

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

glm::vec3 voxelEmission(const Scene& scene, const Material& material) {
    // Without emission the texture's mean (a pass over every texel) would only be multiplied by zero.
    if (material.emissiveTexture < 0 || size_t(material.emissiveTexture) >= scene.textures.size() ||
        material.emission == glm::vec3(0.0f))
        return material.emission;
    return material.emission * meanLinearColor(scene.textures[size_t(material.emissiveTexture)]);
}

}  // namespace vct
