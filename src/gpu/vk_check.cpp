#include "gpu/vk_check.h"

namespace vct {

const char* vkResultName(VkResult result) {
    switch (result) {
#define VCT_RESULT_CASE(name) \
    case name: return #name;
        VCT_RESULT_CASE(VK_SUCCESS)
        VCT_RESULT_CASE(VK_NOT_READY)
        VCT_RESULT_CASE(VK_TIMEOUT)
        VCT_RESULT_CASE(VK_INCOMPLETE)
        VCT_RESULT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
        VCT_RESULT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        VCT_RESULT_CASE(VK_ERROR_INITIALIZATION_FAILED)
        VCT_RESULT_CASE(VK_ERROR_DEVICE_LOST)
        VCT_RESULT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
        VCT_RESULT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
        VCT_RESULT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
        VCT_RESULT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        VCT_RESULT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
        VCT_RESULT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
        VCT_RESULT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
        VCT_RESULT_CASE(VK_ERROR_FRAGMENTED_POOL)
        VCT_RESULT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
        VCT_RESULT_CASE(VK_ERROR_SURFACE_LOST_KHR)
        VCT_RESULT_CASE(VK_ERROR_OUT_OF_DATE_KHR)
        VCT_RESULT_CASE(VK_SUBOPTIMAL_KHR)
#undef VCT_RESULT_CASE
        default: return "VkResult(unknown)";
    }
}

void throwVkError(VkResult result, const char* call, const char* file, int line) {
    std::string message =
        std::string(call) + " failed with " + vkResultName(result) + " (" + file + ":" + std::to_string(line) + ")";
    if (result == VK_ERROR_DEVICE_LOST) message = "the GPU device was lost: " + message;
    if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
        message = "out of memory: " + message + "; try fewer voxels (--voxels) or a smaller image";
    throw Error(message);
}

}  // namespace vct
