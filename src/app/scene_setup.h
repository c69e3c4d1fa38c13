// What the shared options (app/options.h) say of the scene, the device, the camera and the light.
#pragma once

#include <set>
#include <string>

#include "app/arguments.h"
#include "gpu/context.h"
#include "render/settings.h"
#include "scene/scene.h"
#include "scene/scene_limits.h"

namespace vct {

// --scene with --strict and --allowed-root; a file naming more geometry than `limits` allow is
// refused before it is read.
Scene loadSceneFromArguments(const Arguments& arguments, const SceneBufferLimits& limits = {});
ContextOptions contextOptionsFromArguments(const Arguments& arguments);

// --camera-pos/--camera-target/--fov and --light-dir/--light-intensity applied to the scene.
void applyCameraAndLightOverrides(const Arguments& arguments, Scene& scene);

}  // namespace vct
