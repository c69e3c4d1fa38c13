#include "render/setting_table.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace vct {
namespace {

using R = RenderSettings;
using G = SettingGroup;
using W = SettingWidget;

std::vector<SettingRow> makeSettingTable() {
    return {
        // The image.
        {.option = "width",
         .shape = "W",
         .help = "image width in pixels",
         .group = G::Image,
         .access = settingField<&R::image, &ImageSettings::width>(),
         .widget = W::None,
         .min = 1,
         .max = 16384,
         .whole = true},
        {.option = "height",
         .shape = "H",
         .help = "image height in pixels",
         .group = G::Image,
         .access = settingField<&R::image, &ImageSettings::height>(),
         .widget = W::None,
         .min = 1,
         .max = 16384,
         .whole = true},
        {.option = "supersample",
         .shape = "N",
         .help = "samples per pixel side, averaged over the pixel",
         .group = G::Image,
         .access = settingField<&R::image, &ImageSettings::supersample>(),
         .label = "supersample",
         .format = "%d",
         .min = 1,
         .max = 8,
         .whole = true,
         .benchKey = "supersample",
         .labelTag = "ss",
         .legend = "ss2 = 2×2 samples a pixel"},
        {.option = "diffuse-resolution",
         .shape = "full|half|quarter",
         .help = "diffuse cones for every sample, or for one in 2×2 or 4×4, upsampled along the surfaces",
         .group = G::Image,
         .access = settingField<&R::image, &ImageSettings::diffuseDownscale>(),
         .label = "diffuse resolution",
         .widget = W::Choice,
         .names = {{"full", 1, "1"}, {"half", 2, "2"}, {"quarter", 4, "4"}},
         .namesOnly = true,
         .benchKey = "diffuse_resolution",
         .labelTag = "d",
         .legend = "d4 = diffuse cones traced once per 4×4 pixels"},
        {.option = "still-samples",
         .shape = "N",
         .help = "samples per pixel gathered over N still frames, each moving the samples within their pixel, "
                 "averaged with the cones' turns",
         .group = G::Image,
         .access = settingField<&R::shading, &ShadingSettings::stillSamples>(),
         .label = "still samples",
         .format = "%d",
         .min = 1,
         .max = 16,
         .whole = true,
         .benchKey = "still_samples",
         .labelTag = "j",
         .legend = "j4 = 4 samples a pixel over 4 still frames"},
        // What the image shows.
        {.option = "mode",
         .shape = "full|direct|indirect",
         .help = "which light the image holds",
         .group = G::Light,
         .access = settingField<&R::shading, &ShadingSettings::mode>(),
         .label = "mode (M)",
         .widget = W::Choice,
         .names = {{renderModeName(RenderMode::Full), double(RenderMode::Full), ""},
                   {renderModeName(RenderMode::Direct), double(RenderMode::Direct), ""},
                   {renderModeName(RenderMode::Indirect), double(RenderMode::Indirect), ""}},
         .namesOnly = true},
        {.option = "ambient",
         .shape = "F",
         .help = "non-physical ambient light factor",
         .group = G::Light,
         .access = settingField<&R::shading, &ShadingSettings::ambientFactor>(),
         .label = "ambient",
         .format = "%.3f",
         .max = 10,
         .benchKey = "ambient",
         .labelTag = "amb",
         .legend = "amb0.1 = ambient factor 0.1"},
        // The voxels.
        {.option = "voxels",
         .shape = "N",
         .help = "voxels per side of the grid",
         .group = G::Voxels,
         .access = settingField<&R::resources, &ResourceSettings::voxelResolution>(),
         .label = "voxels",
         .widget = W::PowerOfTwo,
         .min = 32,
         .max = 512,
         .whole = true,
         .powerOfTwo = true,
         .benchKey = "voxels",
         .labelTag = "v",
         .alwaysInLabel = true,
         .legend = "v64 = 64³ voxels"},
        {.option = "voxel-mips",
         .shape = "isotropic|anisotropic",
         .help = "one mip chain or six directional ones",
         .group = G::Voxels,
         .access = settingField<&R::resources, &ResourceSettings::anisotropicVoxels>(),
         .label = "voxel mips",
         .widget = W::Choice,
         .names = {{"isotropic", 0, "iso"}, {"anisotropic", 1, "aniso"}},
         .namesOnly = true,
         .benchKey = "mips",
         .alwaysInLabel = true,
         .legend = "aniso / iso = six directional mip chains / one"},
        {.option = "visibility",
         .shape = "mips|rays",
         .help = "what stops a cone: the filtered mips alone, or also a ray along it through the finest voxels (no "
                 "light through walls with voxels of their own; slower)",
         .group = G::Voxels,
         .access = settingField<&R::resources, &ResourceSettings::rayVisibility>(),
         .label = "visibility",
         .widget = W::Choice,
         .names = {{"mips", 0, "mips"}, {"rays", 1, "rays"}},
         .namesOnly = true,
         .benchKey = "visibility",
         .legend = "rays = ray visibility"},
        {.option = "bounces",
         .shape = "N|converged",
         .help = "bounces of indirect light; converged iterates until it changes < 1 %",
         .group = G::Voxels,
         .access = settingField<&R::resources, &ResourceSettings::bounces>(),
         .label = "bounces",
         .format = "%d",
         .min = 1,
         .max = double(kMaxBouncesPerFrame),
         .whole = true,
         .names = {{"converged", double(kConvergedBounces), "conv"}},
         .benchKey = "bounces",
         .labelTag = "b",
         .alwaysInLabel = true,
         .legend = "bconv / b1 = bounces until converged / one bounce"},
        // The cones.
        {.option = "cones",
         .shape = "N",
         .help = "diffuse cones: one along the normal, the rest in a ring around it",
         .group = G::Cones,
         .access = settingField<&R::shading, &ShadingSettings::diffuseConeCount>(),
         .label = "diffuse cones",
         .format = "%d",
         .min = 1,
         .max = 32,
         .whole = true,
         .benchKey = "cones",
         .labelTag = "c",
         .alwaysInLabel = true,
         .legend = "c6 = 6 diffuse cones"},
        {.option = "cone-aperture",
         .shape = "DEGREES",
         .help = "full angle of each diffuse cone",
         .group = G::Cones,
         .access = settingField<&R::shading, &ShadingSettings::diffuseConeAperture>(),
         .label = "aperture",
         .format = "%.0f deg",
         .min = 1,
         .max = 120,
         .benchKey = "aperture_deg",
         .labelTag = "a",
         .alwaysInLabel = true,
         .legend = "a40 = 40° cone aperture"},
        {.option = "centre-weight",
         .shape = "F",
         .help = "the weight of the cone along the normal; the ring shares the rest",
         .group = G::Cones,
         .access = settingField<&R::shading, &ShadingSettings::diffuseCentreWeight>(),
         .label = "centre weight",
         .max = 1,
         .benchKey = "centre_weight",
         .labelTag = "w",
         .legend = "w0.3 = centre cone weighs 0.3 (else 0.25)"},
        {.option = "cone-turns",
         .shape = "N",
         .help = "the diffuse cones' ring turned N times about the normal, one still frame each, and the frames "
                 "averaged (1 = fixed directions); with --visibility rays and N in fours, each turn traces one of "
                 "a cone's five beams",
         .group = G::Cones,
         .access = settingField<&R::shading, &ShadingSettings::diffuseConeTurns>(),
         .label = "ring turns",
         .format = "%d",
         .min = 1,
         .max = 16,
         .whole = true,
         .benchKey = "cone_turns",
         .labelTag = "t",
         .legend = "t4 = the ring of cones turned over 4 still frames, averaged"},
        {.option = "cone-step",
         .shape = "F",
         .help = "cone step as a fraction of its diameter",
         .group = G::Cones,
         .access = settingField<&R::shading, &ShadingSettings::coneStep>(),
         .label = "step",
         .format = "%.2f diameters",
         .min = 0.05,
         .max = 4,
         .benchKey = "step",
         .labelTag = "s",
         .alwaysInLabel = true,
         .legend = "s0.5 = step of 0.5 cone diameters"},
        {.option = "cone-max-distance",
         .shape = "F",
         .help = "longest cone, as a fraction of the grid's side; past it a cone sees the sky",
         .group = G::Cones,
         .access = settingField<&R::shading, &ShadingSettings::coneMaxDistance>(),
         .label = "max distance",
         .format = "%.2f grid",
         .min = 0.01,
         .max = 2,
         .benchKey = "max_distance",
         .labelTag = "md",
         .legend = "md0.5 = cones half the grid's side long (else 1)"},
        {.option = "cone-start-offset",
         .shape = "VOXELS",
         .help = "gap between the surface and a cone's apex, in voxels of a 64³ grid",
         .group = G::Cones,
         .access = settingField<&R::shading, &ShadingSettings::coneStartOffset>(),
         .label = "start offset",
         .format = "%.2f voxels",
         .max = 8,
         .benchKey = "start_offset",
         .labelTag = "o",
         .legend = "o1 = cones start 1 voxel of 64³ off the surface (else 1.5)"},
        {.option = "cone-stop-opacity",
         .shape = "F",
         .help = "a cone stops once this opaque",
         .group = G::Cones,
         .access = settingField<&R::shading, &ShadingSettings::coneStopOpacity>(),
         .label = "stop opacity",
         .min = 0.5,
         .max = 1,
         .benchKey = "stop_opacity",
         .labelTag = "op",
         .legend = "op0.9 = cones stop at opacity 0.9 (else 0.95)"},
        {.option = "ao-falloff",
         .shape = "F",
         .help = "occlusion at distance d weighs 1 / (1 + F · d / the grid's side)",
         .group = G::Cones,
         .access = settingField<&R::shading, &ShadingSettings::aoFalloff>(),
         .label = "AO falloff",
         .format = "%.1f",
         .max = 64,
         .benchKey = "ao_falloff",
         .labelTag = "f",
         .legend = "f4 = AO falloff 4 (else 8)"},
        {.option = "specular-max-aperture",
         .shape = "DEGREES",
         .help = "full angle of the widest specular cone; a rougher lobe reflects the light the diffuse cones gathered",
         .group = G::Cones,
         .access = settingField<&R::shading, &ShadingSettings::specularMaxAperture>(),
         .label = "widest specular",
         .format = "%.0f deg",
         .min = 10,
         .max = 150,
         .benchKey = "specular_max_aperture",
         .labelTag = "sp",
         .legend = "sp60 = specular cones at most 60° wide (else 90°)"},
        // The shadow maps.
        {.option = "shadow-map",
         .shape = "N",
         .help = "sun shadow-map size",
         .group = G::Shadows,
         .access = settingField<&R::resources, &ResourceSettings::sunShadowMapSize>(),
         .label = "sun shadow map",
         .widget = W::PowerOfTwo,
         .min = 16,
         .max = 16384,
         .whole = true,
         .benchKey = "sun_shadow_map",
         .labelTag = "sm",
         .legend = "sm4096 = 4096² sun shadow map (else 2048²)"},
        {.option = "sun-cascades",
         .shape = "N",
         .help = "most view-fitted shadow maps a sun gets near the camera (0: the scene-fitted map alone)",
         .group = G::Shadows,
         .access = settingField<&R::resources, &ResourceSettings::sunCascades>(),
         .label = "sun cascades",
         .format = "%d",
         .min = 0,
         .max = 8,
         .whole = true,
         .benchKey = "sun_cascades",
         .labelTag = "sc",
         .legend = "sc0 = no sun cascades (else up to 4)"},
        {.option = "local-shadow-map",
         .shape = "N",
         .help = "shadow-map size of each spot light and point-light cube face",
         .group = G::Shadows,
         .access = settingField<&R::resources, &ResourceSettings::localShadowMapSize>(),
         .label = "local shadow map",
         .widget = W::PowerOfTwo,
         .min = 16,
         .max = 16384,
         .whole = true,
         .benchKey = "local_shadow_map",
         .labelTag = "lsm",
         .legend = "lsm512 = 512² spot and point shadow maps (else 1024²)"},
        {.option = "area-shadow-map",
         .shape = "N",
         .help = "shadow-map size of each cube face of an area light (an emissive surface)",
         .group = G::Shadows,
         .access = settingField<&R::resources, &ResourceSettings::areaShadowMapSize>(),
         .label = "area shadow map",
         .widget = W::PowerOfTwo,
         .min = 16,
         .max = 16384,
         .whole = true,
         .benchKey = "area_shadow_map",
         .labelTag = "asm",
         .legend = "asm256 = 256² area-light shadow maps (else 512²)"},
    };
}

}  // namespace

const std::vector<SettingRow>& settingTable() {
    static const std::vector<SettingRow> table = makeSettingTable();
    return table;
}

const SettingRow& settingRow(const std::string& option) {
    for (const SettingRow& row : settingTable())
        if (option == row.option) return row;
    throw std::out_of_range("no setting --" + option);
}

const NamedValue* namedValue(const SettingRow& row, double value) {
    for (const NamedValue& named : row.names)
        if (named.value == value) return &named;
    return nullptr;
}

std::string settingText(const SettingRow& row, double value) {
    const NamedValue* named = namedValue(row, value);
    return named ? named->name : shortNumber(value);
}

std::string settingDomain(const SettingRow& row) {
    std::string names;
    for (size_t i = 0; i < row.names.size(); ++i)
        names += (i == 0 ? "" : i + 1 == row.names.size() ? " or " : ", ") + std::string(row.names[i].name);
    if (row.namesOnly) return names;
    const std::string kind = row.powerOfTwo ? "a power of two" : row.whole ? "a whole number" : "a number";
    return (names.empty() ? "" : names + " or ") + kind + " from " + shortNumber(row.min) + " to " +
           shortNumber(row.max);
}

std::optional<double> parseSetting(const SettingRow& row, const std::string& text) {
    for (const NamedValue& named : row.names)
        if (text == named.name) return named.value;
    if (row.namesOnly || text.empty()) return std::nullopt;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (*end != '\0' || !std::isfinite(value) || value < row.min || value > row.max) return std::nullopt;
    if (row.whole && value != std::floor(value)) return std::nullopt;
    if (row.powerOfTwo && (std::exp2(std::round(std::log2(value))) != value)) return std::nullopt;
    return value;
}

std::string labelPart(const SettingRow& row, double value) {
    const NamedValue* named = namedValue(row, value);
    return row.labelTag + (named ? std::string(named->labelPart) : shortNumber(value));
}

std::string settingsMarkdown(const RenderSettings& defaults) {
    std::string table = "| option | takes | default | what it sets |\n| --- | --- | --- | --- |\n";
    for (const SettingRow& row : settingTable()) {
        table += "| `--" + std::string(row.option) + " " + markdownCell(row.shape) + "` | " + settingDomain(row) +
                 " | " + settingText(row, defaults) + " | " + row.help + " |\n";
    }
    return table;
}

std::string shortNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

std::string markdownCell(std::string text) {
    for (size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2)) text.replace(at, 1, "\\|");
    return text;
}

}  // namespace vct
