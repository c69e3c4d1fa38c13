// Averages each pixel's supersample² samples (a box filter over the pixel's square), and still
// frames whose cones turned (ShadingSettings::diffuseConeTurns) into their running mean. At one
// sample per pixel and one frame there is nothing to average: the frame plan leaves it out and the
// shading pass's image is the output.
#pragma once

#include "gpu/pipelines.h"
#include "gpu/resources.h"

namespace vct {

struct ResolvePass {
    ResolvePass(GpuContext& context, uint32_t width, uint32_t height, uint32_t supersample);

    // Reads `supersampled` into `resolved` (their uses declared). `frameShare`: this frame's
    // weight in the running mean, 1 / the frames averaged so far (1: the frame alone).
    void record(VkCommandBuffer commands, const GpuImage& supersampled, float frameShare = 1.0f);

    uint32_t width, height, supersample;
    GpuImage resolved;  // RGBA32F, width × height
    Sampler pointSampler;
    Pipeline pipeline;

private:
    GpuContext& context_;
};

}  // namespace vct
