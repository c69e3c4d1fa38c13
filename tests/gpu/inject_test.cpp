// Light injection: a voxel reflects the light that falls on its surface, wherever in the voxel
// the surface lies and however many surfaces meet in it.
#include <cmath>
#include <vector>

#include "gpu/readback.h"
#include "gpu_test.h"
#include "render/renderer.h"
#include "render/voxel_grid_fit.h"

namespace vct::test {
namespace {

constexpr uint32_t kResolution = 32;

// An empty white scene whose bounds, and so whose voxel grid, are [-1, 2]³ whatever quads a
// test adds: 0.1 m voxels at 32³, the grid's origin at -1.1 m (voxel_grid_fit.cpp).
Scene boundedScene() {
    Scene scene;
    scene.name = "injection";
    Material white;
    white.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    scene.materials.push_back(white);
    // Two vertices no triangle uses: only the bounds see them.
    scene.vertices.push_back({glm::vec3(-1.0f), 0.0f, glm::vec3(0, 1, 0), 0.0f});
    scene.vertices.push_back({glm::vec3(2.0f), 0.0f, glm::vec3(0, 1, 0), 0.0f});
    Camera camera;
    camera.position = glm::vec3(0.5f, 1.5f, 2.0f);
    scene.cameras.push_back(camera);
    return scene;
}

// A one-sided quad of the scene's white material, corners counter-clockwise seen from `normal`.
void addQuad(Scene& scene, const std::array<glm::vec3, 4>& corners, glm::vec3 normal) {
    const uint32_t first = uint32_t(scene.vertices.size());
    for (const glm::vec3& corner : corners) scene.vertices.push_back({corner, 0.0f, normal, 0.0f});
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) scene.indices.push_back(first + i);
    scene.triangleMaterials.insert(scene.triangleMaterials.end(), 2, 0u);
}

void addFloor(Scene& scene, float height) {
    addQuad(scene,
            {glm::vec3(0.2f, height, 0.2f), glm::vec3(0.2f, height, 0.9f), glm::vec3(0.9f, height, 0.9f),
             glm::vec3(0.9f, height, 0.2f)},
            glm::vec3(0, 1, 0));
}

// The light the voxels reflect (level 0 of the radiance volume, premultiplied by opacity, in the
// renderer's storage scale) after one injection without bounces.
std::vector<glm::vec4> injectedLight(const Scene& scene) {
    RenderSettings settings = smallRenderSettings(16, RenderMode::Indirect);
    settings.resources.voxelResolution = kResolution;
    settings.resources.bounces = 1;
    Renderer renderer(gpu(), scene, settings);
    EXPECT_NEAR(fitVoxelGrid(scene.bounds(), kResolution).voxelSize, 0.1f, 1e-6f);
    renderer.renderFrame();
    return readImage3D(gpu(), renderer.volumes().radiance, 0);
}

glm::vec4 voxelAt(const std::vector<glm::vec4>& volume, int x, int y, int z) {
    return volume[size_t(x) + kResolution * (size_t(y) + kResolution * size_t(z))];
}

class Injection : public GpuTest {};

TEST_F(Injection, AFloorTakesTheLightOfItsSurfaceWhereverItLiesInItsVoxel) {
    // A point light 0.4 m (4 voxels) above the floor, over the centre of voxel (16, 11, 16). The
    // floor lies a tenth of a voxel above its voxels' floor, then nine tenths: the voxel's centre
    // is 0.04 m below the surface, then above it. Lit at its centre, the voxel took
    // (0.44 / 0.36)² = 1.49 times more light in the second case.
    std::vector<float> light;
    for (float fraction : {0.1f, 0.9f}) {
        Scene scene = boundedScene();
        const float height = -1.1f + 0.1f * (11.0f + fraction);
        addFloor(scene, height);
        Light lamp;
        lamp.type = LightType::Point;
        lamp.intensity = 1.0f;
        lamp.position = glm::vec3(0.55f, height + 0.4f, 0.55f);
        scene.lights.push_back(lamp);
        const glm::vec4 voxel = voxelAt(injectedLight(scene), 16, 11, 16);
        EXPECT_NEAR(voxel.a, 1.0f, 1e-3f) << "the floor's voxel at fraction " << fraction;
        light.push_back(voxel.r);
    }
    ASSERT_GT(light[0], 0.0f);
    EXPECT_NEAR(light[1] / light[0], 1.0f, 0.01f);
}

TEST_F(Injection, WhereAFloorMeetsAWallTheVoxelTakesTheMeanOfTheirLight) {
    // A floor (y = 0.05, facing up) meets a wall (x = 0.25, facing +x) inside the voxels of column
    // x = 13, y = 11; a sun shines on both, from above and +x. The corner voxel's triangles face
    // the sun at two angles: it reflects the mean of their light, which the floor alone (x = 16)
    // and the wall alone (y = 14) show. With the mean normal renormalized it faced the sun at 45°,
    // and took 1.4 times that.
    Scene scene = boundedScene();
    addFloor(scene, 0.05f);
    addQuad(scene,
            {glm::vec3(0.25f, 0.05f, 0.2f), glm::vec3(0.25f, 0.6f, 0.2f), glm::vec3(0.25f, 0.6f, 0.9f),
             glm::vec3(0.25f, 0.05f, 0.9f)},
            glm::vec3(1, 0, 0));
    Light sun;
    sun.type = LightType::Directional;
    sun.intensity = 1.0f;
    sun.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, 0.0f));
    scene.lights.push_back(sun);
    const std::vector<glm::vec4> volume = injectedLight(scene);
    const float floor = voxelAt(volume, 16, 11, 16).r, wall = voxelAt(volume, 13, 14, 16).r;
    const float corner = voxelAt(volume, 13, 11, 16).r;
    ASSERT_GT(wall, 0.0f);
    EXPECT_NEAR(floor / wall, 1.0f / 0.3f, 0.03f) << "the sun's cosines on the floor and on the wall";
    EXPECT_NEAR(corner / (0.5f * (floor + wall)), 1.0f, 0.02f);
}

}  // namespace
}  // namespace vct::test
