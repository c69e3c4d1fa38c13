// The large scenes the cascades are measured on (tools/make_large_scenes.py writes them into
// assets/scenes/): they load, and hold what the issue asks of them.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "scene/load.h"

namespace vct {
namespace {

const std::string kScenes = VCT_TEST_DATA_DIR "/../../assets/scenes/";

glm::vec3 extent(const Scene& scene) { return scene.bounds().max - scene.bounds().min; }

TEST(LargeScenes, TheCourtyardIsABuildingOf40By25By15MetresWithASunLampsAndCurtains) {
    const Scene scene = loadScene(kScenes + "courtyard.gltf");
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    EXPECT_NEAR(extent(scene).x, 40.0f, 1e-3f);
    EXPECT_NEAR(extent(scene).y, 15.3f, 1e-3f);  // with the floor slab under it
    EXPECT_NEAR(extent(scene).z, 25.0f, 1e-3f);
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].type, LightType::Directional);
    EXPECT_LT(scene.lights[0].direction.y, -0.5f);  // the sun stands high enough to reach the floor
    ASSERT_FALSE(scene.cameras.empty());
    int lamps = 0, curtains = 0;
    for (const Material& material : scene.materials) {
        if (glm::length(material.emission) > 0.0f) ++lamps;
        if (material.name.find("curtain") != std::string::npos) {
            ++curtains;
            EXPECT_TRUE(material.doubleSided) << material.name;
        }
    }
    EXPECT_EQ(lamps, 1);
    EXPECT_EQ(curtains, 3);
    EXPECT_GT(scene.triangleCount(), 3000u);  // arches of twelve segments, not boxes
}

TEST(LargeScenes, TheLandscapeSpansAKilometreWithHousesUnderALowSun) {
    const Scene scene = loadScene(kScenes + "landscape.gltf");
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    EXPECT_NEAR(extent(scene).x, 1000.0f, 1e-2f);
    EXPECT_NEAR(extent(scene).z, 1000.0f, 1e-2f);
    EXPECT_LT(extent(scene).y, 40.0f);  // rolling ground, not mountains
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].type, LightType::Directional);
    // Low and from the doors' side (+z), so the sun reaches into the rooms.
    EXPECT_GT(scene.lights[0].direction.y, -0.6f);
    EXPECT_LT(scene.lights[0].direction.z, -0.7f);
    ASSERT_FALSE(scene.cameras.empty());
    EXPECT_LT(glm::length(scene.cameras[0].position), 15.0f);  // beside the first house
}

}  // namespace
}  // namespace vct
