#include "render/camera.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

namespace vct {

glm::mat4 lookAlong(glm::vec3 eye, glm::vec3 forward, glm::vec3 up) {
    forward = glm::normalize(forward);
    if (std::abs(glm::dot(forward, glm::normalize(up))) > 0.999f)
        up = std::abs(forward.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    return glm::lookAt(eye, eye + forward, up);
}

static float farthestCornerDistance(glm::vec3 from, const Bounds& bounds) {
    float farthest = 0.0f;
    for (int corner = 0; corner < 8; ++corner)
        farthest = std::max(farthest, glm::distance(from, bounds.corner(corner)));
    return farthest;
}

ViewProjection cameraMatrices(const Camera& camera, float aspect, const Bounds& sceneBounds) {
    ViewProjection matrices;
    matrices.view = lookAlong(camera.position, camera.forward, camera.up);
    const float sceneSize = std::max(glm::length(sceneBounds.extent()), 1e-6f);
    float zfar = camera.zfar > 0.0f ? camera.zfar : 1.01f * farthestCornerDistance(camera.position, sceneBounds);
    // Depth precision only needs near/far ≲ 1e5 with a 32-bit float depth buffer.
    float znear = camera.znear > 0.0f ? camera.znear : 1e-4f * sceneSize;
    zfar = std::max(zfar, znear * 2.0f);
    matrices.projection = glm::perspective(camera.yfov, aspect, znear, zfar);
    matrices.projection[1][1] *= -1.0f;  // Vulkan's clip space has y pointing down
    matrices.viewProjection = matrices.projection * matrices.view;
    return matrices;
}

}  // namespace vct
