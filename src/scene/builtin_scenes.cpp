// Built-in scenes, so the renderer and its tests need no file.
//
// The Cornell box uses the published measured geometry of the Cornell Program of Computer
// Graphics ("Cornell Box Data", graphics.cornell.edu/online/box/data.html), converted from
// millimetres to metres, and the RGB reflectances commonly derived from its measured spectra
// (as in the PBRT-v3 and Mitsuba scenes): white 0.725 0.71 0.68, red 0.63 0.065 0.05,
// green 0.14 0.45 0.091. Surfaces are pure Lambertian (KHR_materials_specular weight 0),
// as the measured data describes diffuse reflectance.
//
// Beside it, the scenes `vct bench` measures (see README, "Benchmark"): `sun-room` (a closed room
// lit by the sun through a hole in its roof, so most of what the camera sees is indirect light),
// `cornell-metal` (a glossy gold sphere for the specular cone), `cornell-sun` (the box without its
// ceiling, lit by a sun: the scene of issue 13's comparison with an OpenGL VCT), `terrain` (a procedural
// height field with spheres, about 60 000 triangles, for timing), and two rooms lit only by emissive
// surfaces (area lights): `panel-room` by a screen showing a picture, `tile-room` by 576 small lamps.
#include <algorithm>
#include <array>
#include <cmath>

#include "error.h"
#include "scene/load.h"

namespace vct {
namespace {

using Quad = std::array<glm::vec3, 4>;
constexpr float kMillimetre = 0.001f;

struct SceneBuilder {
    Scene scene;
    float unit = kMillimetre;  // the unit of addQuad's and addBlock's coordinates, in metres

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
        for (glm::vec3& corner : corners) corner *= unit;
        facing *= unit;
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

    // An axis-aligned box (metres) whose faces point outwards.
    void addBox(glm::vec3 lo, glm::vec3 hi, uint32_t material) {
        const glm::vec3 c = 0.5f * (lo + hi);
        const glm::vec3 far = 2.0f * hi - lo;   // a point beyond each +face
        const glm::vec3 near = 2.0f * lo - hi;  // ... and each −face
        addQuad({{{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z}}}, {c.x, near.y, c.z},
                material);
        addQuad({{{lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}}}, {c.x, far.y, c.z},
                material);
        addQuad({{{lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {lo.x, hi.y, hi.z}, {lo.x, lo.y, hi.z}}}, {near.x, c.y, c.z},
                material);
        addQuad({{{hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {hi.x, lo.y, hi.z}}}, {far.x, c.y, c.z},
                material);
        addQuad({{{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z}}}, {c.x, c.y, near.z},
                material);
        addQuad({{{lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}}}, {c.x, c.y, far.z},
                material);
    }

    // A triangle (metres) with per-vertex normals, wound counter-clockwise around them.
    void addTriangle(const std::array<Vertex, 3>& corners, uint32_t material) {
        const uint32_t first = uint32_t(scene.vertices.size());
        for (const Vertex& corner : corners) scene.vertices.push_back(corner);
        for (uint32_t index : {0u, 1u, 2u}) scene.indices.push_back(first + index);
        scene.triangleMaterials.push_back(material);
    }

    // A UV sphere (metres) with smooth normals: `segments` around, `segments / 2` from pole to pole.
    void addSphere(glm::vec3 center, float radius, uint32_t segments, uint32_t material) {
        const uint32_t rings = segments / 2;
        const auto point = [&](uint32_t ring, uint32_t segment) {
            const float theta = float(M_PI) * float(ring) / float(rings);
            const float phi = 2.0f * float(M_PI) * float(segment) / float(segments);
            const glm::vec3 normal(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            return Vertex{center + radius * normal, 0.0f, normal, 0.0f};
        };
        for (uint32_t ring = 0; ring < rings; ++ring) {
            for (uint32_t segment = 0; segment < segments; ++segment) {
                const Vertex a = point(ring, segment), b = point(ring, segment + 1);
                const Vertex c = point(ring + 1, segment), d = point(ring + 1, segment + 1);
                if (ring > 0) addTriangle({a, b, c}, material);  // the poles need one triangle
                if (ring + 1 < rings) addTriangle({b, d, c}, material);
            }
        }
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

Camera cameraLookingAt(const std::string& name, glm::vec3 position, glm::vec3 target, float yfovDegrees) {
    Camera camera;
    camera.name = name;
    camera.position = position;
    camera.forward = glm::normalize(target - position);
    const glm::vec3 right = glm::normalize(glm::cross(camera.forward, glm::vec3(0.0f, 1.0f, 0.0f)));
    camera.up = glm::cross(right, camera.forward);
    camera.yfov = glm::radians(yfovDegrees);
    camera.znear = 0.01f;
    return camera;
}

enum class CornellLight { PointUnderCeiling, EmissiveCeilingPatch, PointWithMetalSphere, SunThroughOpenTop };

Scene makeCornellBox(CornellLight lightKind) {
    SceneBuilder builder;
    builder.scene.name = lightKind == CornellLight::PointUnderCeiling      ? "cornell"
                         : lightKind == CornellLight::EmissiveCeilingPatch ? "cornell-emissive"
                         : lightKind == CornellLight::PointWithMetalSphere ? "cornell-metal"
                                                                           : "cornell-sun";
    const uint32_t white = builder.addMaterial("white", {0.725f, 0.71f, 0.68f});
    const uint32_t red = builder.addMaterial("red", {0.63f, 0.065f, 0.05f});
    const uint32_t green = builder.addMaterial("green", {0.14f, 0.45f, 0.091f});
    const glm::vec3 inside(278.0f, 274.4f, 279.6f);

    builder.addQuad({{{552.8f, 0, 0}, {0, 0, 0}, {0, 0, 559.2f}, {549.6f, 0, 559.2f}}}, inside, white);  // floor
    if (lightKind != CornellLight::SunThroughOpenTop)
        builder.addQuad({{{556, 548.8f, 0}, {556, 548.8f, 559.2f}, {0, 548.8f, 559.2f}, {0, 548.8f, 0}}}, inside,
                        white);  // ceiling
    builder.addQuad({{{549.6f, 0, 559.2f}, {0, 0, 559.2f}, {0, 548.8f, 559.2f}, {556, 548.8f, 559.2f}}}, inside,
                    white);                                                                              // back wall
    builder.addQuad({{{0, 0, 559.2f}, {0, 0, 0}, {0, 548.8f, 0}, {0, 548.8f, 559.2f}}}, inside, green);  // right
    builder.addQuad({{{552.8f, 0, 0}, {549.6f, 0, 559.2f}, {556, 548.8f, 559.2f}, {556, 548.8f, 0}}}, inside,
                    red);                                                                           // left wall
    builder.addBlock({{{130, 165, 65}, {82, 165, 225}, {240, 165, 272}, {290, 165, 114}}}, white);  // short
    if (lightKind != CornellLight::PointWithMetalSphere) {
        builder.addBlock({{{423, 330, 247}, {265, 330, 296}, {314, 330, 456}, {472, 330, 406}}}, white);  // tall
    } else {
        // Where the tall block stood: a glossy gold sphere, so the specular cone has something to
        // reflect. Base colour = gold's linear F0 as listed in the Unreal Engine documentation,
        // "Physically Based Materials" (1.000, 0.766, 0.336); roughness 0.25 is a polished metal.
        const uint32_t gold = builder.addMaterial("gold", {1.0f, 0.766f, 0.336f});
        builder.scene.materials[gold].metallic = 1.0f;
        builder.scene.materials[gold].roughness = 0.25f;
        builder.scene.materials[gold].specularWeight = 1.0f;
        builder.addSphere(glm::vec3(0.3685f, 0.15f, 0.3513f), 0.15f, 48, gold);
    }

    // The published light patch spans x 213–343, z 227–332 at y 548.8.
    const glm::vec3 patchCenter = glm::vec3(278.0f, 548.8f, 279.5f) * kMillimetre;
    if (lightKind == CornellLight::SunThroughOpenTop) {
        // The open-top box lit by a sun, as the OpenGL implementation issue 13 compares against
        // draws it: the sun falls on the floor, the blocks and the red wall, and the rest of the
        // room is lit by what they reflect.
        Light sun;
        sun.name = "sun";
        sun.type = LightType::Directional;
        sun.intensity = 5.0f;
        sun.direction = glm::normalize(glm::vec3(0.45f, -1.0f, 0.3f));
        builder.scene.lights.push_back(sun);
    } else if (lightKind != CornellLight::EmissiveCeilingPatch) {
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

// A closed 4 × 3 × 4 m room with a 1 × 1 m hole in its roof. The sun shines through the hole onto
// one patch of the floor; everything else the camera sees is lit only by light bounced off that
// patch. The room's walls are quads of zero thickness: what the sun-lit roof leaks into the voxels
// inside is exactly the error the benchmark should see.
Scene makeSunRoom() {
    SceneBuilder builder;
    builder.scene.name = "sun-room";
    builder.unit = 1.0f;
    const uint32_t white = builder.addMaterial("white", {0.725f, 0.71f, 0.68f});
    const uint32_t red = builder.addMaterial("red", {0.63f, 0.065f, 0.05f});
    const uint32_t green = builder.addMaterial("green", {0.14f, 0.45f, 0.091f});
    const glm::vec3 inside(2.0f, 1.5f, 2.0f);
    builder.addQuad({{{0, 0, 0}, {4, 0, 0}, {4, 0, 4}, {0, 0, 4}}}, inside, white);  // floor
    builder.addQuad({{{0, 0, 0}, {0, 3, 0}, {0, 3, 4}, {0, 0, 4}}}, inside, red);    // x = 0
    builder.addQuad({{{4, 0, 0}, {4, 3, 0}, {4, 3, 4}, {4, 0, 4}}}, inside, green);  // x = 4
    builder.addQuad({{{0, 0, 0}, {4, 0, 0}, {4, 3, 0}, {0, 3, 0}}}, inside, white);  // behind the camera
    builder.addQuad({{{0, 0, 4}, {4, 0, 4}, {4, 3, 4}, {0, 3, 4}}}, inside, white);  // back wall
    // The roof around the hole x 1.5–2.5, z 1.5–2.5.
    builder.addQuad({{{0, 3, 0}, {4, 3, 0}, {4, 3, 1.5f}, {0, 3, 1.5f}}}, inside, white);
    builder.addQuad({{{0, 3, 2.5f}, {4, 3, 2.5f}, {4, 3, 4}, {0, 3, 4}}}, inside, white);
    builder.addQuad({{{0, 3, 1.5f}, {1.5f, 3, 1.5f}, {1.5f, 3, 2.5f}, {0, 3, 2.5f}}}, inside, white);
    builder.addQuad({{{2.5f, 3, 1.5f}, {4, 3, 1.5f}, {4, 3, 2.5f}, {2.5f, 3, 2.5f}}}, inside, white);
    builder.addBox({0.6f, 0.0f, 2.6f}, {1.4f, 1.0f, 3.4f}, white);

    // 20 lux travelling down and towards +x, +z: the lit patch lies on the floor around x 3, z 2.7.
    Light sun;
    sun.name = "sun";
    sun.type = LightType::Directional;
    sun.intensity = 20.0f;
    sun.direction = glm::normalize(glm::vec3(0.35f, -1.0f, 0.25f));
    builder.scene.lights.push_back(sun);
    builder.scene.cameras.push_back(cameraLookingAt("sun-room camera", {2.0f, 1.6f, 0.2f}, {2.0f, 0.9f, 4.0f}, 70.0f));
    return builder.scene;
}

// The 4 × 2.5 × 4 m room of the area-light scenes: white walls, a grey floor, a blue wall on the
// right, a low box and a tall one on the floor; the camera stands at the front looking to the back.
void addLampRoom(SceneBuilder& builder) {
    builder.unit = 1.0f;
    const uint32_t white = builder.addMaterial("white", {0.725f, 0.71f, 0.68f});
    const uint32_t grey = builder.addMaterial("grey floor", {0.45f, 0.45f, 0.45f});
    const uint32_t blue = builder.addMaterial("blue", {0.1f, 0.2f, 0.6f});
    const glm::vec3 inside(2.0f, 1.25f, 2.0f);
    builder.addQuad({{{0, 0, 0}, {4, 0, 0}, {4, 0, 4}, {0, 0, 4}}}, inside, grey);               // floor
    builder.addQuad({{{0, 2.5f, 0}, {4, 2.5f, 0}, {4, 2.5f, 4}, {0, 2.5f, 4}}}, inside, white);  // ceiling
    builder.addQuad({{{0, 0, 0}, {0, 2.5f, 0}, {0, 2.5f, 4}, {0, 0, 4}}}, inside, white);        // x = 0
    builder.addQuad({{{4, 0, 0}, {4, 2.5f, 0}, {4, 2.5f, 4}, {4, 0, 4}}}, inside, blue);         // x = 4
    builder.addQuad({{{0, 0, 0}, {4, 0, 0}, {4, 2.5f, 0}, {0, 2.5f, 0}}}, inside, white);        // behind the camera
    builder.addQuad({{{0, 0, 4}, {4, 0, 4}, {4, 2.5f, 4}, {0, 2.5f, 4}}}, inside, white);        // back wall
    builder.addBox({0.7f, 0.0f, 2.2f}, {1.9f, 0.45f, 2.9f}, white);
    builder.addBox({2.7f, 0.0f, 2.6f}, {3.2f, 1.6f, 3.1f}, white);
    builder.scene.cameras.push_back(cameraLookingAt("room camera", {2.0f, 1.5f, 0.15f}, {2.0f, 0.9f, 4.0f}, 75.0f));
}

// An sRGB picture of a sunset over the sea, `width` × `height`: sky from blue to orange, a yellow sun
// at the horizon, dark blue water. Procedural, so the scene needs no file.
Texture sunsetPicture(uint32_t width, uint32_t height) {
    Texture texture;
    texture.name = "sunset (procedural)";
    texture.width = width;
    texture.height = height;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            const float u = (float(x) + 0.5f) / float(width), v = (float(y) + 0.5f) / float(height);  // v down
            glm::vec3 colour;
            if (v < 0.6f) {
                const float t = v / 0.6f;  // from the top of the sky to the horizon
                colour = glm::mix(glm::vec3(0.15f, 0.3f, 0.75f), glm::vec3(1.0f, 0.55f, 0.2f), t * t);
            } else {
                colour = glm::mix(glm::vec3(0.1f, 0.15f, 0.35f), glm::vec3(0.02f, 0.05f, 0.15f), (v - 0.6f) / 0.4f);
            }
            const float sun = glm::length(glm::vec2((u - 0.5f) * float(width) / float(height), v - 0.55f));
            if (sun < 0.1f) colour = glm::vec3(1.0f, 0.9f, 0.5f);
            for (float c : {colour.r, colour.g, colour.b}) texture.rgba8.push_back(uint8_t(std::lround(255.0f * c)));
            texture.rgba8.push_back(255);
        }
    return texture;
}

// The lamp room lit only by a textured emissive screen on its back wall (1.6 × 0.9 m, showing a
// sunset): the light's colour and strength come from the texture.
Scene makePanelRoom() {
    SceneBuilder builder;
    builder.scene.name = "panel-room";
    addLampRoom(builder);
    builder.scene.textures.push_back(sunsetPicture(64, 36));
    const uint32_t screen = builder.addMaterial("screen", {0.05f, 0.05f, 0.05f}, glm::vec3(20.0f));
    builder.scene.materials[screen].emissiveTexture.index = 0;
    // 2 cm in front of the back wall, facing the room; u to the right and v down as the camera sees it.
    const float z = 3.98f, left = 2.8f, right = 1.2f, bottom = 0.8f, top = 1.7f;
    const glm::vec3 normal(0.0f, 0.0f, -1.0f);
    const uint32_t first = uint32_t(builder.scene.vertices.size());
    builder.scene.vertices.push_back({{left, top, z}, 0.0f, normal, 0.0f});
    builder.scene.vertices.push_back({{right, top, z}, 1.0f, normal, 0.0f});
    builder.scene.vertices.push_back({{right, bottom, z}, 1.0f, normal, 1.0f});
    builder.scene.vertices.push_back({{left, bottom, z}, 0.0f, normal, 1.0f});
    for (uint32_t index : {0u, 2u, 1u, 0u, 3u, 2u}) builder.scene.indices.push_back(first + index);
    builder.scene.triangleMaterials.insert(builder.scene.triangleMaterials.end(), {screen, screen});
    return builder.scene;
}

// The lamp room lit only by a grid of 24 × 24 small square lamps (5 cm, 1152 triangles) under its
// ceiling: more emitters than the area lights take one by one.
Scene makeTileRoom() {
    SceneBuilder builder;
    builder.scene.name = "tile-room";
    addLampRoom(builder);
    const uint32_t lamp = builder.addMaterial("lamp", {0.8f, 0.8f, 0.8f}, glm::vec3(12.0f, 11.0f, 9.0f));
    const glm::vec3 below(2.0f, 0.0f, 2.0f);
    for (int i = 0; i < 24; ++i)
        for (int j = 0; j < 24; ++j) {
            const float x = 0.275f + 0.15f * float(i), z = 0.275f + 0.15f * float(j), y = 2.49f;
            builder.addQuad({{{x - 0.025f, y, z - 0.025f},
                              {x + 0.025f, y, z - 0.025f},
                              {x + 0.025f, y, z + 0.025f},
                              {x - 0.025f, y, z + 0.025f}}},
                            below, lamp);
        }
    return builder.scene;
}

// A 20 × 20 m height field of 160 × 160 cells (sums of sines, so it needs no random numbers or
// data files) with a 4 × 4 grid of spheres on it, under a low sun: about 60 000 triangles.
Scene makeTerrain() {
    SceneBuilder builder;
    builder.scene.name = "terrain";
    const uint32_t ground = builder.addMaterial("ground", {0.35f, 0.32f, 0.28f});
    const std::array<uint32_t, 3> sphereMaterials = {builder.addMaterial("white", {0.725f, 0.71f, 0.68f}),
                                                     builder.addMaterial("red", {0.63f, 0.065f, 0.05f}),
                                                     builder.addMaterial("green", {0.14f, 0.45f, 0.091f})};
    const auto height = [](float x, float z) {
        return 0.8f * std::sin(0.35f * x) * std::cos(0.3f * z) + 0.4f * std::sin(0.9f * x + 0.7f * z) +
               0.15f * std::cos(2.1f * x - 1.3f * z);
    };
    const auto vertex = [&](float x, float z) {
        const float h = 0.01f;  // central differences: the normal of the height field
        const glm::vec3 normal = glm::normalize(
            glm::vec3(height(x - h, z) - height(x + h, z), 2.0f * h, height(x, z - h) - height(x, z + h)));
        return Vertex{{x, height(x, z), z}, 0.0f, normal, 0.0f};
    };
    constexpr uint32_t kCells = 160;
    constexpr float kSide = 20.0f, kCell = kSide / kCells;
    for (uint32_t i = 0; i < kCells; ++i) {
        for (uint32_t j = 0; j < kCells; ++j) {
            const float x0 = -0.5f * kSide + i * kCell, z0 = -0.5f * kSide + j * kCell;
            const Vertex a = vertex(x0, z0), b = vertex(x0 + kCell, z0);
            const Vertex c = vertex(x0, z0 + kCell), d = vertex(x0 + kCell, z0 + kCell);
            builder.addTriangle({a, c, b}, ground);  // counter-clockwise seen from above
            builder.addTriangle({b, c, d}, ground);
        }
    }
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            const float x = -6.0f + 4.0f * i, z = -6.0f + 4.0f * j;
            builder.addSphere({x, height(x, z) + 0.6f, z}, 0.7f, 32, sphereMaterials[(i + j) % 3]);
        }
    }
    Light sun;
    sun.name = "low sun";
    sun.type = LightType::Directional;
    sun.intensity = 5.0f;
    sun.direction = glm::normalize(glm::vec3(-0.6f, -0.45f, 0.35f));
    builder.scene.lights.push_back(sun);
    builder.scene.cameras.push_back(
        cameraLookingAt("terrain camera", {-11.0f, 6.0f, -11.0f}, {0.0f, -0.5f, 0.0f}, 45.0f));
    return builder.scene;
}

}  // namespace

std::vector<std::string> builtinSceneNames() {
    return {"cornell",  "cornell-emissive", "cornell-metal", "cornell-sun",
            "sun-room", "terrain",          "panel-room",    "tile-room"};
}

Scene loadScene(const std::string& nameOrPath, const LoadOptions& options) {
    if (nameOrPath == "cornell") return makeCornellBox(CornellLight::PointUnderCeiling);
    if (nameOrPath == "cornell-emissive") return makeCornellBox(CornellLight::EmissiveCeilingPatch);
    if (nameOrPath == "cornell-metal") return makeCornellBox(CornellLight::PointWithMetalSphere);
    if (nameOrPath == "cornell-sun") return makeCornellBox(CornellLight::SunThroughOpenTop);
    if (nameOrPath == "sun-room") return makeSunRoom();
    if (nameOrPath == "terrain") return makeTerrain();
    if (nameOrPath == "panel-room") return makePanelRoom();
    if (nameOrPath == "tile-room") return makeTileRoom();
    return loadGltf(nameOrPath, options);
}

}  // namespace vct
