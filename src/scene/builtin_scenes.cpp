// Built-in scenes, so the renderer and its tests need no file.
//
// The Cornell box uses the published measured geometry of the Cornell Program of Computer
// Graphics ("Cornell Box Data", graphics.cornell.edu/online/box/data.html), converted from
// millimetres to metres, and the RGB reflectances commonly derived from its measured spectra
// (as in the PBRT-v3 and Mitsuba scenes): white 0.725 0.71 0.68, red 0.63 0.065 0.05,
// green 0.14 0.45 0.091. Surfaces are pure Lambertian (KHR_materials_specular weight 0),
// as the measured data describes diffuse reflectance.
#include <algorithm>
#include <array>

#include "error.h"
#include "scene/load.h"

namespace vct {
namespace {

using Quad = std::array<glm::vec3, 4>;
constexpr float kMillimetre = 0.001f;

struct SceneBuilder {
    Scene scene;

    uint32_t addMaterial(const std::string& name, glm::vec3 reflectance, glm::vec3 emission = glm::vec3(0.0f)) {
        Material material;
        material.name = name;
        material.baseColorFactor = glm::vec4(reflectance, 1.0f);
        material.metallic = 0.0f;
        material.roughness = 1.0f;
        material.specularWeight = 0.0f;
        material.emission = emission;
        scene.materials.push_back(material);
        return uint32_t(scene.materials.size() - 1);
    }

    // Adds a planar quad (corners in millimetres, in order around the quad) as two triangles
    // whose normal points towards `facing`, so the winding of the published data does not matter.
    void addQuad(Quad corners, glm::vec3 facing, uint32_t material) {
        for (glm::vec3& corner : corners) corner *= kMillimetre;
        facing *= kMillimetre;
        glm::vec3 normal = glm::normalize(glm::cross(corners[1] - corners[0], corners[2] - corners[0]));
        const glm::vec3 center = 0.25f * (corners[0] + corners[1] + corners[2] + corners[3]);
        if (glm::dot(normal, facing - center) < 0.0f) {
            std::reverse(corners.begin(), corners.end());
            normal = -normal;
        }
        const uint32_t first = uint32_t(scene.vertices.size());
        for (const glm::vec3& corner : corners) scene.vertices.push_back({corner, 0.0f, normal, 0.0f});
        for (uint32_t index : {0u, 1u, 2u, 0u, 2u, 3u}) scene.indices.push_back(first + index);
        scene.triangleMaterials.push_back(material);
        scene.triangleMaterials.push_back(material);
    }

    // A block given by its top face (published order) standing on the floor; sides face away from its axis.
    void addBlock(const Quad& top, uint32_t material) {
        const glm::vec3 axis = 0.25f * (top[0] + top[1] + top[2] + top[3]);
        addQuad(top, axis + glm::vec3(0, 1000, 0), material);
        for (int i = 0; i < 4; ++i) {
            const glm::vec3 a = top[i], b = top[(i + 1) % 4];
            const glm::vec3 sideCenter = 0.5f * (a + b);
            const glm::vec3 outward = sideCenter + (sideCenter - glm::vec3(axis.x, sideCenter.y, axis.z));
            addQuad({glm::vec3(a.x, 0, a.z), a, b, glm::vec3(b.x, 0, b.z)}, outward, material);
        }
    }
};

enum class CornellLight { PointUnderCeiling, EmissiveCeilingPatch };

Scene makeCornellBox(CornellLight lightKind) {
    SceneBuilder builder;
    builder.scene.name = lightKind == CornellLight::PointUnderCeiling ? "cornell" : "cornell-emissive";
    const uint32_t white = builder.addMaterial("white", {0.725f, 0.71f, 0.68f});
    const uint32_t red = builder.addMaterial("red", {0.63f, 0.065f, 0.05f});
    const uint32_t green = builder.addMaterial("green", {0.14f, 0.45f, 0.091f});
    const glm::vec3 inside(278.0f, 274.4f, 279.6f);

    builder.addQuad({{{552.8f, 0, 0}, {0, 0, 0}, {0, 0, 559.2f}, {549.6f, 0, 559.2f}}}, inside, white);  // floor
    builder.addQuad({{{556, 548.8f, 0}, {556, 548.8f, 559.2f}, {0, 548.8f, 559.2f}, {0, 548.8f, 0}}}, inside,
                    white);  // ceiling
    builder.addQuad({{{549.6f, 0, 559.2f}, {0, 0, 559.2f}, {0, 548.8f, 559.2f}, {556, 548.8f, 559.2f}}}, inside,
                    white);  // back wall
    builder.addQuad({{{0, 0, 559.2f}, {0, 0, 0}, {0, 548.8f, 0}, {0, 548.8f, 559.2f}}}, inside, green);  // right
    builder.addQuad({{{552.8f, 0, 0}, {549.6f, 0, 559.2f}, {556, 548.8f, 559.2f}, {556, 548.8f, 0}}}, inside,
                    red);  // left wall
    builder.addBlock({{{130, 165, 65}, {82, 165, 225}, {240, 165, 272}, {290, 165, 114}}}, white);   // short
    builder.addBlock({{{423, 330, 247}, {265, 330, 296}, {314, 330, 456}, {472, 330, 406}}}, white);  // tall

    // The published light patch spans x 213–343, z 227–332 at y 548.8.
    const glm::vec3 patchCenter = glm::vec3(278.0f, 548.8f, 279.5f) * kMillimetre;
    if (lightKind == CornellLight::PointUnderCeiling) {
        Light light;
        light.name = "ceiling point light";
        light.type = LightType::Point;
        light.intensity = 1.0f;  // W/sr: the floor below (d = 0.45 m) receives about 5 W/m²
        // 10 cm below the patch: closer, the ceiling above it becomes a hot spot (radiance ∝ 1/d²)
        // that dominates the indirect light and needs very many path-traced samples to converge.
        light.position = patchCenter - glm::vec3(0.0f, 0.1f, 0.0f);
        builder.scene.lights.push_back(light);
    } else {
        // Radiance chosen so the patch emits about as much power as the point light (4π W):
        // Φ = π·L·A with A = 0.13 × 0.105 m², so L ≈ 4π / (π · 0.01365) ≈ 293.
        const uint32_t lamp = builder.addMaterial("light", {0.78f, 0.78f, 0.78f}, glm::vec3(293.0f));
        // 1 mm below the ceiling, so the patch and the ceiling never fight for a pixel or a voxel.
        builder.addQuad({{{343, 547.8f, 227}, {343, 547.8f, 332}, {213, 547.8f, 332}, {213, 547.8f, 227}}},
                        glm::vec3(278, 0, 279.5f), lamp);
    }

    // The published camera: at (278, 273, −800) mm looking along +z, 35 mm lens on a 25 mm film.
    Camera camera;
    camera.name = "cornell camera";
    camera.position = glm::vec3(278.0f, 273.0f, -800.0f) * kMillimetre;
    camera.forward = glm::vec3(0.0f, 0.0f, 1.0f);
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    camera.yfov = 2.0f * std::atan(12.5f / 35.0f);
    camera.znear = 0.01f;
    builder.scene.cameras.push_back(camera);
    return builder.scene;
}

}  // namespace

std::vector<std::string> builtinSceneNames() { return {"cornell", "cornell-emissive"}; }

Scene loadScene(const std::string& nameOrPath, const LoadOptions& options) {
    if (nameOrPath == "cornell") return makeCornellBox(CornellLight::PointUnderCeiling);
    if (nameOrPath == "cornell-emissive") return makeCornellBox(CornellLight::EmissiveCeilingPatch);
    return loadGltf(nameOrPath, options);
}

}  // namespace vct
