// Reading GPU images back to the CPU, for tests and debugging.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "gpu/resources.h"

namespace vct {

// The texels of one mip level of a 3D image as floats, index x + w·(y + h·z). Handles
// R8G8B8A8_UNORM, R16G16B16A16_SFLOAT and R32G32B32A32_SFLOAT (anything else is a vct::Error).
// Read after every earlier GPU write to it (gpu/pass_uses.h); the next pass that uses the image
// moves it back to the layout it needs.
std::vector<glm::vec4> readImage3D(GpuContext& context, const GpuImage& image, uint32_t mip);

// The first `count` 32-bit words of a device-local buffer made with TRANSFER_SRC usage, after all
// earlier GPU writes to it.
std::vector<uint32_t> readBufferWords(GpuContext& context, const Buffer& buffer, size_t count);

}  // namespace vct
