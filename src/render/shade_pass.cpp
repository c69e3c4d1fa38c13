#include "render/shade_pass.h"

#include "bindings.h"
#include "gpu/commands.h"
#include "gpu/pass_uses.h"
#include "render/cone_tracing_pipeline.h"
#include "render/ltc_table.h"
#include "surface_planes.h"

namespace vct {

ShadePass::ShadePass(GpuContext& context, uint32_t targetWidth, uint32_t targetHeight)
    : width(targetWidth), height(targetHeight), context_(context) {
    ImageDesc desc;
    desc.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    desc.extent = {width, height, 1};
    // At one sample per pixel this is the frame's output (Renderer::output()): read back and presented.
    desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    desc.debugName = "radiance";
    radiance = GpuImage(context, desc);
    pointSampler = Sampler(context, nearestClampSampler());
    const std::vector<glsl::GpuLtcEntry> table = ltcGgxTable();
    ltcTable = uploadBuffer(context, table.data(), table.size() * sizeof(table[0]), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
}

const Pipeline& ShadePass::pipeline(const ShadeVariant& variant) {
    Pipeline& slot = pipelines_[variant.index()];
    if (slot.pipeline != VK_NULL_HANDLE) return slot;
    GraphicsPipelineDesc desc;
    desc.vertexShader = "fullscreen.vert";
    desc.fragmentShader = "shade.frag";
    desc.colorFormats = {radiance.desc.format};
    desc.fragmentSpecialization = coneTracingSpecialization(
        variant.skipsEmptySpace, specializationConstants({
                                     {glsl::WITH_DEBUG_VIEWS_CONSTANT_ID, variant.debugViews},
                                     {glsl::TRACES_DIFFUSE_CONES_CONSTANT_ID, variant.tracesDiffuseCones},
                                     {glsl::TRACES_SPECULAR_CONE_CONSTANT_ID, variant.tracesSpecularCone},
                                     {glsl::WITH_AREA_LIGHTS_CONSTANT_ID, variant.areaLights},
                                     {glsl::WITH_SUN_SHADOWS_CONSTANT_ID, variant.sunShadows},
                                     {glsl::WITH_LOCAL_SHADOWS_CONSTANT_ID, variant.localShadows},
                                     {glsl::WITH_AREA_LIGHT_SPECULAR_CONSTANT_ID, variant.areaLightSpecular},
                                 }));
    slot = createGraphicsPipeline(context_, desc);
    return slot;
}

void ShadePass::record(VkCommandBuffer commands, const ShadeInputs& inputs, const GBufferPass& gbuffer,
                       const ShadowPass& shadows, const VoxelVolumes& volumes) {
    // Drawn over whatever read the last frame's image: the resolve, a copy or the viewer's present pass.
    // Without reduced diffuse cones the shader never samples their binding: the base colour stands in.
    const GpuImage& reducedDiffuse = inputs.reducedDiffuse ? *inputs.reducedDiffuse : gbuffer.baseColor;
    PassUses uses;
    uses.use(radiance, access::colorAttachment, Contents::Discard);
    for (const GpuImage* light : volumes.tracedLight()) uses.use(*light, access::fragmentRead);
    uses.use(volumes.albedoOpacity, access::fragmentRead).use(volumes.normal, access::fragmentRead);
    for (const GpuImage* maps : {&shadows.sunMaps, &shadows.localMaps, &shadows.areaMaps})
        uses.use(*maps, access::fragmentSampled);
    for (const GpuImage* target : {&gbuffer.position, &gbuffer.normal, &gbuffer.baseColor, &gbuffer.emissive})
        uses.use(*target, access::fragmentSampled);
    if (inputs.reducedDiffuse) uses.use(reducedDiffuse, access::fragmentSampled);
    uses.record(commands);
    drawFullScreen(commands, radiance.view, width, height, [&] {
        const Pipeline& variant = pipeline(inputs.variant);
        vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, variant.pipeline);
        const VkSampler volumeSampler = volumes.sampler.sampler;
        DescriptorPush()
            .sampledImages(glsl::DIRECTIONAL_VOXELS_BINDING, volumes.directionalViews(), volumeSampler,
                           VK_IMAGE_LAYOUT_GENERAL)
            .buffer(glsl::FRAME_BINDING, inputs.frameConstants, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
            .buffer(glsl::MATERIALS_BINDING, inputs.materials)
            .buffer(glsl::LIGHTS_BINDING, inputs.lights.lights)
            .buffer(glsl::SHADOW_VIEWS_BINDING, inputs.lights.shadowViews)
            .buffer(glsl::EMITTER_TRIANGLES_BINDING, inputs.lights.emitterTriangles)
            .buffer(glsl::LTC_TABLE_BINDING, ltcTable.buffer)
            .sampledImage(glsl::SUN_SHADOW_MAPS_BINDING, shadows.sunMaps.view, shadows.compareSampler.sampler)
            .sampledImage(glsl::LOCAL_SHADOW_MAPS_BINDING, shadows.localMaps.view, shadows.compareSampler.sampler)
            .sampledImage(glsl::G_POSITION_BINDING, gbuffer.position.view, pointSampler.sampler)
            .sampledImage(glsl::G_NORMAL_BINDING, gbuffer.normal.view, pointSampler.sampler)
            .sampledImage(glsl::G_BASE_COLOR_BINDING, gbuffer.baseColor.view, pointSampler.sampler)
            .sampledImage(glsl::VOXEL_RADIANCE_BINDING, volumes.radiance.view, volumeSampler, VK_IMAGE_LAYOUT_GENERAL)
            .sampledImage(glsl::VOXEL_ALBEDO_BINDING, volumes.albedoOpacity.view, volumeSampler,
                          VK_IMAGE_LAYOUT_GENERAL)
            .sampledImage(glsl::VOXEL_NORMAL_BINDING, volumes.normal.view, volumeSampler, VK_IMAGE_LAYOUT_GENERAL)
            .sampledImage(glsl::SURFACE_PLANES_BINDING, volumes.surfacePlanesView(), volumeSampler,
                          VK_IMAGE_LAYOUT_GENERAL)
            .sampledImage(glsl::DIFFUSE_SAMPLES_BINDING, reducedDiffuse.view, pointSampler.sampler)
            .sampledImage(glsl::SUN_SHADOW_DEPTHS_BINDING, shadows.sunMaps.view, pointSampler.sampler)
            .sampledImage(glsl::LOCAL_SHADOW_DEPTHS_BINDING, shadows.localMaps.view, pointSampler.sampler)
            .sampledImage(glsl::G_EMISSIVE_BINDING, gbuffer.emissive.view, pointSampler.sampler)
            .sampledImage(glsl::AREA_SHADOW_MAPS_BINDING, shadows.areaMaps.view, shadows.compareSampler.sampler)
            .sampledImage(glsl::AREA_SHADOW_DEPTHS_BINDING, shadows.areaMaps.view, pointSampler.sampler)
            .sampledImage(glsl::SKY_BINDING, inputs.sky->view(), inputs.sky->sampler())
            .push(context_, commands, VK_PIPELINE_BIND_POINT_GRAPHICS, variant);
    });
}

}  // namespace vct
