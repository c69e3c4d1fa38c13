#include "render/gbuffer_pass.h"

#include <utility>

#include "bindings.h"
#include "gpu/pass_uses.h"

namespace vct {

constexpr uint32_t kColorTargets = 4;  // position, normal, base colour, emissive

static GpuImage makeTarget(GpuContext& context, VkFormat format, uint32_t width, uint32_t height, const char* name) {
    ImageDesc desc;
    desc.format = format;
    desc.extent = {width, height, 1};
    desc.usage = (format == VK_FORMAT_D32_SFLOAT ? VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT
                                                 : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT) |
                 VK_IMAGE_USAGE_SAMPLED_BIT;
    desc.debugName = name;
    return GpuImage(context, desc);
}

GBufferPass::GBufferPass(GpuContext& context, const SceneGpu& scene, uint32_t targetWidth, uint32_t targetHeight)
    : width(targetWidth), height(targetHeight), context_(context) {
    position = makeTarget(context, VK_FORMAT_R32G32B32A32_SFLOAT, width, height, "G-buffer position");
    normal = makeTarget(context, VK_FORMAT_R16G16B16A16_SFLOAT, width, height, "G-buffer normal");
    baseColor = makeTarget(context, VK_FORMAT_R16G16B16A16_SFLOAT, width, height, "G-buffer base colour");
    emissive = makeTarget(context, VK_FORMAT_R16G16B16A16_SFLOAT, width, height, "G-buffer emissive");
    depth = makeTarget(context, VK_FORMAT_D32_SFLOAT, width, height, "G-buffer depth");
    lastPosition = makeTarget(context, position.desc.format, width, height, "G-buffer position, last frame");
    lastNormal = makeTarget(context, normal.desc.format, width, height, "G-buffer normal, last frame");

    GraphicsPipelineDesc desc;
    desc.vertexShader = "gbuffer.vert";
    desc.fragmentShader = "gbuffer.frag";
    desc.colorFormats = {position.desc.format, normal.desc.format, baseColor.desc.format, emissive.desc.format};
    desc.depthFormat = VK_FORMAT_D32_SFLOAT;
    desc.depthTest = true;
    desc.dynamicCullMode = true;  // per material: glTF doubleSided
    // The texture array's size is a specialization constant, so the pipeline is built per scene.
    // Alpha-tested materials get a second pipeline: a shader that may discard tests depth only
    // after shading, and would cost the opaque materials their early depth test (6× the G-buffer
    // time of FlightHelmet on lavapipe when one pipeline drew them all).
    desc.fragmentSpecialization = specializationConstants(
        {{glsl::TEXTURE_COUNT_CONSTANT_ID, scene.textureCount()}, {glsl::ALPHA_TESTED_CONSTANT_ID, VK_FALSE}});
    pipeline = createGraphicsPipeline(context, desc, {scene.textureSetLayout});
    if (!scene.alphaTestedRanges.empty()) {
        desc.fragmentSpecialization = specializationConstants(
            {{glsl::TEXTURE_COUNT_CONSTANT_ID, scene.textureCount()}, {glsl::ALPHA_TESTED_CONSTANT_ID, VK_TRUE}});
        alphaPipeline = createGraphicsPipeline(context, desc, {scene.textureSetLayout});
    }
}

void GBufferPass::record(VkCommandBuffer commands, const SceneGpu& scene, VkBuffer frameConstants) {
    // This frame draws over the images of the frame before last, every pixel.
    std::swap(position, lastPosition);
    std::swap(normal, lastNormal);
    ++recorded;
    GpuImage* targets[kColorTargets] = {&position, &normal, &baseColor, &emissive};
    PassUses drawn;
    for (GpuImage* target : targets) drawn.use(*target, access::colorAttachment, Contents::Discard);
    drawn.use(depth, access::depthAttachment, Contents::Discard).record(commands);

    VkRenderingAttachmentInfo colors[kColorTargets];
    for (uint32_t i = 0; i < kColorTargets; ++i) {
        colors[i] = {VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        colors[i].imageView = targets[i]->view;
        colors[i].imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        colors[i].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        colors[i].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        colors[i].clearValue.color = {{0.0f, 0.0f, 0.0f, 0.0f}};
    }
    VkRenderingAttachmentInfo depthAttachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depthAttachment.imageView = depth.view;
    depthAttachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depthAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depthAttachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depthAttachment.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {width, height}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = kColorTargets;
    rendering.pColorAttachments = colors;
    rendering.pDepthAttachment = &depthAttachment;
    vkCmdBeginRendering(commands, &rendering);
    // Opaque materials first, then the alpha-tested ones (whose discarded fragments leave the
    // depth of what lies behind them).
    auto drawRanges = [&](const Pipeline& drawing, bool alphaTested) {
        vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, drawing.pipeline);
        DescriptorPush()
            .buffer(glsl::FRAME_BINDING, frameConstants, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
            .buffer(glsl::VERTICES_BINDING, scene.vertices.buffer)
            .buffer(glsl::MATERIALS_BINDING, scene.materials.buffer)
            .push(context_, commands, VK_PIPELINE_BIND_POINT_GRAPHICS, drawing);
        vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, drawing.layout, glsl::TEXTURES_SET, 1,
                                &scene.textureSet, 0, nullptr);
        for (const SceneGpu::MaterialRange& range : scene.materialRanges) {
            if (range.alphaTested != alphaTested) continue;
            vkCmdPushConstants(commands, drawing.layout, VK_SHADER_STAGE_ALL, 0, sizeof(uint32_t), &range.material);
            vkCmdSetCullMode(commands, range.doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT);
            vkCmdDrawIndexed(commands, range.indexCount, 1, range.firstIndex, 0, 0);
        }
    };
    if (scene.indexCount > 0) {
        const VkViewport viewport{0.0f, 0.0f, float(width), float(height), 0.0f, 1.0f};
        const VkRect2D scissor{{0, 0}, {width, height}};
        vkCmdSetViewport(commands, 0, 1, &viewport);
        vkCmdSetScissor(commands, 0, 1, &scissor);
        vkCmdBindIndexBuffer(commands, scene.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
        drawRanges(pipeline, false);
        if (alphaPipeline.pipeline != VK_NULL_HANDLE) drawRanges(alphaPipeline, true);
    }
    vkCmdEndRendering(commands);
}

}  // namespace vct
