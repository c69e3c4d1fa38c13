// Direct light against closed-form answers: a Lambertian surface lit by a punctual light has
// radiance L = E · albedo / π with E = I·cosθ/d² (point), × the spot falloff (spot), or
// E·cosθ (sun), in the scene's own units (KHR_lights_punctual, no 683 lm/W factor).
#include <cmath>
#include <optional>

#include "gpu_test.h"
#include "render/camera.h"
#include "render/renderer.h"
#include "scene/load.h"

namespace vct::test {
namespace {

constexpr float kPi = 3.14159265358979f;

struct Hit {
    float distance;
    uint32_t triangle;
    glm::vec3 position;
    glm::vec3 normal;
};

// Brute-force closest hit (Möller–Trumbore); the test scenes have a few dozen triangles.
std::optional<Hit> intersect(const Scene& scene, glm::vec3 origin, glm::vec3 direction, float maxDistance) {
    std::optional<Hit> best;
    for (uint32_t t = 0; t < scene.triangleCount(); ++t) {
        const glm::vec3 a = scene.vertices[scene.indices[3 * t]].position;
        const glm::vec3 b = scene.vertices[scene.indices[3 * t + 1]].position;
        const glm::vec3 c = scene.vertices[scene.indices[3 * t + 2]].position;
        const glm::vec3 e1 = b - a, e2 = c - a;
        const glm::vec3 p = glm::cross(direction, e2);
        const float det = glm::dot(e1, p);
        if (std::abs(det) < 1e-12f) continue;
        const glm::vec3 s = origin - a;
        const float u = glm::dot(s, p) / det;
        const glm::vec3 q = glm::cross(s, e1);
        const float v = glm::dot(direction, q) / det;
        const float distance = glm::dot(e2, q) / det;
        if (u < 0 || v < 0 || u + v > 1 || distance <= 1e-5f || distance >= maxDistance) continue;
        if (!best || distance < best->distance)
            best = Hit{distance, t, origin + direction * distance, glm::normalize(glm::cross(e1, e2))};
    }
    return best;
}

glm::vec3 pixelRay(const Camera& camera, uint32_t x, uint32_t y, uint32_t width, uint32_t height) {
    const glm::vec3 forward = glm::normalize(camera.forward);
    const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::vec3 up = glm::cross(right, forward);
    const float tanHalf = std::tan(0.5f * camera.yfov);
    const float ndcX = (float(x) + 0.5f) / float(width) * 2.0f - 1.0f;
    const float ndcY = (float(y) + 0.5f) / float(height) * 2.0f - 1.0f;  // row 0 is the top
    return glm::normalize(forward + right * (ndcX * tanHalf * float(width) / float(height)) - up * (ndcY * tanHalf));
}

RenderSettings directSettings(uint32_t size) {
    RenderSettings settings;
    settings.image.width = size;
    settings.image.height = size;
    settings.image.supersample = 1;  // one sample at the pixel centre, where the analytic value is computed
    settings.shading.mode = RenderMode::Direct;
    return settings;
}

class CornellDirect : public GpuTest {};

TEST_F(CornellDirect, LitPixelsMatchPointLightOverLambertianWithinOnePercentAndShadowsAreDark) {
    const Scene scene = loadScene("cornell");
    const uint32_t size = 128;
    Renderer renderer(gpu(), scene, directSettings(size));
    renderer.renderFrame();
    const Image image = renderer.readImage();
    const Light& light = scene.lights.at(0);
    const Camera& camera = scene.cameras.at(0);

    struct Expected {
        bool valid;
        glm::vec4 plane;  // normal, offset: neighbours on another plane mean an edge is near
        bool shadowed;
        float radiance[3];
    };
    std::vector<Expected> expected(size * size);
    for (uint32_t y = 0; y < size; ++y) {
        for (uint32_t x = 0; x < size; ++x) {
            Expected& e = expected[y * size + x];
            e.valid = false;
            const std::optional<Hit> hit = intersect(scene, camera.position, pixelRay(camera, x, y, size, size), 1e9f);
            if (!hit) continue;
            e.valid = true;
            e.plane = glm::vec4(hit->normal, glm::dot(hit->normal, hit->position));
            glm::vec3 normal = hit->normal;
            if (glm::dot(normal, camera.position - hit->position) < 0) normal = -normal;  // two-sided
            const glm::vec3 toLight = light.position - hit->position;
            const float distance = glm::length(toLight);
            const float cosTheta = glm::dot(normal, toLight / distance);
            e.shadowed =
                cosTheta <= 0 ||
                intersect(scene, hit->position + normal * 1e-4f, toLight / distance, distance - 1e-4f).has_value();
            const glm::vec3 albedo = glm::vec3(scene.materials[scene.triangleMaterials[hit->triangle]].baseColorFactor);
            const glm::vec3 radiance =
                e.shadowed ? glm::vec3(0.0f)
                           : light.intensity * light.color * cosTheta / (distance * distance) * albedo / kPi;
            for (int c = 0; c < 3; ++c) e.radiance[c] = radiance[c];
        }
    }

    int litChecked = 0, shadowChecked = 0;
    for (uint32_t y = 2; y + 2 < size; ++y) {
        for (uint32_t x = 2; x + 2 < size; ++x) {
            const Expected& e = expected[y * size + x];
            if (!e.valid) continue;
            // Only pixels two pixels (≈ 12 mm) inside one surface and one side of a shadow edge: the
            // 5×5 PCF kernel plus the normal offset blur about 5 mm around an edge seen from the light.
            bool uniform = true;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) {
                    const Expected& n = expected[(y + dy) * size + (x + dx)];
                    uniform &= n.valid && n.shadowed == e.shadowed && glm::distance(n.plane, e.plane) < 1e-4f;
                }
            if (!uniform) continue;
            const float* actual = image.pixel(x, y);
            for (int c = 0; c < 3; ++c) {
                ASSERT_TRUE(std::isfinite(actual[c]));
                if (e.shadowed) {
                    EXPECT_LT(actual[c], 1e-4f) << "shadowed pixel " << x << "," << y << " is lit";
                } else if (e.radiance[c] > 1e-3f) {
                    EXPECT_NEAR(actual[c], e.radiance[c], 0.01f * e.radiance[c]) << "pixel " << x << "," << y;
                }
            }
            (e.shadowed ? shadowChecked : litChecked)++;
        }
    }
    EXPECT_GT(litChecked, 5000) << "too few lit pixels were compared";
    EXPECT_GT(shadowChecked, 300) << "too few shadowed pixels were compared";
}

TEST_F(CornellDirect, EveryModeIsFiniteAndNonNegative) {
    const Scene scene = loadScene("cornell");
    for (RenderMode mode : {RenderMode::Full, RenderMode::Direct, RenderMode::Indirect}) {
        RenderSettings settings = directSettings(64);
        settings.shading.mode = mode;
        settings.image.supersample = 2;
        Renderer renderer(gpu(), scene, settings);
        renderer.renderFrame();
        for (float value : renderer.readImage().rgb) {
            ASSERT_TRUE(std::isfinite(value)) << renderModeName(mode);
            ASSERT_GE(value, 0.0f) << renderModeName(mode);
        }
    }
}

// A large white Lambertian floor (y = 0) seen from above, lit by one light.
Scene floorScene(const Light& light) {
    Scene scene;
    scene.name = "floor";
    Material white;
    white.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    white.metallic = 0.0f;
    white.specularWeight = 0.0f;
    scene.materials.push_back(white);
    const float h = 4.0f;
    for (glm::vec3 p : {glm::vec3(-h, 0, -h), glm::vec3(-h, 0, h), glm::vec3(h, 0, h), glm::vec3(h, 0, -h)})
        scene.vertices.push_back({p, 0.0f, glm::vec3(0, 1, 0), 0.0f});
    scene.indices = {0, 1, 2, 0, 2, 3};
    scene.triangleMaterials = {0, 0};
    scene.lights.push_back(light);
    Camera camera;
    camera.yfov = glm::radians(60.0f);
    aimCamera(camera, glm::vec3(0.0f, 3.0f, 0.0f), glm::vec3(0.0f));
    camera.up = glm::vec3(0.0f, 0.0f, -1.0f);  // looking straight down
    scene.cameras.push_back(camera);
    return scene;
}

// Renders the floor and compares every pixel whose floor point is known against `irradiance`.
template <typename Irradiance>
void expectFloorMatches(const Scene& scene, Irradiance irradiance) {
    const uint32_t size = 48;
    Renderer renderer(gpu(), scene, directSettings(size));
    renderer.renderFrame();
    const Image image = renderer.readImage();
    const Camera& camera = scene.cameras[0];
    int compared = 0;
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const glm::vec3 direction = pixelRay(camera, x, y, size, size);
            const float t = -camera.position.y / direction.y;
            const glm::vec3 point = camera.position + direction * t;
            const float expected = irradiance(point) * 0.8f / kPi;
            if (expected < 1e-3f) continue;
            EXPECT_NEAR(image.pixel(x, y)[0], expected, 0.01f * expected) << "pixel " << x << "," << y;
            ++compared;
        }
    EXPECT_GT(compared, 200);
}

class DirectLight : public GpuTest {};

TEST_F(DirectLight, SunGivesIlluminanceTimesCosine) {
    Light sun;
    sun.type = LightType::Directional;
    sun.intensity = 2.0f;
    sun.direction = glm::normalize(glm::vec3(1.0f, -2.0f, 0.5f));
    expectFloorMatches(floorScene(sun), [&](glm::vec3) { return 2.0f * -sun.direction.y; });
}

TEST_F(DirectLight, PointLightFallsOffWithInverseSquareDistance) {
    Light point;
    point.type = LightType::Point;
    point.intensity = 5.0f;
    point.position = glm::vec3(0.5f, 1.5f, -0.3f);
    expectFloorMatches(floorScene(point), [&](glm::vec3 p) {
        const glm::vec3 toLight = point.position - p;
        const float d = glm::length(toLight);
        return 5.0f * (toLight.y / d) / (d * d);
    });
}

TEST_F(DirectLight, SpotLightFollowsTheKhrConeFalloff) {
    Light spot;
    spot.type = LightType::Spot;
    spot.intensity = 5.0f;
    spot.position = glm::vec3(0.0f, 1.5f, 0.0f);
    spot.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    spot.innerConeAngle = 0.3f;
    spot.outerConeAngle = 0.6f;
    expectFloorMatches(floorScene(spot), [&](glm::vec3 p) {
        const glm::vec3 toLight = spot.position - p;
        const float d = glm::length(toLight);
        // KHR_lights_punctual: smooth ramp from cos(outer) to cos(inner), squared.
        const float cd = glm::dot(spot.direction, -toLight / d);
        const float ramp = glm::clamp((cd - std::cos(0.6f)) / (std::cos(0.3f) - std::cos(0.6f)), 0.0f, 1.0f);
        return 5.0f * (toLight.y / d) / (d * d) * ramp * ramp;
    });
}

// A wall of zero thickness standing on a floor, the sun behind it: the floor along the crease is in
// the wall's shadow however close to the wall it lies. Seen from close by (a pixel covers about
// 3 mm), every pixel the wall shadows must be dark. A slope-scaled depth bias on the wall, which
// the sun sees nearly edge on, and a PCF kernel as wide at contact as far away lit a strip a few
// millimetres wide along such creases (the sun room's direct light had relMSE 3.2 from it).
TEST_F(DirectLight, AWallStandingOnAFloorShadowsItRightUpToTheCrease) {
    Scene scene = floorScene(Light{});
    scene.lights[0].type = LightType::Directional;
    scene.lights[0].intensity = 3.0f;
    scene.lights[0].direction = glm::normalize(glm::vec3(0.35f, -1.0f, 0.25f));
    // The wall x = 0, 2 m high, across the floor.
    const uint32_t first = uint32_t(scene.vertices.size());
    for (glm::vec3 p : {glm::vec3(0, 0, -4), glm::vec3(0, 2, -4), glm::vec3(0, 2, 4), glm::vec3(0, 0, 4)})
        scene.vertices.push_back({p, 0.0f, glm::vec3(1, 0, 0), 0.0f});
    for (uint32_t index : {0u, 1u, 2u, 0u, 2u, 3u}) scene.indices.push_back(first + index);
    scene.triangleMaterials.insert(scene.triangleMaterials.end(), {0, 0});
    Camera& camera = scene.cameras[0];
    camera.yfov = glm::radians(40.0f);
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    aimCamera(camera, glm::vec3(0.4f, 0.4f, 0.1f), glm::vec3(0.0f, 0.0f, 0.0f));

    const uint32_t size = 128;
    Renderer renderer(gpu(), scene, directSettings(size));
    renderer.renderFrame();
    const Image image = renderer.readImage();
    const glm::vec3 toSun = -scene.lights[0].direction;
    const float litFloor = 3.0f * toSun.y * 0.8f / kPi;
    int shadowed = 0, lit = 0;
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const std::optional<Hit> hit = intersect(scene, camera.position, pixelRay(camera, x, y, size, size), 1e9f);
            ASSERT_TRUE(hit.has_value());
            glm::vec3 normal = hit->normal;
            if (glm::dot(normal, camera.position - hit->position) < 0) normal = -normal;
            const bool dark = glm::dot(normal, toSun) <= 0.0f ||
                              intersect(scene, hit->position + normal * 1e-5f, toSun, 1e9f).has_value();
            if (dark) {
                ++shadowed;
                EXPECT_LT(image.pixel(x, y)[0], 0.01f * litFloor) << "shadowed pixel " << x << "," << y << " is lit";
            } else {
                ++lit;
            }
        }
    EXPECT_GT(shadowed, 4000) << "the view should hold the shadowed crease";
}

}  // namespace
}  // namespace vct::test
