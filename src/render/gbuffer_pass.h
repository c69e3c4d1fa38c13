// The G-buffer: what the camera sees at each sample, for the full-screen lighting pass.
#pragma once

#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "render/scene_gpu.h"

namespace vct {

struct GBufferPass {
    GBufferPass(GpuContext& context, const SceneGpu& scene, uint32_t width, uint32_t height);

    // Draws the targets; the passes that sample them declare so (gpu/pass_uses.h).
    void record(VkCommandBuffer commands, const SceneGpu& scene, VkBuffer frameConstants);

    uint32_t width, height;
    GpuImage position;   // RGBA32F: world position, material index + 1 (0 = background)
    GpuImage normal;     // RGBA16F: normal facing the camera, 1 on front faces
    GpuImage baseColor;  // RGBA16F: linear base colour, metallic (after its texture)
    GpuImage emissive;   // RGBA16F: the emissive texture's linear colour (1 without one), roughness
    GpuImage depth;      // D32F
    // The previous record()'s position and normal, for what reuses the last frame's results
    // (the reduced diffuse cones); unwritten before the second.
    GpuImage lastPosition;
    GpuImage lastNormal;
    uint64_t recorded = 0;   // record() calls so far
    Pipeline pipeline;       // opaque materials: no discard, so depth is tested before shading
    Pipeline alphaPipeline;  // MASK and BLEND materials (only for a scene that has them)

private:
    GpuContext& context_;
};

}  // namespace vct
