// The reference path tracer against answers known in closed form, and against itself.
// Scenes are built here, so the tests need no file and no loader.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "bsdf.h"
#include "bvh.h"
#include "lights.h"
#include "path_tracer.h"
#include "pathtracer_test_helpers.h"
#include "sampling.h"

namespace vct::pt {
namespace {

using namespace test;

// Tolerances, in one place.
constexpr double kFurnaceMeanTolerance = 0.01;    // relative, image mean
constexpr double kFurnacePixelNoise = 0.08;       // relative standard error of any pixel
constexpr double kAnalyticPixelTolerance = 0.01;  // relative, point light over a plane
constexpr double kSigmas = 4.5;                   // agreement of independent estimates, in standard errors
constexpr double kPdfIntegralTolerance = 0.005;   // absolute
constexpr double kSamplerTolerance = 0.03;

void addTriangle(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, uint32_t material) {
    const glm::vec3 normal = glm::normalize(glm::cross(b - a, c - a));
    const uint32_t first = uint32_t(scene.vertices.size());
    for (const glm::vec3& p : {a, b, c}) scene.vertices.push_back({p, 0.0f, normal, 0.0f});
    for (uint32_t i = 0; i < 3; ++i) scene.indices.push_back(first + i);
    scene.triangleMaterials.push_back(material);
}

// A planar quad, corners in order around it, wound so that its normal points towards `facing`.
void addQuad(Scene& scene, std::array<glm::vec3, 4> corners, glm::vec3 facing, uint32_t material) {
    const glm::vec3 center = 0.25f * (corners[0] + corners[1] + corners[2] + corners[3]);
    if (glm::dot(glm::cross(corners[1] - corners[0], corners[2] - corners[0]), facing - center) < 0.0f) {
        std::reverse(corners.begin(), corners.end());
    }
    addTriangle(scene, corners[0], corners[1], corners[2], material);
    addTriangle(scene, corners[0], corners[2], corners[3], material);
}

// The six faces of the cube [−h, h]³, facing inwards; `faceMaterials` in the order −x +x −y +y −z +z.
void addInwardBox(Scene& scene, float h, const std::array<uint32_t, 6>& faceMaterials) {
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            std::array<glm::vec3, 4> corners;
            const float su[4] = {-h, h, h, -h}, sv[4] = {-h, -h, h, h};
            for (int i = 0; i < 4; ++i) {
                corners[i][axis] = side == 0 ? -h : h;
                corners[i][u] = su[i];
                corners[i][v] = sv[i];
            }
            addQuad(scene, corners, glm::vec3(0.0f), faceMaterials[2 * axis + side]);
        }
    }
}

// A UV sphere with smooth (vertex) normals pointing outwards.
void addSphere(Scene& scene, glm::vec3 center, float radius, uint32_t material, int rings, int segments) {
    auto point = [&](int ring, int segment) {
        const float theta = kPi * float(ring) / float(rings), phi = 2.0f * kPi * float(segment) / float(segments);
        return glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    };
    for (int ring = 0; ring < rings; ++ring) {
        for (int segment = 0; segment < segments; ++segment) {
            const glm::vec3 n[4] = {point(ring, segment), point(ring + 1, segment), point(ring + 1, segment + 1),
                                    point(ring, segment + 1)};
            for (const auto& tri : {std::array<int, 3>{0, 2, 1}, std::array<int, 3>{0, 3, 2}}) {
                const uint32_t first = uint32_t(scene.vertices.size());
                for (int k : tri) scene.vertices.push_back({center + radius * n[k], 0.0f, n[k], 0.0f});
                for (uint32_t i = 0; i < 3; ++i) scene.indices.push_back(first + i);
                scene.triangleMaterials.push_back(material);
            }
        }
    }
}

// A closed room with coloured walls, a rough metal floor, a glossy dielectric block, a point
// light and an emissive ceiling patch: every kind of light path the tracer knows.
Scene makeTestRoom() {
    Scene scene;
    scene.name = "test room";
    const uint32_t white = addMaterial(scene, lambertian(glm::vec3(0.7f)));
    const uint32_t red = addMaterial(scene, lambertian(glm::vec3(0.7f, 0.1f, 0.1f)));
    Material metal;
    metal.baseColorFactor = glm::vec4(0.9f, 0.8f, 0.6f, 1.0f);
    metal.metallic = 1.0f;
    metal.roughness = 0.4f;
    const uint32_t floor = addMaterial(scene, metal);
    Material plastic;
    plastic.baseColorFactor = glm::vec4(0.2f, 0.3f, 0.8f, 1.0f);
    plastic.metallic = 0.0f;
    plastic.roughness = 0.3f;
    const uint32_t block = addMaterial(scene, plastic);
    const uint32_t lamp = addMaterial(scene, lambertian(glm::vec3(0.5f), glm::vec3(20.0f)));
    addInwardBox(scene, 1.0f, {red, white, floor, white, white, white});
    addQuad(scene,
            {glm::vec3(-0.3f, -1.0f, -0.3f), glm::vec3(0.2f, -1.0f, -0.3f), glm::vec3(0.2f, -0.4f, -0.3f),
             glm::vec3(-0.3f, -0.4f, -0.3f)},
            glm::vec3(0.0f, 0.0f, 1.0f), block);
    addQuad(scene,
            {glm::vec3(-0.2f, 0.99f, -0.2f), glm::vec3(0.2f, 0.99f, -0.2f), glm::vec3(0.2f, 0.99f, 0.2f),
             glm::vec3(-0.2f, 0.99f, 0.2f)},
            glm::vec3(0.0f), lamp);
    Light light;
    light.position = glm::vec3(0.5f, 0.5f, 0.3f);
    light.intensity = 1.5f;
    scene.lights.push_back(light);
    scene.cameras.push_back(cameraLookingAt(glm::vec3(0.0f, 0.0f, 0.95f), glm::vec3(0.0f, -0.2f, 0.0f), 1.4f));
    return scene;
}

bool allFinite(const Image& image) {
    return std::all_of(image.rgb.begin(), image.rgb.end(), [](float x) { return std::isfinite(x); });
}

struct Estimate {
    double mean = 0.0, standardError = 0.0;
};
// Mean luminance and its standard error over the pixels [x0, x1) × [y0, y1).
Estimate regionLuminance(const RenderResult& r, uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1) {
    double sum = 0.0, variance = 0.0;
    for (uint32_t y = y0; y < y1; ++y) {
        for (uint32_t x = x0; x < x1; ++x) {
            sum += luminance(r.image.pixel(x, y));
            variance += r.luminanceVariance[size_t(y) * r.image.width + x];
        }
    }
    const double count = double(x1 - x0) * double(y1 - y0);
    return {sum / count, std::sqrt(variance) / count};
}

// A closed unit box whose walls all emit `emission` and reflect `albedo` diffusely, a camera inside.
Scene furnaceScene(float emission, float albedo) {
    Scene scene;
    const uint32_t wall = addMaterial(scene, lambertian(glm::vec3(albedo), glm::vec3(emission)));
    addInwardBox(scene, 1.0f, {wall, wall, wall, wall, wall, wall});
    scene.cameras.push_back(cameraLookingAt(glm::vec3(0.1f, 0.2f, 0.3f), glm::vec3(1.0f, 0.6f, -1.0f), 1.5f));
    return scene;
}

TEST(PathTracer, WhiteFurnaceClosedBoxGivesEmissionOverOneMinusAlbedo) {
    // Inside a closed box whose walls all emit E and reflect a fraction a diffusely, radiance is
    // E + a·E + a²·E + … = E / (1 − a) in every direction.
    const float emission = 0.5f, albedo = 0.8f;
    const Scene scene = furnaceScene(emission, albedo);
    const PathTracer tracer = createPathTracer(scene);
    const RenderResult result = render(tracer, smallRender(scene, 16, 256, Component::Full, 7));

    const double expected = emission / (1.0 - albedo);
    ASSERT_TRUE(allFinite(result.image));
    EXPECT_EQ(result.discardedSamples, 0u);
    EXPECT_NEAR(result.meanLuminance, expected, kFurnaceMeanTolerance * expected);
    for (size_t i = 0; i < result.luminanceVariance.size(); ++i) {
        const double sigma = std::sqrt(double(result.luminanceVariance[i]));
        EXPECT_LT(sigma, kFurnacePixelNoise * expected);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(result.image.rgb[3 * i + c], expected, kSigmas * sigma);
    }
}

TEST(PathTracer, MaxDepthKeepsThatManyBouncesOfTheFurnace) {
    // The same furnace with paths cut after D light-gathering interactions: the camera sees the
    // emission and D reflections of it, E·(1 + a + … + a^D). D = 1 is direct light only (here the
    // walls' emission reflected once); the bench's one-bounce references use D = 2.
    const float emission = 0.5f, albedo = 0.8f;
    const Scene scene = furnaceScene(emission, albedo);
    PathTracer tracer = createPathTracer(scene);
    for (uint32_t depth : {0u, 1u, 2u, 4u}) {
        tracer.maxDepth = depth;
        const RenderResult result = render(tracer, smallRender(scene, 8, 256, Component::Full, 11));
        double expected = 0.0;
        for (uint32_t k = 0; k <= depth; ++k) expected += emission * std::pow(double(albedo), double(k));
        EXPECT_NEAR(result.meanLuminance, expected, kFurnaceMeanTolerance * expected) << "max depth " << depth;
    }
}

// The irradiance KHR_lights_punctual prescribes at p on the plane y = 0 (normal +Y), no photometric factor.
glm::dvec3 planeIrradiance(const Light& light, const glm::vec3& p) {
    if (light.type == LightType::Directional) {
        return glm::dvec3(light.color * light.intensity * std::max(0.0f, -glm::normalize(light.direction).y));
    }
    const glm::vec3 toLight = light.position - p;
    const float d2 = glm::dot(toLight, toLight);
    const glm::vec3 L = toLight / std::sqrt(d2);
    float falloff = glsl::rangeAttenuation(std::sqrt(d2), light.range);
    if (light.type == LightType::Spot) {
        falloff *=
            glsl::spotAttenuation(glm::normalize(light.direction), -L, light.innerConeAngle, light.outerConeAngle);
    }
    return glm::dvec3(light.color * light.intensity * falloff * std::max(0.0f, L.y) / d2);
}

TEST(PathTracer, PunctualLightsOverLambertianPlaneFollowTheirFalloff) {
    // L = albedo/π · E with E = c·I·cosθ/d² for a point light (× the cone falloff for a spot,
    // × the range falloff when a range is set) and E = c·E·cosθ for a directional one. A lone plane
    // has no indirect light, so `full` must match. Each pixel's expectation is the formula averaged
    // over the pixel's square, computed here on a fine grid of sub-pixel positions.
    const glm::vec3 albedo(0.5f, 0.6f, 0.7f);
    Light point;
    point.position = glm::vec3(0.3f, 1.0f, -0.2f);
    point.color = glm::vec3(1.0f, 0.5f, 0.25f);
    point.intensity = 2.0f;
    Light ranged = point;
    ranged.range = 3.0f;
    Light spot = point;
    spot.type = LightType::Spot;
    spot.direction = glm::normalize(glm::vec3(-0.2f, -1.0f, 0.1f));
    spot.innerConeAngle = 0.3f;
    spot.outerConeAngle = 1.2f;
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, -0.5f));
    sun.intensity = 3.0f;
    for (const Light& light : {point, ranged, spot, sun}) {
        Scene scene;
        const uint32_t plane = addMaterial(scene, lambertian(albedo));
        addQuad(scene, {glm::vec3(-10, 0, -10), glm::vec3(10, 0, -10), glm::vec3(10, 0, 10), glm::vec3(-10, 0, 10)},
                glm::vec3(0, 1, 0), plane);
        scene.lights.push_back(light);
        scene.cameras.push_back(cameraLookingAt(glm::vec3(0, 2.5f, 2.5f), glm::vec3(0, 0, 0), 1.0f));
        const PathTracer tracer = createPathTracer(scene);
        const RenderSettings settings = smallRender(scene, 32, 1024, Component::Full, 3);
        const RenderResult result = render(tracer, settings);

        auto analytic = [&](float x, float y) {
            const Ray ray = cameraRay(settings.camera, settings.width, settings.height, x, y);
            const glm::vec3 p = ray.origin + (-ray.origin.y / ray.direction.y) * ray.direction;
            return glm::dvec3(albedo / kPi) * planeIrradiance(light, p);
        };
        constexpr int kSubpixels = 16;
        for (auto [px, py] : {std::pair{16u, 16u}, {4u, 4u}, {28u, 8u}, {10u, 27u}, {22u, 20u}}) {
            glm::dvec3 expected(0.0);
            for (int i = 0; i < kSubpixels; ++i) {
                for (int j = 0; j < kSubpixels; ++j) {
                    expected += analytic(float(px) + (float(i) + 0.5f) / kSubpixels,
                                         float(py) + (float(j) + 0.5f) / kSubpixels);
                }
            }
            expected /= double(kSubpixels * kSubpixels);
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(result.image.pixel(px, py)[c], expected[c], kAnalyticPixelTolerance * expected[c])
                    << "light type " << int(light.type) << " pixel (" << px << ", " << py << ") channel " << c;
            }
        }
    }
}

TEST(PathTracer, TheSkyIsSeenDirectlyAndLightsAnOpenPlaneIndirectly) {
    // A grey Lambertian plane (albedo 0.5) under a uniform sky L and nothing else (the sun off),
    // seen from above with a view twice as wide as the plane: its pixels get irradiance π·L from the
    // whole hemisphere, so radiance 0.5·L, all of it indirect; the pixels past its edge see L, direct.
    Scene scene;
    addSunlitPlaneSeenFromAbove(scene, lambertian(glm::vec3(0.5f)), glm::vec3(0.0f, -1.0f, 0.0f));
    scene.lights.clear();
    scene.environment = glm::vec3(0.2f, 0.4f, 0.8f);
    scene.cameras[0].yfov = 2.0f * std::atan(2.0f);  // x ∈ [−2, 2]: the plane covers the middle half
    const PathTracer tracer = createPathTracer(scene);
    for (Component component : {Component::Full, Component::Direct, Component::Indirect}) {
        const RenderResult result = render(tracer, smallRender(scene, 16, 16, component, 3));
        const bool direct = component != Component::Indirect, indirect = component != Component::Direct;
        for (uint32_t x : {0u, 2u, 6u, 9u, 13u, 15u}) {
            const bool onPlane = x >= 4 && x < 12;
            const glm::vec3 expected =
                onPlane ? (indirect ? 0.5f : 0.0f) * scene.environment : (direct ? 1.0f : 0.0f) * scene.environment;
            const float* pixel = result.image.pixel(x, 8);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(pixel[c], expected[c], 1e-4f)
                    << "x " << x << ", channel " << c << ", mode " << int(component);
        }
    }
}

TEST(PathTracer, BaseColorTextureIsSrgbDecodedAndFilteredAtTheHitUv) {
    // A 2 × 1 texture (sRGB red 255 | green 128) on a plane with u = (x + 1)/2, lit straight down by a
    // directional light of E = π, so radiance = base colour. The camera sees u ∈ [¼, ¾], between the
    // two texel centres, where bilinear filtering blends the decoded colours linearly.
    Scene scene;
    Texture texture;
    texture.width = 2;
    texture.height = 1;
    texture.rgba8 = {255, 0, 0, 255, 0, 128, 0, 255};
    scene.textures.push_back(texture);
    Material material = lambertian(glm::vec3(1.0f, 0.5f, 1.0f));
    material.baseColorTexture.index = 0;
    addSunlitPlaneSeenFromAbove(scene, material, glm::vec3(0.0f, -1.0f, 0.0f));
    const PathTracer tracer = createPathTracer(scene);
    const RenderResult result = render(tracer, smallRender(scene, 16, 256, Component::Full, 2));

    const double green128 = std::pow((128.0 / 255.0 + 0.055) / 1.055, 2.4);  // IEC 61966-2-1
    for (uint32_t x = 0; x < 16; ++x) {
        const double t = (double(x) + 0.5) / 16.0;  // from the red texel's centre to the green one's
        const float* pixel = result.image.pixel(x, 7);
        EXPECT_NEAR(pixel[0], 1.0 - t, 0.01 * (1.0 - t) + 1e-3) << "x " << x;
        EXPECT_NEAR(pixel[1], 0.5 * green128 * t, 0.01 * 0.5 * green128 * t + 1e-3) << "x " << x;
        EXPECT_NEAR(pixel[2], 0.0, 1e-6) << "x " << x;
    }
}

TEST(PathTracer, MetallicRoughnessTextureIsLinearAndScalesTheFactors) {
    // A plane whose factors say white metal (metallic 1, roughness 1) through a one-texel
    // metallic-roughness texture of blue 128, green 255: metallic 128/255 read linearly, as the same
    // plane with that factor and no texture renders it (with the same seed, the same paths).
    auto renderPlane = [](float metallic, bool textured) {
        Scene scene;
        Texture texture;
        texture.width = texture.height = 1;
        texture.rgba8 = {0, 255, 128, 255};
        texture.srgb = false;
        scene.textures.push_back(texture);
        Material material = lambertian(glm::vec3(1.0f));
        material.metallic = metallic;
        material.roughness = 1.0f;
        material.metallicRoughnessTexture.index = textured ? 0 : -1;
        addSunlitPlaneSeenFromAbove(scene, material, glm::vec3(0.0f, -1.0f, 0.0f));
        return render(createPathTracer(scene), smallRender(scene, 8, 64, Component::Full, 2)).image;
    };
    const Image textured = renderPlane(1.0f, true);
    const Image factor = renderPlane(128.0f / 255.0f, false);
    const Image metal = renderPlane(1.0f, false);
    for (uint32_t x = 0; x < 8; ++x) {
        EXPECT_NEAR(textured.pixel(x, 4)[0], factor.pixel(x, 4)[0], 1e-4f * factor.pixel(x, 4)[0]) << "x " << x;
        EXPECT_GT(textured.pixel(x, 4)[0], 1.5f * metal.pixel(x, 4)[0]) << "x " << x << ": the texture was ignored";
    }
}

// An 8-texel normal texture whose left half holds the texel (tilt, 128, up) and right half
// (128, tilt, up): tilted along +u, then up the image.
Texture halfTiltedNormalTexture(uint8_t tilt, uint8_t up) {
    Texture texture;
    texture.width = 8;
    texture.height = 1;
    texture.srgb = false;
    for (uint32_t x = 0; x < 8; ++x)
        texture.rgba8.insert(texture.rgba8.end(), {uint8_t(x < 4 ? tilt : 128), uint8_t(x < 4 ? 128 : tilt), up, 255});
    return texture;
}

TEST(PathTracer, NormalTextureTiltsTheShadingNormalAlongUAndUpTheImage) {
    // A Lambertian plane facing up (u along +x, v along +z, so up the image is −z) with an 8-texel
    // normal texture tilted 30° along +u on its left half and 30° up the image on its right, lit by
    // a sun of E = π: L = max(n'·l, 0). The camera sees u ∈ [¼, ¾]; columns 0-5 and 10-15 see one
    // half each. Mirrored (u along −x, as the second half of a symmetric model), the halves swap
    // sides, +u tilts towards −x and up the image stays −z.
    const uint8_t tilt = uint8_t(std::lround((0.5 + 0.5 * std::sin(0.5235988)) * 255.0));
    const uint8_t up = uint8_t(std::lround((0.5 + 0.5 * std::cos(0.5235988)) * 255.0));
    for (const bool mirrored : {false, true}) {
        Scene scene;
        scene.textures.push_back(halfTiltedNormalTexture(tilt, up));
        Material material = lambertian(glm::vec3(1.0f));
        material.normalTexture.index = 0;
        addSunlitPlaneSeenFromAbove(scene, material, glm::vec3(0.6f, -1.0f, -0.5f));
        if (mirrored)
            for (Vertex& vertex : scene.vertices) vertex.uv1.x = vertex.u = 1.0f - vertex.u;
        const glm::vec3 toSun = -scene.lights.back().direction;
        const RenderResult result = render(createPathTracer(scene), smallRender(scene, 16, 64, Component::Full, 2));

        const glm::vec3 alongPlusU = mirrored ? glm::vec3(-1, 0, 0) : glm::vec3(1, 0, 0);
        auto expected = [&](glm::vec3 texel) {
            const glm::vec3 local = glm::normalize(texel / 255.0f * 2.0f - 1.0f);
            const glm::vec3 normal =
                local.x * alongPlusU + local.y * glm::vec3(0, 0, -1) + local.z * glm::vec3(0, 1, 0);
            return std::max(glm::dot(normal, toSun), 0.0f);
        };
        const float alongU = expected(glm::vec3(tilt, 128, up)), upImage = expected(glm::vec3(128, tilt, up));
        // Tilts the other way would give other light.
        ASSERT_GT(std::abs(alongU - expected(glm::vec3(255 - tilt, 128, up))), 0.2f * alongU);
        ASSERT_GT(std::abs(upImage - expected(glm::vec3(128, 255 - tilt, up))), 0.2f * upImage);
        const float left = mirrored ? upImage : alongU, right = mirrored ? alongU : upImage;
        for (uint32_t y = 4; y < 12; ++y) {
            for (uint32_t x = 0; x <= 5; ++x)
                EXPECT_NEAR(result.image.pixel(x, y)[0], left, 0.01f * left)
                    << x << "," << y << " mirrored " << mirrored;
            for (uint32_t x = 10; x < 16; ++x)
                EXPECT_NEAR(result.image.pixel(x, y)[0], right, 0.01f * right)
                    << x << "," << y << " mirrored " << mirrored;
        }
    }
}

TEST(PathTracer, ANormalTextureFollowsTheFilesTangents) {
    // The plane and texture above, its vertices given a TANGENT along -x (handedness +1), against
    // +x where u increases: +u tilts towards -x, and up the image, the bitangent cross(+y, -x) = +z,
    // towards +z. From the triangles' coordinates the tilts were +x and -z.
    const uint8_t tilt = uint8_t(std::lround((0.5 + 0.5 * std::sin(0.5235988)) * 255.0));
    const uint8_t up = uint8_t(std::lround((0.5 + 0.5 * std::cos(0.5235988)) * 255.0));
    Scene scene;
    scene.textures.push_back(halfTiltedNormalTexture(tilt, up));
    Material material = lambertian(glm::vec3(1.0f));
    material.normalTexture.index = 0;
    addSunlitPlaneSeenFromAbove(scene, material, glm::vec3(0.6f, -1.0f, -0.5f));
    for (Vertex& vertex : scene.vertices) vertex.tangent = glm::vec4(-1.0f, 0.0f, 0.0f, 1.0f);
    const glm::vec3 toSun = -scene.lights.back().direction;
    const RenderResult result = render(createPathTracer(scene), smallRender(scene, 16, 64, Component::Full, 2));

    auto expected = [&](glm::vec3 texel, glm::vec3 tangent, glm::vec3 bitangent) {
        const glm::vec3 local = glm::normalize(texel / 255.0f * 2.0f - 1.0f);
        return std::max(glm::dot(local.x * tangent + local.y * bitangent + local.z * glm::vec3(0, 1, 0), toSun), 0.0f);
    };
    const glm::vec3 alongU(tilt, 128, up), upImage(128, tilt, up);
    const float left = expected(alongU, {-1, 0, 0}, {0, 0, 1}), right = expected(upImage, {-1, 0, 0}, {0, 0, 1});
    // The frame from the coordinates would give other light.
    ASSERT_GT(std::abs(left - expected(alongU, {1, 0, 0}, {0, 0, -1})), 0.1f * left);
    ASSERT_GT(std::abs(right - expected(upImage, {1, 0, 0}, {0, 0, -1})), 0.1f * right);
    for (uint32_t y = 4; y < 12; ++y) {
        for (uint32_t x = 0; x <= 5; ++x) EXPECT_NEAR(result.image.pixel(x, y)[0], left, 0.01f * left) << x << "," << y;
        for (uint32_t x = 10; x < 16; ++x)
            EXPECT_NEAR(result.image.pixel(x, y)[0], right, 0.01f * right) << x << "," << y;
    }
}

// A quad with u from 0 to 1 along `right` and v from 0 to 1 along `down`, facing down × right: the
// side from which the texture reads as an image (right to the right, down downwards).
void addTexturedQuad(Scene& scene, glm::vec3 corner, glm::vec3 right, glm::vec3 down, uint32_t material) {
    const glm::vec3 normal = glm::normalize(glm::cross(down, right));
    const uint32_t first = uint32_t(scene.vertices.size());
    scene.vertices.push_back({corner, 0.0f, normal, 0.0f});
    scene.vertices.push_back({corner + right, 1.0f, normal, 0.0f});
    scene.vertices.push_back({corner + right + down, 1.0f, normal, 1.0f});
    scene.vertices.push_back({corner + down, 0.0f, normal, 1.0f});
    for (uint32_t i : {0u, 2u, 1u, 0u, 3u, 2u}) scene.indices.push_back(first + i);
    scene.triangleMaterials.insert(scene.triangleMaterials.end(), {material, material});
}

Material texturedEmitter(glm::vec3 emission) {
    Material material = lambertian(glm::vec3(0.0f), emission);
    material.emissiveTexture.index = 0;
    return material;
}

TEST(PathTracer, EmissiveTextureScalesTheEmissionTheCameraSees) {
    // The quad x, y ∈ [−1, 1] facing a camera that sees x, y ∈ [−½, ½]: u = (x + 1)/2 ∈ [¼, ¾], so
    // the texture's black half shows on the left of the image, its white half on the right.
    Scene scene;
    scene.textures.push_back(halfBlackTexture(8));
    const uint32_t emitter = addMaterial(scene, texturedEmitter(glm::vec3(2.0f, 1.0f, 0.5f)));
    addTexturedQuad(scene, glm::vec3(-1, 1, 0), glm::vec3(2, 0, 0), glm::vec3(0, -2, 0), emitter);
    Camera camera;
    camera.position = glm::vec3(0.0f, 0.0f, 1.0f);
    camera.yfov = 2.0f * std::atan(0.5f);
    scene.cameras.push_back(camera);
    const RenderResult result = render(createPathTracer(scene), smallRender(scene, 16, 4, Component::Direct, 3));
    for (uint32_t y = 0; y < 16; ++y) {
        for (uint32_t x : {0u, 1u, 2u, 3u, 4u}) EXPECT_EQ(result.image.pixel(x, y)[0], 0.0f) << x << "," << y;
        for (uint32_t x : {11u, 12u, 13u, 14u, 15u}) {
            EXPECT_NEAR(result.image.pixel(x, y)[0], 2.0f, 1e-5f) << x << "," << y;
            EXPECT_NEAR(result.image.pixel(x, y)[2], 0.5f, 1e-5f) << x << "," << y;
        }
    }
}

// A white floor (4 × 4 m at y = 0) under a 1 m quad of `lamp` at y = 0.5 facing down, textured
// by scene.textures[0] across x, seen from straight above (image right = +x): its light on the
// floor is direct light (one reflection). The two light estimates, light sampling with MIS and
// BRDF sampling alone, rendered at 16 × 16.
struct LampOverFloor {
    RenderResult mis, brdfOnly;
};
LampOverFloor renderLampOverFloor(const Texture& texture, const Material& lamp, uint64_t seed) {
    Scene scene;
    scene.textures.push_back(texture);
    const uint32_t floor = addMaterial(scene, lambertian(glm::vec3(0.8f)));
    const uint32_t emitter = addMaterial(scene, lamp);
    addQuad(scene, {glm::vec3(-2, 0, -2), glm::vec3(2, 0, -2), glm::vec3(2, 0, 2), glm::vec3(-2, 0, 2)},
            glm::vec3(0, 1, 0), floor);
    addTexturedQuad(scene, glm::vec3(-0.5f, 0.5f, 0.5f), glm::vec3(1, 0, 0), glm::vec3(0, 0, -1), emitter);
    Camera camera;
    camera.position = glm::vec3(0.0f, 2.5f, 0.0f);
    camera.forward = glm::vec3(0.0f, -1.0f, 0.0f);
    camera.up = glm::vec3(0.0f, 0.0f, -1.0f);
    camera.yfov = 1.2f;
    scene.cameras.push_back(camera);
    PathTracer tracer = createPathTracer(scene);
    LampOverFloor result;
    result.mis = render(tracer, smallRender(scene, 16, 128, Component::Direct, seed));
    tracer.sampleEmitters = false;
    result.brdfOnly = render(tracer, smallRender(scene, 16, 128, Component::Direct, seed + 1));
    return result;
}

void expectTheEstimatesAgree(const LampOverFloor& lamp, uint32_t x0, uint32_t x1) {
    const Estimate a = regionLuminance(lamp.mis, x0, 0, x1, 16);
    const Estimate b = regionLuminance(lamp.brdfOnly, x0, 0, x1, 16);
    EXPECT_NEAR(a.mean, b.mean, kSigmas * std::hypot(a.standardError, b.standardError)) << "columns from " << x0;
    EXPECT_GT(a.mean, 0.0);
}

TEST(PathTracer, LightFromAnEmissiveTextureAgreesWithBrdfSamplingAlone) {
    // The quad glows through a half-black texture: light sampling must weigh each sampled point by
    // its own texel (the emitter's choice uses the texture's mean).
    const LampOverFloor lamp = renderLampOverFloor(halfBlackTexture(8), texturedEmitter(glm::vec3(4.0f)), 41);
    expectTheEstimatesAgree(lamp, 0, 8);
    expectTheEstimatesAgree(lamp, 8, 16);
}

TEST(PathTracer, LightFromACutOutEmitterAgreesWithBrdfSamplingAlone) {
    // The quad glows evenly but is cut out (alphaMode MASK) where its base colour texture's alpha is
    // 0, on its left half: BRDF samples pass through the holes, so light sampling must not find
    // emission there either (it did, and the floor took half again as much).
    Texture cutOut = halfBlackTexture(8);
    for (uint32_t x = 0; x < 4; ++x) cutOut.rgba8[4 * x + 3] = 0;
    Material lamp = lambertian(glm::vec3(1.0f), glm::vec3(4.0f));
    lamp.baseColorTexture.index = 0;
    lamp.alphaMode = AlphaMode::Mask;
    expectTheEstimatesAgree(renderLampOverFloor(cutOut, lamp, 43), 0, 16);
}

TEST(PathTracer, RendersWithDifferentSeedsAgreeWithinTheirEstimatedNoise) {
    const Scene scene = makeTestRoom();
    const PathTracer tracer = createPathTracer(scene);
    const RenderResult a = render(tracer, smallRender(scene, 24, 32, Component::Full, 1));
    const RenderResult b = render(tracer, smallRender(scene, 24, 32, Component::Full, 2));
    ASSERT_TRUE(allFinite(a.image) && allFinite(b.image));
    EXPECT_NE(a.image.rgb, b.image.rgb);
    EXPECT_NEAR(a.meanLuminance, b.meanLuminance,
                kSigmas * std::hypot(a.meanLuminanceStandardError, b.meanLuminanceStandardError));
    // Per pixel, (a − b)² / (σa² + σb²) averages 1 when both noise estimates are right.
    double normalizedSquares = 0.0;
    for (uint32_t y = 0; y < a.image.height; ++y) {
        for (uint32_t x = 0; x < a.image.width; ++x) {
            const double da = regionLuminance(a, x, y, x + 1, y + 1).mean;
            const double db = regionLuminance(b, x, y, x + 1, y + 1).mean;
            const size_t i = size_t(y) * a.image.width + x;
            const double variance = double(a.luminanceVariance[i]) + double(b.luminanceVariance[i]);
            normalizedSquares += variance > 0.0 ? (da - db) * (da - db) / variance : 1.0;
        }
    }
    const double meanNormalizedSquare = normalizedSquares / double(a.luminanceVariance.size());
    EXPECT_GT(meanNormalizedSquare, 0.6);
    EXPECT_LT(meanNormalizedSquare, 1.6);
}

TEST(PathTracer, SameSeedGivesTheSameImageWithAnyThreadCount) {
    const Scene scene = makeTestRoom();
    const PathTracer tracer = createPathTracer(scene);
    RenderSettings settings = smallRender(scene, 12, 4, Component::Full, 5);
    settings.threads = 1;
    const RenderResult one = render(tracer, settings);
    settings.threads = 3;
    const RenderResult three = render(tracer, settings);
    EXPECT_EQ(one.image.rgb, three.image.rgb);
}

TEST(PathTracer, DirectPlusIndirectEqualsFull) {
    const Scene scene = makeTestRoom();
    const PathTracer tracer = createPathTracer(scene);
    constexpr uint32_t kSize = 24;
    const RenderResult full = render(tracer, smallRender(scene, kSize, 32, Component::Full, 11));
    const RenderResult direct = render(tracer, smallRender(scene, kSize, 32, Component::Direct, 12));
    const RenderResult indirect = render(tracer, smallRender(scene, kSize, 32, Component::Indirect, 13));
    ASSERT_TRUE(allFinite(full.image) && allFinite(direct.image) && allFinite(indirect.image));
    EXPECT_GT(direct.meanLuminance, 0.1 * full.meanLuminance);
    EXPECT_GT(indirect.meanLuminance, 0.1 * full.meanLuminance);
    // The whole image and each quadrant.
    const uint32_t h = kSize / 2;
    for (auto [x0, y0, x1, y1] : {std::array<uint32_t, 4>{0, 0, kSize, kSize},
                                  {0, 0, h, h},
                                  {h, 0, kSize, h},
                                  {0, h, h, kSize},
                                  {h, h, kSize, kSize}}) {
        const Estimate f = regionLuminance(full, x0, y0, x1, y1);
        const Estimate d = regionLuminance(direct, x0, y0, x1, y1);
        const Estimate i = regionLuminance(indirect, x0, y0, x1, y1);
        const double sigma = std::sqrt(f.standardError * f.standardError + d.standardError * d.standardError +
                                       i.standardError * i.standardError);
        EXPECT_NEAR(f.mean, d.mean + i.mean, kSigmas * sigma) << "region " << x0 << "," << y0;
    }
}

TEST(PathTracer, LightSamplingWithMisAgreesWithBrdfSamplingAlone) {
    // Two estimators of the same integral: emissive triangles found by light sampling and BRDF
    // sampling combined by MIS, or by BRDF sampling alone. A wrong density or weight on either side
    // (area-to-solid-angle conversion, emitter choice, back faces, shadow rays) makes them differ.
    const Scene scene = makeTestRoom();
    PathTracer tracer = createPathTracer(scene);
    constexpr uint32_t kSize = 16;
    const RenderResult mis = render(tracer, smallRender(scene, kSize, 128, Component::Indirect, 31));
    tracer.sampleEmitters = false;
    const RenderResult brdfOnly = render(tracer, smallRender(scene, kSize, 128, Component::Indirect, 32));
    ASSERT_TRUE(allFinite(mis.image) && allFinite(brdfOnly.image));
    EXPECT_LT(mis.meanLuminanceStandardError, brdfOnly.meanLuminanceStandardError);  // why MIS is used
    const uint32_t h = kSize / 2;
    for (auto [x0, y0, x1, y1] : {std::array<uint32_t, 4>{0, 0, kSize, kSize},
                                  {0, 0, h, h},
                                  {h, 0, kSize, h},
                                  {0, h, h, kSize},
                                  {h, h, kSize, kSize}}) {
        const Estimate a = regionLuminance(mis, x0, y0, x1, y1);
        const Estimate b = regionLuminance(brdfOnly, x0, y0, x1, y1);
        EXPECT_NEAR(a.mean, b.mean, kSigmas * std::hypot(a.standardError, b.standardError))
            << "region " << x0 << "," << y0;
    }
}

TEST(Bvh, ClosestHitMatchesBruteForceOnRandomRays) {
    std::mt19937 random(1234);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    auto randomPoint = [&] { return glm::vec3(unit(random), unit(random), unit(random)); };
    Scene scene;
    addMaterial(scene, lambertian(glm::vec3(0.5f)));
    for (int i = 0; i < 400; ++i) {
        const glm::vec3 center = randomPoint();
        addTriangle(scene, center + 0.2f * randomPoint(), center + 0.2f * randomPoint(), center + 0.2f * randomPoint(),
                    0);
    }
    // Zero-area triangles: never hit, never a NaN.
    const glm::vec3 p = randomPoint();
    scene.vertices.push_back({p});
    scene.vertices.push_back({p});
    scene.vertices.push_back({p + glm::vec3(0.1f)});
    for (uint32_t i = 0; i < 3; ++i) scene.indices.push_back(uint32_t(scene.vertices.size()) - 3 + i);
    scene.triangleMaterials.push_back(0);

    const Bvh bvh = buildBvh(scene);
    int hits = 0;
    for (int i = 0; i < 5000; ++i) {
        const glm::vec3 origin = 2.0f * randomPoint();
        Ray ray{origin, glm::normalize(0.8f * randomPoint() - origin), 1e30f};
        std::optional<RayHit> expected;
        for (uint32_t t = 0; t < scene.triangleCount(); ++t) {
            const TrianglePositions tri{scene.vertices[scene.indices[3 * t]].position,
                                        scene.vertices[scene.indices[3 * t + 1]].position,
                                        scene.vertices[scene.indices[3 * t + 2]].position};
            Ray shortened = ray;
            shortened.tMax = expected ? expected->t : ray.tMax;
            if (std::optional<RayHit> hit = intersectTriangle(shortened, tri)) {
                expected = hit;
                expected->triangle = t;
            }
        }
        const std::optional<RayHit> actual = closestHit(bvh, ray);
        ASSERT_EQ(actual.has_value(), expected.has_value()) << "ray " << i;
        EXPECT_EQ(anyHit(bvh, ray), expected.has_value());
        if (!expected) continue;
        ++hits;
        EXPECT_EQ(actual->triangle, expected->triangle) << "ray " << i;
        EXPECT_EQ(actual->t, expected->t) << "ray " << i;
        ray.tMax = expected->t * 0.9999f;  // nothing lies nearer than the closest hit
        EXPECT_FALSE(anyHit(bvh, ray)) << "ray " << i;
    }
    EXPECT_GT(hits, 2500);
}

TEST(Bvh, WatertightGridLetsNoRayThroughSharedEdgesAndVertices) {
    Scene scene;
    addMaterial(scene, lambertian(glm::vec3(0.5f)));
    constexpr int kCells = 8;
    for (int i = 0; i < kCells; ++i) {
        for (int j = 0; j < kCells; ++j) {
            const float x = 0.1f * float(i), z = 0.1f * float(j);
            addQuad(scene,
                    {glm::vec3(x, 0.3f, z), glm::vec3(x + 0.1f, 0.3f, z), glm::vec3(x + 0.1f, 0.3f, z + 0.1f),
                     glm::vec3(x, 0.3f, z + 0.1f)},
                    glm::vec3(x, 1.0f, z), 0);
        }
    }
    const Bvh bvh = buildBvh(scene);
    // Rays aimed exactly at interior vertices and edge midpoints, from oblique directions.
    for (int i = 1; i < 2 * kCells; ++i) {
        for (int j = 1; j < 2 * kCells; ++j) {
            const glm::vec3 target(0.05f * float(i), 0.3f, 0.05f * float(j));
            for (const glm::vec3 from :
                 {glm::vec3(0.13f, 1.7f, -0.4f), glm::vec3(-1.0f, 2.0f, 0.3f), glm::vec3(0.4f, -1.3f, 0.4f)}) {
                const Ray ray{from, glm::normalize(target - from), 1e30f};
                EXPECT_TRUE(closestHit(bvh, ray).has_value()) << i << "," << j;
            }
        }
    }
}

// ∫ g(L) dω over the upper hemisphere about +z by the midpoint rule in (cosθ, φ), where dω = dcosθ dφ.
template <typename Integrand>
double integrateHemisphere(Integrand g) {
    constexpr int kSteps = 1000;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const float z = (float(i) + 0.5f) / kSteps, r = std::sqrt(1.0f - z * z);
        for (int j = 0; j < kSteps; ++j) {
            const float phi = 2.0f * kPi * (float(j) + 0.5f) / kSteps;
            sum += g(glm::vec3(r * std::cos(phi), r * std::sin(phi), z));
        }
    }
    return sum * 2.0 * kPi / (double(kSteps) * kSteps);
}

// Mean and standard error of g(sample) over sampleBsdf's draws, a failed draw counting as 0.
template <typename Estimator>
Estimate sampleMean(const SurfaceMaterial& material, const glm::vec3& V, int count, Estimator g) {
    Rng rng = Rng::forSample(9, 0, 0);
    double sum = 0.0, squares = 0.0;
    for (int i = 0; i < count; ++i) {
        const float uLobe = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        if (const std::optional<BsdfSample> s = sampleBsdf(material, glm::vec3(0, 0, 1), V, uLobe, u1, u2)) {
            const double value = g(*s);
            sum += value;
            squares += value * value;
        }
    }
    const double mean = sum / count;
    return {mean, std::sqrt(std::max(0.0, squares / count - mean * mean) / count)};
}

glm::vec3 viewAt(float NdotV) { return glm::vec3(std::sqrt(1.0f - NdotV * NdotV), 0.0f, NdotV); }

TEST(Bsdf, DensityIntegratesToTheShareOfSamplesAboveTheHorizon) {
    // Visible-normal samples reflected below the horizon are discarded, so the density over the
    // hemisphere integrates to the probability that a draw succeeds (1 for a pure diffuse lobe).
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    for (SurfaceMaterial material :
         {SurfaceMaterial{glm::vec3(1.0f), 1.0f, 0.5f, 1.0f}, SurfaceMaterial{glm::vec3(0.5f), 0.0f, 0.5f, 1.0f},
          SurfaceMaterial{glm::vec3(0.5f), 0.0f, 0.5f, 0.0f}}) {
        for (float roughness : {0.5f, 0.75f, 1.0f}) {
            material.roughness = roughness;
            for (float NdotV : {0.2f, 0.7f, 1.0f}) {
                const glm::vec3 V = viewAt(NdotV);
                const double integral = integrateHemisphere([&](glm::vec3 L) { return bsdfPdf(material, N, V, L); });
                const Estimate success = sampleMean(material, V, 200000, [](const BsdfSample&) { return 1.0; });
                EXPECT_LE(integral, 1.0 + kPdfIntegralTolerance);
                EXPECT_NEAR(integral, success.mean, kPdfIntegralTolerance)
                    << "metallic " << material.metallic << " roughness " << roughness << " N·V " << NdotV;
            }
        }
    }
}

TEST(Bsdf, SampledDirectionsFollowTheirDensity) {
    // If directions are drawn with density p, the mean of cosθ / p is ∫ cosθ dω = π (GGX's density is
    // positive over the whole hemisphere, so every direction can be drawn).
    SurfaceMaterial metal{glm::vec3(1.0f), 1.0f, 0.6f, 1.0f};
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    for (float roughness : {0.6f, 1.0f}) {
        metal.roughness = roughness;
        for (float NdotV : {0.3f, 0.9f}) {
            const glm::vec3 V = viewAt(NdotV);
            const Estimate estimate = sampleMean(metal, V, 400000, [&](const BsdfSample& s) {
                EXPECT_NEAR(s.pdf, bsdfPdf(metal, N, V, s.direction), 1e-3f * s.pdf);
                return double(s.direction.z) / s.pdf;
            });
            EXPECT_NEAR(estimate.mean, kPi, kSamplerTolerance * kPi) << "roughness " << roughness << " N·V " << NdotV;
        }
    }
}

TEST(Bsdf, WhiteMetalReflectsAtMostAllLightAndNeverNaN) {
    // Directional albedo ∫ f cosθ dω of a white metal, estimated with the sampler's weights: never
    // above 1, and equal to the quadrature where the lobe is wide enough for it.
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    for (float roughness : {0.0f, 0.05f, 0.3f, 0.6f, 1.0f}) {
        const SurfaceMaterial metal{glm::vec3(1.0f), 1.0f, roughness, 1.0f};
        for (float NdotV : {0.02f, 0.3f, 1.0f}) {
            const glm::vec3 V = viewAt(NdotV);
            const Estimate albedo = sampleMean(metal, V, 100000, [](const BsdfSample& s) {
                EXPECT_TRUE(std::isfinite(s.weight.x + s.weight.y + s.weight.z));
                return double(s.weight.x);
            });
            EXPECT_LE(albedo.mean, 1.0 + kSigmas * albedo.standardError)
                << "roughness " << roughness << " N·V " << NdotV;
            EXPECT_GT(albedo.mean, 0.25) << "roughness " << roughness << " N·V " << NdotV;
            if (roughness >= 0.6f) {
                const double reference =
                    integrateHemisphere([&](glm::vec3 L) { return double(evaluateBsdf(metal, N, V, L).x) * L.z; });
                EXPECT_NEAR(albedo.mean, reference, kSigmas * albedo.standardError + 0.002)
                    << "roughness " << roughness << " N·V " << NdotV;
            }
        }
    }
}

TEST(PathTracer, WhiteMetalSphereInUniformLightIsNoBrighterThanTheLight) {
    // A convex white metal reflects each direction's light once: radiance = directional albedo ≤ E.
    Scene scene;
    const uint32_t sky = addMaterial(scene, lambertian(glm::vec3(0.0f), glm::vec3(1.0f)));
    Material metal;
    metal.baseColorFactor = glm::vec4(1.0f);
    metal.metallic = 1.0f;
    metal.roughness = 0.5f;
    const uint32_t sphere = addMaterial(scene, metal);
    addInwardBox(scene, 2.0f, {sky, sky, sky, sky, sky, sky});
    addSphere(scene, glm::vec3(0.0f), 0.6f, sphere, 24, 48);
    scene.cameras.push_back(cameraLookingAt(glm::vec3(0.0f, 0.3f, 1.8f), glm::vec3(0.0f), 0.9f));
    const PathTracer tracer = createPathTracer(scene);
    const RenderResult result = render(tracer, smallRender(scene, 24, 32, Component::Full, 21));
    ASSERT_TRUE(allFinite(result.image));
    EXPECT_EQ(result.discardedSamples, 0u);
    for (uint32_t y = 0; y < 24; ++y) {
        for (uint32_t x = 0; x < 24; ++x) {
            const double sigma = std::sqrt(result.luminanceVariance[size_t(y) * 24 + x]);
            for (int c = 0; c < 3; ++c) EXPECT_LE(result.image.pixel(x, y)[c], 1.0 + 1e-5 + kSigmas * sigma);
        }
    }
    // The sphere's centre, seen head-on: the directional albedo at N·V = 1, which needs light sampling
    // and BRDF sampling to be combined correctly.
    const glm::vec3 N(0.0f, 0.0f, 1.0f);
    const SurfaceMaterial white{glm::vec3(1.0f), 1.0f, metal.roughness, 1.0f};
    const double albedo = integrateHemisphere([&](glm::vec3 L) { return evaluateBsdf(white, N, N, L).x * L.z; });
    const double sigma = std::sqrt(result.luminanceVariance[12 * 24 + 12]);
    EXPECT_NEAR(result.image.pixel(12, 12)[0], albedo, kSigmas * sigma + 0.01 * albedo);
}

}  // namespace
}  // namespace vct::pt
