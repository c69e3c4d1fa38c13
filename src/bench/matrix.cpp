#include "bench/matrix.h"

#include <cstdio>

#include "error.h"
#include "render/presets.h"

namespace vct::bench {
namespace {

RenderSettings withImage(RenderSettings settings, const RenderSettings& imageSettings) {
    settings.width = imageSettings.width;
    settings.height = imageSettings.height;
    settings.mode = RenderMode::Full;
    return settings;
}

struct Variant {
    uint32_t voxels;
    uint32_t cones;
    float aperture;
    float step;
    bool anisotropic;
    uint32_t bounces;
    uint32_t supersample = 1;
    uint32_t sunShadowMapSize = 2048;
};

// Adds the presets: a preset equal to a matrix setting marks that setting instead of adding one.
void addPresets(std::vector<BenchSetting>& matrix, const RenderSettings& imageSettings) {
    for (const auto& [name, presetSettings] : renderPresets()) {
        const RenderSettings settings = withImage(presetSettings, imageSettings);
        bool found = false;
        for (BenchSetting& existing : matrix) {
            if (existing.preset.empty() && sameMeasuredSettings(existing.settings, settings)) {
                existing.preset = name;
                found = true;
                break;
            }
        }
        if (!found) matrix.push_back({settingLabel(settings), name, settings});
    }
}

}  // namespace

std::string settingLabel(const RenderSettings& s) {
    char text[128];
    std::snprintf(text, sizeof text, "v%u c%u a%g s%g %s b%u", s.voxelResolution, s.diffuseConeCount,
                  double(s.diffuseConeAperture), double(s.coneStep), s.anisotropicVoxels ? "aniso" : "iso", s.bounces);
    std::string label = text;
    if (s.supersample != 1) label += " ss" + std::to_string(s.supersample);
    if (s.sunShadowMapSize != 2048) label += " sm" + std::to_string(s.sunShadowMapSize);
    return label;
}

std::vector<BenchSetting> defaultMatrix(const RenderSettings& imageSettings) {
    // The base: the renderer's defaults at one sample per pixel and a 2048² sun shadow map, 64³.
    RenderSettings base;
    base.supersample = 1;
    base.sunShadowMapSize = 2048;
    // Not the full product of {32,64,128} × {1,6,9} cones × {40°,60°} × {0.5,1} × mips × bounces
    // (144 settings): each axis alone around the base, then the combinations the front suggested
    // in a first run (narrow cones, cheap grids), and what supersampling and a finer sun shadow map
    // do to direct light. Two bounces only at 64³: at 128³ one light change costs seconds. 9 cones
    // of 40° measured the same as 6 at 64³, so only 128³ has them.
    const std::vector<Variant> variants = {
        {64, 6, 60, 0.5f, true, 1},  // the base
        {32, 6, 60, 0.5f, true, 1},  {128, 6, 60, 0.5f, true, 1},                                   // voxels
        {64, 1, 60, 0.5f, true, 1},  {64, 6, 40, 0.5f, true, 1},                                   // cones
        {64, 6, 60, 1.0f, true, 1},                                                                // step
        {64, 6, 60, 0.5f, false, 1}, {64, 6, 60, 0.5f, true, 2},                                    // mips, bounces
        {32, 1, 60, 1.0f, true, 1},  {32, 1, 40, 1.0f, true, 1},   {32, 6, 40, 0.5f, true, 1},
        {64, 1, 40, 0.5f, true, 1},  {128, 9, 40, 0.5f, true, 1},
        {64, 6, 40, 0.5f, true, 1, 2},  {64, 6, 40, 0.5f, true, 1, 1, 4096},  // 2×2 samples; shadow map
    };
    std::vector<BenchSetting> matrix;
    for (const Variant& v : variants) {
        RenderSettings settings = base;
        settings.voxelResolution = v.voxels;
        settings.diffuseConeCount = v.cones;
        settings.diffuseConeAperture = v.aperture;
        settings.coneStep = v.step;
        settings.anisotropicVoxels = v.anisotropic;
        settings.bounces = v.bounces;
        settings.supersample = v.supersample;
        settings.sunShadowMapSize = v.sunShadowMapSize;
        settings = withImage(settings, imageSettings);
        matrix.push_back({settingLabel(settings), "", settings});
    }
    addPresets(matrix, imageSettings);
    return matrix;
}

std::vector<BenchSetting> quickMatrix(const RenderSettings& imageSettings) {
    RenderSettings settings;
    settings.supersample = 1;
    settings.sunShadowMapSize = 512;
    settings.localShadowMapSize = 256;
    settings.voxelResolution = 32;
    settings.diffuseConeCount = 1;
    settings.coneStep = 1.0f;
    std::vector<BenchSetting> matrix;
    settings = withImage(settings, imageSettings);
    matrix.push_back({settingLabel(settings), "", settings});
    settings.diffuseConeCount = 6;
    settings.anisotropicVoxels = false;
    matrix.push_back({settingLabel(settings), "", settings});
    return matrix;
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
    return a.width == b.width && a.height == b.height && a.supersample == b.supersample &&
           a.voxelResolution == b.voxelResolution && a.anisotropicVoxels == b.anisotropicVoxels &&
           a.bounces == b.bounces && a.sunShadowMapSize == b.sunShadowMapSize &&
           a.localShadowMapSize == b.localShadowMapSize;
}

bool sameMeasuredSettings(const RenderSettings& a, const RenderSettings& b) {
    return sameRenderer(a, b) && a.diffuseConeCount == b.diffuseConeCount &&
           a.diffuseConeAperture == b.diffuseConeAperture && a.diffuseCentreWeight == b.diffuseCentreWeight &&
           a.coneStep == b.coneStep && a.coneMaxDistance == b.coneMaxDistance &&
           a.coneStartOffset == b.coneStartOffset && a.coneStopOpacity == b.coneStopOpacity &&
           a.skipEmptySpace == b.skipEmptySpace && a.ambientFactor == b.ambientFactor &&
           a.shadowNormalOffset == b.shadowNormalOffset && a.shadowSlopeBias == b.shadowSlopeBias &&
           a.pcfRadius == b.pcfRadius;
}

}  // namespace vct::bench
