// The sky (Scene::environment): seen by camera rays that meet nothing, gathered by the cones that
// leave the voxel grid, and reflected by the specular cone, against analytic values; and hidden
// from the ground by a slab hovering closer than the cones' start offset (cone_start.glsl). An
// environment image (Scene::environmentMap) is seen where its directions point and lights as the
// uniform sky of its radiance does.
#include <array>
#include <cmath>
#include <cstdio>

#include <glm/gtc/type_ptr.hpp>

#include "../cpu/environment_images.h"
#include "gpu_test.h"
#include "luminance.h"
#include "path_tracer.h"
#include "render/renderer.h"

namespace vct::test {
namespace {

constexpr glm::vec3 kSky{0.2f, 0.4f, 0.8f};

// A 2 m square at y = 0 facing up, under the sky alone, seen straight down from 1 m with a view
// 4 m wide: the plane fills the middle half of the image, the sky the rest.
Scene planeUnderTheSky(const Material& material) {
    Scene scene;
    scene.name = "plane under the sky";
    scene.materials.push_back(material);
    for (auto [x, z] : {std::pair{-1.0f, -1.0f}, {-1.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, -1.0f}})
        scene.vertices.push_back({glm::vec3(x, 0.0f, z), 0.0f, glm::vec3(0.0f, 1.0f, 0.0f), 0.0f});
    scene.indices = {0, 1, 2, 0, 2, 3};
    scene.triangleMaterials = {0, 0};
    scene.environment = kSky;
    Camera above;
    above.position = glm::vec3(0.0f, 1.0f, 0.0f);
    above.forward = glm::vec3(0.0f, -1.0f, 0.0f);
    above.up = glm::vec3(0.0f, 0.0f, -1.0f);
    above.yfov = 2.0f * std::atan(2.0f);
    above.znear = 0.01f;
    scene.cameras.push_back(above);
    return scene;
}

// Albedo 0.5, no specular reflection.
Material greyLambertian() {
    Material grey;
    grey.baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    grey.metallic = 0.0f;
    grey.specularWeight = 0.0f;
    return grey;
}

RenderSettings smallSettings(RenderMode mode) {
    RenderSettings settings;
    settings.image.width = settings.image.height = 32;
    settings.image.supersample = 1;
    settings.resources.voxelResolution = 64;
    settings.shading.mode = mode;
    return settings;
}

// The mean of the 8 × 8 pixels at the image's centre (all plane) and of its leftmost column (sky).
struct PlaneAndSky {
    glm::vec3 plane{0.0f}, sky{0.0f};
};
PlaneAndSky measure(const Image& image) {
    PlaneAndSky result;
    for (uint32_t y = 12; y < 20; ++y)
        for (uint32_t x = 12; x < 20; ++x) result.plane += glm::make_vec3(image.pixel(x, y)) / 64.0f;
    for (uint32_t y = 0; y < 32; ++y) result.sky += glm::make_vec3(image.pixel(0, y)) / 32.0f;
    return result;
}

class Environment : public GpuTest {};

TEST_F(Environment, TheSkyIsSeenDirectlyAndLightsAnOpenPlaneIndirectly) {
    // A grey Lambertian plane (albedo 0.5) gets irradiance π·L from the sky's hemisphere: radiance
    // 0.5·L, all of it indirect (gathered by cones that leave the grid having met nothing); the
    // pixels past its edge see L, as direct light. The path tracer's test of the same scene holds it
    // to 1e-4; the cones to 2 %, what their start above the plane's own voxels may cost.
    const Material grey = greyLambertian();
    const Scene scene = planeUnderTheSky(grey);
    for (RenderMode mode : {RenderMode::Full, RenderMode::Direct, RenderMode::Indirect}) {
        Renderer renderer(gpu(), scene, smallSettings(mode));
        renderer.renderFrame();
        const PlaneAndSky seen = measure(renderer.readImage());
        const bool direct = mode != RenderMode::Indirect, indirect = mode != RenderMode::Direct;
        std::printf("[ sky ] %s: plane (%.4f %.4f %.4f), sky (%.4f %.4f %.4f)\n", renderModeName(mode), seen.plane.r,
                    seen.plane.g, seen.plane.b, seen.sky.r, seen.sky.g, seen.sky.b);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(seen.plane[c], indirect ? 0.5f * kSky[c] : 0.0f, 0.02f * 0.5f * kSky[c])
                << renderModeName(mode);
            EXPECT_NEAR(seen.sky[c], direct ? kSky[c] : 0.0f, 1e-3f) << renderModeName(mode);
        }
    }
}

TEST_F(Environment, SwitchingEmissionOffLeavesTheSkySeen) {
    // `--disable emission` removes emissive surfaces' light, not the sky: the pixels past the
    // plane's edge still see L, and the plane its light.
    const Scene scene = planeUnderTheSky(greyLambertian());
    RenderSettings settings = smallSettings(RenderMode::Full);
    settings.shading.components.emission = false;
    Renderer renderer(gpu(), scene, settings);
    renderer.renderFrame();
    const PlaneAndSky seen = measure(renderer.readImage());
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(seen.sky[c], kSky[c], 1e-3f);
        EXPECT_NEAR(seen.plane[c], 0.5f * kSky[c], 0.02f * 0.5f * kSky[c]);
    }
}

TEST_F(Environment, AMirrorReflectsTheSky) {
    // White metal of roughness 0.1: the specular cone along the reflection leaves the grid and
    // returns L, times the lobe's directional albedo. With F0 = 1 that is A + B of the split-sum fit
    // the renderer uses (cone_tracing.glsl environmentBrdf, Karis 2014): 0.9400 + 0.0050 head on.
    Material mirror;
    mirror.baseColorFactor = glm::vec4(1.0f);
    mirror.metallic = 1.0f;
    mirror.roughness = 0.1f;
    Renderer renderer(gpu(), planeUnderTheSky(mirror), smallSettings(RenderMode::Indirect));
    renderer.renderFrame();
    const PlaneAndSky seen = measure(renderer.readImage());
    std::printf("[ sky ] mirror: (%.4f %.4f %.4f)\n", seen.plane.r, seen.plane.g, seen.plane.b);
    const float lobeAlbedo = 0.9450f;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(seen.plane[c], lobeAlbedo * kSky[c], 0.01f * kSky[c]);
}

// Adds an axis-aligned box with outward faces, two triangles a face, in `material`.
void addBox(Scene& scene, glm::vec3 lo, glm::vec3 hi, uint32_t material) {
    for (int axis = 0; axis < 3; ++axis) {
        for (float side : {-1.0f, 1.0f}) {
            glm::vec3 normal(0.0f);
            normal[axis] = side;
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const uint32_t first = uint32_t(scene.vertices.size());
            for (auto [a, b] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
                glm::vec3 corner = side > 0.0f ? hi : lo;
                corner[u] = a ? hi[u] : lo[u];
                corner[v] = b ? hi[v] : lo[v];
                scene.vertices.push_back({corner, 0.0f, normal, 0.0f});
            }
            // Counter-clockwise seen from outside: the voxelizer takes a triangle's side from its winding.
            const std::array<uint32_t, 6> order =
                side > 0.0f ? std::array<uint32_t, 6>{0, 1, 2, 0, 2, 3} : std::array<uint32_t, 6>{0, 2, 1, 0, 3, 2};
            for (uint32_t index : order) scene.indices.push_back(first + index);
            scene.triangleMaterials.insert(scene.triangleMaterials.end(), {material, material});
        }
    }
}

TEST_F(Environment, UnderASlabTheGroundSeesTheSlabNotTheSkyThroughIt) {
    // A black slab hovers 35 mm over the grey plane, less than the cones' start offset (1.5 voxels
    // of a 64³ grid over 2 m: 48 mm): cones that started at the offset began inside the slab, and
    // its one-sided voxels, empty seen from behind, let them through to the sky. The ground under
    // it sees the slab's black underside nearly everywhere. Seen from a camera in the gap, looking
    // along it.
    const Material grey = greyLambertian();
    Scene scene = planeUnderTheSky(grey);
    Material black = grey;
    black.baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    scene.materials.push_back(black);
    addBox(scene, glm::vec3(-0.4f, 0.035f, -0.4f), glm::vec3(0.4f, 0.15f, 0.4f), 1);
    Camera inTheGap;
    inTheGap.position = glm::vec3(-0.99f, 0.0175f, 0.0f);
    inTheGap.forward = glm::vec3(1.0f, 0.0f, 0.0f);
    inTheGap.up = glm::vec3(0.0f, 1.0f, 0.0f);
    inTheGap.yfov = glm::radians(4.0f);
    inTheGap.znear = 0.001f;
    scene.cameras = {inTheGap};
    Renderer renderer(gpu(), scene, smallSettings(RenderMode::Indirect));
    renderer.renderFrame();
    const Image image = renderer.readImage();
    // The ground 0.6-1.4 m ahead lies 0.7-1.7° below the view axis: image rows 22-29 (row 0 at
    // the top); the middle 0.8-1.2 m of it, under the slab's middle, rows 23-26.
    glm::vec3 underTheSlab(0.0f);
    for (uint32_t y = 23; y <= 26; ++y)
        for (uint32_t x = 12; x < 20; ++x) underTheSlab += glm::make_vec3(image.pixel(x, y)) / 32.0f;
    std::printf("[ sky ] under the slab: (%.4f %.4f %.4f), open ground 0.5 L = (%.4f %.4f %.4f)\n", underTheSlab.r,
                underTheSlab.g, underTheSlab.b, 0.5f * kSky.r, 0.5f * kSky.g, 0.5f * kSky.b);
    // The truth: the sky through the gap, below 5° of elevation, 0.8 % of the open ground's. Cones
    // starting inside the slab gathered 13.5 %.
    for (int c = 0; c < 3; ++c) EXPECT_LT(underTheSlab[c], 0.03f * 0.5f * kSky[c]);
}

TEST_F(Environment, AnImageOfOneRadianceLightsThePlaneAsThatUniformSkyDoes) {
    // The same plane under a 32 × 16 image holding kSky in every texel: the cones read it through
    // its mip chain, so plane and sky must come out as under the uniform sky (the test above).
    const Material grey = greyLambertian();
    Scene scene = planeUnderTheSky(grey);
    scene.environment = glm::vec3(2.0f);  // the factor on the image
    scene.environmentMap = makeEnvironmentMap(32, 16, [](uint32_t, uint32_t) { return 0.5f * kSky; });
    Renderer renderer(gpu(), scene, smallSettings(RenderMode::Full));
    renderer.renderFrame();
    const PlaneAndSky seen = measure(renderer.readImage());
    std::printf("[ sky image ] plane (%.4f %.4f %.4f), sky (%.4f %.4f %.4f)\n", seen.plane.r, seen.plane.g,
                seen.plane.b, seen.sky.r, seen.sky.g, seen.sky.b);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(seen.plane[c], 0.5f * kSky[c], 0.02f * 0.5f * kSky[c]);
        EXPECT_NEAR(seen.sky[c], kSky[c], 1e-3f);
    }
}

TEST_F(Environment, TheCameraSeesTheImageWhereItsDirectionsPoint) {
    // Looking along −Z over the plane with a 30° view: the sky above the horizon is red on the left
    // (x < 0) and green on the right, as the image's halves (the path tracer reads the same); the
    // ±3° around the meridian blend the two, and the rows near the horizon the black below it.
    // Turned (--environment-rotation), the image is seen where the turn takes its directions.
    Scene scene = planeUnderTheSky(Material{});
    scene.environment = glm::vec3(1.0f);
    scene.environmentMap = redLeftGreenRightSky();
    Camera& camera = scene.cameras.front();
    camera.position = glm::vec3(0.0f, 1.0f, 3.0f);
    camera.forward = glm::vec3(0.0f, 0.0f, -1.0f);
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    camera.yfov = glm::radians(30.0f);
    Renderer renderer(gpu(), scene, smallSettings(RenderMode::Direct));
    // Turned half way round the halves swap; a quarter turn counter-clockwise seen from above
    // brings what the image showed along +X, green, ahead (the other way round, red).
    constexpr float kQuarterTurn = 1.57079633f;
    for (const float turn : {0.0f, 2.0f * kQuarterTurn, kQuarterTurn, -kQuarterTurn}) {
        renderer.setEnvironmentRotation(turn);
        renderer.renderFrame();
        const Image image = renderer.readImage();
        for (uint32_t y = 0; y < 10; ++y)
            for (uint32_t x = 0; x < 32; ++x) {
                const bool halves = turn == 0.0f || turn == 2.0f * kQuarterTurn;  // the meridian ahead
                if (halves && x >= 12 && x < 20) continue;
                const bool red = halves ? (x < 16) == (turn == 0.0f) : turn < 0.0f;
                const glm::vec3 seen = glm::make_vec3(image.pixel(x, y));
                const glm::vec3 expected = red ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(seen[c], expected[c], 1e-3f) << x << "," << y << " channel " << c << " turned " << turn;
            }
    }
}

TEST_F(Environment, AnImagesSunCastsTheShadowThePathTracerSees) {
    // A 0.6 m grey box on the grey plane under a sky image whose 4 × 4-texel sun (radiance 2000, 45°
    // up) holds nearly all its light, seen from straight above. Through the cones alone the sun was blurred over their
    // aperture and the box cast no shadow; lit as a sun, its shadow falls where the path tracer,
    // which reads the whole image, finds it, and the light around it is the path tracer's.
    const Material grey = greyLambertian();
    Scene scene = planeUnderTheSky(grey);
    addBox(scene, glm::vec3(-0.3f, 0.0f, -0.3f), glm::vec3(0.3f, 0.6f, 0.3f), 0);
    // Seen from high above, so that the box's top hides little of the ground around it.
    Camera& above = scene.cameras.front();
    above.position = glm::vec3(0.0f, 10.0f, 0.0f);
    above.yfov = 2.0f * std::atan(0.2f);
    scene.environment = glm::vec3(1.0f);
    scene.environmentMap = makeEnvironmentMap(64, 32, [](uint32_t x, uint32_t y) {
        if (x >= 40 && x < 44 && y >= 6 && y < 10) return glm::vec3(2000.0f);
        return y < 16 ? glm::vec3(0.02f, 0.04f, 0.08f) : glm::vec3(0.0f);
    });
    RenderSettings settings = smallSettings(RenderMode::Full);
    settings.image.supersample = 2;
    Renderer renderer(gpu(), scene, settings);
    renderer.renderFrame();
    const Image image = renderer.readImage();

    pt::PathTracer tracer = pt::createPathTracer(scene);
    pt::RenderSettings reference;
    reference.width = reference.height = 32;
    reference.samplesPerPixel = 256;
    reference.threads = 2;
    reference.camera = scene.cameras.front();
    const Image truth = pt::render(tracer, reference).image;

    // The plane's pixels (the middle half of the image) outside the box's top, split by the truth
    // into the box's umbra and the sunlit ground. (The painted sun is 22° wide: the truth's
    // penumbra is wide, the directional light's narrow; the pixels between are left out.)
    auto luminance = [](const Image& from, uint32_t x, uint32_t y) {
        return glsl::luminance(glm::make_vec3(from.pixel(x, y)));
    };
    double litTruth = 0.0, litSeen = 0.0, shadowTruth = 0.0, shadowSeen = 0.0;
    int lit = 0, shadowed = 0;
    float brightest = 0.0f;
    for (uint32_t y = 8; y < 24; ++y)
        for (uint32_t x = 8; x < 24; ++x) brightest = std::max(brightest, luminance(truth, x, y));
    for (uint32_t y = 9; y < 23; ++y)
        for (uint32_t x = 9; x < 23; ++x) {
            if (x >= 13 && x < 19 && y >= 13 && y < 19) continue;  // the box's top
            const float t = luminance(truth, x, y), seen = luminance(image, x, y);
            if (t < 0.06f * brightest) {
                shadowTruth += t;
                shadowSeen += seen;
                ++shadowed;
            } else if (t > 0.8f * brightest) {
                litTruth += t;
                litSeen += seen;
                ++lit;
            }
        }
    std::printf("[ sky sun ] sunlit ground %.3f (path tracer %.3f, %d pixels), in the box's umbra %.3f (%.3f, %d)\n",
                litSeen / lit, litTruth / lit, lit, shadowSeen / shadowed, shadowTruth / shadowed, shadowed);
    ASSERT_GE(shadowed, 6);
    ASSERT_GE(lit, 20);
    EXPECT_NEAR(litSeen / lit, litTruth / lit, 0.05 * litTruth / lit);
    // The umbra is as dark beside the sunlit ground as the truth's, within 2 % of the sunlit ground's
    // light (through the cones alone the box cast no shadow). Its own light, the sky's and what the
    // box's shaded faces bounce, measured 0.16 against the truth's 0.23.
    EXPECT_NEAR(shadowSeen / shadowed, shadowTruth / shadowed, 0.02 * litTruth / lit);
}

}  // namespace
}  // namespace vct::test
