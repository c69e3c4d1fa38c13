#include "scene/default_camera.h"

#include <algorithm>

namespace vct {

Camera defaultCamera(const Bounds& sceneBounds) {
    Camera camera;
    camera.name = "default camera";
    const float radius = std::max(0.5f * glm::length(sceneBounds.extent()), 1e-3f);
    camera.yfov = glm::radians(45.0f);
    camera.znear = radius * 1e-3f;
    aimCamera(camera, sceneBounds.center() + glm::vec3(0.0f, 0.3f, 1.0f) * (radius * 2.6f), sceneBounds.center());
    return camera;
}

void aimCamera(Camera& camera, glm::vec3 position, glm::vec3 target) {
    camera.position = position;
    const glm::vec3 direction = target - position;
    camera.forward = glm::length(direction) > 0.0f ? glm::normalize(direction) : glm::vec3(0, 0, -1);
    camera.up = glm::vec3(0, 1, 0);
}

}  // namespace vct
