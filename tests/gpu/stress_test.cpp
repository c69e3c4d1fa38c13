// Numerical stress: inputs at the edges of what a scene can hold, each rendered on lavapipe and
// held to "no NaN or Inf anywhere (image and voxel volume) and a bounded result". Tolerances are
// measured and stated in kTolerances.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "bench/failure_modes.h"
#include "error.h"
#include "gpu/readback.h"
#include "gpu_test.h"
#include "render/renderer.h"
#include "scene/load.h"

namespace vct::test {
namespace {

struct Tolerances {
    double degenerateTriangles = 1e-6;  // relative L1 change from adding zero-area/collinear triangles
    double zeroNormalsDirect = 0.01;    // relative L1, direct light, zero normals vs. face normals
    double scaled = 0.02;               // relative L1, the Cornell box scaled by 1e-3 or 1e4 vs. 1
    double translated = 0.03;           // relative L1, translated by +1e4 m vs. at the origin (positions
                                        // stored in float there are 1 mm apart: 0.9 % direct, 2.4 % indirect)
    double intensityLinearity = 1e-3;   // relative L1 between image / intensity at 1e-4 … 1e6 and at 1
    double flatSceneIndirect = 0.01;    // indirect / direct mean of a lone plane (truth: 0)
    double wallOnVoxelBoundary = 0.10;  // lit-room mean, wall on a voxel boundary vs. inside a voxel
};
constexpr Tolerances kTolerances;

RenderSettings smallSettings(uint32_t size = 32, uint32_t voxels = 32) {
    RenderSettings settings;
    settings.image.width = settings.image.height = size;
    settings.image.supersample = 1;
    settings.resources.voxelResolution = voxels;
    settings.resources.sunShadowMapSize = 512;
    settings.resources.localShadowMapSize = 256;
    return settings;
}

// Every level of the radiance volume (and of the directional chains) is finite; returns the largest
// stored value, which must stay inside float16 (65504).
float expectFiniteVolume(Renderer& renderer, const char* what) {
    float largest = 0.0f;
    std::vector<const GpuImage*> volumes = {&renderer.volumes().radiance};
    for (const GpuImage* volume : volumes)
        for (uint32_t level = 0; level < volume->desc.mipLevels; ++level)
            for (const glm::vec4& voxel : readImage3D(gpu(), *volume, level))
                for (int c = 0; c < 4; ++c) {
                    EXPECT_TRUE(std::isfinite(voxel[c])) << what << ", level " << level;
                    if (!std::isfinite(voxel[c])) return largest;
                    largest = std::max(largest, voxel[c]);
                }
    return largest;
}

// Renders one frame and checks the image is finite and not negative (and, optionally, the volume).
Image render(Renderer& renderer, const char* what, bool checkVolume = true) {
    renderer.renderFrame();
    Image image = renderer.readImage();
    EXPECT_TRUE(bench::allFiniteAndNonNegative(image)) << what;
    if (checkVolume) expectFiniteVolume(renderer, what);
    return image;
}

Image render(const Scene& scene, const RenderSettings& settings, const char* what, bool checkVolume = true) {
    Renderer renderer(gpu(), scene, settings);
    return render(renderer, what, checkVolume);
}

// The Cornell box with every length (and its camera's near plane) multiplied by `scale`, moved by
// `offset`, and point-light intensities multiplied by scale² so that the radiance is unchanged.
Scene transformedCornell(float scale, glm::vec3 offset) {
    Scene scene = loadScene("cornell");
    for (Vertex& vertex : scene.vertices) vertex.position = vertex.position * scale + offset;
    for (Light& light : scene.lights) {
        light.position = light.position * scale + offset;
        light.intensity *= scale * scale;
    }
    for (Camera& camera : scene.cameras) {
        camera.position = camera.position * scale + offset;
        camera.znear *= scale;
    }
    return scene;
}

class Stress : public GpuTest {};
class StressGuard : public Stress {};

TEST_F(Stress, DegenerateTrianglesChangeNothing) {
    const Scene cornell = loadScene("cornell");
    Scene scene = cornell;
    const glm::vec3 a(0.1f, 0.2f, 0.3f), b(0.4f, 0.2f, 0.3f);
    const uint32_t first = uint32_t(scene.vertices.size());
    // A point (three equal corners), a segment (collinear corners), a triangle repeating an index.
    for (glm::vec3 p : {a, a, a, a, 0.5f * (a + b), b, a, b}) scene.vertices.push_back({p, 0.0f, {0, 1, 0}, 0.0f});
    for (uint32_t index : {0u, 1u, 2u, 3u, 4u, 5u, 6u, 7u, 7u}) scene.indices.push_back(first + index);
    for (int i = 0; i < 3; ++i) scene.triangleMaterials.push_back(0);
    const Image expected = render(cornell, smallSettings(), "cornell");
    const Image actual = render(scene, smallSettings(), "with degenerate triangles");
    EXPECT_LE(bench::relativeL1Difference(expected, actual), kTolerances.degenerateTriangles);
}

TEST_F(Stress, ZeroLengthNormalsFallBackToTheTrianglePlane) {
    const Scene cornell = loadScene("cornell");  // its normals are the face normals
    Scene scene = cornell;
    for (Vertex& vertex : scene.vertices) vertex.normal = glm::vec3(0.0f);
    RenderSettings settings = smallSettings();
    settings.shading.mode = RenderMode::Direct;
    const double change = bench::relativeL1Difference(render(cornell, settings, "face normals", false),
                                                      render(scene, settings, "zero normals", false));
    std::printf("[ stress ] zero normals, direct light: relative L1 change %.5f\n", change);
    EXPECT_LE(change, kTolerances.zeroNormalsDirect);
    render(scene, smallSettings(), "zero normals, full light");
}

TEST_F(Stress, NonFiniteValuesInACodeBuiltSceneAreRefusedWithAnError) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float infinity = std::numeric_limits<float>::infinity();
    const Scene cornell = loadScene("cornell");
    auto expectRefused = [&](const Scene& scene, const std::string& problem) {
        try {
            Renderer renderer(gpu(), scene, smallSettings());
            ADD_FAILURE() << "no error for: " << problem;
        } catch (const Error& error) {
            EXPECT_NE(std::string(error.what()).find(problem), std::string::npos) << error.what();
        }
    };
    Scene scene = cornell;
    scene.vertices[5].position.y = nan;
    expectRefused(scene, "vertex 5 holds a value that is not a finite number");
    scene = cornell;
    scene.vertices[7].normal.x = infinity;
    expectRefused(scene, "vertex 7 holds a value that is not a finite number");
    scene = cornell;
    scene.vertices[2].u = nan;
    expectRefused(scene, "vertex 2");
    scene = cornell;
    scene.vertices[4].tangent.w = nan;
    expectRefused(scene, "vertex 4 holds a value that is not a finite number");
    scene = cornell;
    scene.materials[1].emission.g = infinity;
    expectRefused(scene, "material 1 ('red') holds a value that is not a finite number");
    scene = cornell;
    scene.lights[0].intensity = nan;
    expectRefused(scene, "light 0 ('ceiling point light') holds a value that is not a finite number");
    scene = cornell;
    scene.indices[4] = uint32_t(scene.vertices.size());
    expectRefused(scene, "index 4 names vertex");

    Renderer renderer(gpu(), cornell, smallSettings());
    std::vector<Light> lights = cornell.lights;
    lights[0].position.z = -infinity;
    EXPECT_THROW(renderer.setLights(lights), Error);
    render(renderer, "still renders after a refused light");
}

TEST_F(Stress, FlatSceneWithZeroExtentAlongOneAxisLightsItselfNot) {
    // One 1 m floor at y = 0 under a point light: its bounds have zero height. A lone plane
    // receives no indirect light at all.
    Scene scene;
    scene.name = "lone floor";
    scene.materials.push_back(loadScene("cornell").materials[0]);
    for (glm::vec3 p :
         {glm::vec3(-0.5f, 0, -0.5f), glm::vec3(0.5f, 0, -0.5f), glm::vec3(0.5f, 0, 0.5f), glm::vec3(-0.5f, 0, 0.5f)})
        scene.vertices.push_back({p, 0.0f, {0, 1, 0}, 0.0f});
    scene.indices = {0, 1, 2, 0, 2, 3};
    scene.triangleMaterials = {0, 0};
    Light light;
    light.position = glm::vec3(0.0f, 0.5f, 0.0f);
    scene.lights.push_back(light);
    Camera camera;
    camera.position = glm::vec3(0.0f, 0.8f, 0.9f);
    camera.forward = glm::normalize(-camera.position);
    scene.cameras.push_back(camera);

    RenderSettings settings = smallSettings();
    settings.shading.mode = RenderMode::Direct;
    const double direct = bench::meanLuminance(render(scene, settings, "flat scene, direct", false));
    settings.shading.mode = RenderMode::Indirect;
    const double indirect = bench::meanLuminance(render(scene, settings, "flat scene, indirect"));
    std::printf("[ stress ] lone plane: direct %.4f, indirect %.6f\n", direct, indirect);
    EXPECT_GT(direct, 0.01);
    EXPECT_LE(indirect, kTolerances.flatSceneIndirect * direct);
}

TEST_F(Stress, WallOnAVoxelBoundaryLooksLikeAWallInsideAVoxel) {
    // The two-room scene's grid is centred on x = 0, a voxel boundary at every resolution. The wall
    // is one sheet facing the lit room: two faces 1 cm apart inside one voxel cancel each other's
    // normal there, and the voxel takes no light (the lit room 1.12 against 1.43 with the faces in
    // voxels of their own: bench::measureLightLeak reports it).
    RenderSettings settings = smallSettings(32, 64);
    double luminance[2];
    for (int i = 0; i < 2; ++i) {
        const float wallX = i == 0 ? 0.0f : 0.5f * 2.0f / 62.0f;  // on the boundary, half a voxel in
        Renderer renderer(gpu(), bench::makeTwoRoomScene(wallX, bench::SharedWall::SheetFacingLitRoom), settings);
        renderer.setCamera(bench::litRoomCamera());
        luminance[i] = bench::meanLuminance(render(renderer, i == 0 ? "wall on boundary" : "wall inside"));
    }
    std::printf("[ stress ] lit room, wall on a voxel boundary %.4f, inside a voxel %.4f\n", luminance[0],
                luminance[1]);
    EXPECT_NEAR(luminance[0] / luminance[1], 1.0, kTolerances.wallOnVoxelBoundary);
}

TEST_F(Stress, ScalingTheSceneWithItsLightsKeepsTheImage) {
    // Powers of two scale every float exactly, so the image must not change at all; 1e-3 and 1e4
    // round the positions, and the Cornell box's side walls lie exactly on voxel boundaries, where
    // a rounding flips which voxels the conservative voxelizer marks (direct light: no change;
    // indirect, light converged: 1.5 %).
    const Image reference = render(transformedCornell(1.0f, glm::vec3(0.0f)), smallSettings(), "scale 1");
    for (float scale : {1.0f / 1024.0f, 1024.0f}) {
        const Image scaled = render(transformedCornell(scale, glm::vec3(0.0f)), smallSettings(), "scaled exactly");
        EXPECT_LE(bench::relativeL1Difference(reference, scaled), 1e-6) << "scale " << scale;
    }
    for (float scale : {1e-3f, 1e4f}) {
        const Image scaled = render(transformedCornell(scale, glm::vec3(0.0f)), smallSettings(), "scaled");
        const double change = bench::relativeL1Difference(reference, scaled);
        std::printf("[ stress ] scale %g: relative L1 change %.5f, mean ratio %.5f\n", scale, change,
                    bench::meanLuminance(scaled) / bench::meanLuminance(reference));
        EXPECT_LE(change, kTolerances.scaled) << "scale " << scale;
    }
}

TEST_F(Stress, TranslatingTheSceneFarFromTheOriginKeepsTheImage) {
    const Image reference = render(transformedCornell(1.0f, glm::vec3(0.0f)), smallSettings(), "at the origin");
    const Image moved = render(transformedCornell(1.0f, glm::vec3(1e4f)), smallSettings(), "at +1e4 m");
    const double change = bench::relativeL1Difference(reference, moved);
    std::printf("[ stress ] translated by +1e4 m: relative L1 change %.5f\n", change);
    EXPECT_LE(change, kTolerances.translated);
}

TEST_F(Stress, LightIntensityFrom1eMinus4To1e6ScalesTheImageLinearly) {
    const Scene cornell = loadScene("cornell");
    const Image reference = render(cornell, smallSettings(), "intensity 1");
    for (float intensity : {1e-4f, 1e-2f, 1e2f, 1e4f, 1e6f}) {
        Scene scene = cornell;
        scene.lights[0].intensity = intensity;
        Renderer renderer(gpu(), scene, smallSettings());
        Image image = render(renderer, "intensity", false);
        const float largest = expectFiniteVolume(renderer, "intensity");
        EXPECT_LT(largest, 65504.0f) << "float16 overflow at intensity " << intensity;
        for (float& value : image.rgb) value /= intensity;
        const double change = bench::relativeL1Difference(reference, image);
        std::printf("[ stress ] intensity %g: image / intensity vs. 1: %.2e, largest stored voxel %.1f\n", intensity,
                    change, largest);
        EXPECT_LE(change, kTolerances.intensityLinearity) << "intensity " << intensity;
    }
}

TEST_F(Stress, GrazingViewsStayFiniteAndBounded) {
    const Scene cornell = loadScene("cornell");
    Renderer renderer(gpu(), cornell, smallSettings());
    const Image usual = render(renderer, "usual view");
    const float brightest = *std::max_element(usual.rgb.begin(), usual.rgb.end());
    // Along the floor 1 mm above it, and edge-on to the red wall (x = 0.5528…0.556) from inside it.
    for (const auto& [position, forward] : {std::pair{glm::vec3(0.278f, 0.001f, -0.2f), glm::vec3(0, 0, 1)},
                                            std::pair{glm::vec3(0.5544f, 0.274f, -0.2f), glm::vec3(0, 0, 1)},
                                            std::pair{glm::vec3(0.278f, 0.274f, 0.1f), glm::vec3(1, 1e-4f, 0)}}) {
        Camera camera = renderer.camera();
        camera.position = position;
        camera.forward = forward;
        renderer.setCamera(camera);
        const Image image = render(renderer, "grazing view", false);
        const float largest = *std::max_element(image.rgb.begin(), image.rgb.end());
        EXPECT_LE(largest, 4.0f * brightest) << "grazing view from " << position.x << ", " << position.y;
    }
}

TEST_F(StressGuard, WithTheMipsAloneACameraInsideAClosedBlockSeesNoMoreLightThanItDid) {
    // The shadow maps get the block's inside right; the cones do not: the block's faces are thinner
    // than a voxel, and cones starting on their inner side see the lit outer side's voxels (the
    // light leak of FailureModesGuard.WithTheMipsAloneThinWallsLeak…, at its worst in a closed box),
    // and one-sided voxels are transparent from behind. Measured 0.44 of the usual view's light;
    // bounded so that it cannot grow unnoticed. The target, 5 %, is ray visibility's (below).
    const bench::InsideClosedBlock seen = bench::measureInsideClosedBlock(gpu(), smallSettings(32, 64));
    std::printf("[ stress ] inside the tall block: %.5f, direct %.5f (usual view %.4f)\n", seen.insideLuminance,
                seen.insideDirect, seen.usualLuminance);
    EXPECT_EQ(seen.insideDirect, 0.0);
    EXPECT_LE(seen.ratio(), 0.52) << "regression guard; target 0.05";
}

TEST_F(Stress, WithRayVisibilityACameraInsideAClosedBlockSeesUnderFivePercentOfTheRoomsLight) {
    // The visibility issue's target: at most 5 % of the usual view's light (walls' cones, 64³).
    const bench::InsideClosedBlock seen =
        bench::measureInsideClosedBlock(gpu(), withRayVisibility(smallSettings(32, 64)));
    std::printf("[ stress ] rays, inside the tall block: %.5f, direct %.5f (usual view %.4f): %.4f\n",
                seen.insideLuminance, seen.insideDirect, seen.usualLuminance, seen.ratio());
    EXPECT_EQ(seen.insideDirect, 0.0);
    EXPECT_LE(seen.ratio(), 0.05);
}

TEST_F(Stress, EveryVoxelResolutionFrom32To256RendersFinite) {
    const Scene cornell = loadScene("cornell");
    for (uint32_t voxels : {32u, 64u, 128u, 256u}) {
        // Two bounces run every bounce pass; converging at 256³ would take minutes on lavapipe.
        RenderSettings settings = smallSettings(32, voxels);
        settings.resources.bounces = 2;
        Renderer renderer(gpu(), cornell, settings);
        render(renderer, "resolution", voxels <= 128);
        EXPECT_GT(renderer.renderFrame().gpuMilliseconds(), 0.0);
    }
}

// 512³ takes minutes and gigabytes: run by its own CTest entry with a long timeout
// (tests/CMakeLists.txt), not by the default discovery. Its volumes need 7.5 GiB; a device that
// cannot hold them (lavapipe reports a 2 GiB heap) must refuse with an error naming a grid that fits.
TEST_F(Stress, DISABLED_Voxels512RendersFiniteOrIsRefusedWithAResolutionThatFits) {
    try {
        Renderer renderer(gpu(), loadScene("cornell"), smallSettings(32, 512));
        const FrameStats stats = renderer.renderFrame();
        const Image image = renderer.readImage();
        EXPECT_TRUE(bench::allFiniteAndNonNegative(image));
        EXPECT_GT(bench::meanLuminance(image), 0.0);
        std::printf("[ stress ] 512³: first frame %.0f ms GPU, %.0f ms CPU, device memory %.0f MiB\n",
                    stats.gpuMilliseconds(), stats.cpuMilliseconds, double(renderer.deviceMemoryBytes()) / (1 << 20));
    } catch (const Error& error) {
        std::printf("[ stress ] 512³ refused: %s\n", error.what());
        EXPECT_NE(std::string(error.what()).find("grid would fit"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace vct::test
