#include "app/scene_setup.h"

#include <cstdio>
#include <sstream>

#include "error.h"
#include "render/camera.h"
#include "scene/load.h"

namespace vct {

Scene loadSceneFromArguments(const Arguments& arguments, const SceneBufferLimits& limits) {
    LoadOptions options;
    options.bufferLimits = limits;
    options.strict = arguments.has("strict");
    options.allowedRoot = arguments.text("allowed-root", "");
    Scene scene = loadScene(arguments.text("scene", "cornell"), options);
    for (const std::string& warning : scene.warnings) std::fprintf(stderr, "warning: %s\n", warning.c_str());
    applyCameraAndLightOverrides(arguments, scene);
    return scene;
}

ContextOptions contextOptionsFromArguments(const Arguments& arguments) {
    ContextOptions options;
    options.validation = arguments.has("validate");
    options.deviceName = arguments.text("device", "");
    return options;
}

void applyCameraAndLightOverrides(const Arguments& arguments, Scene& scene) {
    if (scene.cameras.empty()) scene.cameras.push_back(defaultCamera(scene.bounds()));
    Camera& camera = scene.cameras.front();
    const std::optional<glm::vec3> position = arguments.vector3("camera-pos");
    const std::optional<glm::vec3> target = arguments.vector3("camera-target");
    if (position || target)
        aimCamera(camera, position.value_or(camera.position), target.value_or(camera.position + camera.forward));
    if (arguments.has("fov")) camera.yfov = glm::radians(arguments.number("fov", 45.0f, 1.0f, 179.0f));

    // --light-intensity sets the scene's first sun, or the one --light-dir adds; a scene without a
    // sun and no --light-dir has nothing it could set, which is said rather than ignored.
    Light* sun = nullptr;
    for (Light& light : scene.lights)
        if (light.type == LightType::Directional) sun = sun ? sun : &light;
    const std::optional<glm::vec3> direction = arguments.vector3("light-dir");
    if (!direction && arguments.has("light-intensity")) {
        if (!sun)
            throw Error("--light-intensity sets the illuminance of a sun, and scene '" + scene.name +
                        "' has none: give --light-dir too to add one");
        sun->intensity = arguments.number("light-intensity", 3.0f, 0.0f, 1e9f);
    }
    if (direction) {
        if (glm::length(*direction) < 1e-6f) throw Error("--light-dir must not be the zero vector");
        if (!sun) {
            scene.lights.push_back(Light{});
            sun = &scene.lights.back();
            sun->name = "command-line sun";
            sun->type = LightType::Directional;
            sun->intensity = 3.0f;
        }
        sun->direction = glm::normalize(*direction);
        if (arguments.has("light-intensity")) sun->intensity = arguments.number("light-intensity", 3.0f, 0.0f, 1e9f);
    }
}

}  // namespace vct
