// The GGX table of linearly transformed cosines (shaders_glsl/ltc.h), fitted by tools/ltc_fit and
// compiled in from src/render/ltc_ggx_table.inc. No Vulkan: the CPU tests read it too.
#pragma once

#include <vector>

#include "ltc.h"

namespace vct {

// LTC_TABLE_SIZE² entries, as the shading pass's storage buffer holds them.
std::vector<glsl::GpuLtcEntry> ltcGgxTable();

// The entry for (roughness, N·V), blended bilinearly between its four neighbours: the CPU twin of
// the shader's lookup (area_lights.glsl).
glsl::GpuLtcEntry lookupLtcGgx(const std::vector<glsl::GpuLtcEntry>& table, float roughness, float NdotV);

}  // namespace vct
