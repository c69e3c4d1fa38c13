// The side-by-side with an OpenGL implementation of the same design (issue 13): it draws a
// 1280×720 frame of an open-top Cornell box lit by a sun, with a 128³ RGBA8 volume, a 4096² shadow
// map and 6 × 60° diffuse cones stepping one diameter at a time, in about 0.38 s on this project's
// kind of machine (2 cores, Mesa llvmpipe), with the sun moving every frame. This measures the
// renderer on that workload, `cornell-sun` at that size and with those resources, while the camera
// moves and while the sun moves (as in `vct view`: one bounce per frame, fed by the last frame's
// light), and the error of the same settings against the path-traced references.
#pragma once

#include <optional>
#include <string>

#include "bench/measure.h"

namespace vct::bench {

// The workload, with the renderer's own choices on top (diffuse cones at a quarter resolution,
// bounces converging progressively).
RenderSettings comparisonSettings();

struct ComparisonReport {
    std::string setting;  // matrix.h's label
    uint32_t width = 0, height = 0, frames = 0;
    FrameTiming cameraMoving;  // medians over `frames` frames, each with the camera moved
    FrameTiming sunMoving;     // … each with the sun turned
    // The same settings at the references' size, the light converged: full, direct and indirect light.
    std::optional<ModeErrors> errors;
};

// `references`: cornell-sun's, at their own size (nullptr: no error reported).
ComparisonReport measureComparison(GpuContext& context, const References* references, uint32_t referenceWidth,
                                   uint32_t referenceHeight, const MeasureOptions& options);

std::string comparisonText(const ComparisonReport& report);
std::string comparisonJson(const ComparisonReport& report);

}  // namespace vct::bench
