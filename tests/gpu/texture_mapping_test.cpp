// Where the camera sees material textures read: the texture-coordinate set each textureInfo names,
// through KHR_texture_transform; and the occlusion texture, which scales indirect light only.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../cpu/gltf_test_helpers.h"
#include "gpu_test.h"
#include "render/renderer.h"
#include "scene/default_light.h"
#include "scene/load.h"

namespace vct::test {
namespace {

constexpr uint32_t kSize = 32;
constexpr float kRelativeTolerance = 0.01f;

RenderSettings smallSettings(RenderMode mode) {
    RenderSettings settings = smallRenderSettings(kSize, mode);
    settings.resources.bounces = 1;
    return settings;
}

Scene loadBuilt(GltfBuilder& gltf) {
    TempFolder folder;
    return loadGltf(gltf.writeGltf(folder, "scene").string());
}

std::string pngUri(uint32_t width, uint32_t height, const std::vector<uint16_t>& rgba) {
    return "data:image/png;base64," + base64(encodePng(width, height, 4, 8, rgba));
}

// quadFacingCamera at pixel (x, y)'s centre: its TEXCOORD_0 (u = (x + 1)/2, v = (1 − y)/2 on the
// quad; the camera 2 away with a 30° field sees x, y ∈ ±2·tan 15°).
glm::vec2 quadTexCoordAtPixel(uint32_t x, uint32_t y) {
    const float halfExtent = 2.0f * std::tan(0.2617994f);
    const float worldX = halfExtent * (2.0f * (float(x) + 0.5f) / float(kSize) - 1.0f);
    const float worldY = halfExtent * (1.0f - 2.0f * (float(y) + 0.5f) / float(kSize));
    return glm::vec2(0.5f * (worldX + 1.0f), 0.5f * (1.0f - worldY));
}

// How far `t` lies from the nearest multiple of ½ (a half's edge in a texture, repeating).
float distanceToHalfEdge(float t) {
    const float inHalf = 2.0f * (t - std::floor(t));
    return 0.5f * std::abs(inHalf - std::round(inHalf));
}

class TextureMapping : public GpuTest {
protected:
    // The quad as a white Lambertian surface with this base colour texture (textureInfo), lit by
    // the default sun alone, in direct light: L = E·cosθ·colour/π.
    Image renderLitQuad(GltfBuilder& gltf, const json& baseColorTexture) {
        gltf.document["materials"][0] = {
            {"pbrMetallicRoughness", {{"baseColorTexture", baseColorTexture}, {"metallicFactor", 0.0}}},
            {"extensions", {{"KHR_materials_specular", {{"specularFactor", 0.0}}}}}};
        gltf.document["extensionsUsed"] = {"KHR_materials_specular", "KHR_texture_transform"};
        Scene scene = loadBuilt(gltf);
        EXPECT_TRUE(scene.warnings.empty()) << scene.warnings[0];
        EXPECT_TRUE(addDefaultSunAndSkyIfUnlit(scene));
        Renderer renderer(gpu(), scene, smallSettings(RenderMode::Direct));
        renderer.renderFrame();
        return renderer.readImage();
    }

    static float lambertian() { return kDefaultSunIlluminance * -glm::normalize(kDefaultSunTravel).z / 3.14159265f; }
};

TEST_F(TextureMapping, ATextureNamingTexCoord1IsReadWithTheSecondSet) {
    // TEXCOORD_1 mirrors TEXCOORD_0 left to right; the 8-texel texture is black on its left half.
    // Read with TEXCOORD_1 the quad is lit on the image's left and black on its right.
    GltfBuilder gltf = quadFacingCamera();
    gltf.document["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] =
        gltf.addVec2({{1, 1}, {0, 1}, {0, 0}, {1, 0}});
    gltf.document["images"] = json::array({{{"uri", halfBlackHalfWhitePngUri(8)}}});
    gltf.document["textures"] = json::array({{{"source", 0}}});
    const Image image = renderLitQuad(gltf, {{"index", 0}, {"texCoord", 1}});
    uint32_t checked = 0;
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
            const float u1 = 1.0f - quadTexCoordAtPixel(x, y).x;
            if (std::abs(u1 - 0.5f) < 1.0f / 16.0f + 1.0f / 32.0f) continue;  // half a texel + a pixel
            const float expected = u1 > 0.5f ? lambertian() : 0.0f;
            EXPECT_NEAR(image.pixel(x, y)[0], expected, kRelativeTolerance * lambertian()) << x << "," << y;
            ++checked;
        }
    EXPECT_GT(checked, kSize * kSize / 2);
}

TEST_F(TextureMapping, ATransformedTextureIsReadWhereTheExtensionsFormulaSays) {
    // An 8 × 8 texture of four quadrants: red top left, green top right, blue bottom left, white
    // bottom right. With scale 2, rotation π/2 and offset ½, KHR_texture_transform reads it at
    // u' = 2v + ½, v' = −2u + ½ (worked out by hand from T·R·S). Pixels whose (u', v') lie within
    // half a texel and a pixel's footprint of a quadrant's edge see blends and are skipped.
    const glm::u16vec3 quadrant[2][2] = {{{255, 0, 0}, {0, 255, 0}}, {{0, 0, 255}, {255, 255, 255}}};
    std::vector<uint16_t> texels;
    for (uint32_t y = 0; y < 8; ++y)
        for (uint32_t x = 0; x < 8; ++x) {
            const glm::u16vec3 color = quadrant[y / 4][x / 4];
            texels.insert(texels.end(), {color.r, color.g, color.b, 255});
        }
    GltfBuilder gltf = quadFacingCamera();
    gltf.document["images"] = json::array({{{"uri", pngUri(8, 8, texels)}}});
    gltf.document["textures"] = json::array({{{"source", 0}}});
    const json transform = {{"offset", {0.5, 0.5}}, {"rotation", 1.5707963}, {"scale", {2, 2}}};
    const Image image = renderLitQuad(gltf, {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}});

    // A pixel spans 0.54/32 of u and v on the quad, twice that after the scale.
    const float margin = 1.0f / 16.0f + 2.0f * 0.54f / float(kSize);
    uint32_t checked = 0;
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
            const glm::vec2 uv = quadTexCoordAtPixel(x, y);
            const glm::vec2 transformed(2.0f * uv.y + 0.5f, -2.0f * uv.x + 0.5f);
            if (distanceToHalfEdge(transformed.x) < margin || distanceToHalfEdge(transformed.y) < margin) continue;
            const glm::vec2 wrapped = transformed - glm::floor(transformed);
            const glm::vec3 color = glm::vec3(quadrant[wrapped.y < 0.5f ? 0 : 1][wrapped.x < 0.5f ? 0 : 1]) / 255.0f;
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(image.pixel(x, y)[c], lambertian() * color[c], kRelativeTolerance * lambertian())
                    << x << "," << y << " channel " << c;
            ++checked;
        }
    EXPECT_GT(checked, kSize * kSize / 5);
}

// The quad (base colour 0.8, a glossy dielectric, so that both indirect lobes carry light), with the
// 8-texel occlusion texture whose red is 128 on its left half and 255 on its right when `occluded`,
// and a 4 × 4 black panel glowing towards it from behind the camera. Area lights are off, so the panel
// lights the quad through the voxels and cones alone: all its light on the quad is indirect. A sun
// adds direct light.
Scene occlusionScene(bool occluded) {
    GltfBuilder gltf = quadFacingCamera();
    const int positions = gltf.addVec3({{-2, -2, 3}, {2, -2, 3}, {2, 2, 3}, {-2, 2, 3}});
    const int normals = gltf.addVec3({{0, 0, -1}, {0, 0, -1}, {0, 0, -1}, {0, 0, -1}});
    const int panel = gltf.addMesh({{"POSITION", positions}, {"NORMAL", normals}}, gltf.addIndices({0, 2, 1, 0, 3, 2}),
                                   /*material=*/1);
    gltf.document["scenes"][0]["nodes"].push_back(gltf.addNode({{"mesh", panel}}));
    gltf.document["materials"][0] = {
        {"pbrMetallicRoughness",
         {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.4}}}};
    gltf.document["materials"].push_back(
        {{"emissiveFactor", {1.0, 1.0, 1.0}}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.0, 0.0, 0.0, 1.0}}}}});
    if (occluded) {
        std::vector<uint16_t> texels;
        for (uint32_t x = 0; x < 8; ++x) texels.insert(texels.end(), {uint16_t(x < 4 ? 128 : 255), 0, 0, 255});
        gltf.document["images"] = json::array({{{"uri", pngUri(8, 1, texels)}}});
        gltf.document["textures"] = json::array({{{"source", 0}}});
        gltf.document["materials"][0]["occlusionTexture"] = {{"index", 0}, {"strength", 0.75}};
    }
    Scene scene = loadBuilt(gltf);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = kDefaultSunTravel;
    sun.intensity = kDefaultSunIlluminance;
    scene.lights.push_back(sun);
    return scene;
}

TEST_F(TextureMapping, AMinifiedCheckerboardIsItsMeanInEveryPixel) {
    // A checkerboard of single black and white texels, 256 a side, about 4.3 texels to a pixel:
    // through the mip chain every pixel averages its footprint, 0.5 in linear light. A single level
    // gave each pixel the few texels around its centre (black, white or between: aliasing), and
    // averaging the sRGB codes instead of the light (a blit that did not linearize) gives 0.21.
    constexpr uint32_t kTexels = 256;
    std::vector<uint16_t> rgba;
    for (uint32_t y = 0; y < kTexels; ++y)
        for (uint32_t x = 0; x < kTexels; ++x) {
            const uint16_t value = (x + y) % 2 ? 255 : 0;
            rgba.insert(rgba.end(), {value, value, value, 255});
        }
    GltfBuilder gltf = quadFacingCamera();
    gltf.document["images"] = json::array({{{"uri", pngUri(kTexels, kTexels, rgba)}}});
    gltf.document["textures"] = json::array({{{"source", 0}}});
    const Image image = renderLitQuad(gltf, {{"index", 0}});
    float lowest = 1e9f, highest = 0.0f;
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
            lowest = std::min(lowest, image.pixel(x, y)[0]);
            highest = std::max(highest, image.pixel(x, y)[0]);
        }
    std::printf("[ mips ] checkerboard: pixels %.4f-%.4f of a mean %.4f\n", lowest, highest, 0.5f * lambertian());
    EXPECT_NEAR(lowest, 0.5f * lambertian(), 0.05f * lambertian());
    EXPECT_NEAR(highest, 0.5f * lambertian(), 0.05f * lambertian());
}

TEST_F(TextureMapping, EachWrapModeReadsOutsideTheTextureAsGltfSays) {
    // The 8-texel texture black on its left half, read at u' = 3u − 1.5 (KHR_texture_transform):
    // the quad's visible u ∈ [0.23, 0.77] reads u' ∈ [−0.80, 0.80], half of it outside the texture,
    // where the sampler's wrapS decides: repeat takes u' − ⌊u'⌋, clamp-to-edge the first texel
    // (black), mirrored repeat |u'|. Pixels within half a texel and a pixel of a change are skipped.
    const std::pair<int, float (*)(float)> modes[] = {
        {10497, [](float t) { return t - std::floor(t); }},
        {33071, [](float t) { return std::clamp(t, 0.0f, 1.0f); }},
        {33648, [](float t) { return std::abs(t); }},
    };
    for (const auto& [glWrap, wrapped] : modes) {
        GltfBuilder gltf = quadFacingCamera();
        gltf.document["images"] = json::array({{{"uri", halfBlackHalfWhitePngUri(8)}}});
        gltf.document["samplers"] = json::array({{{"wrapS", glWrap}}});
        gltf.document["textures"] = json::array({{{"source", 0}, {"sampler", 0}}});
        const json transform = {{"offset", {-1.5, 0.0}}, {"scale", {3.0, 1.0}}};
        const Image image = renderLitQuad(gltf, {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}});
        uint32_t checked = 0;
        for (uint32_t y = 0; y < kSize; ++y)
            for (uint32_t x = 0; x < kSize; ++x) {
                const float t = 3.0f * quadTexCoordAtPixel(x, y).x - 1.5f;
                const float margin = 1.0f / 16.0f + 3.0f * 0.536f / float(kSize);  // half a texel + a pixel
                const bool white = wrapped(t) > 0.5f;
                if ((wrapped(t - margin) > 0.5f) != white || (wrapped(t + margin) > 0.5f) != white) continue;
                const float expected = white ? lambertian() : 0.0f;
                EXPECT_NEAR(image.pixel(x, y)[0], expected, kRelativeTolerance * lambertian())
                    << "wrapS " << glWrap << " at " << x << "," << y << " (u' " << t << ")";
                ++checked;
            }
        EXPECT_GT(checked, kSize * kSize / 3) << glWrap;
    }
}

TEST_F(TextureMapping, TheOcclusionTextureScalesIndirectLightAndLeavesDirectLightAlone) {
    // glTF: occlusion = 1 + strength·(red − 1), read linearly: 1 + 0.75·(128/255 − 1) = 0.626 on the
    // left half (0.41 if it were read as sRGB, 0.50 without the strength), 1 on the right.
    const float leftOcclusion = 1.0f + 0.75f * (128.0f / 255.0f - 1.0f);
    auto render = [&](bool occluded, RenderMode mode) {
        const Scene scene = occlusionScene(occluded);
        RenderSettings settings = smallSettings(mode);
        settings.shading.components.areaLights = false;
        Renderer renderer(gpu(), scene, settings);
        renderer.renderFrame();
        return renderer.readImage();
    };
    const Image indirect = render(true, RenderMode::Indirect), indirectOpen = render(false, RenderMode::Indirect);
    const Image direct = render(true, RenderMode::Direct), directOpen = render(false, RenderMode::Direct);
    // Columns 0-10 see the left half's texels only, 21-31 the right half's (as in MaterialTextures).
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            if (x > 10 && x < 21) continue;
            const float expected = x <= 10 ? leftOcclusion : 1.0f;
            const float open = indirectOpen.pixel(x, y)[0];
            ASSERT_GT(open, 1e-3f) << x << "," << y << ": the panel's light reaches the quad";
            EXPECT_NEAR(indirect.pixel(x, y)[0] / open, expected, kRelativeTolerance) << x << "," << y;
            const float lit = directOpen.pixel(x, y)[0];
            ASSERT_GT(lit, 1e-3f) << x << "," << y << ": the sun lights the quad";
            EXPECT_NEAR(direct.pixel(x, y)[0], lit, 1e-4f * lit) << x << "," << y;
        }
    }
}

TEST_F(TextureMapping, TheAmbientOcclusionViewShowsTheOcclusionTexture) {
    // The AO debug view is the cones' occlusion times the texture's, what scales the indirect light:
    // the left half's 0.626 of the right's, the cones alike on both halves (the quad is open).
    const float leftOcclusion = 1.0f + 0.75f * (128.0f / 255.0f - 1.0f);
    auto render = [&](bool occluded) {
        RenderSettings settings = smallSettings(RenderMode::Full);
        settings.shading.debugView = DebugView::AmbientOcclusion;
        Renderer renderer(gpu(), occlusionScene(occluded), settings);
        renderer.renderFrame();
        return renderer.readImage();
    };
    const Image occluded = render(true), open = render(false);
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            if (x > 10 && x < 21) continue;
            const float expected = x <= 10 ? leftOcclusion : 1.0f;
            ASSERT_GT(open.pixel(x, y)[0], 0.1f) << x << "," << y;
            EXPECT_NEAR(occluded.pixel(x, y)[0] / open.pixel(x, y)[0], expected, kRelativeTolerance) << x << "," << y;
        }
    }
}

}  // namespace
}  // namespace vct::test
