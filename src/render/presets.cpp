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

    // Finer voxels, shorter steps, 2×2 supersampling: for stills and comparisons with the reference.
    RenderSettings quality;
    quality.supersample = 2;
    quality.voxelResolution = 256;
    quality.sunShadowMapSize = 4096;
    quality.coneStep = 0.3f;

    return {{"fast", fast}, {"balanced", balanced}, {"quality", quality}};
}

}  // namespace vct
