#include "render/settings.h"

#include <algorithm>
#include <numeric>

#include <glm/gtc/constants.hpp>

namespace vct {

const char* renderModeName(RenderMode mode) {
    switch (mode) {
        case RenderMode::Full: return "full";
        case RenderMode::Direct: return "direct";
        case RenderMode::Indirect: return "indirect";
    }
    return "?";
}

const char* debugViewLabel(DebugView view) {
    static const char* const labels[debugViewCount] = {
        "lit image",    "base colour",  "normal",         "depth",        "ambient occlusion",
        "voxel albedo", "voxel normal", "voxel radiance", "sun cascades",
    };
    const uint32_t index = uint32_t(view);
    return index < debugViewCount ? labels[index] : "?";
}

const std::array<ComponentInfo, 8>& componentTable() {
    static const std::array<ComponentInfo, 8> table = {{
        {&Components::directDiffuse, glsl::SHOW_DIRECT_DIFFUSE, "direct-diffuse", "direct diffuse"},
        {&Components::directSpecular, glsl::SHOW_DIRECT_SPECULAR, "direct-specular", "direct specular"},
        {&Components::indirectDiffuse, glsl::SHOW_INDIRECT_DIFFUSE, "indirect-diffuse", "indirect diffuse"},
        {&Components::indirectSpecular, glsl::SHOW_INDIRECT_SPECULAR, "indirect-specular", "indirect specular"},
        {&Components::ambientOcclusion, glsl::SHOW_AMBIENT_OCCLUSION, "ao", "ambient occlusion"},
        {&Components::emission, glsl::SHOW_EMISSION, "emission", "emission"},
        {&Components::shadows, glsl::USE_SHADOWS, "shadows", "shadows"},
        {&Components::areaLights, glsl::USE_AREA_LIGHTS, "area-lights", "area lights"},
    }};
    return table;
}

uint32_t componentFlags(const Components& components) {
    uint32_t flags = 0;
    for (const ComponentInfo& component : componentTable())
        if (components.*component.member) flags |= component.shaderFlag;
    return flags;
}

Components effectiveComponents(const ShadingSettings& shading) {
    Components shown = shading.components;
    const bool direct = shading.mode != RenderMode::Indirect;
    const bool indirect = shading.mode != RenderMode::Direct;
    shown.directDiffuse &= direct;
    shown.directSpecular &= direct;
    shown.emission &= direct;
    shown.indirectDiffuse &= indirect;
    shown.indirectSpecular &= indirect;
    shown.ambientOcclusion &= indirect;
    return shown;
}

bool needsVoxels(const ShadingSettings& shading) {
    const Components shown = effectiveComponents(shading);
    return shown.indirectDiffuse || shown.indirectSpecular ||
           (shown.ambientOcclusion && shading.ambientFactor > 0.0f) || shading.debugView >= DebugView::AmbientOcclusion;
}

bool needsDiffuseCones(const ShadingSettings& shading) {
    const Components shown = effectiveComponents(shading);
    return shading.debugView == DebugView::None &&
           (shown.indirectDiffuse || (shown.ambientOcclusion && shading.ambientFactor > 0.0f));
}

uint32_t diffuseRingTurns(const ShadingSettings& shading) {
    const bool ring = needsDiffuseCones(shading) && shading.diffuseConeCount > 1;
    return ring ? std::max(shading.diffuseConeTurns, 1u) : 1u;
}

DiffuseBeam diffuseBeamOfTurn(const ShadingSettings& shading, bool rayVisibility, uint32_t turn) {
    const uint32_t turns = diffuseRingTurns(shading);
    if (!rayVisibility || turns % 4 != 0) return {};
    turn %= turns;
    if (turn % 4 == 0) return {.beam = glsl::AXIS_BEAM};
    // The beams around the axis in a stride of 7 (coprime with every count up to 12): taken in
    // order, their azimuth turned with the ring's and a sunlit patch came out as a V-shaped streak.
    const uint32_t around = turn - turn / 4 - 1, aroundCount = turns - turns / 4;
    return {.beam = glsl::BEAM_AROUND_AXIS,
            .azimuth = 2.0f * glm::pi<float>() * float((around * 7u) % aroundCount) / float(aroundCount)};
}

uint32_t stillFramesAveraged(const ShadingSettings& shading) {
    return std::lcm(diffuseRingTurns(shading), std::max(shading.stillSamples, 1u));
}

namespace {

// The radical inverse of `index` in base 2 (van der Corput), in [0, 1).
float radicalInverse2(uint32_t index) {
    float inverse = 0.0f, digit = 0.5f;
    for (; index > 0; index /= 2, digit *= 0.5f) inverse += float(index % 2) * digit;
    return inverse;
}

}  // namespace

glm::vec2 stillSampleOffset(const ShadingSettings& shading, uint32_t frame) {
    const uint32_t count = std::max(shading.stillSamples, 1u), index = frame % count;
    // The Hammersley set (i / n, van der Corput of i): for a power of two, one point in each of the
    // pixel's n elementary rectangles (a 4×4 grid's cells for 16); shifted by half a sample, modulo
    // the sample, so that the first point is its centre.
    auto centred = [](float u) { return u < 0.5f ? u : u - 1.0f; };
    return {centred(float(index) / float(count)), centred(radicalInverse2(index))};
}

bool resolvesImage(const RenderSettings& settings) {
    return settings.image.supersample > 1 || stillFramesAveraged(settings.shading) > 1;
}

}  // namespace vct
