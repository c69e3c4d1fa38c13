#include "app/scene_setup.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "error.h"
#include "render/camera.h"
#include "scene/default_light.h"
#include "scene/load.h"

namespace vct {

void checkSceneArguments(const Arguments& arguments) {
    sceneOverridesFromArguments(arguments);
    checkSceneName(arguments.text("scene", "cornell"), "--scene");
}

void checkSceneName(const std::string& scene, const std::string& option) {
    const std::vector<std::string> builtins = builtinSceneNames();
    if (std::find(builtins.begin(), builtins.end(), scene) != builtins.end()) return;
    std::error_code error;
    if (std::filesystem::exists(scene, error)) return;
    const std::string extension = std::filesystem::path(scene).extension().string();
    if (extension == ".gltf" || extension == ".glb") throw Error(scene + ": file not found");
    std::string names;
    for (const std::string& name : builtins) names += (names.empty() ? "" : ", ") + name;
    throw Error(option + " '" + scene + "' is neither a file nor a built-in scene (" + names + ")");
}

Scene loadSceneFromArguments(const Arguments& arguments, const SceneBufferLimits& limits) {
    LoadOptions options;
    options.bufferLimits = limits;
    options.strict = arguments.has("strict");
    options.allowedRoot = arguments.text("allowed-root", "");
    Scene scene = loadScene(arguments.text("scene", "cornell"), options);
    const SceneOverrides overrides = sceneOverridesFromArguments(arguments);
    // --light-dir's sun is light enough, and so is --environment's sky, black included (the way to
    // render a file lit by its own glow alone); --light-intensity alone sets the default sun's.
    if (overrides.environment) scene.environment = *overrides.environment;
    if (!overrides.environmentImage.empty()) useEnvironmentImage(scene, loadEnvironmentImage(overrides));
    scene.environmentRotation = overrides.environmentRotation;
    if (!overrides.lightDirection && !overrides.environment && overrides.environmentImage.empty())
        addDefaultSunAndSkyIfUnlit(scene);
    applySceneOverrides(overrides, scene);
    return scene;
}

std::shared_ptr<const EnvironmentMap> loadEnvironmentImage(const SceneOverrides& overrides) {
    if (overrides.environmentImage.empty()) return nullptr;
    return std::make_shared<const EnvironmentMap>(loadEnvironmentMap(overrides.environmentImage));
}

void printSceneWarnings(const Scene& scene) {
    for (const std::string& warning : scene.warnings) std::fprintf(stderr, "warning: %s\n", warning.c_str());
}

ContextOptions contextOptionsFromArguments(const Arguments& arguments) {
    ContextOptions options;
    options.validation = arguments.has("validate");
    options.deviceName = arguments.text("device", "");
    return options;
}

void applySceneOverrides(const SceneOverrides& overrides, Scene& scene) {
    if (scene.cameras.empty()) scene.cameras.push_back(defaultCamera(scene.bounds()));
    Camera& camera = scene.cameras.front();
    if (overrides.cameraPosition || overrides.cameraTarget)
        aimCamera(camera, overrides.cameraPosition.value_or(camera.position),
                  overrides.cameraTarget.value_or(camera.position + camera.forward));
    if (overrides.yfovDegrees) camera.yfov = glm::radians(*overrides.yfovDegrees);

    // --light-intensity sets the scene's first sun, or the one --light-dir adds; a scene without a
    // sun and no --light-dir has nothing it could set, which is said rather than ignored.
    Light* sun = nullptr;
    for (Light& light : scene.lights)
        if (light.type == LightType::Directional) sun = sun ? sun : &light;
    if (!overrides.lightDirection && overrides.lightIntensity) {
        if (!sun)
            throw Error("--light-intensity sets the illuminance of a sun, and scene '" + scene.name +
                        "' has none: give --light-dir too to add one");
        sun->intensity = *overrides.lightIntensity;
    }
    if (overrides.lightDirection) {
        if (!sun) {
            scene.lights.push_back(Light{});
            sun = &scene.lights.back();
            sun->name = "command-line sun";
            sun->type = LightType::Directional;
            sun->intensity = kDefaultSunIlluminance;
        }
        sun->direction = glm::normalize(*overrides.lightDirection);
        if (overrides.lightIntensity) sun->intensity = *overrides.lightIntensity;
    }
}

}  // namespace vct
