// Named quality presets: the viewer's preset buttons and `vct bench`'s settings matrix share them,
// so "balanced" means the same thing wherever it is chosen. Image size is not part of a preset:
// whoever applies one keeps its own width and height.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/settings.h"

namespace vct {

// fast, balanced, quality: from cheapest to closest to the path-traced reference; walls, balanced
// with ray visibility; then classic, the seed's cone set, off the front.
std::vector<std::pair<std::string, RenderSettings>> renderPresets();

// The preset `vct render` and `vct bench`'s defaults start from when none is named: the most
// accurate the front offers whose light change fits kStillBudgetMs (lavapipe, 2 cores, 128×128).
// A still lights the voxels once, so a preset whose light change alone takes longer does not
// qualify, however accurate (walls, docs/bench.json).
inline constexpr const char* kDefaultPreset = "quality";
inline constexpr double kStillBudgetMs = 2000.0;

// What a preset is, costs and gets right, as `render --help` lists it.
struct PresetSummary {
    const char* name;
    const char* what;
    double stillFrameMs;  // GPU time of a still frame at 128×128, lavapipe, mean over the scenes
    double fullRelMse;    // relMSE of full light against the path tracer, geometric mean over the scenes
};
const std::vector<PresetSummary>& presetSummaries();

// The preset called `name`, or nullopt.
std::optional<RenderSettings> findRenderPreset(const std::string& name);
// The presets' names in renderPresets() order, comma-separated: for help texts and errors.
std::string presetNameList();

}  // namespace vct
