// Emissive triangles grouped into area lights (src/scene/area_lights.h): one light per surface,
// merged past kMaxAreaLights, and approximated past the triangle budget with their power kept.
#include <gtest/gtest.h>

#include "luminance.h"
#include "scene/area_lights.h"
#include "scene/load.h"
#include "scene/material_textures.h"

namespace vct {
namespace {

using glsl::luminance;

// A floor-sized scene with `n`×`n` separate square tiles of side 0.1 m under a ceiling at y = 2,
// glowing downwards with radiance 5; the tiles of the first row glow 10.
Scene tiledCeiling(int n) {
    Scene scene;
    scene.name = "tiles";
    Material dark;
    Material glow;
    glow.emission = glm::vec3(5.0f);
    Material brighter;
    brighter.emission = glm::vec3(10.0f);
    scene.materials = {dark, glow, brighter};
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const glm::vec3 c(0.3f * float(i), 2.0f, 0.3f * float(j));
            const uint32_t base = uint32_t(scene.vertices.size());
            for (glm::vec3 d : {glm::vec3(-0.05f, 0, -0.05f), glm::vec3(0.05f, 0, -0.05f), glm::vec3(0.05f, 0, 0.05f),
                                glm::vec3(-0.05f, 0, 0.05f)})
                scene.vertices.push_back({c + d, 0.0f, glm::vec3(0, -1, 0), 0.0f});
            for (uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) scene.indices.push_back(base + k);
            const uint32_t material = i == 0 ? 2u : 1u;
            scene.triangleMaterials.insert(scene.triangleMaterials.end(), {material, material});
        }
    return scene;
}

float lightPower(const AreaLight& light) {
    float power = 0.0f;
    for (const EmitterTriangle& t : light.triangles)
        power += 0.5f * glm::length(glm::cross(t.corners[1] - t.corners[0], t.corners[2] - t.corners[0])) *
                 luminance(t.radiance);
    return power;
}

TEST(AreaLightGrouping, TheCornellPatchIsOneLightFacingDown) {
    const std::vector<AreaLight> lights = findAreaLights(loadScene("cornell-emissive"));
    ASSERT_EQ(lights.size(), 1u);
    const AreaLight& patch = lights[0];
    EXPECT_EQ(patch.triangles.size(), 2u);
    EXPECT_EQ(patch.approximation, AreaLight::Approximation::None);
    EXPECT_NEAR(patch.area, 0.13f * 0.105f, 1e-5f);
    EXPECT_NEAR(patch.normal.y, -1.0f, 1e-5f);
    EXPECT_NEAR(patch.meanRadiance.r, 293.0f, 1e-3f);
    // Every triangle is wound to face down, where it emits.
    for (const EmitterTriangle& t : patch.triangles)
        EXPECT_LT(glm::cross(t.corners[1] - t.corners[0], t.corners[2] - t.corners[0]).y, 0.0f);
    EXPECT_TRUE(findAreaLights(loadScene("cornell")).empty()) << "no emissive surface, no area light";
}

TEST(AreaLightGrouping, ManyTilesMergeIntoPanelsThatKeepTheirPower) {
    // 256 tiles: 8 lights of 32 tiles (64 triangles) each, over a budget of 16 triangles a light,
    // so each becomes the rectangle bounding its tiles, as bright in all as its tiles together.
    const Scene scene = tiledCeiling(16);
    const std::vector<AreaLight> lights = findAreaLights(scene);
    ASSERT_EQ(lights.size(), kMaxAreaLights);
    float power = 0.0f;
    size_t triangles = 0, sources = 0;
    for (const AreaLight& light : lights) {
        EXPECT_EQ(light.approximation, AreaLight::Approximation::BoundingRectangle);
        EXPECT_EQ(light.triangles.size(), 2u);
        EXPECT_NEAR(light.normal.y, -1.0f, 1e-5f);
        power += lightPower(light);
        triangles += light.triangles.size();
        sources += light.sourceTriangles;
    }
    EXPECT_LE(triangles, kMaxAreaLightTriangles);
    EXPECT_EQ(sources, 512u);
    const float tilePower = 0.01f * luminance(glm::vec3(5.0f));
    EXPECT_NEAR(power, 240.0f * tilePower + 16.0f * 2.0f * tilePower, 1e-3f * power);
}

TEST(AreaLightGrouping, ACurvedEmitterOverItsBudgetKeepsItsBrightestTrianglesAndItsPower) {
    // Every other tile turned 30° about its x axis: no group of them is flat, so none can become
    // one rectangle.
    Scene scene = tiledCeiling(12);  // 144 tiles, 288 triangles: one light per tile, merged into 8
    for (size_t tile = 0; tile < 144; ++tile) {
        if ((tile / 12 + tile % 12) % 2 == 0) continue;
        for (size_t k = 0; k < 4; ++k) {
            Vertex& vertex = scene.vertices[4 * tile + k];
            const float dz = (k == 0 || k == 1) ? -0.05f : 0.05f;
            vertex.position.y += dz * 0.57735f;  // tan 30°
            vertex.normal = glm::vec3(0.0f, -0.866f, 0.5f);
        }
    }
    float scenePower = 0.0f;
    for (size_t t = 0; t < scene.triangleCount(); ++t) {
        const glm::vec3 a = scene.vertices[scene.indices[3 * t]].position,
                        b = scene.vertices[scene.indices[3 * t + 1]].position,
                        c = scene.vertices[scene.indices[3 * t + 2]].position;
        scenePower += 0.5f * glm::length(glm::cross(b - a, c - a)) *
                      luminance(scene.materials[scene.triangleMaterials[t]].emission);
    }
    float power = 0.0f;
    size_t triangles = 0;
    bool someBrightest = false;
    for (const AreaLight& light : findAreaLights(scene)) {
        power += lightPower(light);
        triangles += light.triangles.size();
        someBrightest |= light.approximation == AreaLight::Approximation::BrightestTriangles;
    }
    EXPECT_TRUE(someBrightest);
    EXPECT_LE(triangles, kMaxAreaLightTriangles);
    EXPECT_NEAR(power, scenePower, 1e-3f * scenePower);
}

// A 16×16 texture, black but for its top-left 4×4 texels, which are white.
Texture glowingCorner() {
    Texture texture;
    texture.name = "glowing corner";
    texture.width = texture.height = 16;
    texture.rgba8.assign(16 * 16 * 4, 0);
    for (uint32_t y = 0; y < 4; ++y)
        for (uint32_t x = 0; x < 4; ++x)
            for (int c = 0; c < 4; ++c) texture.rgba8[4 * (y * 16 + x) + size_t(c)] = 255;
    return texture;
}

TEST(EmissiveTextureMean, IsTakenOverTheTrianglesOwnTextureCoordinates) {
    const Texture texture = glowingCorner();
    const glm::vec2 inCorner[3] = {{0.0f, 0.0f}, {0.25f, 0.0f}, {0.0f, 0.25f}};
    const glm::vec2 outside[3] = {{0.5f, 0.5f}, {1.0f, 0.5f}, {0.5f, 1.0f}};
    EXPECT_NEAR(meanLinearColorOverTriangle(texture, inCorner).g, 1.0f, 1e-6f);
    EXPECT_EQ(meanLinearColorOverTriangle(texture, outside), glm::vec3(0.0f));
    // Two triangles covering the texture once average to its mean (1/16 white) between them.
    const glm::vec2 lower[3] = {{0, 0}, {1, 0}, {0, 1}}, upper[3] = {{1, 0}, {1, 1}, {0, 1}};
    const float both =
        0.5f * (meanLinearColorOverTriangle(texture, lower).r + meanLinearColorOverTriangle(texture, upper).r);
    EXPECT_NEAR(both, meanLinearColor(texture).r, 0.01f);
    // Coordinates repeat, as glTF's default sampler does.
    const glm::vec2 shifted[3] = {{2.0f, -1.0f}, {2.25f, -1.0f}, {2.0f, -0.75f}};
    EXPECT_NEAR(meanLinearColorOverTriangle(texture, shifted).b, 1.0f, 1e-6f);
}

// A ceiling of 4×4 quads sharing one emissive material whose texture glows in one corner: only the
// quad mapped onto that corner is a light (a texture atlas of a model glows in a few places).
TEST(EmissiveTextureMean, OnlyTheTrianglesMappedOntoTheGlowBecomeLights) {
    Scene scene;
    scene.name = "atlas";
    scene.textures.push_back(glowingCorner());
    Material glow;
    glow.emission = glm::vec3(3.0f);
    glow.emissiveTexture.index = 0;
    scene.materials = {glow};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const uint32_t base = uint32_t(scene.vertices.size());
            for (glm::vec2 d : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)}) {
                const glm::vec2 uv = (glm::vec2(float(i), float(j)) + d) * 0.25f;
                scene.vertices.push_back(
                    {glm::vec3(float(i) + d.x, 2.0f, float(j) + d.y), uv.x, glm::vec3(0, -1, 0), uv.y});
            }
            for (uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) scene.indices.push_back(base + k);
            scene.triangleMaterials.insert(scene.triangleMaterials.end(), {0u, 0u});
        }
    const std::vector<AreaLight> lights = findAreaLights(scene);
    ASSERT_EQ(lights.size(), 1u);
    EXPECT_EQ(lights[0].sourceTriangles, 2u);
    EXPECT_NEAR(lights[0].area, 1.0f, 1e-5f);
    EXPECT_NEAR(lights[0].centroid.x, 0.5f, 1e-5f);
    EXPECT_NEAR(lights[0].meanRadiance.g, 3.0f, 1e-5f);
}

// One emissive quad under the ceiling (y = 2, glowing down with radiance 3, uv over [0, 1]²) whose
// base colour texture is opaque on its right half (u ≥ ½) and transparent on its left: a lamp
// shade's cut-out, say.
Scene halfCutOutLamp(AlphaMode mode) {
    Scene scene;
    scene.name = "cut-out lamp";
    Texture texture;
    texture.name = "right half opaque";
    texture.width = 8;
    texture.height = 1;
    for (uint32_t x = 0; x < 8; ++x)
        texture.rgba8.insert(texture.rgba8.end(), {255, 255, 255, uint8_t(x < 4 ? 0 : 255)});
    scene.textures.push_back(texture);
    Material lamp;
    lamp.emission = glm::vec3(3.0f);
    lamp.baseColorTexture.index = 0;
    lamp.alphaMode = mode;
    scene.materials = {lamp};
    for (glm::vec2 d : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)})
        scene.vertices.push_back({glm::vec3(d.x, 2.0f, d.y), d.x, glm::vec3(0, -1, 0), d.y});
    scene.indices = {0, 1, 2, 0, 2, 3};
    scene.triangleMaterials = {0, 0};
    return scene;
}

TEST(EmissiveCoverage, AMaskedOrBlendedLampsHolesEmitNothing) {
    // Half the quad is a hole (MASK) or fully transparent (BLEND): the light keeps its shape and
    // emits half the power, the mean radiance over the quad halved, as the path tracer, whose rays
    // pass through the holes, sees it. Opaque, the alpha is ignored.
    for (const AlphaMode mode : {AlphaMode::Mask, AlphaMode::Blend, AlphaMode::Opaque}) {
        const std::vector<AreaLight> lights = findAreaLights(halfCutOutLamp(mode));
        ASSERT_EQ(lights.size(), 1u);
        EXPECT_NEAR(lights[0].area, 1.0f, 1e-5f);
        EXPECT_NEAR(lights[0].meanRadiance.r, mode == AlphaMode::Opaque ? 3.0f : 1.5f, 0.01f) << int(mode);
    }
    // Without a texture the factor's alpha decides: below the cutoff the whole lamp is a hole.
    Scene hidden = halfCutOutLamp(AlphaMode::Mask);
    hidden.materials[0].baseColorTexture.index = -1;
    hidden.materials[0].baseColorFactor.a = 0.2f;
    EXPECT_TRUE(findAreaLights(hidden).empty());
    hidden.materials[0].alphaMode = AlphaMode::Blend;
    ASSERT_EQ(findAreaLights(hidden).size(), 1u);
    EXPECT_NEAR(findAreaLights(hidden)[0].meanRadiance.r, 0.6f, 1e-5f);
}

}  // namespace
}  // namespace vct
