// The settings `vct bench` measures: a default matrix that runs on lavapipe in a few minutes, a
// tiny one for tests, and the named presets (src/render/presets.h) placed among them.
#pragma once

#include <string>
#include <vector>

#include "render/settings.h"

namespace vct::bench {

struct BenchSetting {
    std::string label;   // short, e.g. "v64 aniso b1 c6 a60 s0.5"
    std::string preset;  // the preset this setting is, or empty
    RenderSettings settings;
};

// "v64 aniso b1 c6 a60 s0.5": the voxels, mips, bounces, cones, aperture and step, then each
// setting the bench records where it differs from the matrix's base (" ss2", " sm4096", " d4",
// " rays", " t4", ...), as the setting table spells it (src/render/setting_table.h).
std::string settingLabel(const RenderSettings& settings);
// What each part of a label means, a few lines for the plot's key.
std::vector<std::string> settingLabelLegend();

// One axis at a time around a cheap base (64³, 6 cones of 60°, step 0.5, anisotropic, 1 bounce),
// a few combinations, and every preset; image size from `imageSettings`.
std::vector<BenchSetting> defaultMatrix(const RenderSettings& imageSettings);
// Two cheap settings at 32³, for tests.
std::vector<BenchSetting> quickMatrix(const RenderSettings& imageSettings);
// Just the preset `name`; throws vct::Error naming the presets when there is none by that name.
std::vector<BenchSetting> presetMatrix(const std::string& name, const RenderSettings& imageSettings);

// True when `b` can reuse a Renderer made for `a` (same voxels, mips, bounces, shadow maps, size).
bool sameRenderer(const RenderSettings& a, const RenderSettings& b);

}  // namespace vct::bench
