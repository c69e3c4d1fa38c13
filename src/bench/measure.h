// Measuring one scene over a list of settings: GPU time per pass, device memory, and the error of
// full, direct and indirect light against the path-traced reference.
//
// One Renderer serves every setting that needs the same voxels, mips, bounces and shadow maps;
// the others are applied with setShadingSettings. A new Renderer's first frame (every pass runs,
// voxelization included) and `warmupFrames` more are not measured. Then, for each setting:
//   1. `frames` frames after a light "change" (setLights with the same lights): shadow maps,
//      injection, mips, the bounces to convergence and shading run → median times, and how many
//      bounces that took. The first also re-lights the voxels with this setting's cones;
//   2. `frames` static frames (nothing changed: the voxel passes are skipped) → median times, and
//      the full image;
//   3. one frame in `direct` and one in `indirect` mode → their images.
// Voxelization runs only when geometry changes; its time comes from the Renderer's first frame.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bench/matrix.h"
#include "bench/metrics.h"
#include "gpu/context.h"
#include "gpu/timing.h"
#include "io/image_io.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace vct::bench {

struct References {
    Image full, direct, indirect;            // full = direct + indirect unless a -full.pfm exists
    std::optional<Image> indirectOneBounce;  // SCENE-indirect-1bounce.pfm: paths cut after one bounce
    double directNoise = -1.0;               // the path tracer's relative noise from the JSON sidecars; −1 = unknown
    double indirectNoise = -1.0;
    uint32_t directSpp = 0, indirectSpp = 0;
};

// Reads DIR/SCENE-direct.pfm and DIR/SCENE-indirect.pfm (and their .json sidecars). No reference,
// or one of another size: nullopt. A reference that exists but cannot be read throws.
std::optional<References> loadReferences(const std::string& directory, const std::string& scene, uint32_t width,
                                         uint32_t height);

struct FrameTiming {
    double gpuMilliseconds = 0.0;  // median over frames of the sum of the passes
    double cpuMilliseconds = 0.0;  // median wall time of renderFrame (record, submit, wait)
    std::vector<PassTime> passes;  // median of each pass that ran
};

// The median over `frames` of the GPU time, the wall time and each pass.
FrameTiming medianTiming(const std::vector<FrameStats>& frames);

struct ModeErrors {
    ImageError full, direct, indirect;
    double shadowedIndirectRatio = 0.0;  // shadowedLuminanceRatio of the indirect image (metrics.h)
};

struct Measurement {
    std::string scene;
    BenchSetting setting;
    FrameTiming staticFrame;  // nothing changed
    // After a light change, the frames until the image settled (Renderer::settling: reused diffuse
    // light traced anew, the ring's turns averaged) and their wall time.
    uint32_t settleFrames = 0;
    double settleMilliseconds = 0.0;
    FrameTiming lightChangeFrame;  // a light changed: shadow maps, injection, mips and shading
    // The viewer's frame while a light moves (converged bounces only): one progressive bounce
    // gathered for one of bounceSlices slices of the voxels.
    std::optional<FrameTiming> lightMovingFrame;
    uint32_t bounceSlices = 1;
    // A camera walking along its view at 5 m/s, a step of a 30 Hz frame (at most a fiftieth of the
    // scene's size) each frame: what a fly-through costs (a new G-buffer, a sun's cascades, reused
    // diffuse light reprojected), the median frame and the slowest, wall time.
    FrameTiming cameraMovingFrame;
    double cameraMovingWorstMilliseconds = 0.0;
    double voxelizeMilliseconds = 0.0;
    uint32_t bounces = 0;             // bounces a light change ran (from the light sources' light on)
    bool bouncesConverged = true;     // they reached kBounceTolerance
    double bounceMilliseconds = 0.0;  // wall time of a light change beyond a static frame's, per bounce
    uint64_t deviceMemoryBytes = 0;
    bool imagesFinite = true;  // no NaN or Inf in the full, direct or indirect image
    std::optional<ModeErrors> errors;
    Image fullImage;  // what the static frames showed
};

struct MeasureOptions {
    uint32_t warmupFrames = 1;
    uint32_t frames = 3;
    std::function<void(const Measurement&)> onMeasured;  // progress, called after each setting
};

// Measurements in the order of `settings`.
std::vector<Measurement> measureScene(GpuContext& context, const Scene& scene,
                                      const std::vector<BenchSetting>& settings, const References* references,
                                      const MeasureOptions& options);

}  // namespace vct::bench
