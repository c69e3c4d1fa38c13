#include "render/settings.h"

namespace vct {

std::optional<RenderMode> parseRenderMode(const std::string& name) {
    if (name == "full") return RenderMode::Full;
    if (name == "direct") return RenderMode::Direct;
    if (name == "indirect") return RenderMode::Indirect;
    return std::nullopt;
}

const char* renderModeName(RenderMode mode) {
    switch (mode) {
        case RenderMode::Full: return "full";
        case RenderMode::Direct: return "direct";
        case RenderMode::Indirect: return "indirect";
    }
    return "?";
}

Components effectiveComponents(const RenderSettings& settings) {
    Components shown = settings.components;
    const bool direct = settings.mode != RenderMode::Indirect;
    const bool indirect = settings.mode != RenderMode::Direct;
    shown.directDiffuse &= direct;
    shown.directSpecular &= direct;
    shown.emission &= direct;
    shown.indirectDiffuse &= indirect;
    shown.indirectSpecular &= indirect;
    shown.ambientOcclusion &= indirect;
    return shown;
}

}  // namespace vct
