#include "scene/default_light.h"

#include <cstdio>
#include <vector>

#include "error.h"
#include "scene/material_textures.h"

namespace vct {

void checkSkyRadiance(glm::vec3 radiance) {
    if (!(glm::all(glm::greaterThanEqual(radiance, glm::vec3(0.0f))) &&
          glm::all(glm::lessThanEqual(radiance, glm::vec3(1e9f)))))
        throw Error("--environment must be a radiance from 0 to 1e9 in each of red, green and blue");
}

bool sceneHasLight(const Scene& scene) {
    if (!scene.lights.empty()) return true;
    if (scene.environment.r > 0.0f || scene.environment.g > 0.0f || scene.environment.b > 0.0f) return true;
    std::vector<char> emits;
    for (const Material& material : scene.materials) emits.push_back(emitsLight(scene, material));
    for (uint32_t material : scene.triangleMaterials)
        if (material < emits.size() && emits[material]) return true;
    return false;
}

bool addDefaultSunAndSkyIfUnlit(Scene& scene) {
    if (sceneHasLight(scene)) return false;
    Light sun;
    sun.name = kDefaultSunName;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(kDefaultSunTravel);
    sun.intensity = kDefaultSunIlluminance;
    scene.lights.push_back(sun);
    scene.environment = kDefaultSkyRadiance;
    char text[300];
    std::snprintf(text, sizeof text,
                  ": no light, sky or emissive surface, so a default sun and sky are added: the sun travelling "
                  "along (%.2f, %.2f, %.2f) at %g lux, the sky of radiance (%g, %g, %g)",
                  sun.direction.x, sun.direction.y, sun.direction.z, sun.intensity, kDefaultSkyRadiance.r,
                  kDefaultSkyRadiance.g, kDefaultSkyRadiance.b);
    scene.warnings.push_back(scene.name + text);
    return true;
}

}  // namespace vct
