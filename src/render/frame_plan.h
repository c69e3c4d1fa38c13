// Which passes a frame runs, as data: a pure function of what is out of date and the settings,
// tested on the CPU (tests/cpu/frame_plan_test.cpp). Shadow maps are redrawn when a light moved,
// the G-buffer when the view changed;
// the scene is voxelized once per geometry; light is re-injected (and the mips rebuilt) when a
// light changed or the voxels were rebuilt; and no voxel pass runs while the image shows nothing
// that reads the voxels. With converged bounces the injection gathers the voxels' own cones from
// the last light (so it is the first bounce of the series), and `bounce` repeats it until the light
// converges, or, progressively, the next frames do. The diffuse cones have a pass of their own
// only at a reduced resolution (ImageSettings::diffuseDownscale); otherwise shading traces them.
// The resolve runs only with supersamples or still frames to average: otherwise it would be a copy.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "render/settings.h"

namespace vct {

// In pipeline order.
enum class Pass : uint32_t { Shadow, Voxelize, Inject, Mips, Bounce, GBuffer, DiffuseCones, Shade, Resolve };
inline constexpr std::array<Pass, 9> kPipelineOrder = {Pass::Shadow,       Pass::Voxelize, Pass::Inject,
                                                       Pass::Mips,         Pass::Bounce,   Pass::GBuffer,
                                                       Pass::DiffuseCones, Pass::Shade,    Pass::Resolve};
// "shadow", "voxelize", … as the timings and the profiler name them.
const char* passName(Pass pass);

// What changed since the passes that depend on it last ran.
struct StaleInputs {
    bool shadows = true;   // lights moved or geometry changed
    bool voxels = true;    // geometry changed
    bool radiance = true;  // lights changed
    bool bounces = false;  // the bounce series has not converged yet (progressive bounces)
    bool view = true;      // the camera moved, or the scene or the image size changed: the G-buffer
    bool operator==(const StaleInputs&) const = default;
};

struct FramePlan {
    std::vector<Pass> passes;  // in pipeline order
    bool runs(Pass pass) const;
    // The passes not in the plan, in pipeline order.
    std::vector<Pass> skipped() const;
};

FramePlan planFrame(const StaleInputs& stale, const RenderSettings& settings);
// What is still stale once `plan` has run: voxels and light stay stale while nothing reads them;
// `converged` says whether the frame's bounces reached kBounceTolerance.
StaleInputs afterFrame(const StaleInputs& stale, const FramePlan& plan, bool converged);

}  // namespace vct
