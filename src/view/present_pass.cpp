#include "view/present_pass.h"

#include "bindings.h"
#include "gpu/commands.h"
#include "gpu/pass_uses.h"
#include "gpu/vk_check.h"

namespace vct {

static VkRenderPass createRenderPass(GpuContext& context, VkFormat format) {
    VkAttachmentDescription attachment{};
    attachment.format = format;
    attachment.samples = VK_SAMPLE_COUNT_1_BIT;
    attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;  // the image may leave part of the window (beside the settings)
    attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachment.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    attachment.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    const VkAttachmentReference colorReference{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &colorReference;
    // The layout transition waits for the acquire semaphore, which the submit waits on at the
    // colour-output stage.
    VkSubpassDependency dependency{};
    dependency.srcSubpass = VK_SUBPASS_EXTERNAL;
    dependency.dstSubpass = 0;
    dependency.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dependency.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dependency.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = 1;
    info.pAttachments = &attachment;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 1;
    info.pDependencies = &dependency;
    VkRenderPass renderPass = VK_NULL_HANDLE;
    VK_CHECK(vkCreateRenderPass(context.device, &info, nullptr, &renderPass));
    return renderPass;
}

// gpu/pipelines.h makes pipelines for dynamic rendering; these belong to a VkRenderPass. The
// tone map draws a full-screen triangle, the grid bounds a line list; neither blends.
static VkPipeline createPresentPipeline(GpuContext& context, VkPipelineLayout layout, VkRenderPass renderPass,
                                        const ShaderCode& vertexCode, const ShaderCode& fragmentCode,
                                        VkPrimitiveTopology topology) {
    const VkShaderModule vertex = createShaderModule(context, vertexCode);
    const VkShaderModule fragment = createShaderModule(context, fragmentCode);
    VkPipelineShaderStageCreateInfo stages[2]{};
    stages[0] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                 nullptr,
                 0,
                 VK_SHADER_STAGE_VERTEX_BIT,
                 vertex,
                 "main",
                 nullptr};
    stages[1] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                 nullptr,
                 0,
                 VK_SHADER_STAGE_FRAGMENT_BIT,
                 fragment,
                 "main",
                 nullptr};
    const VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    VkPipelineInputAssemblyStateCreateInfo inputAssembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    inputAssembly.topology = topology;
    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo rasterization{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    rasterization.polygonMode = VK_POLYGON_MODE_FILL;
    rasterization.cullMode = VK_CULL_MODE_NONE;
    rasterization.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineColorBlendAttachmentState blendAttachment{};
    blendAttachment.colorWriteMask =
        VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = 1;
    blend.pAttachments = &blendAttachment;
    const VkDynamicState dynamicStates[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = 2;
    dynamic.pDynamicStates = dynamicStates;

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.stageCount = 2;
    info.pStages = stages;
    info.pVertexInputState = &vertexInput;
    info.pInputAssemblyState = &inputAssembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &rasterization;
    info.pMultisampleState = &multisample;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
    info.layout = layout;
    info.renderPass = renderPass;
    VkPipeline pipeline = VK_NULL_HANDLE;
    const VkResult result = vkCreateGraphicsPipelines(context.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
    vkDestroyShaderModule(context.device, vertex, nullptr);
    vkDestroyShaderModule(context.device, fragment, nullptr);
    VK_CHECK(result);
    return pipeline;
}

PresentPass::PresentPass(GpuContext& context, VkFormat swapchainFormat)
    : format(swapchainFormat), context_(context), sampler_(context, linearClampSampler()) {
    renderPass = createRenderPass(context, swapchainFormat);
    const ShaderCode vertex = loadShader("fullscreen.vert"), fragment = loadShader("tonemap.frag");
    const ShaderLayout layout = createShaderLayout(context, {vertex, fragment});
    tonemap_ = Pipeline(context, VK_NULL_HANDLE, layout);  // freed on a throw
    tonemap_.pipeline = createPresentPipeline(context, layout.layout, renderPass, vertex, fragment,
                                              VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST);
    const ShaderCode boxVertex = loadShader("grid_bounds.vert"), boxFragment = loadShader("grid_bounds.frag");
    const ShaderLayout boxLayout = createShaderLayout(context, {boxVertex, boxFragment});
    gridBounds_ = Pipeline(context, VK_NULL_HANDLE, boxLayout);
    gridBounds_.pipeline = createPresentPipeline(context, boxLayout.layout, renderPass, boxVertex, boxFragment,
                                                 VK_PRIMITIVE_TOPOLOGY_LINE_LIST);
}

PresentPass::~PresentPass() {
    destroyFramebuffers();
    vkDestroyRenderPass(context_.device, renderPass, nullptr);
}

void PresentPass::destroyFramebuffers() {
    for (VkFramebuffer framebuffer : framebuffers_) vkDestroyFramebuffer(context_.device, framebuffer, nullptr);
    framebuffers_.clear();
}

void PresentPass::createFramebuffers(const Swapchain& swapchain) {
    destroyFramebuffers();
    for (VkImageView view : swapchain.views) {
        VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        info.renderPass = renderPass;
        info.attachmentCount = 1;
        info.pAttachments = &view;
        info.width = swapchain.extent.width;
        info.height = swapchain.extent.height;
        info.layers = 1;
        framebuffers_.push_back(VK_NULL_HANDLE);
        VK_CHECK(vkCreateFramebuffer(context_.device, &info, nullptr, &framebuffers_.back()));
    }
}

void PresentPass::begin(VkCommandBuffer commands, uint32_t imageIndex, VkExtent2D extent, VkRect2D area,
                        const GpuImage& radiance, const TonemapParams& params) {
    PassUses().use(radiance, access::fragmentRead).record(commands);
    VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    info.renderPass = renderPass;
    info.framebuffer = framebuffers_.at(imageIndex);
    info.renderArea = {{0, 0}, extent};
    const VkClearValue black{};
    info.clearValueCount = 1;
    info.pClearValues = &black;
    vkCmdBeginRenderPass(commands, &info, VK_SUBPASS_CONTENTS_INLINE);
    // The tone map and the grid bounds draw into the image's area; ImGui sets its own viewport.
    const VkViewport viewport{
        float(area.offset.x), float(area.offset.y), float(area.extent.width), float(area.extent.height), 0.0f, 1.0f};
    const VkRect2D scissor = area;
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &scissor);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, tonemap_.pipeline);
    DescriptorPush()
        .sampledImage(glsl::DISPLAYED_BINDING, radiance.view, sampler_.sampler, VK_IMAGE_LAYOUT_GENERAL)
        .push(context_, commands, VK_PIPELINE_BIND_POINT_GRAPHICS, tonemap_);
    const glsl::TonemapPush push{glm::vec2(float(area.offset.x), float(area.offset.y)),
                                 glm::vec2(1.0f / float(area.extent.width), 1.0f / float(area.extent.height)),
                                 params.exposure, params.toneCurve ? 1u : 0u, uint32_t(params.curve)};
    vkCmdPushConstants(commands, tonemap_.layout, VK_SHADER_STAGE_ALL, 0, sizeof(push), &push);
    vkCmdDraw(commands, 3, 1, 0, 0);
}

void PresentPass::drawGridBounds(VkCommandBuffer commands, const glsl::GridBoundsPush& push) {
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, gridBounds_.pipeline);
    vkCmdPushConstants(commands, gridBounds_.layout, VK_SHADER_STAGE_ALL, 0, sizeof(push), &push);
    vkCmdDraw(commands, 24, 1, 0, 0);
}

void PresentPass::end(VkCommandBuffer commands) { vkCmdEndRenderPass(commands); }

}  // namespace vct
