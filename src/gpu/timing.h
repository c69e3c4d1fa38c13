// GPU time of each pass, from timestamp queries written around it.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "gpu/context.h"

namespace vct {

struct PassTime {
    std::string name;
    double milliseconds = 0.0;
};

class GpuTimer {
public:
    explicit GpuTimer(GpuContext& context, uint32_t maxPasses = 32);
    ~GpuTimer();
    GpuTimer(const GpuTimer&) = delete;
    GpuTimer& operator=(const GpuTimer&) = delete;

    void reset(VkCommandBuffer commands);  // start of a frame's command buffer
    void begin(VkCommandBuffer commands, const std::string& pass);
    void end(VkCommandBuffer commands);
    std::vector<PassTime> results();  // after the commands completed; empty without timestamp support

private:
    GpuContext& context_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
    uint32_t maxPasses_;
    std::vector<std::string> names_;
};

}  // namespace vct
