// Scenes and settings the path tracer tests share: small, built in code, so each test shows its input.
#pragma once

#include <cmath>
#include <utility>

#include "path_tracer.h"
#include "sampling.h"

namespace vct::pt::test {

inline Material lambertian(glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.0f)) {
    Material material;
    material.baseColorFactor = glm::vec4(albedo, 1.0f);
    material.metallic = 0.0f;
    material.roughness = 1.0f;
    material.specularWeight = 0.0f;
    material.emission = emission;
    return material;
}

inline uint32_t addMaterial(Scene& scene, const Material& material) {
    scene.materials.push_back(material);
    return uint32_t(scene.materials.size() - 1);
}

inline RenderSettings smallRender(const Scene& scene, uint32_t size, uint32_t spp, Component component, uint64_t seed) {
    RenderSettings settings;
    settings.width = settings.height = size;
    settings.samplesPerPixel = spp;
    settings.component = component;
    settings.seed = seed;
    settings.threads = 2;
    settings.camera = scene.cameras.at(0);
    return settings;
}

// `scene` (its textures set) plus a 2 × 2 plane facing up with `material`, u = (x + 1)/2 and
// v = (z + 1)/2, lit by a sun of E = π travelling along `sunTravel`, and a camera above looking
// down that sees x, z ∈ [−½, ½] with image right = +x (so up the image is −z).
inline void addSunlitPlaneSeenFromAbove(Scene& scene, const Material& material, glm::vec3 sunTravel) {
    const uint32_t plane = addMaterial(scene, material);
    for (auto [x, z] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}})
        scene.vertices.push_back({glm::vec3(x, 0.0f, z), 0.5f * (x + 1.0f), glm::vec3(0, 1, 0), 0.5f * (z + 1.0f)});
    scene.indices = {0, 2, 1, 0, 3, 2};
    scene.triangleMaterials = {plane, plane};
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(sunTravel);
    sun.intensity = kPi;
    scene.lights.push_back(sun);
    Camera camera;
    camera.position = glm::vec3(0.0f, 1.0f, 0.0f);
    camera.forward = glm::vec3(0.0f, -1.0f, 0.0f);
    camera.up = glm::vec3(0.0f, 0.0f, -1.0f);  // image right = +x
    camera.yfov = 2.0f * std::atan(0.5f);      // sees x, z ∈ [−½, ½]
    scene.cameras.push_back(camera);
}

// A texture `width` × 1, black on its left half and white on its right (sRGB 0 and 255).
inline Texture halfBlackTexture(uint32_t width) {
    Texture texture;
    texture.width = width;
    texture.height = 1;
    for (uint32_t x = 0; x < width; ++x) {
        const uint8_t value = x < width / 2 ? 0 : 255;
        texture.rgba8.insert(texture.rgba8.end(), {value, value, value, 255});
    }
    return texture;
}

}  // namespace vct::pt::test
