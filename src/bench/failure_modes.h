// The failures users of other voxel-cone-tracing renderers report most, as measurements that the
// tests guard and `vct bench` can report: light leaking through thin walls, brightness that drifts
// with the voxel resolution, and flicker when the camera or a light moves a little.
//
// Each function renders with the caller's settings (image size, cones, mips...), so a benchmark
// can run them over its matrix; the tests use small images on lavapipe.
#pragma once

#include <cstdint>
#include <vector>

#include "bench/metrics.h"
#include "gpu/context.h"
#include "io/image_io.h"
#include "render/settings.h"
#include "scene/scene.h"

namespace vct::bench {

// Rec. 709 luminance averaged over the image.
double meanLuminance(const Image& image);
// True when every value is finite and not negative.
bool allFiniteAndNonNegative(const Image& image);
// Σ|a − b| / Σ|a| over all channels: how much of the image changed (0 = identical). Same sizes.
double relativeL1Difference(const Image& a, const Image& b);

// ---- Light leaking: two 1 m rooms side by side along x share a wall thinner than any voxel at
// x = wallX. A point light hangs in the lit room (x < wallX); the dark room receives no light at
// all, so its ground truth is exactly 0.
// The wall: one sheet of zero thickness facing either room (a double-sided quad, as files often
// model a thin wall: the voxels take one side from its winding), or two faces 1 cm apart, each
// facing its room (a wall with a thickness).
enum class SharedWall { SheetFacingLitRoom, SheetFacingDarkRoom, TwoFaces };
inline constexpr SharedWall kSharedWalls[] = {SharedWall::SheetFacingLitRoom, SharedWall::SheetFacingDarkRoom,
                                              SharedWall::TwoFaces};
// "sheet-facing-lit-room", "sheet-facing-dark-room", "two-faces".
const char* sharedWallName(SharedWall wall);
inline constexpr float kTwoFacedWallThickness = 0.01f;  // metres: a third of a voxel at 64³
// `thickness`: the two faces' distance apart (TwoFaces only), metres.
Scene makeTwoRoomScene(float wallX, SharedWall wall, float thickness = kTwoFacedWallThickness);
// The voxel size of the grid fitted to the two rooms at `resolution`: what a wall's position inside
// its voxel and its thickness are counted in.
float twoRoomVoxelSize(uint32_t resolution);
// Cameras inside each room, looking at the shared wall.
Camera litRoomCamera();
Camera darkRoomCamera();

struct LeakMeasurement {
    double litRoomLuminance = 0.0;   // mean luminance the lit room's camera sees (full light)
    double darkRoomLuminance = 0.0;  // the same in the dark room: the leak (ground truth 0)
    Image litRoom, darkRoom;         // what the two cameras saw
    // darkRoomLuminance / litRoomLuminance: the leaked share of the light on the other side.
    double leakRatio() const { return litRoomLuminance > 0.0 ? darkRoomLuminance / litRoomLuminance : 0.0; }
};
LeakMeasurement measureLightLeak(GpuContext& context, const RenderSettings& settings, float wallX, SharedWall wall);
LeakMeasurement measureLightLeak(GpuContext& context, const RenderSettings& settings, const Scene& twoRooms);

// ---- A room inside a sunlit shell: the built-in sun room, whose walls and roof are single sheets,
// inside an outer shell `gap` metres out whose roof has a hole where the sun's beam through the
// room's own hole crosses it. The shell changes nothing inside the room (the same sunlight comes
// in), so the sun room's path-traced references are its truth; what its sunlit outside adds to the
// room's light leaked through the sheets.
Scene makeSunRoomInASunlitShell(float gap);
inline constexpr float kShellGap = 0.25f;  // metres
// The indirect light of the sun room in a shell kShellGap out (its camera, the settings' image
// size) over the sun room's path-traced indirect light `sunRoomIndirect` (the same size): 1 where
// the shell adds nothing.
double measureShelledRoomIndirect(GpuContext& context, RenderSettings settings, const Image& sunRoomIndirect);

// ---- A camera inside a closed block: the middle of the Cornell box's tall block, looking at one
// of its faces. No light reaches its inner faces, so its ground truth is black.
struct InsideClosedBlock {
    double usualLuminance = 0.0;   // the Cornell box's own view, full light
    double insideLuminance = 0.0;  // inside the block, full light (ground truth 0)
    double insideDirect = 0.0;     // the same, direct light alone (ground truth 0)
    double ratio() const { return usualLuminance > 0.0 ? insideLuminance / usualLuminance : 0.0; }
};
InsideClosedBlock measureInsideClosedBlock(GpuContext& context, RenderSettings settings);

// ---- Self-illumination: a lone 2 m square lit by a sun 45° up, and nothing else. No light can
// reach it twice, so its true indirect light is 0: whatever indirect light it gets, it gathered from
// its own voxels.
Scene makeLonePlaneScene();
struct SelfIllumination {
    double directLuminance = 0.0;    // mean over the image, which the plane fills
    double indirectLuminance = 0.0;  // the same, ground truth 0
    double ratio() const { return directLuminance > 0.0 ? indirectLuminance / directLuminance : 0.0; }
};
SelfIllumination measureSelfIllumination(GpuContext& context, RenderSettings settings);

// ---- Brightness against voxel resolution: the mean luminance of `settings.shading.mode` (e.g. indirect)
// for each resolution, all else equal.
struct ResolutionLuminance {
    uint32_t voxelResolution = 0;
    double meanLuminance = 0.0;
    bool finite = false;
};
std::vector<ResolutionLuminance> measureResolutionDrift(GpuContext& context, const Scene& scene,
                                                        RenderSettings settings,
                                                        const std::vector<uint32_t>& resolutions);

// ---- The first bounce against its own truth: one bounce of indirect light with the caller's
// settings, against the path tracer's paths cut after one bounce (SCENE-indirect-1bounce.pfm, the
// image's size). Every later bounce is fed by the first and repeats its error, and the converged
// light's error against the all-bounce truth can hide two errors that cancel.
struct FirstBounce {
    ImageError error;
    bool finite = false;
};
FirstBounce measureFirstBounce(GpuContext& context, const Scene& scene, RenderSettings settings,
                               const Image& oneBounceReference);

// ---- Flicker: the relative L1 change of the image when the camera or the first light moves by a
// small step (metres, along x), against the image before. A step of zero must change nothing.
struct FlickerMeasurement {
    double cameraChange = 0.0;  // relativeL1Difference after moving the camera by cameraStep
    double lightChange = 0.0;   // the same after moving the first light by lightStep
};
FlickerMeasurement measureFlicker(GpuContext& context, const Scene& scene, const RenderSettings& settings,
                                  float cameraStep, float lightStep);

}  // namespace vct::bench
