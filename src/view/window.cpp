#include "view/window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "error.h"
#include "gpu/commands.h"
#include "gpu/vk_check.h"

namespace vct {

GlfwSession::GlfwSession() {
    glfwSetErrorCallback([](int code, const char* text) { std::fprintf(stderr, "GLFW error %d: %s\n", code, text); });
    if (!glfwInit()) throw Error("cannot open a window: GLFW found no display (set DISPLAY, or run under xvfb-run)");
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw Error("cannot open a window: GLFW found no Vulkan loader with surface support");
    }
}

GlfwSession::~GlfwSession() { glfwTerminate(); }

Window::Window(uint32_t width, uint32_t height) {
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    handle = glfwCreateWindow(int(width), int(height), "vct view", nullptr, nullptr);
    if (!handle) throw Error("cannot create a " + std::to_string(width) + "x" + std::to_string(height) + " window");
}

Window::~Window() { glfwDestroyWindow(handle); }

Surface::Surface(GpuContext& context, GLFWwindow* window) : instance(context.instance) {
    VK_CHECK(glfwCreateWindowSurface(instance, window, nullptr, &surface));
}

Surface::~Surface() { vkDestroySurfaceKHR(instance, surface, nullptr); }

PresentCommands::PresentCommands(GpuContext& context) : device(context.device) {
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = context.queueFamily;
    VK_CHECK(vkCreateCommandPool(device, &poolInfo, nullptr, &pool));
    VkCommandBufferAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocateInfo.commandPool = pool;
    allocateInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocateInfo.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(device, &allocateInfo, &commands));
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fenceInfo.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    VK_CHECK(vkCreateFence(device, &fenceInfo, nullptr, &fence));
    const VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VK_CHECK(vkCreateSemaphore(device, &semaphoreInfo, nullptr, &imageAcquired));
}

PresentCommands::~PresentCommands() {
    vkDestroySemaphore(device, imageAcquired, nullptr);
    vkDestroyFence(device, fence, nullptr);
    vkDestroyCommandPool(device, pool, nullptr);
}

ImGuiSession::ImGuiSession(GpuContext& context, GLFWwindow* window, const Swapchain& swapchain, VkRenderPass renderPass)
    : device(context.device) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the user's folder
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 4.0f;
    ImGui_ImplGlfw_InitForVulkan(window, true);  // chains to the viewer's own callbacks

    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    poolInfo.maxSets = 4;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &size;
    VK_CHECK(vkCreateDescriptorPool(device, &poolInfo, nullptr, &descriptorPool));

    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = context.instance;
    info.PhysicalDevice = context.physicalDevice;
    info.Device = context.device;
    info.QueueFamily = context.queueFamily;
    info.Queue = context.queue;
    info.DescriptorPool = descriptorPool;
    info.MinImageCount = std::max(swapchain.minImageCount, 2u);
    info.ImageCount = std::max(uint32_t(swapchain.images.size()), info.MinImageCount);
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = [](VkResult result) {
        if (result != VK_SUCCESS) throwVkError(result, "Dear ImGui's Vulkan backend", __FILE__, __LINE__);
    };
    ImGui_ImplVulkan_Init(&info, renderPass);
    submitAndWait(context, [](VkCommandBuffer commands) { ImGui_ImplVulkan_CreateFontsTexture(commands); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

ImGuiSession::~ImGuiSession() {
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    vkDestroyDescriptorPool(device, descriptorPool, nullptr);
}

}  // namespace vct
