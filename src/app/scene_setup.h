// What the shared options (app/options.h) say of the scene, the device, the camera and the light.
#pragma once

#include <set>
#include <string>

#include "app/arguments.h"
#include "gpu/context.h"
#include "render/settings.h"
#include "scene/scene.h"

namespace vct {

Scene loadSceneFromArguments(const Arguments& arguments);
ContextOptions contextOptionsFromArguments(const Arguments& arguments);

// --camera-pos/--camera-target/--fov and --light-dir/--light-intensity applied to the scene.
void applyCameraAndLightOverrides(const Arguments& arguments, Scene& scene);

}  // namespace vct
