// The scene the alphaMode and doubleSided tests share (renderer and path tracer): a red quad whose base colour
// texture's alpha is a checkerboard, in front of a white wall, both lit head-on by a sun, so the
// camera sees the wall through the quad's holes and the sun casts the checkerboard onto the wall.
#pragma once

#include <cmath>
#include <cstdint>
#include <utility>

#include "scene/scene.h"

namespace vct::test {

constexpr uint32_t kCheckerCells = 8;           // squares along each side of the occluder
constexpr uint32_t kCheckerTexels = 64;         // texels along each side of its texture
constexpr float kOccluderZ = 0.5f;              // the occluder's plane; the wall's is z = 0
constexpr float kSunIlluminance = 3.14159265f;  // lit white Lambertian surfaces have radiance 1
constexpr float kCameraFov = 1.0471976f;        // 60°, vertical and horizontal (square images)

// RGB `rgb`; alpha a checkerboard of kCheckerCells² squares, 255 where column + row is even (the
// top-left square), 0 elsewhere. Magnified nearest, so its squares stay square up close.
inline Texture checkerAlphaTexture(glm::u8vec3 rgb) {
    Texture texture;
    texture.name = "checker alpha";
    texture.width = texture.height = kCheckerTexels;
    for (uint32_t y = 0; y < kCheckerTexels; ++y)
        for (uint32_t x = 0; x < kCheckerTexels; ++x) {
            const bool opaque = (x * kCheckerCells / kCheckerTexels + y * kCheckerCells / kCheckerTexels) % 2 == 0;
            texture.rgba8.insert(texture.rgba8.end(), {rgb.r, rgb.g, rgb.b, uint8_t(opaque ? 255 : 0)});
        }
    texture.nearestMagnification = true;
    return texture;
}

// The occluder spans x, y ∈ [−1, 1] with u = (x + 1)/2, v = (1 − y)/2 (the texture's top row at y = 1).
inline glm::vec2 occluderTexCoord(glm::vec2 xy) { return glm::vec2(0.5f * (xy.x + 1.0f), 0.5f * (1.0f - xy.y)); }

// Whether the checkerboard is opaque at (x, y) on the occluder (outside it: false, nothing there).
inline bool checkerOpaqueAt(glm::vec2 xy) {
    if (std::abs(xy.x) >= 1.0f || std::abs(xy.y) >= 1.0f) return false;
    const glm::vec2 cell = glm::floor(occluderTexCoord(xy) * float(kCheckerCells));
    return (int(cell.x) + int(cell.y)) % 2 == 0;
}

// World distance from (x, y) to the nearest edge between the checkerboard's squares.
inline float distanceToCheckerEdge(glm::vec2 xy) {
    const float cellSize = 2.0f / float(kCheckerCells);
    const glm::vec2 inCell = (xy + 1.0f) / cellSize;
    const glm::vec2 toEdge = glm::abs(inCell - glm::round(inCell)) * cellSize;
    return std::min(toEdge.x, toEdge.y);
}

inline Material lambertianMaterial(glm::vec3 albedo) {
    Material material;
    material.baseColorFactor = glm::vec4(albedo, 1.0f);
    material.metallic = 0.0f;
    material.roughness = 1.0f;
    material.specularWeight = 0.0f;
    return material;
}

// Material 0: the wall, white, x, y ∈ [−2, 2] at z = 0. Material 1: the occluder, red, with
// `alphaMode`, alpha `alphaFactor` times (when `checkerTexture`) the checkerboard texture's, at
// z = kOccluderZ. Both face +Z, towards the camera at (0, 0, 2) looking down −Z (kCameraFov: it
// sees the occluder's plane only, x, y within ±1.5·tan 30°), and towards the sun of kSunIlluminance
// travelling along −Z.
inline Scene occluderBeforeWall(AlphaMode alphaMode, bool checkerTexture, float alphaFactor = 1.0f) {
    Scene scene;
    scene.name = "alpha occluder before a wall";
    scene.materials.push_back(lambertianMaterial(glm::vec3(1.0f)));
    Material occluder = lambertianMaterial(glm::vec3(1.0f, 0.0f, 0.0f));
    occluder.baseColorFactor.a = alphaFactor;
    occluder.alphaMode = alphaMode;
    if (checkerTexture) {
        occluder.baseColorTexture.index = 0;
        scene.textures.push_back(checkerAlphaTexture(glm::u8vec3(255)));
    }
    scene.materials.push_back(occluder);
    auto addQuad = [&](float halfSide, float z, uint32_t material) {
        const uint32_t first = uint32_t(scene.vertices.size());
        for (const glm::vec2 corner : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
            Vertex vertex;
            vertex.position = glm::vec3(halfSide * corner, z);
            vertex.normal = glm::vec3(0.0f, 0.0f, 1.0f);
            const glm::vec2 uv = occluderTexCoord(corner);
            vertex.u = uv.x;
            vertex.v = uv.y;
            vertex.uv1 = uv;
            scene.vertices.push_back(vertex);
        }
        for (uint32_t corner : {0u, 1u, 2u, 0u, 2u, 3u}) scene.indices.push_back(first + corner);
        scene.triangleMaterials.insert(scene.triangleMaterials.end(), {material, material});
    };
    addQuad(2.0f, 0.0f, 0);
    addQuad(1.0f, kOccluderZ, 1);
    Light sun;
    sun.name = "sun";
    sun.type = LightType::Directional;
    sun.direction = glm::vec3(0.0f, 0.0f, -1.0f);
    sun.intensity = kSunIlluminance;
    scene.lights.push_back(sun);
    Camera camera;
    camera.position = glm::vec3(0.0f, 0.0f, 2.0f);
    camera.yfov = kCameraFov;
    scene.cameras.push_back(camera);
    return scene;
}

// occluderBeforeWall with an opaque occluder wound the other way round, its front facing away from
// the camera and the sun (−Z), and `doubleSided` as glTF's: single-sided, the camera must not see it
// (it sees the wall in its shadow instead); double-sided, it sees its back lit red.
inline Scene occluderSeenFromBehind(bool doubleSided) {
    Scene scene = occluderBeforeWall(AlphaMode::Opaque, false);
    scene.materials[1].doubleSided = doubleSided;
    for (size_t t = 0; t < scene.triangleMaterials.size(); ++t)
        if (scene.triangleMaterials[t] == 1) std::swap(scene.indices[3 * t + 1], scene.indices[3 * t + 2]);
    return scene;
}

}  // namespace vct::test
