// The Vulkan instance, device and queue: the one object every pass is given.
//
// Device choice: the device named by `deviceName` (or $VCT_DEVICE), matched as a substring of
// the device name; otherwise the first discrete GPU; otherwise any device (lavapipe on a
// machine without a GPU). A missing loader, device or feature is a vct::Error saying which.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace vct {

struct ContextOptions {
    bool validation = false;                      // enable VK_LAYER_KHRONOS_validation
    bool synchronizationValidation = false;       // and its hazard checks (the tests; slow)
    std::string deviceName;                       // substring of the device to use; empty = choose
    std::vector<const char*> instanceExtensions;  // e.g. the surface extensions a window needs
    bool swapchain = false;                       // enable VK_KHR_swapchain on the device
};

class GpuContext {
public:
    explicit GpuContext(const ContextOptions& options);
    ~GpuContext();
    GpuContext(const GpuContext&) = delete;
    GpuContext& operator=(const GpuContext&) = delete;

    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t queueFamily = 0;
    VkCommandPool commandPool = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memoryProperties{};
    bool timestampsSupported = false;
    PFN_vkCmdPushDescriptorSetKHR cmdPushDescriptorSet = nullptr;

    std::string deviceName() const { return properties.deviceName; }
    bool isSoftwareRasterizer() const { return properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }

    // Validation messages (errors and warnings) seen so far; tests fail when this is not empty.
    std::vector<std::string> validationMessages() const;
    void clearValidationMessages();

    // Longest a fence wait may take before the GPU is declared stuck (seconds).
    double fenceTimeoutSeconds = 120.0;

private:
    // The constructor's steps, and the destructor's: the constructor calls destroy() when a step
    // throws, so a context that fails half-way (no device, a missing feature) leaks nothing.
    void create(const ContextOptions& options);
    void destroy();

    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    mutable std::mutex messagesMutex_;
    std::vector<std::string> messages_;

    static VKAPI_ATTR VkBool32 VKAPI_CALL onDebugMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                         VkDebugUtilsMessageTypeFlagsEXT types,
                                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void* self);
};

}  // namespace vct
