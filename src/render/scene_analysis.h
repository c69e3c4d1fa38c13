// What the renderer reads off a scene before it uploads it (Renderer::setGeometry): the frame the
// GPU works in, the area lights among its emissive surfaces, the sun painted into its environment
// image, and the facts its light and shading pipelines depend on. Pure: no device.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scene/area_lights.h"
#include "scene/environment_sun.h"
#include "scene/scene.h"

namespace vct {

struct SceneFacts {
    // The centre of the scene's bounds. The GPU works in a frame centred there: far from the origin
    // a float's step is too coarse for view and shadow matrices built from world positions (at
    // +1e4 m it is 1 mm, and shadows there changed 9 % of the Cornell box's pixels).
    glm::vec3 origin{0.0f};
    Bounds bounds;                                 // in that frame (world − origin)
    std::vector<AreaLight> areaLights;             // the emissive surfaces, in that frame
    std::optional<EnvironmentSun> environmentSun;  // lit as a directional light (environment_sun.h)
    glm::vec3 skyMean{1.0f};                       // the mean radiance of the sky image without its sun (1 without one)
    float brightestEmission = 0.0f;                // of any material, per channel
    bool anySpecularMaterial = false;              // metallic or with a specular weight: the specular cone can matter

    // The environment image the cones see: `scene`'s without its sun, or its own, or none.
    const EnvironmentMap* sky(const Scene& scene) const {
        return environmentSun ? environmentSun->withoutSun.get() : scene.environmentMap.get();
    }
};

struct SceneAnalysis {
    Scene local;  // the scene moved into the frame centred on its bounds (exact: Sterbenz)
    SceneFacts facts;
};

SceneAnalysis analyzeScene(const Scene& scene);

}  // namespace vct
