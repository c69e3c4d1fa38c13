#include "gpu/timing.h"

#include "gpu/vk_check.h"

namespace vct {

GpuTimer::GpuTimer(GpuContext& context, uint32_t maxPasses) : context_(context), maxPasses_(maxPasses) {
    if (!context.timestampsSupported) return;
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = maxPasses * 2;
    VK_CHECK(vkCreateQueryPool(context.device, &info, nullptr, &pool_));
}

GpuTimer::~GpuTimer() {
    if (pool_) vkDestroyQueryPool(context_.device, pool_, nullptr);
}

void GpuTimer::reset(VkCommandBuffer commands) {
    names_.clear();
    if (pool_) vkCmdResetQueryPool(commands, pool_, 0, maxPasses_ * 2);
}

void GpuTimer::begin(VkCommandBuffer commands, const std::string& pass) {
    if (!pool_ || names_.size() >= maxPasses_) return;
    names_.push_back(pass);
    vkCmdWriteTimestamp2(commands, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, uint32_t(names_.size() - 1) * 2);
}

void GpuTimer::end(VkCommandBuffer commands) {
    if (!pool_ || names_.empty()) return;
    vkCmdWriteTimestamp2(commands, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, uint32_t(names_.size() - 1) * 2 + 1);
}

std::vector<PassTime> GpuTimer::results() {
    std::vector<PassTime> times;
    if (!pool_ || names_.empty()) return times;
    std::vector<uint64_t> ticks(names_.size() * 2);
    VK_CHECK(vkGetQueryPoolResults(context_.device, pool_, 0, uint32_t(ticks.size()), ticks.size() * sizeof(uint64_t),
                                   ticks.data(), sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    const double nanosecondsPerTick = context_.properties.limits.timestampPeriod;
    // A pass that recorded no work (a shadow pass with no stale map) can read its end before its
    // start on lavapipe: zero, not an unsigned wrap to 10^13 ms.
    for (size_t i = 0; i < names_.size(); ++i) {
        const uint64_t ticksTaken = ticks[2 * i + 1] > ticks[2 * i] ? ticks[2 * i + 1] - ticks[2 * i] : 0;
        times.push_back({names_[i], double(ticksTaken) * nanosecondsPerTick * 1e-6});
    }
    return times;
}

}  // namespace vct
