// The viewer's present pass: tone-maps the renderer's image onto a swapchain image inside a
// VkRenderPass (Dear ImGui 1.86's Vulkan backend draws into a render pass, so it shares this one).
//
//   begin(): render pass begins, full-screen triangle with tonemap.frag → drawGridBounds() if asked
//   → caller draws the UI → end()
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "io/display_transform.h"
#include "present.h"
#include "view/swapchain.h"

namespace vct {

struct TonemapParams {
    float exposure = 1.0f;
    bool toneCurve = true;  // false for debug views whose values are colours already
    ToneCurve curve = ToneCurve::PbrNeutral;
};

class PresentPass {
public:
    PresentPass(GpuContext& context, VkFormat swapchainFormat);
    ~PresentPass();
    PresentPass(const PresentPass&) = delete;
    PresentPass& operator=(const PresentPass&) = delete;

    // One framebuffer per swapchain image; call again after the swapchain was recreated.
    void createFramebuffers(const Swapchain& swapchain);

    // `radiance`: the renderer's frame, written by earlier submissions (its read is declared here).
    // The image fills `area` of the window (`extent`); the rest is cleared to black.
    void begin(VkCommandBuffer commands, uint32_t imageIndex, VkExtent2D extent, VkRect2D area,
               const GpuImage& radiance, const TonemapParams& params);
    // The voxel grid's 12 edges as 1-pixel lines over the tone-mapped image. Not depth-tested (the
    // present pass has no depth): edges behind the scene show too, so the whole box reads at once.
    void drawGridBounds(VkCommandBuffer commands, const glsl::GridBoundsPush& push);
    void end(VkCommandBuffer commands);

    VkRenderPass renderPass = VK_NULL_HANDLE;
    VkFormat format;

private:
    void destroyFramebuffers();
    GpuContext& context_;
    Pipeline tonemap_;
    Pipeline gridBounds_;
    Sampler sampler_;
    std::vector<VkFramebuffer> framebuffers_;
};

}  // namespace vct
