#include "scene/scene_limits.h"

#include <algorithm>
#include <cstdio>

#include "error.h"

namespace vct {

std::string bytesText(uint64_t bytes) {
    char text[32];
    if (bytes >= (uint64_t(1) << 20)) std::snprintf(text, sizeof text, "%.0f MiB", double(bytes) / double(1 << 20));
    else if (bytes >= 1024) std::snprintf(text, sizeof text, "%.0f KiB", double(bytes) / 1024.0);
    else std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
    return text;
}

void checkSceneBufferFits(const std::string& prefix, uint64_t count, uint64_t elementBytes, const std::string& what,
                          const SceneBufferLimits& limits, uint64_t countInFile) {
    const uint64_t range = limits.maxBufferBytes;
    // Counts from a file can be anything: compare without overflowing.
    const bool fits = count <= UINT32_MAX && count <= range / elementBytes;
    if (fits) return;
    const std::string needed =
        count <= UINT64_MAX / elementBytes ? bytesText(count * elementBytes) : "more than 16 EiB";
    const std::string counted = countInFile == 0 || countInFile == count
                                    ? std::to_string(count) + " " + what
                                    : std::to_string(countInFile) + " " + what + " (" + std::to_string(count) +
                                          " once each triangle has its own)";
    throw Error(prefix + "its " + counted + " need " + needed + " in one storage buffer, more than " +
                limits.deviceName + "'s maxStorageBufferRange of " + bytesText(range) + "; at most " +
                std::to_string(std::min<uint64_t>(range / elementBytes, UINT32_MAX)) + " " + what + " fit");
}

}  // namespace vct
