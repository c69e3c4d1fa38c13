// The structs that C++ fills and the shaders read byte for byte (shaders_glsl/gpu_types.h):
// tests/cpu/spirv_reflect_test.cpp checks every member's C++ offset against its offset in the
// SPIR-V (SpirvReflect.TheSharedStructsHaveTheirCppOffsetsInTheShaders). What can be checked at
// compile time without restating std140's rules is here.
#pragma once

#include <cstddef>

#include "gpu_types.h"

namespace vct::glsl {

static_assert(sizeof(FrameConstants) % 16 == 0, "a std140 struct's size is a multiple of 16");
static_assert(sizeof(GpuMaterial) % 16 == 0 && sizeof(GpuVertex) % 16 == 0, "std430 arrays of vec4 structs");

}  // namespace vct::glsl
