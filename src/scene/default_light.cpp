#include "scene/default_light.h"

#include <cstdio>
#include <vector>

#include "scene/material_textures.h"

namespace vct {

bool sceneHasLight(const Scene& scene) {
    if (!scene.lights.empty()) return true;
    std::vector<char> emits;
    for (const Material& material : scene.materials) {
        const glm::vec3 emission = voxelEmission(scene, material);
        emits.push_back(emission.r > 0.0f || emission.g > 0.0f || emission.b > 0.0f);
    }
    for (uint32_t material : scene.triangleMaterials)
        if (material < emits.size() && emits[material]) return true;
    return false;
}

bool addDefaultSunIfUnlit(Scene& scene) {
    if (sceneHasLight(scene)) return false;
    Light sun;
    sun.name = kDefaultSunName;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(kDefaultSunTravel);
    sun.intensity = kDefaultSunIlluminance;
    scene.lights.push_back(sun);
    char text[200];
    std::snprintf(text, sizeof text,
                  ": no light and no emissive surface, so a default sun is added: travelling along (%.2f, %.2f, "
                  "%.2f), %g lux",
                  sun.direction.x, sun.direction.y, sun.direction.z, sun.intensity);
    scene.warnings.push_back(scene.name + text);
    return true;
}

}  // namespace vct
