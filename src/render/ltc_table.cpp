#include "render/ltc_table.h"

#include <cmath>

namespace vct {
namespace {

#include "render/ltc_ggx_table.inc"

static_assert(sizeof(kLtcGgxFit) / sizeof(kLtcGgxFit[0]) == glsl::LTC_TABLE_SIZE * glsl::LTC_TABLE_SIZE);
// The shader reads GpuLtcEntry[] as std430: two vec4s, 32 bytes, as C++ lays them out.
static_assert(sizeof(glsl::GpuLtcEntry) == 32 && alignof(glsl::GpuLtcEntry) <= 16);

}  // namespace

std::vector<glsl::GpuLtcEntry> ltcGgxTable() {
    std::vector<glsl::GpuLtcEntry> table;
    table.reserve(glsl::LTC_TABLE_SIZE * glsl::LTC_TABLE_SIZE);
    for (const auto& fit : kLtcGgxFit)
        table.push_back({glm::vec4(fit[0], fit[1], fit[2], fit[3]), glm::vec4(fit[4], fit[5], 0.0f, 0.0f)});
    return table;
}

glsl::GpuLtcEntry lookupLtcGgx(const std::vector<glsl::GpuLtcEntry>& table, float roughness, float NdotV) {
    const glm::vec2 coordinate = glsl::ltcTableCoordinate(roughness, NdotV);
    const glm::uvec2 low = glm::min(glm::uvec2(coordinate), glm::uvec2(glsl::LTC_TABLE_SIZE - 2u));
    const glm::vec2 t = coordinate - glm::vec2(low);
    auto at = [&](uint32_t x, uint32_t y) { return table[y * glsl::LTC_TABLE_SIZE + x]; };
    auto blend = [&](glm::vec4 a, glm::vec4 b, glm::vec4 c, glm::vec4 d) {
        return glm::mix(glm::mix(a, b, t.x), glm::mix(c, d, t.x), t.y);
    };
    const glsl::GpuLtcEntry e00 = at(low.x, low.y), e10 = at(low.x + 1, low.y), e01 = at(low.x, low.y + 1),
                            e11 = at(low.x + 1, low.y + 1);
    return {blend(e00.inverseMatrix, e10.inverseMatrix, e01.inverseMatrix, e11.inverseMatrix),
            blend(e00.magnitudeFresnel, e10.magnitudeFresnel, e01.magnitudeFresnel, e11.magnitudeFresnel)};
}

}  // namespace vct
