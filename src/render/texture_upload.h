// A material texture on the device: RGBA8, sRGB or linear as glTF says, with its whole mip chain.
#pragma once

#include <cstdint>

#include "gpu/resources.h"

namespace vct {

// Uploads `rgba8` (width × height, rows top to bottom) and filters each level from the one above
// by a linear blit, which averages an sRGB texture's colours in linear space. Where the device
// cannot blit the format linearly, the texture keeps its single level (sampled as before). Leaves
// it in SHADER_READ_ONLY_OPTIMAL for the fragment and compute stages.
GpuImage uploadTexture(GpuContext& context, uint32_t width, uint32_t height, const uint8_t* rgba8, bool srgb);

}  // namespace vct
