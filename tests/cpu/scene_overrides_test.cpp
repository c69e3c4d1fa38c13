// The camera, sun and sky options (app/scene_overrides.h): read from their rows, refused with the
// option's name, and the README's table the one the rows make.
#include <gtest/gtest.h>

#include <set>

#include "app/scene_overrides.h"
#include "error.h"
#include "readme_tables.h"
#include "scene/scene_limits.h"

namespace vct {
namespace {

Arguments sceneArguments(const std::vector<std::string>& words) {
    std::set<std::string> valued;
    for (const SceneOverrideRow& row : sceneOverrideTable()) valued.insert(row.option);
    return Arguments(words, {}, valued);
}

std::string errorOf(const std::vector<std::string>& words) {
    try {
        sceneOverridesFromArguments(sceneArguments(words));
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

TEST(SceneOverrides, EachRowReadsItsOption) {
    const SceneOverrides overrides = sceneOverridesFromArguments(
        sceneArguments({"--camera-pos", "1,2,3", "--camera-target", "0,1,0", "--fov", "50", "--light-dir", "0,-1,0",
                        "--light-intensity", "7", "--environment", "0.1,0.2,0.3"}));
    EXPECT_EQ(overrides.cameraPosition, glm::vec3(1, 2, 3));
    EXPECT_EQ(overrides.cameraTarget, glm::vec3(0, 1, 0));
    EXPECT_EQ(overrides.yfovDegrees, 50.0f);
    EXPECT_EQ(overrides.lightDirection, glm::vec3(0, -1, 0));
    EXPECT_EQ(overrides.lightIntensity, 7.0f);
    EXPECT_EQ(overrides.environment, glm::vec3(0.1f, 0.2f, 0.3f));
    const SceneOverrides none = sceneOverridesFromArguments(sceneArguments({}));
    EXPECT_FALSE(none.cameraPosition || none.yfovDegrees || none.lightDirection || none.lightIntensity ||
                 none.environment);
}

TEST(SceneOverrides, AWrongValueIsRefusedNamingItsOption) {
    EXPECT_NE(errorOf({"--fov", "180"}).find("--fov must be a number from 1 to 179"), std::string::npos);
    EXPECT_NE(errorOf({"--light-dir", "0,0,0"}).find("--light-dir"), std::string::npos);
    EXPECT_NE(errorOf({"--light-intensity", "-1"}).find("--light-intensity"), std::string::npos);
    EXPECT_NE(errorOf({"--environment-rotation", "90"}).find("give --environment FILE.hdr too"), std::string::npos);
}

// A sun as bright as a glTF file's may be (and the viewer's slider goes): one limit, not two.
TEST(SceneOverrides, TheSunsIlluminanceGoesAsHighAsTheLoadersLimit) {
    const SceneOverrides brightest =
        sceneOverridesFromArguments(sceneArguments({"--light-intensity", std::to_string(kBrightestRepresentable)}));
    EXPECT_EQ(brightest.lightIntensity, float(kBrightestRepresentable));
    EXPECT_NE(errorOf({"--light-intensity", std::to_string(kBrightestRepresentable * 10.0)}).find("--light-intensity"),
              std::string::npos);
}

// The README's table of these options, between its markers. VCT_UPDATE_README=1 writes it instead.
TEST(SceneOverrides, TheReadmesTableIsTheOneTheRowsMake) {
    test::expectReadmeTable("<!-- scene options table: made from src/app/scene_overrides.cpp -->\n",
                            "<!-- end of the scene options table -->", sceneOverridesMarkdown());
}

}  // namespace
}  // namespace vct
