#include "bench/failure_modes.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "render/renderer.h"
#include "render/voxel_grid_fit.h"
#include "scene/load.h"

namespace vct::bench {

double meanLuminance(const Image& image) {
    double sum = 0.0;
    const size_t pixels = size_t(image.width) * image.height;
    for (size_t i = 0; i < pixels; ++i) sum += luminance(&image.rgb[i * 3]);
    return pixels > 0 ? sum / double(pixels) : 0.0;
}

bool allFiniteAndNonNegative(const Image& image) {
    for (float value : image.rgb)
        if (!std::isfinite(value) || value < 0.0f) return false;
    return true;
}

double relativeL1Difference(const Image& a, const Image& b) {
    double difference = 0.0, total = 0.0;
    for (size_t i = 0; i < a.rgb.size() && i < b.rgb.size(); ++i) {
        difference += std::abs(double(a.rgb[i]) - double(b.rgb[i]));
        total += std::abs(double(a.rgb[i]));
    }
    return total > 0.0 ? difference / total : (difference > 0.0 ? 1.0 : 0.0);
}

namespace {

// A quad as two triangles, corners in order around it, wound counter-clockwise seen from the side
// `normal` (its shading normal) points to, as glTF's front faces are and the voxels take their side
// from. (Wound as listed, the two rooms' floor, front wall, far end and shared wall faced away from
// their normals, and the leak measured was that of a wall facing the dark room, whose voxels the
// dark room's cones could not see through.)
void addQuad(Scene& scene, std::array<glm::vec3, 4> corners, glm::vec3 normal, uint32_t material) {
    if (glm::dot(glm::cross(corners[1] - corners[0], corners[2] - corners[0]), normal) < 0.0f)
        std::reverse(corners.begin(), corners.end());
    const uint32_t first = uint32_t(scene.vertices.size());
    for (const glm::vec3& corner : corners) scene.vertices.push_back({corner, 0.0f, normal, 0.0f});
    for (uint32_t index : {0u, 1u, 2u, 0u, 2u, 3u}) scene.indices.push_back(first + index);
    scene.triangleMaterials.push_back(material);
    scene.triangleMaterials.push_back(material);
}

Camera roomCamera(glm::vec3 position, glm::vec3 forward) {
    Camera camera;
    camera.position = position;
    camera.forward = forward;
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    camera.yfov = 1.3f;
    camera.znear = 0.01f;
    return camera;
}

// A grey that reflects only diffusely (no specular lobe, so no specular cone either).
Material lambertianWhite(float albedo) {
    Material white;
    white.name = "white";
    white.baseColorFactor = glm::vec4(albedo, albedo, albedo, 1.0f);
    white.metallic = 0.0f;
    white.roughness = 1.0f;
    white.specularWeight = 0.0f;
    return white;
}

}  // namespace

const char* sharedWallName(SharedWall wall) {
    switch (wall) {
        case SharedWall::SheetFacingLitRoom: return "sheet-facing-lit-room";
        case SharedWall::SheetFacingDarkRoom: return "sheet-facing-dark-room";
        case SharedWall::TwoFaces: break;
    }
    return "two-faces";
}

Scene makeTwoRoomScene(float wallX, SharedWall wall, float thickness) {
    Scene scene;
    scene.name = "two rooms";
    scene.materials.push_back(lambertianWhite(0.7f));  // no specular cone: the leak is all diffuse

    // The outer shell spans x −1…1, y 0…1, z 0…1 whatever wallX is, so the voxel grid is fixed and
    // wallX alone says where the wall falls inside its voxels.
    addQuad(scene, {{{-1, 0, 0}, {1, 0, 0}, {1, 0, 1}, {-1, 0, 1}}}, {0, 1, 0}, 0);    // floor
    addQuad(scene, {{{-1, 1, 0}, {1, 1, 0}, {1, 1, 1}, {-1, 1, 1}}}, {0, -1, 0}, 0);   // ceiling
    addQuad(scene, {{{-1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 1, 0}}}, {0, 0, 1}, 0);    // back
    addQuad(scene, {{{-1, 0, 1}, {1, 0, 1}, {1, 1, 1}, {-1, 1, 1}}}, {0, 0, -1}, 0);   // front
    addQuad(scene, {{{-1, 0, 0}, {-1, 1, 0}, {-1, 1, 1}, {-1, 0, 1}}}, {1, 0, 0}, 0);  // lit room's end
    addQuad(scene, {{{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}}, {-1, 0, 0}, 0);     // dark room's end
    // The shared wall, reflecting on both sides like every surface.
    auto addWall = [&](float x, float facing) {
        addQuad(scene, {{{x, 0, 0}, {x, 1, 0}, {x, 1, 1}, {x, 0, 1}}}, {facing, 0, 0}, 0);
    };
    switch (wall) {
        case SharedWall::SheetFacingLitRoom: addWall(wallX, -1.0f); break;
        case SharedWall::SheetFacingDarkRoom: addWall(wallX, 1.0f); break;
        case SharedWall::TwoFaces:
            addWall(wallX - 0.5f * thickness, -1.0f);
            addWall(wallX + 0.5f * thickness, 1.0f);
            break;
    }

    Light light;
    light.name = "lit room's light";
    light.type = LightType::Point;
    light.intensity = 1.0f;
    light.position = glm::vec3(-0.5f, 0.6f, 0.5f);
    scene.lights.push_back(light);
    scene.cameras.push_back(darkRoomCamera());
    return scene;
}

Scene makeSunRoomInASunlitShell(float gap) {
    Scene scene = loadScene("sun-room");
    scene.name = "sun room in a sunlit shell";
    const uint32_t white = uint32_t(scene.materials.size());
    scene.materials.push_back(lambertianWhite(0.725f));
    const float lo = -gap, hi = 4.0f + gap, bottom = -gap, top = 3.0f + gap;
    // The shell faces out, as a building's outer walls do; the sun lights its roof and two walls.
    addQuad(scene, {{{lo, bottom, lo}, {lo, top, lo}, {lo, top, hi}, {lo, bottom, hi}}}, {-1, 0, 0}, white);
    addQuad(scene, {{{hi, bottom, lo}, {hi, top, lo}, {hi, top, hi}, {hi, bottom, hi}}}, {1, 0, 0}, white);
    addQuad(scene, {{{lo, bottom, lo}, {hi, bottom, lo}, {hi, top, lo}, {lo, top, lo}}}, {0, 0, -1}, white);
    addQuad(scene, {{{lo, bottom, hi}, {hi, bottom, hi}, {hi, top, hi}, {lo, top, hi}}}, {0, 0, 1}, white);
    addQuad(scene, {{{lo, bottom, lo}, {hi, bottom, lo}, {hi, bottom, hi}, {lo, bottom, hi}}}, {0, -1, 0}, white);
    // Its roof's hole lies where the sun's beam through the room's hole (x, z 1.5-2.5) crosses the
    // shell's roof: the sun travels (0.35, −1, 0.25), so the same light enters the room.
    const float x0 = 1.5f - 0.35f * gap, x1 = 2.5f - 0.35f * gap, z0 = 1.5f - 0.25f * gap, z1 = 2.5f - 0.25f * gap;
    const glm::vec3 up(0, 1, 0);
    addQuad(scene, {{{lo, top, lo}, {hi, top, lo}, {hi, top, z0}, {lo, top, z0}}}, up, white);
    addQuad(scene, {{{lo, top, z1}, {hi, top, z1}, {hi, top, hi}, {lo, top, hi}}}, up, white);
    addQuad(scene, {{{lo, top, z0}, {x0, top, z0}, {x0, top, z1}, {lo, top, z1}}}, up, white);
    addQuad(scene, {{{x1, top, z0}, {hi, top, z0}, {hi, top, z1}, {x1, top, z1}}}, up, white);
    return scene;
}

double measureShelledRoomIndirect(GpuContext& context, RenderSettings settings, const Image& sunRoomIndirect) {
    settings.shading.mode = RenderMode::Indirect;
    Renderer renderer(context, makeSunRoomInASunlitShell(kShellGap), settings);
    renderer.renderSettled();
    const double truth = meanLuminance(sunRoomIndirect);
    return truth > 0.0 ? meanLuminance(renderer.readImage()) / truth : 0.0;
}

InsideClosedBlock measureInsideClosedBlock(GpuContext& context, RenderSettings settings) {
    Renderer renderer(context, loadScene("cornell"), settings);
    InsideClosedBlock seen;
    renderer.renderSettled();
    seen.usualLuminance = meanLuminance(renderer.readImage());
    Camera camera = renderer.camera();
    camera.position = glm::vec3(0.368f, 0.2f, 0.351f);  // the middle of the tall block
    camera.forward = glm::vec3(0.0f, 0.0f, 1.0f);
    camera.znear = 0.001f;
    renderer.setCamera(camera);
    renderer.renderSettled();
    seen.insideLuminance = meanLuminance(renderer.readImage());
    settings.shading.mode = RenderMode::Direct;
    renderer.setShading(settings.shading);
    renderer.renderSettled();
    seen.insideDirect = meanLuminance(renderer.readImage());
    return seen;
}

float twoRoomVoxelSize(uint32_t resolution) {
    return fitVoxelGrid(makeTwoRoomScene(0.0f, SharedWall::TwoFaces).bounds(), resolution).voxelSize;
}

Scene makeLonePlaneScene() {
    Scene scene;
    scene.name = "lone plane";
    scene.materials.push_back(lambertianWhite(0.8f));
    addQuad(scene, {{{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}}}, {0, 1, 0}, 0);
    Light sun;
    sun.name = "sun";
    sun.type = LightType::Directional;
    sun.intensity = 3.0f;
    sun.direction = glm::normalize(glm::vec3(1.0f, -1.0f, 0.3f));
    scene.lights.push_back(sun);
    Camera above = roomCamera({0.0f, 1.2f, 0.0f}, {0.0f, -1.0f, 0.0f});  // the plane fills its view
    above.up = glm::vec3(0.0f, 0.0f, -1.0f);
    scene.cameras.push_back(above);
    return scene;
}

SelfIllumination measureSelfIllumination(GpuContext& context, RenderSettings settings) {
    Renderer renderer(context, makeLonePlaneScene(), settings);
    SelfIllumination result;
    for (RenderMode mode : {RenderMode::Direct, RenderMode::Indirect}) {
        settings.shading.mode = mode;
        renderer.setShading(settings.shading);
        renderer.renderSettled();
        (mode == RenderMode::Direct ? result.directLuminance : result.indirectLuminance) =
            meanLuminance(renderer.readImage());
    }
    return result;
}

Camera litRoomCamera() { return roomCamera({-0.97f, 0.5f, 0.5f}, {1.0f, 0.0f, 0.0f}); }
Camera darkRoomCamera() { return roomCamera({0.97f, 0.5f, 0.5f}, {-1.0f, 0.0f, 0.0f}); }

LeakMeasurement measureLightLeak(GpuContext& context, const RenderSettings& settings, float wallX, SharedWall wall) {
    return measureLightLeak(context, settings, makeTwoRoomScene(wallX, wall));
}

LeakMeasurement measureLightLeak(GpuContext& context, const RenderSettings& settings, const Scene& twoRooms) {
    Renderer renderer(context, twoRooms, settings);
    LeakMeasurement leak;
    renderer.setCamera(litRoomCamera());
    renderer.renderSettled();
    leak.litRoom = renderer.readImage();
    leak.litRoomLuminance = meanLuminance(leak.litRoom);
    renderer.setCamera(darkRoomCamera());
    renderer.renderSettled();
    leak.darkRoom = renderer.readImage();
    leak.darkRoomLuminance = meanLuminance(leak.darkRoom);
    return leak;
}

std::vector<ResolutionLuminance> measureResolutionDrift(GpuContext& context, const Scene& scene,
                                                        RenderSettings settings,
                                                        const std::vector<uint32_t>& resolutions) {
    std::vector<ResolutionLuminance> results;
    for (uint32_t resolution : resolutions) {
        settings.resources.voxelResolution = resolution;
        Renderer renderer(context, scene, settings);
        renderer.renderSettled();
        const Image image = renderer.readImage();
        results.push_back({resolution, meanLuminance(image), allFiniteAndNonNegative(image)});
    }
    return results;
}

FirstBounce measureFirstBounce(GpuContext& context, const Scene& scene, RenderSettings settings,
                               const Image& oneBounceReference) {
    settings.shading.mode = RenderMode::Indirect;
    settings.resources.bounces = 1;
    Renderer renderer(context, scene, settings);
    renderer.renderSettled();
    const Image image = renderer.readImage();
    return {compareImages(image, oneBounceReference), allFiniteAndNonNegative(image)};
}

FlickerMeasurement measureFlicker(GpuContext& context, const Scene& scene, const RenderSettings& settings,
                                  float cameraStep, float lightStep) {
    Renderer renderer(context, scene, settings);
    const Camera start = renderer.camera();
    const std::vector<Light> lights = renderer.lights();
    renderer.renderSettled();
    const Image before = renderer.readImage();

    FlickerMeasurement flicker;
    Camera moved = start;
    moved.position.x += cameraStep;
    renderer.setCamera(moved);
    renderer.renderFrame();  // the first frame a viewer shows after the step
    flicker.cameraChange = relativeL1Difference(before, renderer.readImage());
    renderer.setCamera(start);

    if (!lights.empty()) {
        std::vector<Light> movedLights = lights;
        movedLights[0].position.x += lightStep;
        renderer.setLights(movedLights);
        renderer.renderFrame();
        flicker.lightChange = relativeL1Difference(before, renderer.readImage());
    }
    return flicker;
}

}  // namespace vct::bench
