// The camera a scene without one is seen from, the same in vct render, view, bench and the path
// tracer.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace vct {

// A camera that frames the whole scene, for scenes that bring none: 45° vertical field of view,
// from in front (+Z) and a little above the bounds' centre, 2.6 bounding radii away.
Camera defaultCamera(const Bounds& sceneBounds);

// Points the camera from `position` at `target`.
void aimCamera(Camera& camera, glm::vec3 position, glm::vec3 target);

}  // namespace vct
