// The failure-modes section of `vct bench`: light leaking through a thin wall and walls 1-4 voxels
// thick, a room inside a sunlit shell, a camera inside a closed block, brightness against voxel
// resolution, self-illumination, flicker and each scene's first bounce against its own truth
// (src/bench/failure_modes.h), measured with one setting and reported
// as text and JSON next to the accuracy matrix. The tests hold the same measurements to bounds
// (tests/gpu/failure_modes_test.cpp); the benchmark reports them at the bench's image size.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bench/failure_modes.h"

namespace vct::bench {

struct FailureModeReport {
    std::string setting;  // the settings' label (matrix.h)
    struct Leak {
        SharedWall wall = SharedWall::TwoFaces;
        float wallOffsetVoxels = 0.0f;  // where the wall sits inside its voxel
        LeakMeasurement measurement;
    };
    std::vector<Leak> leaks;
    struct ThickWall {
        float thicknessVoxels = 0.0f;  // the two faces' distance apart, the wall's middle on a voxel boundary
        LeakMeasurement measurement;
    };
    std::vector<ThickWall> thickWalls;          // 1, 2 and 4 voxels
    std::optional<double> shelledRoomIndirect;  // measureShelledRoomIndirect, where the sun room has a reference
    InsideClosedBlock insideBlock;
    std::vector<ResolutionLuminance> drift;           // Cornell box, the first bounce of indirect light
    double driftReference = -1.0;                     // the path tracer's one-bounce mean luminance; −1 = none
    FlickerMeasurement flickerFull, flickerIndirect;  // 1 mm camera and light steps, Cornell box
    SelfIllumination selfIllumination;                // a lone sunlit plane, ground truth 0
    struct SceneFirstBounce {
        std::string scene;
        FirstBounce firstBounce;
    };
    std::vector<SceneFirstBounce> firstBounces;  // the scenes that have a one-bounce reference
};

// A benchmarked scene and its path tracer's paths cut after one bounce, at the bench's image size.
struct OneBounceTruth {
    const Scene* scene = nullptr;
    const Image* reference = nullptr;
};

// `settings` gives the image size and the cone setup; the drift runs its first bounce at
// 32³…256³. Each of `truths` has its first bounce measured against its reference, and the Cornell
// box's (a scene named "cornell" among them) is what the drift is also compared with.
// `sunRoomIndirect`: the sun room's path-traced indirect light at the image's size, the truth of
// the room in a shell (none: not measured).
FailureModeReport measureFailureModes(GpuContext& context, const RenderSettings& settings,
                                      const std::vector<OneBounceTruth>& truths, const Image* sunRoomIndirect);

std::string failureModesText(const FailureModeReport& report);
std::string failureModesJson(const FailureModeReport& report);

}  // namespace vct::bench
