// The renderer's scene: what every pass and the path tracer agree on.
//
// Geometry is flattened to world space at load time (node transforms applied, normals
// transformed by the inverse transpose), so a triangle is three indices into `vertices`
// plus one material index. Units are the scene's own: lengths in metres, light
// intensities as KHR_lights_punctual defines them (point/spot: candela = W/sr in our
// radiometric reading, directional: lux = W/m²), emission as radiance.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/environment_map.h"

namespace vct {

// 64 bytes, laid out as four vec4 so the GPU can read it from a storage buffer (std430).
struct Vertex {
    glm::vec3 position{0.0f};
    float u = 0.0f;  // TEXCOORD_0
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    float v = 0.0f;
    glm::vec2 uv1{0.0f};     // TEXCOORD_1; a file without one gets TEXCOORD_0 here
    glm::vec2 unused{0.0f};  // fills the third vec4
    // The file's TANGENT in world space, or one generated where a normal texture needs it
    // (tangent_generation.h): xyz unit, along increasing u of TEXCOORD_0; w = ±1, the bitangent
    // cross(normal, xyz)·w. All zero where there is none (normal_map.h).
    glm::vec4 tangent{0.0f};
};

// A material's use of a texture, as a glTF textureInfo says it: which texture, read at which
// texture-coordinate set, through KHR_texture_transform's offset, rotation and scale
// (shaders_glsl/texture_transform.h).
struct TextureReference {
    int index = -1;         // into Scene::textures, -1 = none
    uint32_t texCoord = 0;  // 0 = TEXCOORD_0 (Vertex::u, v), 1 = TEXCOORD_1 (Vertex::uv1)
    glm::vec2 offset{0.0f};
    float rotation = 0.0f;  // radians
    glm::vec2 scale{1.0f};
};

// glTF alphaMode (§3.9.4): what the base colour's alpha, the factor's times the texture's, means.
// Opaque ignores it; Mask makes the surface a hole where it is below alphaCutoff; Blend makes it
// that fraction of the surface (rendered as the README's glTF table says).
enum class AlphaMode : uint8_t { Opaque, Mask, Blend };

// glTF pbrMetallicRoughness, plus emission and KHR_materials_specular's weight.
struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};    // linear RGB + alpha
    TextureReference baseColorTexture;  // sRGB
    float metallic = 1.0f;              // glTF defaults
    float roughness = 1.0f;
    // Linear: blue scales `metallic`, green `roughness`.
    TextureReference metallicRoughnessTexture;
    // Linear: the tangent-space normal (glTF: +x along increasing u, +y up the image, u and v the
    // texture's own, after its transform), its x and y scaled by `normalScale`.
    TextureReference normalTexture;
    float normalScale = 1.0f;
    // Linear: red is how much of the indirect light reaches the surface, 1 + occlusionStrength ·
    // (red − 1) (glTF 2.0 §3.9.3). The renderer applies it; the path tracer, which finds occlusion
    // itself, does not.
    TextureReference occlusionTexture;
    float occlusionStrength = 1.0f;
    // KHR_materials_specular specularFactor: 1 = glTF default dielectric (F0 = 0.04),
    // 0 = pure Lambertian (used by the Cornell box, whose reflectances are diffuse).
    float specularWeight = 1.0f;
    glm::vec3 emission{0.0f};          // emissiveFactor × KHR_materials_emissive_strength: radiance
    TextureReference emissiveTexture;  // sRGB; multiplies `emission`
    // glTF doubleSided: false culls the back faces, so the camera does not see the surface from
    // behind. glTF's default is false, which the loader gives files that leave it out; a scene built
    // in code is seen from both sides unless it says otherwise.
    bool doubleSided = true;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;  // Mask: where alpha < alphaCutoff there is no surface (glTF default 0.5)
};

// How texture coordinates outside [0, 1] read a texture (glTF sampler wrapS / wrapT).
enum class TextureWrap : uint8_t { Repeat, ClampToEdge, MirroredRepeat };

// An 8-bit RGBA image: sRGB-encoded colour (base colour, emission) or linear data (metallic and
// roughness, normals), as glTF stores each, with its glTF sampler's wrapping and magnification.
// An image a file uses both ways, or through two different samplers, is two textures.
struct Texture {
    std::string name;  // the URI or a description, for messages
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> rgba8;
    bool srgb = true;
    TextureWrap wrapS = TextureWrap::Repeat;  // along u
    TextureWrap wrapT = TextureWrap::Repeat;  // along v
    bool nearestMagnification = false;        // magFilter NEAREST: texels stay square up close
};

enum class LightType : uint32_t { Directional = 0, Point = 1, Spot = 2 };

// KHR_lights_punctual, already placed in world space.
struct Light {
    std::string name;
    LightType type = LightType::Point;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;               // cd for point/spot, lux for directional
    glm::vec3 position{0.0f};             // point and spot
    glm::vec3 direction{0, 0, -1};        // direction the light travels (node's −Z), directional and spot
    float range = 0.0f;                   // 0 = infinite
    float innerConeAngle = 0.0f;          // spot, radians
    float outerConeAngle = 0.785398163f;  // spot, radians (π/4, the glTF default)

    bool operator==(const Light&) const = default;
};

// A glTF perspective camera, placed in world space. It looks down its local −Z with +Y up.
struct Camera {
    std::string name;
    glm::vec3 position{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float yfov = 0.8f;  // radians, vertical
    float znear = 0.01f;
    float zfar = 0.0f;  // 0 = infinite (glTF), the renderer then fits it to the scene
};

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    glm::vec3 center() const { return 0.5f * (min + max); }
    glm::vec3 extent() const { return max - min; }
    // Corner i of 8: bit 0 picks max.x over min.x, bit 1 max.y, bit 2 max.z.
    glm::vec3 corner(int i) const {
        return {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
    }
};

struct Scene {
    std::string name;  // file path or built-in name, for messages
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;            // 3 per triangle
    std::vector<uint32_t> triangleMaterials;  // 1 per triangle, index into materials
    std::vector<Material> materials;          // never empty after loading (a default is added)
    std::vector<Texture> textures;
    std::vector<Light> lights;
    std::vector<Camera> cameras;  // the first is the default view
    // Radiance (scene units) of the sky that every ray leaving the scene sees, the same in every
    // direction: black unless the command line sets it or the scene has no light of its own.
    // With an environment image, the factor its radiance is multiplied by (1 as loaded).
    glm::vec3 environment{0.0f};
    std::shared_ptr<const EnvironmentMap> environmentMap;  // --environment FILE.hdr; shared, never copied
    // How far the environment image is turned about +Y, in radians, counter-clockwise seen from above
    // (--environment-rotation; equirectangular.h).
    float environmentRotation = 0.0f;
    std::vector<std::string> warnings;  // non-fatal problems met while loading

    size_t triangleCount() const { return indices.size() / 3; }
    Bounds bounds() const;
    // Whether any material is MASK or BLEND: only then does the voxelizer keep an opacity channel.
    bool hasAlphaMaterials() const {
        for (const Material& material : materials)
            if (material.alphaMode != AlphaMode::Opaque) return true;
        return false;
    }
};

// Computes the axis-aligned bounds of all vertices (zero bounds for an empty scene).
inline Bounds Scene::bounds() const {
    if (vertices.empty()) return {};
    Bounds b{vertices[0].position, vertices[0].position};
    for (const Vertex& v : vertices) {
        b.min = glm::min(b.min, v.position);
        b.max = glm::max(b.max, v.position);
    }
    return b;
}

}  // namespace vct
