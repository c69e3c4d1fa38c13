#include "app/scene_overrides.h"

#include <glm/trigonometric.hpp>

#include "error.h"
#include "render/setting_table.h"
#include "scene/default_light.h"
#include "scene/environment_map.h"
#include "scene/scene_limits.h"

namespace vct {
namespace {

constexpr float kMinFov = 1.0f, kMaxFov = 179.0f;
// As bright as a glTF file's sun may be, and the viewer's slider goes.
constexpr float kMaxIlluminance = float(kBrightestRepresentable);
constexpr float kMaxRotation = 3600.0f;  // degrees: ten turns either way

std::vector<SceneOverrideRow> makeSceneOverrideTable() {
    using A = const Arguments&;
    using O = SceneOverrides&;
    return {
        {"camera-pos", "x,y,z", "camera position (overrides the scene's camera)",
         [](A arguments, O overrides) { overrides.cameraPosition = arguments.vector3("camera-pos"); }},
        {"camera-target", "x,y,z", "the point the camera looks at",
         [](A arguments, O overrides) { overrides.cameraTarget = arguments.vector3("camera-target"); }},
        {"fov", "DEGREES",
         "vertical field of view; a number from " + shortNumber(kMinFov) + " to " + shortNumber(kMaxFov),
         [](A arguments, O overrides) {
             if (arguments.has("fov")) overrides.yfovDegrees = arguments.number("fov", 0.0f, kMinFov, kMaxFov);
         }},
        {"light-dir", "x,y,z", "direction the sun's light travels (adds a sun if the scene has none)",
         [](A arguments, O overrides) {
             overrides.lightDirection = arguments.vector3("light-dir");
             if (overrides.lightDirection && glm::length(*overrides.lightDirection) < 1e-6f)
                 throw Error("--light-dir must not be the zero vector");
         }},
        {"light-intensity", "E",
         "illuminance (lux) of the scene's first sun, or of the one --light-dir adds (default " +
             shortNumber(kDefaultSunIlluminance) + "); refused without --light-dir if the scene has no sun",
         [](A arguments, O overrides) {
             if (arguments.has("light-intensity"))
                 overrides.lightIntensity = arguments.number("light-intensity", 0.0f, 0.0f, kMaxIlluminance);
         }},
        {"environment", "R,G,B|FILE.hdr",
         "the sky every ray leaving the scene sees: a uniform radiance, or an equirectangular Radiance "
         "image (its centre looks along -Z, its top up) (default black; a scene without light gets a "
         "default sky with its default sun, unless this names its sky, 0,0,0 included)",
         [](A arguments, O overrides) {
             const std::string environment = arguments.text("environment", "");
             if (namesEnvironmentImage(environment)) {
                 checkEnvironmentImageExists(environment);
                 overrides.environmentImage = environment;
             } else {
                 overrides.environment = arguments.vector3("environment");
                 if (overrides.environment) checkSkyRadiance(*overrides.environment);
             }
         }},
        {"environment-rotation", "DEGREES",
         "turn the --environment image about +Y, counter-clockwise seen from above (default 0)",
         [](A arguments, O overrides) {  // after --environment: it turns that image
             if (!arguments.has("environment-rotation")) return;
             if (overrides.environmentImage.empty())
                 throw Error("--environment-rotation turns an environment image: give --environment FILE.hdr too");
             overrides.environmentRotation =
                 glm::radians(arguments.number("environment-rotation", 0.0f, -kMaxRotation, kMaxRotation));
         }},
    };
}

}  // namespace

const std::vector<SceneOverrideRow>& sceneOverrideTable() {
    static const std::vector<SceneOverrideRow> table = makeSceneOverrideTable();
    return table;
}

SceneOverrides sceneOverridesFromArguments(const Arguments& arguments) {
    SceneOverrides overrides;
    for (const SceneOverrideRow& row : sceneOverrideTable()) row.read(arguments, overrides);
    return overrides;
}

std::string sceneOverridesMarkdown() {
    std::string table = "| option | what it sets |\n| --- | --- |\n";
    for (const SceneOverrideRow& row : sceneOverrideTable())
        table += "| `--" + std::string(row.option) + " " + markdownCell(row.shape) + "` | " + row.help + " |\n";
    return table;
}

}  // namespace vct
