#include "app/scene_setup.h"

#include <cstdio>
#include <sstream>

#include "error.h"
#include "render/camera.h"
#include "render/presets.h"
#include "scene/load.h"

namespace vct {

std::set<std::string> sceneOptionNames() {
    return {"scene",       "width",      "height",     "mode",         "supersample", "camera-pos",
            "camera-target", "fov",      "light-dir",  "light-intensity", "device",   "ambient",
            "shadow-map",  "local-shadow-map", "disable", "allowed-root", "gpu-timeout", "voxels", "cones", "cone-aperture", "cone-step", "voxel-mips", "bounces", "preset"};
}

std::set<std::string> sceneFlagNames() { return {"validate", "strict"}; }

std::string sceneOptionsHelp() {
    std::ostringstream help;
    help << "  --scene FILE|NAME        a .gltf/.glb file or a built-in scene:";
    for (const std::string& name : builtinSceneNames()) help << " " << name;
    help << " (default cornell)\n"
            "  --width W --height H     image size in pixels (default 512×512)\n"
            "  --supersample N          samples per pixel side, averaged over the pixel (default 2)\n"
            "  --mode full|direct|indirect   which light the image holds (default full)\n"
            "  --disable LIST           components to switch off, comma-separated: direct-diffuse,\n"
            "                           direct-specular, indirect-diffuse, indirect-specular, ao, emission, shadows\n"
            "  --ambient F              non-physical ambient light factor (default 0)\n"
            "  --voxels N               voxels per side of the grid, a power of two 32..512 (default 128)\n"
            "  --cones N                diffuse cones (default 6); --cone-aperture DEGREES (default 60)\n"
            "  --cone-step F            cone step as a fraction of its diameter (default 0.5)\n"
            "  --voxel-mips isotropic|anisotropic   one mip chain or six directional ones\n"
            "  --bounces 1|2            2 re-injects the light gathered by the voxels (default 1)\n"
            "  --preset fast|balanced|quality   start from a preset; the options above override it\n"
            "  --camera-pos x,y,z --camera-target x,y,z --fov DEGREES   override the scene camera\n"
            "  --light-dir x,y,z        direction the sun's light travels (adds a sun if the scene has none)\n"
            "  --light-intensity E      that sun's illuminance (default 3)\n"
            "  --shadow-map N           sun shadow-map size (default 4096); --local-shadow-map N for spot/point\n"
            "  --device NAME            use the Vulkan device whose name contains NAME (or $VCT_DEVICE)\n"
            "  --validate               enable the Khronos validation layer\n"
            "  --strict                 treat scene warnings (e.g. a missing texture) as errors\n"
            "  --allowed-root DIR       let the scene's URIs reach files under DIR (default: its folder)\n"
            "  --gpu-timeout SECONDS    longest wait for the GPU before giving up (default 120)\n";
    return help.str();
}

Scene loadSceneFromArguments(const Arguments& arguments) {
    LoadOptions options;
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

RenderSettings renderSettingsFromArguments(const Arguments& arguments) {
    RenderSettings settings;
    if (arguments.has("preset")) {
        const std::optional<RenderSettings> preset = findRenderPreset(arguments.text("preset", ""));
        if (!preset) {
            std::string names;
            for (const auto& [name, unused] : renderPresets()) names += (names.empty() ? "" : ", ") + name;
            throw Error("--preset must be one of " + names + ", not '" + arguments.text("preset", "") + "'");
        }
        settings = *preset;
    }
    settings.width = arguments.unsignedInt("width", settings.width, 1, 16384);
    settings.height = arguments.unsignedInt("height", settings.height, 1, 16384);
    settings.supersample = arguments.unsignedInt("supersample", settings.supersample, 1, 8);
    const std::string modeName = arguments.text("mode", "full");
    const std::optional<RenderMode> mode = parseRenderMode(modeName);
    if (!mode) throw Error("--mode must be full, direct or indirect, not '" + modeName + "'");
    settings.mode = *mode;
    settings.ambientFactor = arguments.number("ambient", 0.0f, 0.0f, 1e6f);
    settings.sunShadowMapSize = arguments.unsignedInt("shadow-map", settings.sunShadowMapSize, 16, 16384);
    settings.localShadowMapSize = arguments.unsignedInt("local-shadow-map", settings.localShadowMapSize, 16, 16384);

    settings.voxelResolution = arguments.unsignedInt("voxels", settings.voxelResolution, 32, 512);
    settings.diffuseConeCount = arguments.unsignedInt("cones", settings.diffuseConeCount, 1, 32);
    settings.diffuseConeAperture = arguments.number("cone-aperture", settings.diffuseConeAperture, 1.0f, 120.0f);
    settings.coneStep = arguments.number("cone-step", settings.coneStep, 0.05f, 4.0f);
    settings.bounces = arguments.unsignedInt("bounces", settings.bounces, 1, 2);
    const std::string mips = arguments.text("voxel-mips", settings.anisotropicVoxels ? "anisotropic" : "isotropic");
    if (mips != "isotropic" && mips != "anisotropic")
        throw Error("--voxel-mips must be isotropic or anisotropic, not '" + mips + "'");
    settings.anisotropicVoxels = mips == "anisotropic";

    std::istringstream disabled(arguments.text("disable", ""));
    for (std::string name; std::getline(disabled, name, ',');) {
        Components& c = settings.components;
        if (name == "direct-diffuse") c.directDiffuse = false;
        else if (name == "direct-specular") c.directSpecular = false;
        else if (name == "indirect-diffuse") c.indirectDiffuse = false;
        else if (name == "indirect-specular") c.indirectSpecular = false;
        else if (name == "ao") c.ambientOcclusion = false;
        else if (name == "emission") c.emission = false;
        else if (name == "shadows") c.shadows = false;
        else if (!name.empty()) throw Error("--disable: unknown component '" + name + "'");
    }
    return settings;
}

void applyCameraAndLightOverrides(const Arguments& arguments, Scene& scene) {
    if (scene.cameras.empty()) scene.cameras.push_back(defaultCamera(scene.bounds()));
    Camera& camera = scene.cameras.front();
    const std::optional<glm::vec3> position = arguments.vector3("camera-pos");
    const std::optional<glm::vec3> target = arguments.vector3("camera-target");
    if (position || target)
        aimCamera(camera, position.value_or(camera.position), target.value_or(camera.position + camera.forward));
    if (arguments.has("fov")) camera.yfov = glm::radians(arguments.number("fov", 45.0f, 1.0f, 179.0f));

    if (const std::optional<glm::vec3> direction = arguments.vector3("light-dir")) {
        if (glm::length(*direction) < 1e-6f) throw Error("--light-dir must not be the zero vector");
        Light* sun = nullptr;
        for (Light& light : scene.lights)
            if (light.type == LightType::Directional) sun = sun ? sun : &light;
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
