// What the shared options (app/options.h) say of the scene, the device, the camera and the light.
#pragma once

#include <optional>
#include <set>
#include <string>

#include "app/arguments.h"
#include "app/scene_overrides.h"
#include "gpu/context.h"
#include "render/settings.h"
#include "scene/scene.h"
#include "scene/scene_limits.h"

namespace vct {

// Everything the scene options say that can be checked without loading the scene or a device:
// the overrides' values, and that --scene names a built-in scene or a file that exists (the
// loader checks the file itself). Commands call it before they touch the GPU.
void checkSceneArguments(const Arguments& arguments);
// That `scene` is a built-in scene's name or a file that exists; `option` names where it came from.
void checkSceneName(const std::string& scene, const std::string& option);

// --scene with --strict and --allowed-root, the default sun if the scene has no light (and no
// --light-dir), then the overrides; a file naming more geometry than `limits` allow is refused
// before it is read. The scene's warnings (the default sun's among them) are for the caller to show.
Scene loadSceneFromArguments(const Arguments& arguments, const SceneBufferLimits& limits = {});
// --environment FILE.hdr read (null without one); a file that cannot be is a vct::Error naming it.
std::shared_ptr<const EnvironmentMap> loadEnvironmentImage(const SceneOverrides& overrides);
// "warning: ..." on stderr, one line each.
void printSceneWarnings(const Scene& scene);
ContextOptions contextOptionsFromArguments(const Arguments& arguments);

// The overrides applied to the scene (a scene without a camera gets the default one).
void applySceneOverrides(const SceneOverrides& overrides, Scene& scene);

}  // namespace vct
