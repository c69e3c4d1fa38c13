#include "bench/matrix.h"

#include <cstdio>

#include "error.h"
#include "render/presets.h"

namespace vct::bench {
namespace {

RenderSettings withImage(RenderSettings settings, const RenderSettings& imageSettings) {
    settings.image.width = imageSettings.image.width;
    settings.image.height = imageSettings.image.height;
    settings.shading.mode = RenderMode::Full;
    return settings;
}

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

std::string settingLabel(const RenderSettings& s) {
    char text[128];
    std::snprintf(text, sizeof text, "v%u c%u a%g s%g %s b%s", s.resources.voxelResolution, s.shading.diffuseConeCount,
                  double(s.shading.diffuseConeAperture), double(s.shading.coneStep),
                  s.resources.anisotropicVoxels ? "aniso" : "iso",
                  s.resources.bounces == kConvergedBounces ? "conv" : std::to_string(s.resources.bounces).c_str());
    std::string label = text;
    if (s.image.supersample != 1) label += " ss" + std::to_string(s.image.supersample);
    if (s.resources.sunShadowMapSize != 2048) label += " sm" + std::to_string(s.resources.sunShadowMapSize);
    if (s.image.diffuseDownscale != 1) label += " d" + std::to_string(s.image.diffuseDownscale);
    if (s.resources.rayVisibility) label += " rays";
    if (s.shading.diffuseConeTurns != 1) label += " t" + std::to_string(s.shading.diffuseConeTurns);
    return label;
}

std::vector<std::string> settingLabelLegend() {
    return {
        "labels: v64 = 64³ voxels, c6 = 6 diffuse cones,",
        "a40 = 40° cone aperture, s0.5 = step of 0.5 cone diameters,",
        "aniso / iso = six directional mip chains / one,",
        "bconv / b1 = bounces until converged / one bounce,",
        "ss2 = 2×2 samples a pixel, sm4096 = 4096² sun shadow map (else 2048²),",
        "d4 = diffuse cones traced once per 4×4 pixels, rays = ray visibility,",
        "t4 = the cones' ring turned over 4 still frames, averaged; * = on the front",
    };
}

std::vector<BenchSetting> defaultMatrix(const RenderSettings& imageSettings) {
    // The base: the renderer's defaults at one sample per pixel and a 2048² sun shadow map, 64³.
    // Not the full product of {32,64,128} × {1,6,9} cones × {40°,60°} × {0.5,1} × mips × bounces
    // (144 settings): each axis alone around the base, then the combinations the front suggested
    // in a first run (narrow cones, cheap grids), and what supersampling and a finer sun shadow map
    // do to direct light. The light converges everywhere but at 128³, where converging takes about
    // a minute per light change on lavapipe: there, one bounce (b1). 9 cones of 40° measured the
    // same as 6 at 64³, so only 128³ has them.
    const uint32_t sun = 2048;
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
