// The full-screen lighting pass: direct light (and, with cone tracing, indirect light) per sample
// of the G-buffer, into an HDR radiance target in the scene's units.
#pragma once

#include <array>

#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "render/gbuffer_pass.h"
#include "render/shadow_pass.h"
#include "render/sky_image.h"
#include "render/voxel_volumes.h"

namespace vct {

// What the shading pipeline has to be able to do this frame (its specialization constants):
// each combination is its own pipeline, since code a frame skips still slows lavapipe down.
struct ShadeVariant {
    bool debugViews = false;
    bool tracesDiffuseCones = true;   // false: reads ShadeInputs::reducedDiffuse instead
    bool tracesSpecularCone = false;  // some material reflects specularly and the component is on
    bool areaLights = false;          // the scene has area lights and the component is on
    bool sunShadows = true;           // some sun casts shadows (has a shadow map)
    bool localShadows = true;         // some spot or point light does
    bool areaLightSpecular = true;    // some material reflects specularly (the area lights' highlights)
    bool skipsEmptySpace = true;      // the cones skip empty space (cone_tracing_pipeline.h)
    uint32_t index() const {
        return (debugViews ? 1u : 0u) | (tracesDiffuseCones ? 2u : 0u) | (tracesSpecularCone ? 4u : 0u) |
               (areaLights ? 8u : 0u) | (sunShadows ? 16u : 0u) | (localShadows ? 32u : 0u) |
               (areaLightSpecular ? 64u : 0u) | (skipsEmptySpace ? 128u : 0u);
    }
};

struct ShadeInputs {
    VkBuffer frameConstants;
    VkBuffer materials;
    LightBuffers lights;
    const GpuImage* reducedDiffuse = nullptr;  // DiffuseConesPass::diffuse, when the cones run reduced
    ShadeVariant variant;
    const SkyImage* sky = nullptr;  // required
};

struct ShadePass {
    ShadePass(GpuContext& context, uint32_t width, uint32_t height);

    // Draws `radiance`; what reads it next (the resolve, a copy, the viewer) declares so.
    void record(VkCommandBuffer commands, const ShadeInputs& inputs, const GBufferPass& gbuffer,
                const ShadowPass& shadows, const VoxelVolumes& volumes);

    uint32_t width, height;
    GpuImage radiance;  // RGBA32F
    Sampler pointSampler;
    Buffer ltcTable;  // the area lights' GGX table (render/ltc_table.h), read by the shader at binding 20

private:
    // Built the first time a frame asks for its variant.
    const Pipeline& pipeline(const ShadeVariant& variant);
    std::array<Pipeline, 256> pipelines_;
    GpuContext& context_;
};

}  // namespace vct
