// The suns' shadow cascades (src/render/sun_cascades.h): where they are needed, that each holds
// its slice of the view and every occluder towards the sun, and that their texel grids stay put
// when the camera moves.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/glm.hpp>

#include "render/sun_cascades.h"

namespace vct {
namespace {

// A camera 1.6 m above the middle of a 1 km landscape, looking along +x and a little down.
CascadeView landscapeView(float nearestGeometry) {
    CascadeView view;
    view.camera.position = glm::vec3(0.0f, 1.6f, 0.0f);
    view.camera.forward = glm::normalize(glm::vec3(1.0f, -0.1f, 0.2f));
    view.camera.yfov = glm::radians(60.0f);
    view.aspect = 16.0f / 9.0f;
    view.imageHeight = 540;
    view.nearestGeometry = nearestGeometry;
    return view;
}

const Bounds kLandscape{{-500.0f, -20.0f, -500.0f}, {500.0f, 40.0f, 500.0f}};
const uint32_t kMapSize = 4096;
// The scene-fitted map's texel: its sphere's diameter over the map.
const float kSceneTexel = glm::length(kLandscape.extent()) / float(kMapSize);
const glm::vec3 kSun = glm::normalize(glm::vec3(0.4f, -0.5f, 0.3f));

glm::vec3 mapCoordinates(const glsl::ShadowView& view, glm::vec3 point) {
    const glm::vec4 clip = view.viewProjection * glm::vec4(point, 1.0f);
    return glm::vec3(glm::vec2(clip) / clip.w * 0.5f + 0.5f, clip.z / clip.w);
}

// The corners of the camera's view between two distances along its axis.
std::vector<glm::vec3> sliceCorners(const CascadeView& view, float nearDistance, float farDistance) {
    const glm::vec3 forward = glm::normalize(view.camera.forward);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    const glm::vec3 up = glm::cross(right, forward);
    const float tanHalf = std::tan(0.5f * view.camera.yfov);
    std::vector<glm::vec3> corners;
    for (float distance : {nearDistance, farDistance})
        for (float x : {-1.0f, 1.0f})
            for (float y : {-1.0f, 1.0f})
                corners.push_back(view.camera.position +
                                  distance * (forward + x * tanHalf * view.aspect * right + y * tanHalf * up));
    return corners;
}

TEST(SunCascades, NoneWhereTheSceneFittedMapIsFineEnoughForTheNearestGeometry) {
    // d*: where the scene-fitted map's texel covers one pixel.
    const CascadeView view = landscapeView(0.0f);
    const float matched = kSceneTexel / (2.0f * std::tan(0.5f * view.camera.yfov) / float(view.imageHeight));
    EXPECT_TRUE(cascadeDistances(landscapeView(1.01f * matched), kSceneTexel, 4).empty());
    EXPECT_TRUE(cascadeDistances(landscapeView(0.5f), kSceneTexel, 0).empty()) << "0 cascades asked for";

    const std::vector<float> one = cascadeDistances(landscapeView(0.5f * matched), kSceneTexel, 4);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_FLOAT_EQ(one[0], matched);
    const std::vector<float> two = cascadeDistances(landscapeView(0.2f * matched), kSceneTexel, 4);
    ASSERT_EQ(two.size(), 2u);
    EXPECT_FLOAT_EQ(two[0], 0.25f * matched);
    EXPECT_FLOAT_EQ(two[1], matched);
    EXPECT_EQ(cascadeDistances(landscapeView(1e-3f), kSceneTexel, 4).size(), 4u) << "at most as many as asked for";
}

TEST(SunCascades, EachHoldsItsSliceAndEveryOccluderTowardsTheSun) {
    const CascadeView view = landscapeView(0.3f);
    const std::vector<float> distances = cascadeDistances(view, kSceneTexel, 4);
    ASSERT_EQ(distances.size(), 4u);
    float nearDistance = 0.0f, lastTexel = 0.0f;
    for (float farDistance : distances) {
        // Drawn into the last of four tiles of its layer.
        const glsl::ShadowView shadow =
            cascadeShadowView(kSun, view, nearDistance, farDistance, kLandscape, kMapSize / 2, kMapSize, 3);
        EXPECT_FLOAT_EQ(shadow.depthRange.z, 0.5f);
        EXPECT_EQ(glsl::shadowTileCorner(shadow), glm::vec2(0.5f, 0.5f)) << "the fourth of four tiles";
        for (const glm::vec3& corner : sliceCorners(view, nearDistance, farDistance)) {
            const glm::vec3 map = mapCoordinates(shadow, corner);
            EXPECT_GE(map.x, 0.5f);
            EXPECT_LE(map.x, 1.0f);
            EXPECT_GE(map.y, 0.5f);
            EXPECT_LE(map.y, 1.0f);
        }
        // Every corner of the scene lies between the map's near and far planes: a mountain outside
        // the slice still shadows it.
        for (int corner = 0; corner < 8; ++corner) {
            const float depth = mapCoordinates(shadow, kLandscape.corner(corner)).z;
            EXPECT_GT(depth, 0.0f);
            EXPECT_LT(depth, 1.0f);
        }
        EXPECT_GT(shadow.params.z, lastTexel) << "each cascade coarser than the one inside it";
        EXPECT_LT(shadow.params.z, kSceneTexel) << "and finer than the scene-fitted map";
        lastTexel = shadow.params.z;
        nearDistance = farDistance;
    }
}

TEST(SunCascades, AMapHasEightTexelsAPixelAtMostTheLayersSize) {
    EXPECT_EQ(cascadeMapSize(128, 4096), 1024u);
    EXPECT_EQ(cascadeMapSize(300, 4096), 4096u);
    EXPECT_EQ(cascadeMapSize(540, 2048), 2048u);
    EXPECT_EQ(cascadeMapSize(1, 4096), 16u);
}

TEST(SunCascades, AMovingCameraShiftsTheTexelGridByWholeTexels) {
    CascadeView view = landscapeView(0.3f);
    const glsl::ShadowView before = cascadeShadowView(kSun, view, 0.0f, 20.0f, kLandscape, kMapSize, kMapSize, 0);
    view.camera.position += glm::vec3(0.137f, 0.05f, -0.291f);
    const glsl::ShadowView after = cascadeShadowView(kSun, view, 0.0f, 20.0f, kLandscape, kMapSize, kMapSize, 0);
    ASSERT_FLOAT_EQ(before.params.z, after.params.z) << "the same slice: the same texel";
    const glm::vec3 point(3.0f, 0.5f, 1.0f);
    const glm::vec2 shift =
        (glm::vec2(mapCoordinates(after, point)) - glm::vec2(mapCoordinates(before, point))) * float(kMapSize);
    EXPECT_GT(glm::length(shift), 1.0f) << "the camera moved several texels";
    EXPECT_NEAR(shift.x, std::round(shift.x), 0.02f);
    EXPECT_NEAR(shift.y, std::round(shift.y), 0.02f);
}

TEST(SunCascades, TheNearestGeometryIsTheNearestTrianglesBox) {
    Scene scene;
    for (const glm::vec3 position : {glm::vec3(2, 0, 0), glm::vec3(3, 1, 0), glm::vec3(2, 1, 1)}) {
        Vertex vertex;
        vertex.position = position;
        scene.vertices.push_back(vertex);
    }
    scene.indices = {0, 1, 2};
    const std::vector<Bounds> boxes = triangleBoxes(scene);
    ASSERT_EQ(boxes.size(), 1u);
    EXPECT_FLOAT_EQ(nearestBoxDistance(boxes, glm::vec3(0.0f, 0.5f, 0.5f)), 2.0f);
    EXPECT_FLOAT_EQ(nearestBoxDistance(boxes, glm::vec3(2.5f, 0.5f, 0.5f)), 0.0f) << "inside the box";
    EXPECT_TRUE(std::isinf(nearestBoxDistance({}, glm::vec3(0.0f))));
}

}  // namespace
}  // namespace vct
