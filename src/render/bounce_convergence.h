// Whether the bounces of light have converged: the radiance volume's mean (its 1×1×1 level, read
// back) moved by less than kBounceTolerance since the last reading.
#pragma once

#include "gpu/context.h"
#include "gpu/resources.h"

namespace vct {

class BounceConvergence {
public:
    explicit BounceConvergence(GpuContext& context);
    // Records a copy of `radiance`'s coarsest level, after its mips, for the host.
    void record(VkCommandBuffer commands, const GpuImage& radiance);
    // Once the recorded commands ran: whether the mean's luminance moved by less than
    // kBounceTolerance since the last reading (which it replaces).
    bool settled();

private:
    Buffer mean_;  // host-visible RGBA16F texel
    float lastLuminance_ = 0.0f;
};

}  // namespace vct
