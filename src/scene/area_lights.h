// Emissive surfaces as area lights: in glTF a lamp, a window or a screen is an emissive mesh, and
// its light reaches the room directly (shaders_glsl/area_light.h integrates it exactly over each
// triangle). Emissive triangles are grouped into lights by the surfaces they form; each light gets
// one cube of shadow maps, seen from just in front of its centre.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace vct {

// Bounds on what the direct light evaluates per pixel: lights (a shadow cube each) and triangles
// over all of them. Past kMaxAreaLights, surfaces that lie near each other merge into one light;
// a light with more than its share of the triangles is approximated: a flat one by the rectangle
// that bounds it, glowing evenly with its power (a grid of small tiles becomes one panel: right
// from afar and in its mean, too even right under it), another by its brightest triangles, whose
// radiance is raised so that the light keeps its power.
constexpr size_t kMaxAreaLights = 8;
constexpr size_t kMaxAreaLightTriangles = 128;

struct EmitterTriangle {
    glm::vec3 corners[3];  // world space, wound so that cross(c1 − c0, c2 − c0) points out of the front
    glm::vec3 radiance;    // from the front face: emission × its emissive texture's mean over it (scene units)
};

struct AreaLight {
    std::vector<EmitterTriangle> triangles;
    glm::vec3 centroid{0.0f};            // area-weighted
    glm::vec3 normal{0.0f, 1.0f, 0.0f};  // area-weighted front normal, unit
    float area = 0.0f;                   // of the scene's triangles it stands for
    float radius = 0.0f;                 // of the sphere around the centroid that holds every corner
    glm::vec3 meanRadiance{0.0f};        // area-weighted, of the triangles it is drawn with
    size_t sourceTriangles = 0;          // the scene's triangles it stands for
    enum class Approximation { None, BoundingRectangle, BrightestTriangles };
    Approximation approximation = Approximation::None;
};

// The scene's emissive triangles (front-face emission above zero) grouped into lights: triangles of
// one material joined through shared vertices are one light, and past kMaxAreaLights the groups are
// merged with their neighbours in space. Degenerate triangles are skipped.
std::vector<AreaLight> findAreaLights(const Scene& scene);

}  // namespace vct
