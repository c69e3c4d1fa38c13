// Everything a frame can be asked to do, grouped by what a change costs:
//   ImageSettings    the image-sized targets (G-buffer, radiance, resolve): Renderer::resize rebuilds them;
//   ResourceSettings the voxel volumes and shadow maps: a change needs a new Renderer;
//   ShadingSettings  constants of the frame only: Renderer::setShading takes them at no cost.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "gpu_types.h"

namespace vct {

// What the final image holds. `indirect` is everything but direct light (the same split as the
// reference path tracer's: direct = emission seen directly + the light of punctual lights and of
// emissive surfaces at the first hit).
enum class RenderMode { Full, Direct, Indirect };

// "full", "direct", "indirect": as --mode spells it (its row in setting_table.cpp reads these).
const char* renderModeName(RenderMode mode);

// Views for understanding, shown instead of light: the values the shading pass reads.
enum class DebugView : uint32_t {
    None = glsl::DEBUG_NONE,
    BaseColor = glsl::DEBUG_BASE_COLOR,
    Normal = glsl::DEBUG_NORMAL,
    Depth = glsl::DEBUG_DEPTH,
    AmbientOcclusion = glsl::DEBUG_AMBIENT_OCCLUSION,
    VoxelAlbedo = glsl::DEBUG_VOXEL_ALBEDO,
    VoxelNormal = glsl::DEBUG_VOXEL_NORMAL,
    VoxelRadiance = glsl::DEBUG_VOXEL_RADIANCE,
    SunCascades = glsl::DEBUG_SUN_CASCADES,
};
constexpr uint32_t debugViewCount = glsl::DEBUG_VIEW_COUNT;
// Its label in the viewer, e.g. "voxel albedo"; DebugView::None is "lit image".
const char* debugViewLabel(DebugView view);

struct Components {
    bool directDiffuse = true;
    bool directSpecular = true;
    bool indirectDiffuse = true;
    bool indirectSpecular = true;
    bool ambientOcclusion = true;
    bool emission = true;
    bool shadows = true;
    bool areaLights = true;
    bool operator==(const Components&) const = default;
};

// Each component once: its member, the SHOW_*/USE_* bit the shaders test, its --disable name and
// its label in the viewer (whose keys 1…8 follow this order).
struct ComponentInfo {
    bool Components::*member;
    uint32_t shaderFlag;
    const char* option;
    const char* label;
};
const std::array<ComponentInfo, 8>& componentTable();
uint32_t componentFlags(const Components& components);

// ResourceSettings::bounces for "every bounce": each voxel's light includes what its own cones
// gather, iterated until the volume's mean changes by less than kBounceTolerance.
inline constexpr uint32_t kConvergedBounces = 0;
inline constexpr float kBounceTolerance = 0.01f;
// Iterations one frame runs at most while converging (vct render and vct bench).
inline constexpr uint32_t kMaxBouncesPerFrame = 32;

// The grid whose voxels ShadingSettings::coneStartOffset counts: the offset is a world distance,
// the same at every voxel resolution.
inline constexpr uint32_t kConeStartGrid = 64;

struct ImageSettings {
    uint32_t width = 512;
    uint32_t height = 512;
    // Each pixel averages supersample² samples over its square, as "radiance of a pixel" means.
    uint32_t supersample = 2;
    // Diffuse cones once per diffuseDownscale² samples (1, 2 or 4), upsampled along the surfaces
    // (shaders_glsl/reduced_diffuse.glsl): they are most of a frame's cost, and the light they
    // gather changes over voxels, not pixels.
    uint32_t diffuseDownscale = 1;
    bool operator==(const ImageSettings&) const = default;
};

struct ResourceSettings {
    uint32_t voxelResolution = 128;  // voxels per side, a power of two from 32 to 512
    // Six directional mip chains (Crassin et al.) instead of one. On the Cornell box isotropic mips
    // recover 22 % of the path-traced indirect light and anisotropic ones 75 %: thin walls stay
    // opaque for the wide diffuse cones.
    bool anisotropicVoxels = true;
    // Bounces of indirect light the voxels carry: 1 = the light sources' light reflected once,
    // N = N reflections, kConvergedBounces = every bounce, iterated until the light converges.
    uint32_t bounces = kConvergedBounces;
    uint32_t sunShadowMapSize = 4096;  // directional lights
    // The most view-fitted maps (cascades, sun_cascades.h) a sun gets beside its scene-fitted one,
    // each a tile of the sun array at eight texels a pixel of image height; as many as the camera's
    // nearest geometry needs, none in most small scenes. 0: the scene-fitted map alone.
    uint32_t sunCascades = 4;
    uint32_t localShadowMapSize = 1024;  // each spot light and each cube face of a point light
    // Each cube face of an area light: their shadows are soft, tested by rays that are spread over
    // the light, so a coarser map serves (eight lights at 1024² took 200 MB).
    uint32_t areaShadowMapSize = 512;
    // Pay for visibility: every cone stops where a ray along it meets a surface at the grid's
    // finest level (shaders_glsl/visibility_ray.glsl), and the diffuse cones are traced as five
    // beams each. No light passes a wall that has voxels of its own; about 2.2× a still frame and
    // 4.6× a light change on lavapipe. Off: the cones see only the filtered mips, as Crassin et al.
    bool rayVisibility = false;
    bool operator==(const ResourceSettings&) const = default;
};

struct ShadingSettings {
    RenderMode mode = RenderMode::Full;
    Components components;
    // Light that is not physical: off by default so `full` converges towards the ground truth.
    float ambientFactor = 0.0f;

    float shadowNormalOffset = 1.5f;  // texels (shadows.glsl: no depth bias on the occluders)
    float pcfRadius = 2.0f;           // texels covered by the 5×5 kernel on each side, at most

    // Voxel cone tracing.
    uint32_t diffuseConeCount = 6;      // one along the normal, the rest in a ring around it
    float diffuseConeAperture = 60.0f;  // full angle of each diffuse cone, degrees
    float diffuseCentreWeight = 0.25f;  // the ring shares the rest equally (0.15 each for 6 cones)
    float coneStep = 0.5f;              // step along a cone, as a fraction of its diameter there
    float coneMaxDistance = 1.0f;       // longest cone, as a fraction of the grid's side
    float coneStartOffset = 1.5f;       // surface to cone apex, in voxels of a 64³ grid (and at least of this one)
    float coneStopOpacity = 0.95f;      // a cone stops once this opaque
    float aoFalloff = 8.0f;             // occlusion at distance d weighs 1 / (1 + aoFalloff · d / grid side)
    float specularMaxAperture = 90.0f;  // the widest specular cone, degrees; a rougher lobe takes the diffuse light
    // The screen's ring of diffuse cones turned this many times about the normal, by equal shares
    // of the spacing between its cones, one still frame each, and those frames averaged
    // (Renderer::settling): more directions from the same cones a frame. With ray visibility the
    // cones see sharply, and six fixed directions drew a small sunlit patch as streaks; turns in
    // fours then trace one of each cone's five beams a turn (diffuseBeamOfTurn). 1: fixed.
    uint32_t diffuseConeTurns = 1;
    // Samples per pixel gathered over still frames: each still frame moves the image's samples
    // within their pixel (a Hammersley set whose first point is the centre, so a moving view shows
    // the unmoved image) and the frames are averaged with the ring's turns. The pixel then
    // averages its square as `supersample` does, at no cost per frame: small bright emitters seen
    // directly (the tile room's lamps) alias at one sample. 1: the samples stay put.
    uint32_t stillSamples = 1;
    // March through empty space with the coarse mips. Unset: on, except on a software rasterizer,
    // which runs both sides of the test at every step and measured each cone 25 % faster without it.
    std::optional<bool> skipEmptySpace;

    // With converged bounces, one bounce per frame, each fed by the last frame's light, so that a
    // moving light never resets (and pumps) the indirect light: the viewer's choice. Otherwise
    // every frame that re-lights the voxels iterates to convergence.
    bool progressiveBounces = false;
    // ...and each frame's bounce gathers for every Nth occupied voxel only, in turn, so that a
    // moving light costs a fraction of a bounce per frame; the light sources' own light (the
    // first bounce) is still re-injected whole every frame. 0: by the work (progressiveSlices()).
    uint32_t progressiveSlices = 0;

    DebugView debugView = DebugView::None;
    uint32_t debugVoxelMip = 0;  // the mip level the voxel views show
    bool operator==(const ShadingSettings&) const = default;
};

struct RenderSettings {
    ImageSettings image;
    ResourceSettings resources;
    ShadingSettings shading;
    bool operator==(const RenderSettings&) const = default;
};

// The components a mode shows (toggles switched off stay off).
Components effectiveComponents(const ShadingSettings& shading);

// Whether the cones skip empty space: the setting, or its default on the device (on, but not on a
// software rasterizer).
inline bool skipsEmptySpace(const ShadingSettings& shading, bool softwareRasterizer) {
    return shading.skipEmptySpace.value_or(!softwareRasterizer);
}

// One bounce per frame (progressiveBounces honoured: only converging light can be progressive).
inline bool bouncesProgressively(const RenderSettings& settings) {
    return settings.resources.bounces == kConvergedBounces && settings.shading.progressiveBounces;
}

// The cones a progressive bounce traces per frame, at most: 15-20 ms on lavapipe (2 cores, about
// 2 µs a cone at 64³, once the dispatch covers the slice alone), well under a millisecond on a
// discrete GPU.
inline constexpr uint32_t kProgressiveGatherCones = 8192;
// The slices a progressive bounce is spread over, for `occupiedVoxels` voxels each gathering
// through the diffuse cones: one on the `fast` preset's Cornell box (32³, one cone), 19 on
// `balanced` (64³, six cones).
inline uint32_t progressiveSlices(const RenderSettings& settings, uint32_t occupiedVoxels) {
    if (settings.shading.progressiveSlices != 0) return settings.shading.progressiveSlices;
    const uint64_t cones = uint64_t(occupiedVoxels) * std::max(settings.shading.diffuseConeCount, 1u);
    return uint32_t(std::max<uint64_t>(1, (cones + kProgressiveGatherCones - 1) / kProgressiveGatherCones));
}

// Whether the frame reads the voxels at all (indirect light, AO, voxel views): if not, no voxel
// pass runs.
bool needsVoxels(const ShadingSettings& shading);
// Whether the lit image traces diffuse cones (indirect diffuse light, or AO for the ambient term).
bool needsDiffuseCones(const ShadingSettings& shading);
// The turns of the diffuse ring the still frames trace: ShadingSettings::diffuseConeTurns where the
// image shows a ring of diffuse cones (1 otherwise: every turn would be the same image).
uint32_t diffuseRingTurns(const ShadingSettings& shading);
// The still frames the image averages: every turn of the ring with every still sample, the least
// common multiple of the two counts (1: the image is each frame's own).
uint32_t stillFramesAveraged(const ShadingSettings& shading);
// Which of each screen cone's five beams a turn of the ring traces, with ray visibility
// (cone_tracing.glsl, traceDiffuseCone): `beam` glsl::ALL_BEAMS, AXIS_BEAM, or BEAM_AROUND_AXIS at
// `azimuth` (radians). Where the ring turns in fours, each turn traces one beam a cone:
// the axis every fourth turn, else one around it, those azimuths spread evenly over the turns, so the
// turns' mean weighs the beams as the five do (a quarter the axis) at a fifth of the cones a frame.
struct DiffuseBeam {
    uint32_t beam = glsl::ALL_BEAMS;
    float azimuth = 0.0f;
};
DiffuseBeam diffuseBeamOfTurn(const ShadingSettings& shading, bool rayVisibility, uint32_t turn);
// The offset of still frame `frame`'s samples from their centres, in samples (each in [−½, ½)).
glm::vec2 stillSampleOffset(const ShadingSettings& shading, uint32_t frame);
// Whether the frame ends with the resolve pass: supersamples to average, or still frames.
bool resolvesImage(const RenderSettings& settings);

}  // namespace vct
