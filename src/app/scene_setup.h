// Options shared by `render`, `view` and `bench`: which scene, which device, which camera and light.
#pragma once

#include <set>
#include <string>

#include "app/arguments.h"
#include "gpu/context.h"
#include "render/settings.h"
#include "scene/scene.h"

namespace vct {

// Option names understood by the functions below.
std::set<std::string> sceneOptionNames();
std::set<std::string> sceneFlagNames();
std::string sceneOptionsHelp();

Scene loadSceneFromArguments(const Arguments& arguments);
ContextOptions contextOptionsFromArguments(const Arguments& arguments);
RenderSettings renderSettingsFromArguments(const Arguments& arguments);

// --camera-pos/--camera-target/--fov and --light-dir/--light-intensity applied to the scene.
void applyCameraAndLightOverrides(const Arguments& arguments, Scene& scene);

}  // namespace vct
