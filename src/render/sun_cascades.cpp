#include "render/sun_cascades.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "render/camera.h"

namespace vct {

std::vector<float> cascadeDistances(const CascadeView& view, float sceneTexel, uint32_t maxCascades) {
    const float pixelAngle = 2.0f * std::tan(0.5f * view.camera.yfov) / float(std::max(view.imageHeight, 1u));
    const float matched = sceneTexel / pixelAngle;  // d*: beyond it the scene-fitted map is fine enough
    if (maxCascades == 0 || !(view.nearestGeometry < matched)) return {};
    // Slices a quarter as deep as the next keep a cascade's texel within a few times the pixel at its
    // near end; enough of them that the finest one reaches the nearest geometry.
    const float ratio = matched / std::max(view.nearestGeometry, 1e-6f * matched);
    const uint32_t count = std::min(maxCascades, 1u + uint32_t(std::floor(std::log(ratio) / std::log(4.0f))));
    std::vector<float> distances;
    for (uint32_t j = count; j-- > 0;) distances.push_back(matched / std::pow(4.0f, float(j)));
    return distances;
}

glsl::ShadowView cascadeShadowView(glm::vec3 direction, const CascadeView& view, float nearDistance, float farDistance,
                                   const Bounds& sceneBounds, uint32_t mapSize, uint32_t layerSize, uint32_t tile) {
    direction = glm::normalize(direction);
    // The slice's bounding sphere: its centre on the view axis, equally far from the near and the
    // far corners (a and b along the axis, k·a and k·b off it), no farther out than the far plane.
    // It depends on the slice alone, not on where the camera looks, so turning does not resize it.
    const float a = nearDistance, b = farDistance;
    const float k2 = std::pow(std::tan(0.5f * view.camera.yfov), 2.0f) * (1.0f + view.aspect * view.aspect);
    const float along = std::min(0.5f * (a + b) * (1.0f + k2), b);
    const float radius =
        std::max(std::sqrt((b - along) * (b - along) + k2 * b * b), std::sqrt((along - a) * (along - a) + k2 * a * a));
    const glm::vec3 centre = view.camera.position + glm::normalize(view.camera.forward) * along;

    // Snap the centre to the map's texel grid across the light, so the grid stays put in the world.
    const float texel = 2.0f * radius / float(mapSize);
    const glm::mat3 toLight(lookAlong(glm::vec3(0.0f), direction, glm::vec3(0, 1, 0)));
    glm::vec3 inLight = toLight * centre;
    inLight.x = std::floor(inLight.x / texel) * texel;
    inLight.y = std::floor(inLight.y / texel) * texel;
    const glm::vec3 snapped = glm::transpose(toLight) * inLight;

    // In depth, the whole scene along the light: an occluder outside the slice still casts into it.
    float lowest = std::numeric_limits<float>::max(), highest = -lowest;
    for (int corner = 0; corner < 8; ++corner) {
        lowest = std::min(lowest, glm::dot(sceneBounds.corner(corner), direction));
        highest = std::max(highest, glm::dot(sceneBounds.corner(corner), direction));
    }
    const float pad = 0.01f * (highest - lowest) + radius * 1e-3f;
    const glm::vec3 eye = snapped + direction * (lowest - pad - glm::dot(snapped, direction));

    // Clip space scaled into the tile: x, y from [−1, 1] to [2·corner − 1, 2·(corner + share) − 1].
    glsl::ShadowView shadowView{};
    const float share = float(mapSize) / float(layerSize);
    shadowView.depthRange = glm::vec4(0.0f, 0.0f, share, float(tile));
    const glm::vec2 corner = glsl::shadowTileCorner(shadowView);
    glm::mat4 intoTile(1.0f);
    intoTile[0][0] = intoTile[1][1] = share;
    intoTile[3][0] = 2.0f * corner.x + share - 1.0f;
    intoTile[3][1] = 2.0f * corner.y + share - 1.0f;
    shadowView.viewProjection =
        intoTile * glm::ortho(-radius, radius, -radius, radius, 0.5f * pad, highest - lowest + 1.5f * pad) *
        lookAlong(eye, direction, glm::vec3(0, 1, 0));
    shadowView.params = glm::vec4(0.0f, 0.0f, texel, 0.0f);  // the caller places it in an array
    return shadowView;
}

uint32_t cascadeMapSize(uint32_t imageHeight, uint32_t layerSize) {
    uint32_t size = 16;
    while (size < 8 * imageHeight && size < layerSize) size *= 2;
    return std::min(size, layerSize);
}

std::vector<Bounds> triangleBoxes(const Scene& scene) {
    std::vector<Bounds> boxes;
    boxes.reserve(scene.indices.size() / 3);
    for (size_t i = 0; i + 2 < scene.indices.size(); i += 3) {
        Bounds box{scene.vertices[scene.indices[i]].position, scene.vertices[scene.indices[i]].position};
        for (size_t corner = 1; corner < 3; ++corner) {
            box.min = glm::min(box.min, scene.vertices[scene.indices[i + corner]].position);
            box.max = glm::max(box.max, scene.vertices[scene.indices[i + corner]].position);
        }
        boxes.push_back(box);
    }
    return boxes;
}

float nearestBoxDistance(const std::vector<Bounds>& boxes, glm::vec3 point) {
    float nearest = std::numeric_limits<float>::infinity();
    for (const Bounds& box : boxes) {
        const glm::vec3 outside = glm::max(glm::max(box.min - point, point - box.max), glm::vec3(0.0f));
        nearest = std::min(nearest, glm::dot(outside, outside));
    }
    return std::sqrt(nearest);
}

}  // namespace vct
