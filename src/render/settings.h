// Everything a frame can be asked to do: image size, light components, shadow and cone parameters.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <glm/glm.hpp>

namespace vct {

// What the final image holds. `indirect` is everything but direct light (the same split as the
// reference path tracer's: direct = punctual lights at the first hit + emission seen directly).
enum class RenderMode { Full, Direct, Indirect };

std::optional<RenderMode> parseRenderMode(const std::string& name);
const char* renderModeName(RenderMode mode);

// Views for understanding, shown instead of light (values as in shaders_glsl/gpu_types.h).
enum class DebugView : uint32_t {
    None = 0,
    BaseColor = 1,
    Normal = 2,
    Depth = 3,
    AmbientOcclusion = 4,
    VoxelAlbedo = 5,
    VoxelNormal = 6,
    VoxelRadiance = 7,
};

struct Components {
    bool directDiffuse = true;
    bool directSpecular = true;
    bool indirectDiffuse = true;
    bool indirectSpecular = true;
    bool ambientOcclusion = true;
    bool emission = true;
    bool shadows = true;
};

struct RenderSettings {
    uint32_t width = 512;
    uint32_t height = 512;
    // Each pixel averages supersample² samples over its square, as "radiance of a pixel" means.
    uint32_t supersample = 2;
    RenderMode mode = RenderMode::Full;
    Components components;
    // Light that is not physical: off by default so `full` converges towards the ground truth.
    float ambientFactor = 0.0f;

    uint32_t sunShadowMapSize = 4096;    // directional lights
    uint32_t localShadowMapSize = 1024;  // each spot light and each cube face of a point light
    float shadowNormalOffset = 1.5f;     // texels
    float shadowSlopeBias = 2.0f;
    float pcfRadius = 2.0f;              // texels covered by the 5×5 kernel on each side

    // Voxel cone tracing.
    uint32_t voxelResolution = 128;      // voxels per side, a power of two from 32 to 512
    uint32_t diffuseConeCount = 6;       // one along the normal, the rest in a ring around it
    float diffuseConeAperture = 60.0f;   // full angle of each diffuse cone, degrees
    float diffuseCentreWeight = 0.25f;   // the ring shares the rest equally (0.15 each for 6 cones)
    float coneStep = 0.5f;               // step along a cone, as a fraction of its diameter there
    float coneMaxDistance = 1.0f;        // longest cone, as a fraction of the grid's side
    float coneStartOffset = 1.5f;        // voxels between the surface and a cone's apex
    float coneStopOpacity = 0.95f;       // a cone stops once this opaque
    float aoFalloff = 8.0f;              // occlusion at distance d weighs 1 / (1 + aoFalloff · d / grid side)
    bool skipEmptySpace = true;          // march through empty space with the coarse mips
    // Six directional mip chains (Crassin et al.) instead of one. On the Cornell box isotropic mips
    // recover 22 % of the path-traced indirect light and anisotropic ones 75 %: thin walls stay
    // opaque for the wide diffuse cones.
    bool anisotropicVoxels = true;
    uint32_t bounces = 1;                // 2 = re-inject the light the voxels gather by cones

    DebugView debugView = DebugView::None;
    uint32_t debugVoxelMip = 0;          // the mip level the voxel views show
};

// The components a mode shows (toggles switched off stay off).
Components effectiveComponents(const RenderSettings& settings);

}  // namespace vct
