// The window-side objects the viewer owns, each destroyed with its owner in reverse order of
// creation: GLFW itself, the window, its Vulkan surface, the present pass's command buffer and
// synchronization, and Dear ImGui with its GLFW and Vulkan backends.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

#include "gpu/context.h"
#include "view/swapchain.h"

struct GLFWwindow;

namespace vct {

struct GlfwSession {
    GlfwSession();  // a vct::Error when there is no display or no Vulkan surface support
    ~GlfwSession();
    GlfwSession(const GlfwSession&) = delete;
    GlfwSession& operator=(const GlfwSession&) = delete;
};

struct Window {
    Window(uint32_t width, uint32_t height);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;
    GLFWwindow* handle = nullptr;
};

struct Surface {
    Surface(GpuContext& context, GLFWwindow* window);
    ~Surface();
    Surface(const Surface&) = delete;
    Surface& operator=(const Surface&) = delete;
    VkInstance instance;
    VkSurfaceKHR surface = VK_NULL_HANDLE;
};

// One command buffer for the present pass; one frame in flight (the renderer waits for its own
// work anyway, so more would not overlap anything).
struct PresentCommands {
    explicit PresentCommands(GpuContext& context);
    ~PresentCommands();
    PresentCommands(const PresentCommands&) = delete;
    PresentCommands& operator=(const PresentCommands&) = delete;
    VkDevice device;
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer commands = VK_NULL_HANDLE;
    VkFence fence = VK_NULL_HANDLE;
    VkSemaphore imageAcquired = VK_NULL_HANDLE;
};

// Dear ImGui with its GLFW and Vulkan backends; the descriptor pool holds the font texture's set.
struct ImGuiSession {
    ImGuiSession(GpuContext& context, GLFWwindow* window, const Swapchain& swapchain, VkRenderPass renderPass);
    ~ImGuiSession();
    ImGuiSession(const ImGuiSession&) = delete;
    ImGuiSession& operator=(const ImGuiSession&) = delete;
    VkDevice device;
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
};

}  // namespace vct
