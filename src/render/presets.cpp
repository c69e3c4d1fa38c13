#include "render/presets.h"

namespace vct {

std::vector<std::pair<std::string, RenderSettings>> renderPresets() {
    // Each preset is a point on the Pareto front `vct bench` measured over the built-in scenes on
    // lavapipe (README, "Accuracy"): GPU time of a static frame against the relMSE of full light,
    // the light converged. Narrow 40° cones beat the renderer's default 60° ones wherever six cones
    // are traced; with one cone the wide one is better. 128³ voxels measured no better than 64³ at
    // 128×128. Diffuse cones at a quarter resolution (one trace per 4×4 samples, upsampled along
    // the surfaces) cost a fraction and measured no worse than tracing every sample: what they
    // smooth away is mostly the voxels' own pattern. Every preset but `classic` averages 16 samples a
    // pixel over still frames (ShadingSettings::stillSamples): a frame costs what one sample does,
    // and a still image is the pixels' average that the path tracer's is (walls 0.035 -> 0.021 full
    // relMSE over the scenes, the tile room's seen lamps 0.094 -> 0.018; docs/experiments.md).
    constexpr uint32_t kStillSamples = 16;

    // Six 60° cones at 32³ stepping a whole diameter: the viewer's start on a software rasterizer (a
    // 960×540 window moving through the Cornell box at render scale 0.5: 65 ms a frame on lavapipe,
    // 2 cores, where one cone along the normal took 53 ms for three times the error: full relMSE
    // 0.085 against 0.248 over the built-in scenes).
    const RenderSettings fast{
        .image = {.supersample = 1, .diffuseDownscale = 4},
        .resources = {.voxelResolution = 32, .sunShadowMapSize = 2048},
        .shading = {.diffuseConeCount = 6,
                    .diffuseConeAperture = 60.0f,
                    .coneStep = 1.0f,
                    .stillSamples = kStillSamples},
    };

    // 6 cones of 40° at 64³, with a 2048² sun shadow map: at 128×128 it measured as accurate as
    // 4096² (full relMSE: terrain 0.0599 against 0.0585, cornell-sun and sun-room a little lower)
    // for a quarter of the shadow pass that each light move redraws (sun-room 21 -> 6 ms on
    // lavapipe). A light change converges in 3-7 bounces.
    const RenderSettings balanced{
        .image = {.supersample = 1, .diffuseDownscale = 4},
        .resources = {.voxelResolution = 64, .sunShadowMapSize = 2048},
        .shading = {.diffuseConeCount = 6,
                    .diffuseConeAperture = 40.0f,
                    .coneStep = 0.5f,
                    .stillSamples = kStillSamples},
    };

    // `balanced` with a 4096² sun shadow map: sharper shadow edges and sun patches. (With 2×2
    // samples a pixel besides the still samples: full relMSE 0.0350 against 0.0356 over the
    // scenes, for four times a frame.)
    const RenderSettings quality{
        .image = {.supersample = 1, .diffuseDownscale = 4},
        .resources = {.voxelResolution = 64, .sunShadowMapSize = 4096},
        .shading = {.diffuseConeCount = 6,
                    .diffuseConeAperture = 40.0f,
                    .coneStep = 0.5f,
                    .stillSamples = kStillSamples},
    };

    // The seed's set (Crassin et al. 2011's layout): six 60° cones weighted 0.25 + 5 × 0.15 at 128³,
    // 2×2 samples, the cones traced for every sample: the renderer's settings before the front was
    // measured, kept by name for comparison with other implementations.
    const RenderSettings classic{};

    // `balanced` paying for visibility (ResourceSettings::rayVisibility), for buildings: no light
    // through a wall with voxels of its own, the first bounce the same at every grid size. Its
    // cones are 60° wide: with a ray along each, the 40° set sees a third of the hemisphere, and a
    // small bright patch (the sun room's) shows as a blotch where a cone meets it. Even at 60° six
    // fixed directions drew it as streaks: the ring turns over the 16 still frames, averaged, and
    // each turn traces one of each cone's five beams (diffuseBeamOfTurn): as accurate as all five
    // over four turns (full relMSE 0.0195 against 0.0194) at a fifth of a frame's cones.
    RenderSettings walls = balanced;
    walls.resources.rayVisibility = true;
    walls.shading.diffuseConeAperture = 60.0f;
    walls.shading.diffuseConeTurns = 16;

    return {{"fast", fast}, {"balanced", balanced}, {"quality", quality}, {"walls", walls}, {"classic", classic}};
}

const std::vector<PresetSummary>& presetSummaries() {
    // From the committed bench run (docs/bench.json: lavapipe, 2 cores, 128×128, over the eight
    // built-in scenes); a test holds these to it.
    static const std::vector<PresetSummary> summaries = {
        {"fast", "32³, six 60° cones, one trace per 4×4 pixels, 16 samples a pixel over still frames", 15.81, 0.05075},
        {"balanced", "64³, six 40° cones, one trace per 4×4 pixels, 16 samples a pixel over still frames", 18.02,
         0.03379},
        {"quality", "balanced with a 4096² sun shadow map", 17.07, 0.03324},
        {"walls",
         "balanced with ray visibility and 60° cones, one beam of each a still frame over 16 turns: no light "
         "through walls; light changes ~5× slower",
         20.15, 0.01902},
        {"classic", "the seed's six 60° cones (0.25 + 5 × 0.15) at 128³, 2×2 samples, every sample traced", 741.38,
         0.05833},
    };
    return summaries;
}

std::string presetNameList() {
    std::string names;
    for (const auto& [name, unused] : renderPresets()) names += (names.empty() ? "" : ", ") + name;
    return names;
}

std::optional<RenderSettings> findRenderPreset(const std::string& name) {
    for (const auto& [presetName, settings] : renderPresets())
        if (presetName == name) return settings;
    return std::nullopt;
}

}  // namespace vct
