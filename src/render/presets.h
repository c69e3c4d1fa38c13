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

// fast, balanced, quality: from cheapest to closest to the path-traced reference.
std::vector<std::pair<std::string, RenderSettings>> renderPresets();

// The preset called `name`, or nullopt.
std::optional<RenderSettings> findRenderPreset(const std::string& name);

}  // namespace vct
