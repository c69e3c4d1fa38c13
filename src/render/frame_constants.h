// FrameConstants (shaders_glsl/gpu_types.h) is copied to a std140 uniform block byte for byte: these
// checks fail the build if a member's C++ offset ever differs from its std140 offset.
#pragma once

#include <cstddef>

#include "gpu_types.h"

namespace vct::glsl {

static_assert(offsetof(FrameConstants, viewProjection) == 0);
static_assert(sizeof(GpuMaterial) == 256 && offsetof(GpuMaterial, metallic) == 48);  // std430 array stride
static_assert(offsetof(GpuMaterial, alphaMode) == 88 && offsetof(GpuMaterial, alphaCutoff) == 92);
static_assert(offsetof(GpuMaterial, baseColorTransform) == 96 && sizeof(GpuTextureTransform) == 32);
static_assert(sizeof(GpuVertex) == 64);
static_assert(offsetof(FrameConstants, inverseViewProjection) == 64);
static_assert(offsetof(FrameConstants, grid) == 128 && sizeof(VoxelGridParams) == 32);
static_assert(offsetof(FrameConstants, cameraPosition) == 160);  // a vec3 starts on 16 bytes
static_assert(offsetof(FrameConstants, lightCount) == 172);      // and a scalar may follow it
static_assert(offsetof(FrameConstants, debugView) == 188);
static_assert(offsetof(FrameConstants, renderSize) == 192);  // a vec2 starts on 8 bytes
static_assert(offsetof(FrameConstants, inverseRenderSize) == 200);
static_assert(offsetof(FrameConstants, environment) == 272);  // a vec4 starts on 16 bytes
static_assert(offsetof(FrameConstants, ambientFactor) == 208);
static_assert(offsetof(FrameConstants, radianceScale) == 220);
static_assert(offsetof(FrameConstants, coneTanHalfAperture) == 224);
static_assert(offsetof(FrameConstants, diffuseConeCount) == 252);
static_assert(offsetof(FrameConstants, debugVoxelMip) == 260);
static_assert(sizeof(FrameConstants) == 288);  // a multiple of 16, as a std140 struct

}  // namespace vct::glsl
