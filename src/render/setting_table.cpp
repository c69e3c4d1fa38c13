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
constexpr double kNamesOnly[2] = {1.0, 0.0};  // min > max

std::vector<SettingRow> makeSettingTable() {
    return {
        // The image.
        {"width",
         "W",
         "image width in pixels",
         G::Image,
         nullptr,
         W::None,
         "%d",
         1,
         16384,
         true,
         false,
         {},
         nullptr,
         nullptr,
         false,
         nullptr,
         settingField<&R::image, &ImageSettings::width>()},
        {"height",
         "H",
         "image height in pixels",
         G::Image,
         nullptr,
         W::None,
         "%d",
         1,
         16384,
         true,
         false,
         {},
         nullptr,
         nullptr,
         false,
         nullptr,
         settingField<&R::image, &ImageSettings::height>()},
        {"supersample",
         "N",
         "samples per pixel side, averaged over the pixel",
         G::Image,
         "supersample",
         W::Slider,
         "%d",
         1,
         8,
         true,
         false,
         {},
         "supersample",
         "ss",
         false,
         "ss2 = 2×2 samples a pixel",
         settingField<&R::image, &ImageSettings::supersample>()},
        {"diffuse-resolution",
         "full|half|quarter",
         "diffuse cones for every sample, or for one in 2×2 or 4×4, upsampled along the surfaces",
         G::Image,
         "diffuse cones for",
         W::Choice,
         nullptr,
         kNamesOnly[0],
         kNamesOnly[1],
         true,
         false,
         {{"full", 1, "1"}, {"half", 2, "2"}, {"quarter", 4, "4"}},
         "diffuse_resolution",
         "d",
         false,
         "d4 = diffuse cones traced once per 4×4 pixels",
         settingField<&R::image, &ImageSettings::diffuseDownscale>()},
        // What the image shows.
        {"mode",
         "full|direct|indirect",
         "which light the image holds",
         G::Light,
         "mode (M)",
         W::Choice,
         nullptr,
         kNamesOnly[0],
         kNamesOnly[1],
         true,
         false,
         {{"full", double(RenderMode::Full), ""},
          {"direct", double(RenderMode::Direct), ""},
          {"indirect", double(RenderMode::Indirect), ""}},
         nullptr,
         nullptr,
         false,
         nullptr,
         settingField<&R::shading, &ShadingSettings::mode>()},
        {"ambient",
         "F",
         "non-physical ambient light factor",
         G::Light,
         "ambient",
         W::Slider,
         "%.3f",
         0,
         10,
         false,
         false,
         {},
         "ambient",
         "amb",
         false,
         "amb0.1 = ambient factor 0.1",
         settingField<&R::shading, &ShadingSettings::ambientFactor>()},
        // The voxels.
        {"voxels",
         "N",
         "voxels per side of the grid",
         G::Voxels,
         "voxels",
         W::PowerOfTwo,
         "%d",
         32,
         512,
         true,
         true,
         {},
         "voxels",
         "v",
         true,
         "v64 = 64³ voxels",
         settingField<&R::resources, &ResourceSettings::voxelResolution>()},
        {"voxel-mips",
         "isotropic|anisotropic",
         "one mip chain or six directional ones",
         G::Voxels,
         "voxel mips",
         W::Choice,
         nullptr,
         kNamesOnly[0],
         kNamesOnly[1],
         true,
         false,
         {{"isotropic", 0, "iso"}, {"anisotropic", 1, "aniso"}},
         "mips",
         "",
         true,
         "aniso / iso = six directional mip chains / one",
         settingField<&R::resources, &ResourceSettings::anisotropicVoxels>()},
        {"visibility",
         "mips|rays",
         "what stops a cone: the filtered mips alone, or also a ray along it through the finest voxels (no light "
         "through walls with voxels of their own; slower)",
         G::Voxels,
         "visibility",
         W::Choice,
         nullptr,
         kNamesOnly[0],
         kNamesOnly[1],
         true,
         false,
         {{"mips", 0, "mips"}, {"rays", 1, "rays"}},
         "visibility",
         "",
         false,
         "rays = ray visibility",
         settingField<&R::resources, &ResourceSettings::rayVisibility>()},
        {"bounces",
         "N|converged",
         "bounces of indirect light; converged iterates until it changes < 1 %",
         G::Voxels,
         "bounces",
         W::Slider,
         "%d",
         1,
         double(kMaxBouncesPerFrame),
         true,
         false,
         {{"converged", double(kConvergedBounces), "conv"}},
         "bounces",
         "b",
         true,
         "bconv / b1 = bounces until converged / one bounce",
         settingField<&R::resources, &ResourceSettings::bounces>()},
        // The cones.
        {"cones",
         "N",
         "diffuse cones: one along the normal, the rest in a ring around it",
         G::Cones,
         "diffuse cones",
         W::Slider,
         "%d",
         1,
         32,
         true,
         false,
         {},
         "cones",
         "c",
         true,
         "c6 = 6 diffuse cones",
         settingField<&R::shading, &ShadingSettings::diffuseConeCount>()},
        {"cone-aperture",
         "DEGREES",
         "full angle of each diffuse cone",
         G::Cones,
         "aperture",
         W::Slider,
         "%.0f deg",
         1,
         120,
         false,
         false,
         {},
         "aperture_deg",
         "a",
         true,
         "a40 = 40° cone aperture",
         settingField<&R::shading, &ShadingSettings::diffuseConeAperture>()},
        {"centre-weight",
         "F",
         "the weight of the cone along the normal; the ring shares the rest",
         G::Cones,
         "centre weight",
         W::Slider,
         "%.2f",
         0,
         1,
         false,
         false,
         {},
         "centre_weight",
         "w",
         false,
         "w0.3 = centre cone weighs 0.3 (else 0.25)",
         settingField<&R::shading, &ShadingSettings::diffuseCentreWeight>()},
        {"cone-turns",
         "N",
         "the diffuse cones' ring turned N times about the normal, one still frame each, and the frames averaged "
         "(1 = fixed directions)",
         G::Cones,
         "ring turns",
         W::Slider,
         "%d",
         1,
         16,
         true,
         false,
         {},
         "cone_turns",
         "t",
         false,
         "t4 = the ring of cones turned over 4 still frames, averaged",
         settingField<&R::shading, &ShadingSettings::diffuseConeTurns>()},
        {"cone-step",
         "F",
         "cone step as a fraction of its diameter",
         G::Cones,
         "step",
         W::Slider,
         "%.2f diameters",
         0.05,
         4,
         false,
         false,
         {},
         "step",
         "s",
         true,
         "s0.5 = step of 0.5 cone diameters",
         settingField<&R::shading, &ShadingSettings::coneStep>()},
        {"cone-max-distance",
         "F",
         "longest cone, as a fraction of the grid's side; past it a cone sees the sky",
         G::Cones,
         "max distance",
         W::Slider,
         "%.2f grid",
         0.01,
         2,
         false,
         false,
         {},
         "max_distance",
         "md",
         false,
         "md0.5 = cones half the grid's side long (else 1)",
         settingField<&R::shading, &ShadingSettings::coneMaxDistance>()},
        {"cone-start-offset",
         "VOXELS",
         "gap between the surface and a cone's apex, in voxels of a 64³ grid",
         G::Cones,
         "start offset",
         W::Slider,
         "%.2f voxels",
         0,
         8,
         false,
         false,
         {},
         "start_offset",
         "o",
         false,
         "o1 = cones start 1 voxel of 64³ off the surface (else 1.5)",
         settingField<&R::shading, &ShadingSettings::coneStartOffset>()},
        {"cone-stop-opacity",
         "F",
         "a cone stops once this opaque",
         G::Cones,
         "stop opacity",
         W::Slider,
         "%.2f",
         0.5,
         1,
         false,
         false,
         {},
         "stop_opacity",
         "op",
         false,
         "op0.9 = cones stop at opacity 0.9 (else 0.95)",
         settingField<&R::shading, &ShadingSettings::coneStopOpacity>()},
        {"ao-falloff",
         "F",
         "occlusion at distance d weighs 1 / (1 + F · d / the grid's side)",
         G::Cones,
         "AO falloff",
         W::Slider,
         "%.1f",
         0,
         64,
         false,
         false,
         {},
         "ao_falloff",
         "f",
         false,
         "f4 = AO falloff 4 (else 8)",
         settingField<&R::shading, &ShadingSettings::aoFalloff>()},
        // The shadow maps.
        {"shadow-map",
         "N",
         "sun shadow-map size",
         G::Shadows,
         "sun shadow map",
         W::PowerOfTwo,
         "%d",
         16,
         16384,
         true,
         false,
         {},
         "sun_shadow_map",
         "sm",
         false,
         "sm4096 = 4096² sun shadow map (else 2048²)",
         settingField<&R::resources, &ResourceSettings::sunShadowMapSize>()},
        {"local-shadow-map",
         "N",
         "shadow-map size of each spot light and point-light cube face",
         G::Shadows,
         "local shadow map",
         W::PowerOfTwo,
         "%d",
         16,
         16384,
         true,
         false,
         {},
         "local_shadow_map",
         "lsm",
         false,
         "lsm512 = 512² spot and point shadow maps (else 1024²)",
         settingField<&R::resources, &ResourceSettings::localShadowMapSize>()},
        {"area-shadow-map",
         "N",
         "shadow-map size of each cube face of an area light (an emissive surface)",
         G::Shadows,
         "area shadow map",
         W::PowerOfTwo,
         "%d",
         16,
         16384,
         true,
         false,
         {},
         "area_shadow_map",
         "asm",
         false,
         "asm256 = 256² area-light shadow maps (else 512²)",
         settingField<&R::resources, &ResourceSettings::areaShadowMapSize>()},
    };
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
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
    return named ? named->name : number(value);
}

std::string settingDomain(const SettingRow& row) {
    std::string names;
    for (size_t i = 0; i < row.names.size(); ++i)
        names += (i == 0 ? "" : i + 1 == row.names.size() ? " or " : ", ") + std::string(row.names[i].name);
    if (row.namesOnly()) return names;
    const std::string kind = row.powerOfTwo ? "a power of two" : row.whole ? "a whole number" : "a number";
    return (names.empty() ? "" : names + " or ") + kind + " from " + number(row.min) + " to " + number(row.max);
}

std::optional<double> parseSetting(const SettingRow& row, const std::string& text) {
    for (const NamedValue& named : row.names)
        if (text == named.name) return named.value;
    if (row.namesOnly() || text.empty()) return std::nullopt;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (*end != '\0' || !std::isfinite(value) || value < row.min || value > row.max) return std::nullopt;
    if (row.whole && value != std::floor(value)) return std::nullopt;
    if (row.powerOfTwo && (std::exp2(std::round(std::log2(value))) != value)) return std::nullopt;
    return value;
}

std::string labelPart(const SettingRow& row, double value) {
    const NamedValue* named = namedValue(row, value);
    return row.labelTag + (named ? std::string(named->labelPart) : number(value));
}

std::string settingsMarkdown(const RenderSettings& defaults) {
    std::string table = "| option | takes | default | what it sets |\n| --- | --- | --- | --- |\n";
    for (const SettingRow& row : settingTable()) {
        std::string shape = row.shape;
        for (size_t at = shape.find('|'); at != std::string::npos; at = shape.find('|', at + 2))
            shape.replace(at, 1, "\\|");  // a bar inside a Markdown table cell
        table += "| `--" + std::string(row.option) + " " + shape + "` | " + settingDomain(row) + " | " +
                 settingText(row, defaults) + " | " + row.help + " |\n";
    }
    return table;
}

}  // namespace vct
