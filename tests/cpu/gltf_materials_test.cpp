// glTF materials beyond the base colour: emissive textures, the light a scene without any gets, and
// the warnings for extensions that change how a model looks.
#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include "gltf_test_helpers.h"
#include "scene/default_light.h"
#include "scene/load.h"
#include "scene/material_textures.h"

namespace vct {
namespace {

using test::GltfBuilder;
using test::json;
using test::TempFolder;

Scene loadBuilt(GltfBuilder& gltf) {
    TempFolder folder;
    return loadGltf(gltf.writeGltf(folder, "scene").string());
}

// The quad glowing with emissiveFactor (2, 1, 0.5) through a texture black on its left half.
GltfBuilder emissiveQuad() {
    GltfBuilder gltf = test::quadFacingCamera();
    gltf.document["images"] = json::array({{{"uri", test::halfBlackHalfWhitePngUri(8)}}});
    gltf.document["textures"] = json::array({{{"source", 0}}});
    gltf.document["materials"][0] = {{"emissiveFactor", {2.0, 1.0, 0.5}}, {"emissiveTexture", {{"index", 0}}}};
    return gltf;
}

TEST(EmissiveTexture, IsDecodedAsAColourTextureOfTheMaterial) {
    GltfBuilder gltf = emissiveQuad();
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.materials[0].emissiveTexture.index, 0);
    EXPECT_EQ(scene.materials[0].baseColorTexture.index, -1);
    EXPECT_EQ(scene.materials[0].emission, glm::vec3(2.0f, 1.0f, 0.5f));
    EXPECT_EQ(scene.textures[0].width, 8u);
    EXPECT_EQ(scene.textures[0].rgba8[0], 0);
    EXPECT_EQ(scene.textures[0].rgba8[4 * 7], 255);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings[0];
}

TEST(EmissiveTexture, SharesTheImageWithABaseColourTextureNamingIt) {
    GltfBuilder gltf = emissiveQuad();
    gltf.document["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}}};
    const Scene scene = loadBuilt(gltf);
    EXPECT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.materials[0].baseColorTexture.index, 0);
    EXPECT_EQ(scene.materials[0].emissiveTexture.index, 0);
}

TEST(EmissiveTexture, AnImageThatCannotBeReadFallsBackToTheFactorWithAWarning) {
    GltfBuilder gltf = emissiveQuad();
    gltf.document["images"][0]["uri"] = "missing.png";
    const Scene scene = loadBuilt(gltf);
    EXPECT_EQ(scene.materials[0].emissiveTexture.index, -1);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("falls back to its emissive factor"), std::string::npos) << scene.warnings[0];
}

TEST(TextureSampler, WrapModesAndMagnificationReachTheTextureAndSplitAnImageUsedThroughTwo) {
    // The emissive texture clamps along u and mirrors along v, magnified nearest; the base colour
    // reads the same image through no sampler: repeat both ways, linear.
    GltfBuilder gltf = emissiveQuad();
    gltf.document["samplers"] = json::array({{{"wrapS", 33071}, {"wrapT", 33648}, {"magFilter", 9728}}});
    gltf.document["textures"] = json::array({{{"source", 0}, {"sampler", 0}}, {{"source", 0}}});
    gltf.document["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 1}}}};
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.textures.size(), 2u);
    const Texture& emissive = scene.textures[size_t(scene.materials[0].emissiveTexture.index)];
    const Texture& baseColor = scene.textures[size_t(scene.materials[0].baseColorTexture.index)];
    EXPECT_EQ(emissive.wrapS, TextureWrap::ClampToEdge);
    EXPECT_EQ(emissive.wrapT, TextureWrap::MirroredRepeat);
    EXPECT_TRUE(emissive.nearestMagnification);
    EXPECT_EQ(baseColor.wrapS, TextureWrap::Repeat);
    EXPECT_EQ(baseColor.wrapT, TextureWrap::Repeat);
    EXPECT_FALSE(baseColor.nearestMagnification);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings[0];
}

TEST(TextureSampler, WrapTexelRepeatsClampsAndMirrors) {
    // Four texels: 0 1 2 3 | repeat 0 1 2 3, clamp 3 3 3 3, mirror 3 2 1 0; and before texel 0.
    const uint32_t repeat[] = {0, 1, 2, 3, 0, 1}, clamp[] = {0, 1, 2, 3, 3, 3}, mirror[] = {0, 1, 2, 3, 3, 2};
    for (int i = 0; i < 6; ++i) {
        EXPECT_EQ(wrapTexel(i, 4, TextureWrap::Repeat), repeat[i]) << i;
        EXPECT_EQ(wrapTexel(i, 4, TextureWrap::ClampToEdge), clamp[i]) << i;
        EXPECT_EQ(wrapTexel(i, 4, TextureWrap::MirroredRepeat), mirror[i]) << i;
    }
    EXPECT_EQ(wrapTexel(-1, 4, TextureWrap::Repeat), 3u);
    EXPECT_EQ(wrapTexel(-1, 4, TextureWrap::ClampToEdge), 0u);
    EXPECT_EQ(wrapTexel(-1, 4, TextureWrap::MirroredRepeat), 0u);
    EXPECT_EQ(wrapTexel(-5, 4, TextureWrap::MirroredRepeat), 3u);
    EXPECT_EQ(wrapTexel(1e300, 4, TextureWrap::Repeat), 0u);  // far out: some texel, no overflow
    EXPECT_EQ(wrapTexel(std::nan(""), 4, TextureWrap::MirroredRepeat), 0u);
}

TEST(MetallicRoughnessTexture, IsDecodedAsLinearDataBesideTheSameImageAsColour) {
    // One image used as the emissive (sRGB) and the metallic-roughness (linear) texture: two scene
    // textures, each with its own encoding, both holding the image's bytes as they are.
    GltfBuilder gltf = emissiveQuad();
    gltf.document["materials"][0]["pbrMetallicRoughness"] = {{"metallicRoughnessTexture", {{"index", 0}}}};
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.textures.size(), 2u);
    const Material& material = scene.materials[0];
    ASSERT_GE(material.metallicRoughnessTexture.index, 0);
    ASSERT_GE(material.emissiveTexture.index, 0);
    EXPECT_NE(material.metallicRoughnessTexture.index, material.emissiveTexture.index);
    EXPECT_FALSE(scene.textures[size_t(material.metallicRoughnessTexture.index)].srgb);
    EXPECT_TRUE(scene.textures[size_t(material.emissiveTexture.index)].srgb);
    EXPECT_EQ(scene.textures[size_t(material.metallicRoughnessTexture.index)].rgba8,
              scene.textures[size_t(material.emissiveTexture.index)].rgba8);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings[0];
}

TEST(NormalTexture, IsDecodedAsLinearDataWithItsScale) {
    GltfBuilder gltf = emissiveQuad();
    gltf.document["materials"][0]["normalTexture"] = {{"index", 0}, {"scale", 0.5}};
    const Scene scene = loadBuilt(gltf);
    const Material& material = scene.materials[0];
    ASSERT_GE(material.normalTexture.index, 0);
    EXPECT_FALSE(scene.textures[size_t(material.normalTexture.index)].srgb);
    EXPECT_EQ(material.normalScale, 0.5f);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings[0];
}

TEST(MaterialTextures, VoxelEmissionIsTheEmissionTimesTheTexturesMeanLinearColour) {
    GltfBuilder gltf = emissiveQuad();
    const Scene scene = loadBuilt(gltf);
    EXPECT_EQ(meanLinearColor(scene.textures[0]), glm::vec3(0.5f));
    EXPECT_EQ(voxelEmission(scene, scene.materials[0]), glm::vec3(1.0f, 0.5f, 0.25f));

    Texture grey;  // sRGB 128 is 0.2158605 in linear terms (IEC 61966-2-1)
    grey.width = grey.height = 1;
    grey.rgba8 = {128, 128, 128, 255};
    EXPECT_NEAR(meanLinearColor(grey).g, 0.2158605f, 1e-6f);
}

TEST(AlphaMode, IsReadWithItsCutoffAndDefaultsToOpaqueAtHalf) {
    GltfBuilder gltf = test::quadFacingCamera();
    gltf.document["materials"] = json::array({json::object(),
                                              {{"alphaMode", "MASK"}, {"alphaCutoff", 0.25}},
                                              {{"alphaMode", "BLEND"}},
                                              {{"alphaMode", "OPAQUE"}}});
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.materials.size(), 4u);
    EXPECT_EQ(scene.materials[0].alphaMode, AlphaMode::Opaque);
    EXPECT_EQ(scene.materials[0].alphaCutoff, 0.5f);
    EXPECT_EQ(scene.materials[1].alphaMode, AlphaMode::Mask);
    EXPECT_EQ(scene.materials[1].alphaCutoff, 0.25f);
    EXPECT_EQ(scene.materials[2].alphaMode, AlphaMode::Blend);
    EXPECT_EQ(scene.materials[3].alphaMode, AlphaMode::Opaque);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings[0];
}

TEST(AlphaMode, AnUnknownModeIsOpaqueWithAWarningNamingIt) {
    GltfBuilder gltf = test::quadFacingCamera();
    gltf.document["materials"][0] = {{"alphaMode", "CUTOUT"}};
    const Scene scene = loadBuilt(gltf);
    EXPECT_EQ(scene.materials[0].alphaMode, AlphaMode::Opaque);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("materials[0].alphaMode: 'CUTOUT'"), std::string::npos) << scene.warnings[0];
}

TEST(DefaultLight, SceneWithoutLightGetsOneSunAndASkyNamedInOneWarning) {
    GltfBuilder gltf = test::quadFacingCamera();
    Scene scene = loadBuilt(gltf);
    ASSERT_TRUE(scene.lights.empty());
    EXPECT_TRUE(addDefaultSunAndSkyIfUnlit(scene));
    ASSERT_EQ(scene.lights.size(), 1u);
    const Light& sun = scene.lights[0];
    EXPECT_EQ(sun.type, LightType::Directional);
    EXPECT_EQ(sun.intensity, kDefaultSunIlluminance);
    EXPECT_NEAR(glm::length(sun.direction), 1.0f, 1e-6f);
    EXPECT_LT(sun.direction.y, 0.0f);  // from above
    EXPECT_LT(sun.direction.z, 0.0f);  // onto the side glTF models face (+Z)
    EXPECT_EQ(scene.environment, kDefaultSkyRadiance);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("default sun and sky are added: the sun travelling along (0.25, -0.83, -0.50) "
                                     "at 3 lux, the sky of radiance (0.11, 0.14, 0.18)"),
              std::string::npos)
        << scene.warnings[0];
    EXPECT_FALSE(addDefaultSunAndSkyIfUnlit(scene));  // now it has a light
    EXPECT_EQ(scene.lights.size(), 1u);
}

TEST(DefaultLight, ASkyIsLightEnough) {
    GltfBuilder gltf = test::quadFacingCamera();
    Scene scene = loadBuilt(gltf);
    scene.environment = glm::vec3(0.0f, 0.0f, 0.5f);
    EXPECT_TRUE(sceneHasLight(scene));
    EXPECT_FALSE(addDefaultSunAndSkyIfUnlit(scene));
    EXPECT_TRUE(scene.lights.empty());
    EXPECT_EQ(scene.environment, glm::vec3(0.0f, 0.0f, 0.5f));
}

TEST(DefaultLight, AnEmissiveSurfaceIsLightEnough) {
    GltfBuilder gltf = emissiveQuad();
    Scene scene = loadBuilt(gltf);
    EXPECT_FALSE(addDefaultSunAndSkyIfUnlit(scene));
    EXPECT_TRUE(scene.lights.empty());
}

TEST(DefaultLight, AGlowTooDimToLightTheSceneGetsTheSunAndSaysHowDim) {
    // The 2 × 2 m quad, half of it glowing at a twentieth of emissiveQuad's radiance: π·L·A = 0.37 W
    // against the 5.98 W the default sun brings onto it (3 lux across the quad's shadow, 0.50 × 4 m²).
    GltfBuilder gltf = emissiveQuad();
    gltf.document["materials"][0]["emissiveFactor"] = {0.1, 0.05, 0.025};
    Scene scene = loadBuilt(gltf);
    EXPECT_NEAR(emittedPower(scene), glm::pi<double>() * 0.0588 * 0.5 * 4.0, 0.005);
    EXPECT_NEAR(defaultSunPowerOnBounds(scene.bounds()), 3.0 * 0.6 / glm::length(kDefaultSunTravel) * 4.0, 1e-4);
    EXPECT_FALSE(sceneHasLight(scene));
    EXPECT_TRUE(addDefaultSunAndSkyIfUnlit(scene));
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_NE(scene.warnings[0].find("no light or sky, and its emissive surfaces send out 6.2% of the power the "
                                     "default sun brings (too little to light it), so a default sun and sky are added"),
              std::string::npos)
        << scene.warnings[0];
}

TEST(DefaultLight, EveryBuiltInSceneHasALightOfItsOwn) {
    // Their references were path-traced under their own lights: none may gain the default sun.
    for (const std::string& name : builtinSceneNames()) {
        Scene scene = loadScene(name);
        EXPECT_TRUE(sceneHasLight(scene)) << name;
        if (scene.lights.empty()) {
            EXPECT_GT(emittedPower(scene), 1.5 * kEmittersLightTheSceneShare * defaultSunPowerOnBounds(scene.bounds()))
                << name << ": its lamps are near the threshold";
        }
    }
}

TEST(DefaultLight, AnEmissiveFactorThroughABlackTextureIsNoLight) {
    GltfBuilder gltf = emissiveQuad();
    std::vector<uint16_t> black = {0, 0, 0, 255};
    gltf.document["images"][0]["uri"] = "data:image/png;base64," + test::base64(test::encodePng(1, 1, 4, 8, black));
    Scene scene = loadBuilt(gltf);
    EXPECT_TRUE(addDefaultSunAndSkyIfUnlit(scene));
}

size_t warningsNaming(const Scene& scene, const std::string& text) {
    size_t count = 0;
    for (const std::string& warning : scene.warnings) count += warning.find(text) != std::string::npos;
    return count;
}

TEST(UnsupportedExtension, ClearcoatOnEveryMaterialGetsOneWarningSayingWhatIsLost) {
    GltfBuilder gltf = test::quadFacingCamera();
    const json clearcoat = {{"KHR_materials_clearcoat", {{"clearcoatFactor", 1.0}}}};
    gltf.document["materials"] = json::array({{{"extensions", clearcoat}}, {{"extensions", clearcoat}}});
    gltf.document["extensionsUsed"] = {"KHR_materials_clearcoat", "KHR_materials_clearcoat"};
    const Scene scene = loadBuilt(gltf);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(warningsNaming(scene,
                             "extensionsUsed[0]: extension KHR_materials_clearcoat is not supported and is "
                             "ignored: the clear coat layer is not drawn"),
              1u)
        << scene.warnings[0];
}

TEST(UnsupportedExtension, AnExtensionMissingFromExtensionsUsedIsStillNamed) {
    GltfBuilder gltf = test::quadFacingCamera();
    gltf.document["materials"][0] = {
        {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}},
        {"pbrMetallicRoughness",
         {{"baseColorTexture", {{"index", 0}, {"extensions", {{"ACME_texture_tint", json::object()}}}}}}}};
    gltf.document["images"] = json::array({{{"uri", test::halfBlackHalfWhitePngUri(2)}}});
    gltf.document["textures"] = json::array({{{"source", 0}}});
    const Scene scene = loadBuilt(gltf);
    EXPECT_EQ(scene.warnings.size(), 2u);
    EXPECT_EQ(warningsNaming(scene,
                             "materials[0].extensions.KHR_materials_transmission: extension "
                             "KHR_materials_transmission is not supported"),
              1u);
    EXPECT_EQ(warningsNaming(scene,
                             "materials[0].pbrMetallicRoughness.baseColorTexture.extensions.ACME_texture_tint: "
                             "extension ACME_texture_tint is not supported and is ignored"),
              1u);
}

TEST(UnsupportedExtension, SupportedExtensionsGetNoWarning) {
    GltfBuilder gltf = test::quadFacingCamera();
    gltf.document["materials"][0] = {
        {"emissiveFactor", {1.0, 1.0, 1.0}},
        {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 2.0}}}}}};
    gltf.document["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    const Scene scene = loadBuilt(gltf);
    EXPECT_TRUE(scene.warnings.empty());
}

TEST(UnsupportedExtension, ARequiredOneStaysAnErrorNamingIt) {
    GltfBuilder gltf = test::quadFacingCamera();
    gltf.document["extensionsUsed"] = {"KHR_materials_volume"};
    gltf.document["extensionsRequired"] = {"KHR_materials_volume"};
    try {
        loadBuilt(gltf);
        FAIL() << "a required extension that is not supported was accepted";
    } catch (const std::exception& error) {
        EXPECT_NE(std::string(error.what()).find("requires extension KHR_materials_volume, which is not supported"),
                  std::string::npos)
            << error.what();
    }
}

}  // namespace
}  // namespace vct
