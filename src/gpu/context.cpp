#include "gpu/context.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "gpu/vk_check.h"

namespace vct {
namespace {

bool hasLayer(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    for (const VkLayerProperties& layer : layers)
        if (std::strcmp(layer.layerName, name) == 0) return true;
    return false;
}

bool hasDeviceExtension(VkPhysicalDevice device, const char* name) {
    uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
    for (const VkExtensionProperties& extension : extensions)
        if (std::strcmp(extension.extensionName, name) == 0) return true;
    return false;
}

// Why a device cannot run the renderer, or empty when it can.
std::string missingRequirement(VkPhysicalDevice device, bool swapchain) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(device, &properties);
    if (properties.apiVersion < VK_API_VERSION_1_3) return "it supports Vulkan 1.2 or older, 1.3 is needed";
    VkPhysicalDeviceVulkan13Features features13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &features13};
    vkGetPhysicalDeviceFeatures2(device, &features);

    if (!features13.dynamicRendering) return "it lacks dynamicRendering";
    if (!features13.synchronization2) return "it lacks synchronization2";
    if (!features13.maintenance4) return "it lacks maintenance4";
    if (!features.features.fragmentStoresAndAtomics) return "it lacks fragmentStoresAndAtomics";
    if (!features.features.shaderStorageImageWriteWithoutFormat) return "it lacks shaderStorageImageWriteWithoutFormat";
    if (!hasDeviceExtension(device, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME)) return "it lacks VK_KHR_push_descriptor";
    if (swapchain && !hasDeviceExtension(device, VK_KHR_SWAPCHAIN_EXTENSION_NAME)) return "it lacks VK_KHR_swapchain";
    return {};
}

}  // namespace

VKAPI_ATTR VkBool32 VKAPI_CALL GpuContext::onDebugMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                          VkDebugUtilsMessageTypeFlagsEXT,
                                                          const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                          void* self) {
    const bool isError = severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    const std::string message = std::string(isError ? "validation error: " : "validation warning: ") +
                                (data->pMessage ? data->pMessage : "(no message)");
    std::fprintf(stderr, "%s\n", message.c_str());
    auto* context = static_cast<GpuContext*>(self);
    std::lock_guard lock(context->messagesMutex_);
    context->messages_.push_back(message);
    return VK_FALSE;
}

GpuContext::GpuContext(const ContextOptions& options) {
    // A destructor runs only for a finished constructor: clean up here what a failed step left.
    try {
        create(options);
    } catch (...) {
        destroy();
        throw;
    }
}

void GpuContext::create(const ContextOptions& options) {
    const char* environmentDevice = std::getenv("VCT_DEVICE");
    const std::string wantedDevice =
        !options.deviceName.empty() ? options.deviceName : (environmentDevice ? environmentDevice : "");

    VkApplicationInfo application{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    application.pApplicationName = "vct";
    application.apiVersion = VK_API_VERSION_1_3;

    std::vector<const char*> layers;
    std::vector<const char*> extensions = options.instanceExtensions;
    if (options.validation) {
        if (!hasLayer("VK_LAYER_KHRONOS_validation"))
            throw Error(
                "the Vulkan validation layer is not installed (Debian: apt-get install vulkan-validationlayers)");
        layers.push_back("VK_LAYER_KHRONOS_validation");
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        if (options.synchronizationValidation) extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    }

    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT;
    messengerInfo.pfnUserCallback = onDebugMessage;
    messengerInfo.pUserData = this;
    const VkValidationFeatureEnableEXT synchronization = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT validationFeatures{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    validationFeatures.enabledValidationFeatureCount = 1;
    validationFeatures.pEnabledValidationFeatures = &synchronization;
    // The instance's chain: its validation features (when asked for), then the messenger, so the
    // layer's messages from vkCreateInstance on arrive too. (The messenger's own create info
    // must end the chain: vkCreateDebugUtilsMessengerEXT takes it with no pNext.)
    validationFeatures.pNext = &messengerInfo;

    VkInstanceCreateInfo instanceInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    instanceInfo.pNext = !options.validation                 ? nullptr
                         : options.synchronizationValidation ? static_cast<const void*>(&validationFeatures)
                                                             : &messengerInfo;
    instanceInfo.pApplicationInfo = &application;
    instanceInfo.enabledLayerCount = uint32_t(layers.size());
    instanceInfo.ppEnabledLayerNames = layers.data();
    instanceInfo.enabledExtensionCount = uint32_t(extensions.size());
    instanceInfo.ppEnabledExtensionNames = extensions.data();
    VkResult result = vkCreateInstance(&instanceInfo, nullptr, &instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw Error("no Vulkan driver found (Debian: apt-get install mesa-vulkan-drivers for the CPU driver lavapipe)");
    VK_CHECK(result);

    if (options.validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
        VK_CHECK(create(instance, &messengerInfo, nullptr, &messenger_));
    }

    uint32_t deviceCount = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &deviceCount, nullptr));
    std::vector<VkPhysicalDevice> devices(deviceCount);
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &deviceCount, devices.data()));
    if (devices.empty()) throw Error("no Vulkan device found (Debian: apt-get install mesa-vulkan-drivers)");

    std::string rejected;
    int bestScore = -1;
    for (VkPhysicalDevice candidate : devices) {
        VkPhysicalDeviceProperties candidateProperties;
        vkGetPhysicalDeviceProperties(candidate, &candidateProperties);
        const std::string name = candidateProperties.deviceName;
        if (!wantedDevice.empty() && name.find(wantedDevice) == std::string::npos) {
            rejected += "\n  " + name + ": not the requested device '" + wantedDevice + "'";
            continue;
        }
        const std::string missing = missingRequirement(candidate, options.swapchain);
        if (!missing.empty()) {
            rejected += "\n  " + name + ": " + missing;
            continue;
        }
        const int score = candidateProperties.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU     ? 3
                          : candidateProperties.deviceType == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU ? 2
                                                                                                     : 1;
        if (score > bestScore) {
            bestScore = score;
            physicalDevice = candidate;
        }
    }
    if (!physicalDevice) throw Error("no Vulkan device can run the renderer:" + rejected);

    vkGetPhysicalDeviceProperties(physicalDevice, &properties);
    vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memoryProperties);

    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, families.data());
    bool foundQueue = false;
    for (uint32_t i = 0; i < familyCount && !foundQueue; ++i) {
        if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT)) {
            queueFamily = i;
            foundQueue = true;
        }
    }
    if (!foundQueue) throw Error(deviceName() + " has no queue that does both graphics and compute");
    timestampsSupported = properties.limits.timestampComputeAndGraphics && families[queueFamily].timestampValidBits > 0;

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;

    VkPhysicalDeviceVulkan13Features features13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    features13.dynamicRendering = VK_TRUE;
    features13.synchronization2 = VK_TRUE;
    features13.maintenance4 = VK_TRUE;  // glslang's Vulkan 1.3 target writes LocalSizeId
    VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &features13};
    features.features.fragmentStoresAndAtomics = VK_TRUE;
    features.features.shaderStorageImageWriteWithoutFormat = VK_TRUE;
    // The scene's texture array is indexed by the material: per draw in the G-buffer, per
    // workgroup in the voxelizer (dynamically uniform). Enabled where the device offers it; lavapipe
    // 22.3 does not report it and indexes such arrays all the same.
    VkPhysicalDeviceFeatures offered{};
    vkGetPhysicalDeviceFeatures(physicalDevice, &offered);
    features.features.shaderSampledImageArrayDynamicIndexing = offered.shaderSampledImageArrayDynamicIndexing;

    std::vector<const char*> deviceExtensions = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
    if (options.swapchain) deviceExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);

    VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features};
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    deviceInfo.enabledExtensionCount = uint32_t(deviceExtensions.size());
    deviceInfo.ppEnabledExtensionNames = deviceExtensions.data();
    VK_CHECK(vkCreateDevice(physicalDevice, &deviceInfo, nullptr, &device));
    vkGetDeviceQueue(device, queueFamily, 0, &queue);

    cmdPushDescriptorSet =
        reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(vkGetDeviceProcAddr(device, "vkCmdPushDescriptorSetKHR"));

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = queueFamily;
    VK_CHECK(vkCreateCommandPool(device, &poolInfo, nullptr, &commandPool));
}

GpuContext::~GpuContext() { destroy(); }

void GpuContext::destroy() {
    if (device) {
        vkDeviceWaitIdle(device);  // may report VK_ERROR_DEVICE_LOST; destroying is still allowed then
        if (commandPool) vkDestroyCommandPool(device, commandPool, nullptr);
        vkDestroyDevice(device, nullptr);
        device = VK_NULL_HANDLE;
        commandPool = VK_NULL_HANDLE;
    }
    if (messenger_) {
        auto destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        destroyMessenger(instance, messenger_, nullptr);
        messenger_ = VK_NULL_HANDLE;
    }
    if (instance) vkDestroyInstance(instance, nullptr);
    instance = VK_NULL_HANDLE;
}

std::vector<std::string> GpuContext::validationMessages() const {
    std::lock_guard lock(messagesMutex_);
    return messages_;
}

void GpuContext::clearValidationMessages() {
    std::lock_guard lock(messagesMutex_);
    messages_.clear();
}

}  // namespace vct
