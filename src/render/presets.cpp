#include "render/presets.h"

namespace vct {

std::vector<std::pair<std::string, RenderSettings>> renderPresets() {
    // Interactive on a software rasterizer: coarse voxels, few long cone steps, one sample per pixel.
    RenderSettings fast;
    fast.supersample = 1;
    fast.voxelResolution = 64;
    fast.sunShadowMapSize = 1024;
    fast.localShadowMapSize = 512;
    fast.diffuseConeCount = 4;
    fast.diffuseConeAperture = 70.0f;
    fast.diffuseCentreWeight = 0.25f;  // the ring of 3 shares the rest: 0.25 each
    fast.coneStep = 1.0f;

    // The renderer's defaults, except one sample per pixel and a smaller sun shadow map.
    RenderSettings balanced;
    balanced.supersample = 1;
    balanced.sunShadowMapSize = 2048;

    // More, narrower cones and 2×2 supersampling at 128³: for stills and comparisons with the
    // reference. (256³ voxels cost about 8× the injection time of 128³.)
    RenderSettings quality;
    quality.supersample = 2;
    quality.voxelResolution = 128;
    quality.sunShadowMapSize = 4096;
    quality.diffuseConeCount = 9;
    quality.diffuseConeAperture = 40.0f;
    quality.coneStep = 0.5f;

    return {{"fast", fast}, {"balanced", balanced}, {"quality", quality}};
}

std::optional<RenderSettings> findRenderPreset(const std::string& name) {
    for (const auto& [presetName, settings] : renderPresets())
        if (presetName == name) return settings;
    return std::nullopt;
}

}  // namespace vct
