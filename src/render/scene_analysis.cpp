#include "render/scene_analysis.h"

#include <algorithm>

#include "scene/environment_map.h"

namespace vct {

SceneAnalysis analyzeScene(const Scene& scene) {
    SceneAnalysis analysis;
    SceneFacts& facts = analysis.facts;
    facts.origin = scene.bounds().center();
    analysis.local = scene;
    for (Vertex& vertex : analysis.local.vertices) vertex.position -= facts.origin;
    facts.bounds = analysis.local.bounds();
    facts.areaLights = findAreaLights(analysis.local);
    facts.environmentSun = scene.environmentMap ? separateSun(*scene.environmentMap) : std::nullopt;
    const EnvironmentMap* sky = facts.sky(scene);
    facts.skyMean = sky ? meanEnvironmentRadiance(*sky) : glm::vec3(1.0f);
    facts.anySpecularMaterial = std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) {
        return m.metallic > 0.0f || m.specularWeight > 0.0f;
    });
    for (const Material& material : scene.materials)
        facts.brightestEmission =
            std::max({facts.brightestEmission, material.emission.r, material.emission.g, material.emission.b});
    return analysis;
}

}  // namespace vct
