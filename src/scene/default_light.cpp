#include "scene/default_light.h"

#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "error.h"
#include "luminance.h"
#include "scene/material_textures.h"

namespace vct {

void checkSkyRadiance(glm::vec3 radiance) {
    if (!(glm::all(glm::greaterThanEqual(radiance, glm::vec3(0.0f))) &&
          glm::all(glm::lessThanEqual(radiance, glm::vec3(1e9f)))))
        throw Error("--environment must be a radiance from 0 to 1e9 in each of red, green and blue");
}

double defaultSunPowerOnBounds(const Bounds& bounds) {
    const glm::dvec3 travel = glm::normalize(glm::dvec3(kDefaultSunTravel));
    const glm::dvec3 extent = glm::dvec3(bounds.extent());
    const glm::dvec3 faceAreas(extent.y * extent.z, extent.z * extent.x, extent.x * extent.y);
    return double(kDefaultSunIlluminance) * glm::dot(glm::abs(travel), faceAreas);
}

double emittedPower(const Scene& scene) {
    std::vector<char> emits;
    for (const Material& material : scene.materials) emits.push_back(emitsLight(scene, material));
    double power = 0.0;
    for (size_t t = 0; t < scene.triangleMaterials.size(); ++t) {
        const uint32_t material = scene.triangleMaterials[t];
        if (material >= emits.size() || !emits[material]) continue;
        const Vertex* v[3] = {&scene.vertices[scene.indices[3 * t]], &scene.vertices[scene.indices[3 * t + 1]],
                              &scene.vertices[scene.indices[3 * t + 2]]};
        const glm::dvec3 radiance = glm::dvec3(emittedRadianceOverTriangle(scene, scene.materials[material], v));
        const double area = 0.5 * glm::length(glm::cross(glm::dvec3(v[1]->position - v[0]->position),
                                                         glm::dvec3(v[2]->position - v[0]->position)));
        // A Lambertian emitter of radiance L sends π·L out of each unit of its front face.
        if (std::isfinite(area)) power += glm::pi<double>() * glsl::luminance(radiance) * area;
    }
    return power;
}

namespace {

bool hasLightOrSky(const Scene& scene) {
    return !scene.lights.empty() || scene.environment.r > 0.0f || scene.environment.g > 0.0f ||
           scene.environment.b > 0.0f;
}

// Emitted power over what the default sun would bring: lit by its emitters from kEmittersLightTheSceneShare on.
double emittedShareOfDefaultSun(const Scene& scene) {
    const double emitted = emittedPower(scene);
    return emitted > 0.0 ? emitted / defaultSunPowerOnBounds(scene.bounds()) : 0.0;
}

}  // namespace

bool sceneHasLight(const Scene& scene) {
    return hasLightOrSky(scene) || emittedShareOfDefaultSun(scene) >= kEmittersLightTheSceneShare;
}

bool addDefaultSunAndSkyIfUnlit(Scene& scene) {
    if (hasLightOrSky(scene)) return false;
    const double emittedShare = emittedShareOfDefaultSun(scene);  // the emitters' pass, once
    if (emittedShare >= kEmittersLightTheSceneShare) return false;
    Light sun;
    sun.name = kDefaultSunName;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(kDefaultSunTravel);
    sun.intensity = kDefaultSunIlluminance;
    scene.lights.push_back(sun);
    scene.environment = kDefaultSkyRadiance;
    char why[160] = ": no light, sky or emissive surface";
    if (emittedShare > 0.0)
        std::snprintf(why, sizeof why,
                      ": no light or sky, and its emissive surfaces send out %.2g%% of the power the default sun "
                      "brings (too little to light it)",
                      100.0 * emittedShare);
    char text[420];
    std::snprintf(text, sizeof text,
                  "%s, so a default sun and sky are added: the sun travelling along (%.2f, %.2f, %.2f) at %g lux, "
                  "the sky of radiance (%g, %g, %g)",
                  why, sun.direction.x, sun.direction.y, sun.direction.z, sun.intensity, kDefaultSkyRadiance.r,
                  kDefaultSkyRadiance.g, kDefaultSkyRadiance.b);
    scene.warnings.push_back(scene.name + text);
    return true;
}

}  // namespace vct
