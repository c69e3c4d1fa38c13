// Camera matrices for Vulkan (depth 0..1, y down in clip space) from a glTF-style camera.
#pragma once

#include <glm/glm.hpp>

#include "scene/default_camera.h"
#include "scene/scene.h"

namespace vct {

struct ViewProjection {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::mat4 viewProjection{1.0f};
};

// A view matrix looking from `eye` along `forward`, robust to `up` parallel to `forward`.
glm::mat4 lookAlong(glm::vec3 eye, glm::vec3 forward, glm::vec3 up);

// The camera's matrices for an image of the given aspect ratio. Near and far are the camera's
// own when it has them; an infinite glTF far plane is fitted to the scene bounds.
ViewProjection cameraMatrices(const Camera& camera, float aspect, const Bounds& sceneBounds);

}  // namespace vct
