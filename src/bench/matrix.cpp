#include "bench/matrix.h"

#include <cstdio>

#include "error.h"
#include "render/presets.h"
#include "render/setting_table.h"

namespace vct::bench {
namespace {

RenderSettings withImage(RenderSettings settings, const RenderSettings& imageSettings) {
    settings.image.width = imageSettings.image.width;
    settings.image.height = imageSettings.image.height;
    settings.shading.mode = RenderMode::Full;
    return settings;
}

// The matrix's sun shadow map where a setting does not name another.
constexpr uint32_t kMatrixSunShadowMap = 2048;

// A matrix entry: what differs from the renderer's defaults, at one sample per pixel.
RenderSettings variant(const ResourceSettings& resources, const ShadingSettings& shading, uint32_t supersample = 1,
                       uint32_t diffuseDownscale = 1) {
    return RenderSettings{.image = {.supersample = supersample, .diffuseDownscale = diffuseDownscale},
                          .resources = resources,
                          .shading = shading};
}

// Adds the presets: a preset equal to a matrix setting marks that setting instead of adding one.
void addPresets(std::vector<BenchSetting>& matrix, const RenderSettings& imageSettings) {
    for (const auto& [name, presetSettings] : renderPresets()) {
        const RenderSettings settings = withImage(presetSettings, imageSettings);
        bool found = false;
        for (BenchSetting& existing : matrix) {
            if (existing.preset.empty() && existing.settings == settings) {
                existing.preset = name;
                found = true;
                break;
            }
        }
        if (!found) matrix.push_back({settingLabel(settings), name, settings});
    }
}

}  // namespace

std::string settingLabel(const RenderSettings& settings) {
    // What a label leaves out: the matrix's base, the renderer's defaults at one sample a pixel
    // with the matrix's sun shadow map. Its main axes first, always; then what differs from the base.
    const RenderSettings base = variant({.sunShadowMapSize = kMatrixSunShadowMap}, {});
    std::string always, differs;
    for (const SettingRow& row : settingTable()) {
        if (!row.benchKey) continue;
        const double value = row.get(settings);
        if (row.alwaysInLabel) always += (always.empty() ? "" : " ") + labelPart(row, value);
        else if (value != row.get(base)) differs += " " + labelPart(row, value);
    }
    return always + differs;
}

std::vector<std::string> settingLabelLegend() {
    // In the label's order: the parts every label has, then the others.
    std::vector<std::string> lines = {"labels:"};
    for (bool always : {true, false})
        for (const SettingRow& row : settingTable()) {
            if (!row.benchKey || !row.legend || row.alwaysInLabel != always) continue;
            const std::string part = std::string(row.legend) + ",";
            if (lines.back().size() + 1 + part.size() > 72) lines.push_back(part);
            else lines.back() += " " + part;
        }
    lines.back().back() = ';';
    lines.back() += " * = on the front";
    return lines;
}

std::vector<BenchSetting> defaultMatrix(const RenderSettings& imageSettings) {
    // The base: the renderer's defaults at one sample per pixel and a 2048² sun shadow map, 64³.
    // Not the full product of {32,64,128} × {1,6,9} cones × {40°,60°} × {0.5,1} × mips × bounces
    // (144 settings): each axis alone around the base, then the combinations the front suggested
    // in a first run (narrow cones, cheap grids), and what supersampling and a finer sun shadow map
    // do to direct light. The light converges everywhere but at 128³, where converging takes about
    // a minute per light change on lavapipe: there, one bounce (b1). 9 cones of 40° measured the
    // same as 6 at 64³, so only 128³ has them.
    const uint32_t sun = kMatrixSunShadowMap;
    const std::vector<RenderSettings> variants = {
        variant({.voxelResolution = 64, .sunShadowMapSize = sun}, {}),  // the base
        // voxels
        variant({.voxelResolution = 32, .sunShadowMapSize = sun}, {}),
        variant({.voxelResolution = 128, .bounces = 1, .sunShadowMapSize = sun}, {}),
        // cones
        variant({.voxelResolution = 64, .sunShadowMapSize = sun}, {.diffuseConeCount = 1}),
        variant({.voxelResolution = 64, .sunShadowMapSize = sun}, {.diffuseConeAperture = 40.0f}),
        // step
        variant({.voxelResolution = 64, .sunShadowMapSize = sun}, {.coneStep = 1.0f}),
        // mips, bounces
        variant({.voxelResolution = 64, .anisotropicVoxels = false, .sunShadowMapSize = sun}, {}),
        variant({.voxelResolution = 64, .bounces = 1, .sunShadowMapSize = sun}, {}),
        variant({.voxelResolution = 64, .bounces = 1, .sunShadowMapSize = sun}, {.diffuseConeAperture = 40.0f}),
        // combinations
        variant({.voxelResolution = 32, .sunShadowMapSize = sun}, {.diffuseConeCount = 1, .coneStep = 1.0f}),
        variant({.voxelResolution = 32, .sunShadowMapSize = sun},
                {.diffuseConeCount = 1, .diffuseConeAperture = 40.0f, .coneStep = 1.0f}),
        variant({.voxelResolution = 32, .sunShadowMapSize = sun}, {.diffuseConeAperture = 40.0f}),
        variant({.voxelResolution = 64, .sunShadowMapSize = sun},
                {.diffuseConeCount = 1, .diffuseConeAperture = 40.0f}),
        variant({.voxelResolution = 128, .bounces = 1, .sunShadowMapSize = sun},
                {.diffuseConeCount = 9, .diffuseConeAperture = 40.0f}),
        // 2×2 samples; a finer sun shadow map
        variant({.voxelResolution = 64, .sunShadowMapSize = sun}, {.diffuseConeAperture = 40.0f}, 2),
        variant({.voxelResolution = 64, .sunShadowMapSize = 4096}, {.diffuseConeAperture = 40.0f}),
        // diffuse cones for one sample in 2×2 or 4×4 (d2, d4), upsampled; with 2×2 supersampling
        // d2 traces them once per pixel while direct light gets four samples
        variant({.voxelResolution = 64, .sunShadowMapSize = 4096}, {.diffuseConeAperture = 40.0f}, 1, 2),
        variant({.voxelResolution = 64, .sunShadowMapSize = 4096}, {.diffuseConeAperture = 40.0f}, 1, 4),
        variant({.voxelResolution = 64, .sunShadowMapSize = 4096}, {.diffuseConeAperture = 40.0f}, 2, 2),
        variant({.voxelResolution = 64, .sunShadowMapSize = 4096}, {.diffuseConeAperture = 40.0f}, 2, 4),
        variant({.voxelResolution = 32, .sunShadowMapSize = sun}, {.diffuseConeAperture = 40.0f}, 1, 2),
        variant({.voxelResolution = 32, .sunShadowMapSize = sun}, {.diffuseConeAperture = 40.0f}, 1, 4),
        variant({.voxelResolution = 32, .sunShadowMapSize = sun}, {.diffuseConeCount = 1, .coneStep = 1.0f}, 1, 2),
        variant({.voxelResolution = 32, .sunShadowMapSize = sun}, {.diffuseConeCount = 1, .coneStep = 1.0f}, 1, 4),
        variant({.voxelResolution = 64, .sunShadowMapSize = 4096}, {.diffuseConeAperture = 40.0f}, 2),
    };
    std::vector<BenchSetting> matrix;
    for (const RenderSettings& settings : variants) {
        const RenderSettings sized = withImage(settings, imageSettings);
        matrix.push_back({settingLabel(sized), "", sized});
    }
    addPresets(matrix, imageSettings);
    return matrix;
}

std::vector<BenchSetting> quickMatrix(const RenderSettings& imageSettings) {
    const ResourceSettings small{.voxelResolution = 32, .sunShadowMapSize = 512, .localShadowMapSize = 256};
    const RenderSettings oneCone = withImage(variant(small, {.diffuseConeCount = 1, .coneStep = 1.0f}), imageSettings);
    const RenderSettings sixIsotropic = withImage(
        variant({.voxelResolution = 32, .anisotropicVoxels = false, .sunShadowMapSize = 512, .localShadowMapSize = 256},
                {.diffuseConeCount = 6, .coneStep = 1.0f}),
        imageSettings);
    return {{settingLabel(oneCone), "", oneCone}, {settingLabel(sixIsotropic), "", sixIsotropic}};
}

std::vector<BenchSetting> presetMatrix(const std::string& name, const RenderSettings& imageSettings) {
    std::string names;
    for (const auto& [presetName, settings] : renderPresets()) {
        if (presetName == name) {
            const RenderSettings sized = withImage(settings, imageSettings);
            return {{settingLabel(sized), presetName, sized}};
        }
        names += (names.empty() ? "" : ", ") + presetName;
    }
    throw Error("there is no preset '" + name + "' (the presets are " + names + ")");
}

bool sameRenderer(const RenderSettings& a, const RenderSettings& b) {
    return a.image == b.image && a.resources == b.resources;
}

}  // namespace vct::bench
