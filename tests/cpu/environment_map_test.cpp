// Environment images (--environment FILE.hdr): where a direction reads them, how they are loaded,
// and how a bad file is refused; the path tracer's escaping rays read them.
#include <gtest/gtest.h>

#include <stb/stb_image_write.h>

#include <cmath>

#include "environment_images.h"
#include "equirectangular.h"
#include "error.h"
#include "gltf_test_helpers.h"
#include "path_tracer.h"
#include "sampling.h"
#include "scene/scene.h"

namespace vct {
namespace {

using test::TempFolder;

TEST(Equirectangular, TheCentreLooksAlongMinusZWithPlusXToTheRightAndUpOnTop) {
    auto expectAt = [](glm::vec3 direction, glm::vec2 expected) {
        const glm::vec2 uv = glsl::equirectangularCoordinates(glm::normalize(direction), 0.0f);
        EXPECT_NEAR(uv.x, expected.x, 1e-6f) << direction.x << "," << direction.y << "," << direction.z;
        EXPECT_NEAR(uv.y, expected.y, 1e-6f) << direction.x << "," << direction.y << "," << direction.z;
    };
    expectAt({0, 0, -1}, {0.5f, 0.5f});
    expectAt({1, 0, 0}, {0.75f, 0.5f});
    expectAt({-1, 0, 0}, {0.25f, 0.5f});
    // At the poles every u is the same direction: only v is asked.
    EXPECT_EQ(glsl::equirectangularCoordinates(glm::vec3(0, 1, 0), 0.0f).y, 0.0f);
    EXPECT_NEAR(glsl::equirectangularCoordinates(glm::vec3(0, -1, 0), 0.0f).y, 1.0f, 1e-6f);
    expectAt({0, 1, -1}, {0.5f, 0.25f});
    // A cone as wide as a texel reads level 0, one twice as wide level 1.
    const float texel = 2.0f * 3.14159265f / 1024.0f;
    EXPECT_NEAR(glsl::equirectangularLevel(std::tan(0.5f * texel), 1024.0f), 0.0f, 1e-4f);
    EXPECT_NEAR(glsl::equirectangularLevel(std::tan(texel), 1024.0f), 1.0f, 1e-3f);
}

TEST(Equirectangular, ATurnedImageShowsAlongADirectionWhatItShowedThatFarRoundBefore) {
    // A quarter turn counter-clockwise seen from above brings what the image showed along −Z (its
    // centre) to −X, and what it showed along +X to −Z; the turn in radians wraps to [0, 1) turns.
    EXPECT_NEAR(glsl::equirectangularCoordinates(glm::vec3(-1, 0, 0), 0.25f).x, 0.5f, 1e-6f);
    EXPECT_NEAR(glsl::equirectangularCoordinates(glm::vec3(0, 0, -1), 0.25f).x, 0.75f, 1e-6f);
    EXPECT_NEAR(environmentTurns(0.5f * 3.14159265f), 0.25f, 1e-6f);
    EXPECT_NEAR(environmentTurns(-0.5f * 3.14159265f), 0.75f, 1e-6f);
    EXPECT_NEAR(environmentTurns(4.5f * 3.14159265f), 0.25f, 1e-6f);
    const auto map = test::redLeftGreenRightSky();
    const glm::vec3 ahead = glm::normalize(glm::vec3(0, 0.5f, -1));
    EXPECT_EQ(environmentRadiance(*map, ahead, 0.5f * 3.14159265f), glm::vec3(0, 1, 0)) << "+X's green ahead";
    EXPECT_EQ(environmentRadiance(*map, ahead, -0.5f * 3.14159265f), glm::vec3(1, 0, 0)) << "-X's red ahead";
    const glm::vec3 right = glm::normalize(glm::vec3(1, 0.5f, -1));
    EXPECT_EQ(environmentRadiance(*map, right, 3.14159265f), glm::vec3(1, 0, 0)) << "half a turn swaps the halves";
}

TEST(EnvironmentMap, ADirectionReadsItsTexelAndBlendsBilinearlyBetweenCentres) {
    const auto map = test::redLeftGreenRightSky();
    const glm::vec3 left = environmentRadiance(*map, glm::normalize(glm::vec3(-1, 0.5f, -1)), 0.0f);
    const glm::vec3 right = environmentRadiance(*map, glm::normalize(glm::vec3(1, 0.5f, -1)), 0.0f);
    EXPECT_EQ(left, glm::vec3(1, 0, 0));
    EXPECT_EQ(right, glm::vec3(0, 1, 0));
    EXPECT_EQ(environmentRadiance(*map, glm::vec3(0, -1, 0), 0.0f), glm::vec3(0.0f));
    // On the meridian, u = ½, half way between the centres of texels 31 and 32.
    const glm::vec3 meridian = environmentRadiance(*map, glm::normalize(glm::vec3(0, 0.5f, -1)), 0.0f);
    EXPECT_NEAR(meridian.r, 0.5f, 1e-5f);
    EXPECT_NEAR(meridian.g, 0.5f, 1e-5f);
    // Half the sphere is black, the upper half half red and half green.
    const glm::vec3 mean = meanEnvironmentRadiance(*map);
    EXPECT_NEAR(mean.r, 0.25f, 1e-3f);
    EXPECT_NEAR(mean.g, 0.25f, 1e-3f);
}

TEST(EnvironmentMap, AnHdrFileIsReadAsTheRadianceItHolds) {
    TempFolder folder;
    const std::string path = (folder.path / "sky.HDR").string();
    // Radiance's shared-exponent format holds these exactly: powers of two, and ½ + ¼.
    const float texels[2 * 4 * 3] = {1,     2,    4, 0.5f, 0.75f, 8, 0, 0, 0, 16, 16, 16,
                                     0.25f, 0.5f, 1, 3,    0,     0, 1, 1, 1, 0,  0,  0.125f};
    ASSERT_TRUE(stbi_write_hdr(path.c_str(), 4, 2, 3, texels));
    EXPECT_TRUE(namesEnvironmentImage(path));
    EXPECT_FALSE(namesEnvironmentImage("0.2,0.4,0.8"));
    const EnvironmentMap map = loadEnvironmentMap(path);
    ASSERT_EQ(map.width, 4u);
    ASSERT_EQ(map.height, 2u);
    for (uint32_t i = 0; i < 8; ++i)
        EXPECT_EQ(map.texel(i % 4, i / 4), glm::vec3(texels[3 * i], texels[3 * i + 1], texels[3 * i + 2])) << i;
}

TEST(EnvironmentMap, AFileThatIsNotAnHdrImageIsRefusedNamingIt) {
    TempFolder folder;
    auto expectRefused = [](const std::string& path, const std::string& why) {
        try {
            loadEnvironmentMap(path);
            ADD_FAILURE() << path << " was read";
        } catch (const Error& error) {
            const std::string message = error.what();
            EXPECT_NE(message.find(path), std::string::npos) << message;
            EXPECT_NE(message.find(why), std::string::npos) << message;
        }
    };
    expectRefused((folder.path / "missing.hdr").string(), "not found");
    expectRefused(folder.write("noise.hdr", "#?RADIANCE\nthis is not a picture").string(), "not an image");
    const std::string png = test::encodePng(2, 2, 4, 8, std::vector<uint16_t>(16, 255));
    expectRefused(folder.write("photo.hdr", png).string(), "not a Radiance .hdr image");
    expectRefused(folder.write("huge.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 100000\n").string(),
                  "more than the");
}

TEST(PathTracerEnvironment, ARayLeavingTheSceneSeesTheImageAlongItsDirection) {
    Scene scene;
    scene.name = "nothing but sky";
    scene.environment = glm::vec3(2.0f);  // the factor on the image
    scene.environmentMap = test::redLeftGreenRightSky();
    for (const float rotation : {0.0f, 2.0f}) {  // turned about +Y by `rotation` radians
        scene.environmentRotation = rotation;
        const pt::PathTracer tracer = pt::createPathTracer(scene);
        pt::Rng rng = pt::Rng::forSample(1, 0, 0);
        for (const glm::vec3 direction : {glm::vec3(-1, 0.3f, -1), glm::vec3(1, 0.3f, -1), glm::vec3(0.2f, -1, 0.4f)}) {
            const glm::vec3 unit = glm::normalize(direction);
            const glm::vec3 seen =
                pt::tracePath(tracer, pt::Ray{glm::vec3(0.0f), unit, 1e30f}, pt::Component::Full, rng);
            const glm::vec3 expected = 2.0f * environmentRadiance(*scene.environmentMap, unit, rotation);
            EXPECT_EQ(seen, expected) << direction.x << "," << direction.y << "," << direction.z << " turned "
                                      << rotation;
        }
    }
}

}  // namespace
}  // namespace vct
