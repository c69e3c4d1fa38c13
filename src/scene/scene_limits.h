// How much geometry one storage buffer can take, checked twice with the same sentence: by the
// glTF loader from the counts in the file, before it builds any array (a 300-byte file can name
// 2²⁸ vertices), and by the renderer on the built scene (renderer_limits.h).
#pragma once

#include <cstdint>
#include <string>

namespace vct {

struct SceneBufferLimits {
    // The device's maxStorageBufferRange; without a device, 2 GiB, what most GPUs allow.
    uint64_t maxBufferBytes = uint64_t(1) << 31;
    std::string deviceName = "a typical GPU";
    // The RGBA8 bytes all of a scene's decoded images may take, checked from each image's header
    // before it is decoded; a quarter of the device's memory, at most 1 GiB (one 16384² image,
    // the largest the loader decodes). See decodedImageBudget().
    uint64_t maxDecodedImageBytes = kMaxDecodedImageBytes;
    static constexpr uint64_t kMaxDecodedImageBytes = uint64_t(1) << 30;
};

// The budget for a device whose largest device-local heap has `heapBytes`.
inline uint64_t decodedImageBudget(uint64_t heapBytes) {
    return heapBytes / 4 < SceneBufferLimits::kMaxDecodedImageBytes ? heapBytes / 4
                                                                    : SceneBufferLimits::kMaxDecodedImageBytes;
}

// Throws vct::Error "`prefix`its N vertices need 4096 MiB in one storage buffer, more than
// DEVICE's maxStorageBufferRange of 2048 MiB; at most M vertices fit" when `count` elements of
// `elementBytes` do not fit one buffer, or are more than 32-bit indices can address. When the file
// holds fewer (`countInFile`: a mesh without normals gets three vertices per triangle), the sentence
// gives the file's count first: "its 1000 vertices (3000 once each triangle has its own) need...".
void checkSceneBufferFits(const std::string& prefix, uint64_t count, uint64_t elementBytes, const std::string& what,
                          const SceneBufferLimits& limits, uint64_t countInFile = 0);

// The brightest light (intensity × colour) or emission (emissiveFactor × strength) the renderer
// represents: its shading multiplies a few such values with BRDFs and distances in 32-bit floats
// (at most 3.4·10³⁸), and 10²⁰ is fifteen orders of magnitude above the sun's 10⁵ lux.
inline constexpr double kBrightestRepresentable = 1e20;

// "512 bytes", "3 KiB", "2048 MiB".
std::string bytesText(uint64_t bytes);

}  // namespace vct
