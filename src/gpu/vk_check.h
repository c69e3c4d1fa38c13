// VK_CHECK: a failed Vulkan call becomes a vct::Error naming the call, the result, file and line.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

#include "error.h"

namespace vct {

const char* vkResultName(VkResult result);

[[noreturn]] void throwVkError(VkResult result, const char* call, const char* file, int line);

}  // namespace vct

#define VK_CHECK(call)                                                                                    \
    do {                                                                                                  \
        VkResult vkCheckResult_ = (call);                                                                 \
        if (vkCheckResult_ != VK_SUCCESS) ::vct::throwVkError(vkCheckResult_, #call, __FILE__, __LINE__); \
    } while (0)
