// The camera a scene without one is seen from (vct render, view, bench and vct_pathtrace alike).
#include <cmath>

#include <gtest/gtest.h>

#include "scene/default_camera.h"

namespace vct {
namespace {

TEST(DefaultCamera, FramesEveryCornerOfTheSceneInASquareImage) {
    for (const Bounds bounds : {Bounds{glm::vec3(-1.0f), glm::vec3(1.0f)},
                                Bounds{glm::vec3(10.0f, 0.0f, -3.0f), glm::vec3(10.5f, 4.0f, -2.0f)},
                                Bounds{glm::vec3(-100.0f, -0.01f, -100.0f), glm::vec3(100.0f, 0.01f, 100.0f)}}) {
        const Camera camera = defaultCamera(bounds);
        const glm::vec3 right = glm::normalize(glm::cross(camera.forward, camera.up));
        const glm::vec3 up = glm::cross(right, camera.forward);
        const float tanHalf = std::tan(0.5f * camera.yfov);
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 toPoint = bounds.corner(corner) - camera.position;
            const float depth = glm::dot(toPoint, camera.forward);
            ASSERT_GT(depth, camera.znear) << corner;
            EXPECT_LE(std::abs(glm::dot(toPoint, right)) / depth, tanHalf) << corner;
            EXPECT_LE(std::abs(glm::dot(toPoint, up)) / depth, tanHalf) << corner;
        }
    }
}

}  // namespace
}  // namespace vct
