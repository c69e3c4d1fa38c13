// SPIR-V reflection (src/gpu/spirv_reflect): the committed shaders in spirv/ give the bindings their GLSL
// declares, small modules compiled offline cover each descriptor kind, and malformed words are errors.
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bindings.h"
#include "equirectangular.h"
#include "error.h"
#include "gpu/spirv_reflect.h"
#include "gpu_types.h"
#include "present.h"
#include "surface_planes.h"
#include "voxelize.h"

namespace vct {
namespace {

constexpr VkDescriptorType kUniformBuffer = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
constexpr VkDescriptorType kStorageBuffer = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
constexpr VkDescriptorType kCombined = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
constexpr VkDescriptorType kStorageImage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
constexpr VkShaderStageFlags kVertex = VK_SHADER_STAGE_VERTEX_BIT;
constexpr VkShaderStageFlags kFragment = VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;

// glslangValidator -V --target-env vulkan1.3 -g0 of:
//   #version 460
//   layout(local_size_x = 8, local_size_y = 4, local_size_z = 2) in;
//   layout(set = 0, binding = 0) uniform Frame { vec4 color; } frame;
//   layout(std430, set = 0, binding = 1) buffer Values { uint values[]; };
//   layout(set = 0, binding = 2, rgba8) uniform writeonly image2D target;
//   layout(set = 0, binding = 3) uniform samplerBuffer texels;
//   layout(set = 0, binding = 4, r32ui) uniform uimageBuffer counters;
//   layout(set = 0, binding = 5) uniform texture2D plainTexture;
//   layout(set = 0, binding = 6) uniform sampler plainSampler;
//   layout(set = 0, binding = 12) uniform sampler3D volumes[6];
//   layout(set = 1, binding = 3) uniform sampler2D neverRead;
//   layout(set = 2, binding = 0) uniform Light { vec4 position; } lights[4];
//   layout(push_constant) uniform Push {
//       mat4 transform;
//       float weights[3];
//       vec3 tint;
//       layout(row_major) mat2x3 rows;
//   } push;
//   void main() { values[0] = uint(push.tint.x); }
const std::vector<uint32_t> kEveryKind = {
    0x07230203, 0x00010600, 0x0008000b, 0x00000043, 0x00000000, 0x00020011, 0x00000001, 0x00020011, 0x0000002e,
    0x00020011, 0x0000002f, 0x0006000b, 0x00000001, 0x4c534c47, 0x6474732e, 0x3035342e, 0x00000000, 0x0003000e,
    0x00000000, 0x00000001, 0x0010000f, 0x00000005, 0x00000004, 0x6e69616d, 0x00000000, 0x0000000d, 0x00000019,
    0x00000026, 0x00000029, 0x0000002c, 0x0000002f, 0x00000032, 0x00000035, 0x0000003b, 0x0000003e, 0x00000042,
    0x0006014b, 0x00000004, 0x00000026, 0x00000007, 0x00000008, 0x00000009, 0x00040047, 0x0000000a, 0x00000006,
    0x00000004, 0x00050048, 0x0000000b, 0x00000000, 0x00000023, 0x00000000, 0x00030047, 0x0000000b, 0x00000002,
    0x00040047, 0x0000000d, 0x00000022, 0x00000000, 0x00040047, 0x0000000d, 0x00000021, 0x00000001, 0x00040047,
    0x00000014, 0x00000006, 0x00000004, 0x00040048, 0x00000017, 0x00000000, 0x00000005, 0x00050048, 0x00000017,
    0x00000000, 0x00000023, 0x00000000, 0x00050048, 0x00000017, 0x00000000, 0x00000007, 0x00000010, 0x00050048,
    0x00000017, 0x00000001, 0x00000023, 0x00000040, 0x00050048, 0x00000017, 0x00000002, 0x00000023, 0x00000050,
    0x00040048, 0x00000017, 0x00000003, 0x00000004, 0x00050048, 0x00000017, 0x00000003, 0x00000023, 0x00000060,
    0x00050048, 0x00000017, 0x00000003, 0x00000007, 0x00000008, 0x00030047, 0x00000017, 0x00000002, 0x00050048,
    0x00000024, 0x00000000, 0x00000023, 0x00000000, 0x00030047, 0x00000024, 0x00000002, 0x00040047, 0x00000026,
    0x00000022, 0x00000000, 0x00040047, 0x00000026, 0x00000021, 0x00000000, 0x00040047, 0x00000029, 0x00000022,
    0x00000000, 0x00040047, 0x00000029, 0x00000021, 0x00000002, 0x00030047, 0x00000029, 0x00000019, 0x00040047,
    0x0000002c, 0x00000022, 0x00000000, 0x00040047, 0x0000002c, 0x00000021, 0x00000003, 0x00040047, 0x0000002f,
    0x00000022, 0x00000000, 0x00040047, 0x0000002f, 0x00000021, 0x00000004, 0x00040047, 0x00000032, 0x00000022,
    0x00000000, 0x00040047, 0x00000032, 0x00000021, 0x00000005, 0x00040047, 0x00000035, 0x00000022, 0x00000000,
    0x00040047, 0x00000035, 0x00000021, 0x00000006, 0x00040047, 0x0000003b, 0x00000022, 0x00000000, 0x00040047,
    0x0000003b, 0x00000021, 0x0000000c, 0x00040047, 0x0000003e, 0x00000022, 0x00000001, 0x00040047, 0x0000003e,
    0x00000021, 0x00000003, 0x00050048, 0x0000003f, 0x00000000, 0x00000023, 0x00000000, 0x00030047, 0x0000003f,
    0x00000002, 0x00040047, 0x00000042, 0x00000022, 0x00000002, 0x00040047, 0x00000042, 0x00000021, 0x00000000,
    0x00020013, 0x00000002, 0x00030021, 0x00000003, 0x00000002, 0x00040015, 0x00000006, 0x00000020, 0x00000000,
    0x0004002b, 0x00000006, 0x00000007, 0x00000008, 0x0004002b, 0x00000006, 0x00000008, 0x00000004, 0x0004002b,
    0x00000006, 0x00000009, 0x00000002, 0x0003001d, 0x0000000a, 0x00000006, 0x0003001e, 0x0000000b, 0x0000000a,
    0x00040020, 0x0000000c, 0x0000000c, 0x0000000b, 0x0004003b, 0x0000000c, 0x0000000d, 0x0000000c, 0x00040015,
    0x0000000e, 0x00000020, 0x00000001, 0x0004002b, 0x0000000e, 0x0000000f, 0x00000000, 0x00030016, 0x00000010,
    0x00000020, 0x00040017, 0x00000011, 0x00000010, 0x00000004, 0x00040018, 0x00000012, 0x00000011, 0x00000004,
    0x0004002b, 0x00000006, 0x00000013, 0x00000003, 0x0004001c, 0x00000014, 0x00000010, 0x00000013, 0x00040017,
    0x00000015, 0x00000010, 0x00000003, 0x00040018, 0x00000016, 0x00000015, 0x00000002, 0x0006001e, 0x00000017,
    0x00000012, 0x00000014, 0x00000015, 0x00000016, 0x00040020, 0x00000018, 0x00000009, 0x00000017, 0x0004003b,
    0x00000018, 0x00000019, 0x00000009, 0x0004002b, 0x0000000e, 0x0000001a, 0x00000002, 0x0004002b, 0x00000006,
    0x0000001b, 0x00000000, 0x00040020, 0x0000001c, 0x00000009, 0x00000010, 0x00040020, 0x00000020, 0x0000000c,
    0x00000006, 0x00040017, 0x00000022, 0x00000006, 0x00000003, 0x0006002c, 0x00000022, 0x00000023, 0x00000007,
    0x00000008, 0x00000009, 0x0003001e, 0x00000024, 0x00000011, 0x00040020, 0x00000025, 0x00000002, 0x00000024,
    0x0004003b, 0x00000025, 0x00000026, 0x00000002, 0x00090019, 0x00000027, 0x00000010, 0x00000001, 0x00000000,
    0x00000000, 0x00000000, 0x00000002, 0x00000004, 0x00040020, 0x00000028, 0x00000000, 0x00000027, 0x0004003b,
    0x00000028, 0x00000029, 0x00000000, 0x00090019, 0x0000002a, 0x00000010, 0x00000005, 0x00000000, 0x00000000,
    0x00000000, 0x00000001, 0x00000000, 0x00040020, 0x0000002b, 0x00000000, 0x0000002a, 0x0004003b, 0x0000002b,
    0x0000002c, 0x00000000, 0x00090019, 0x0000002d, 0x00000006, 0x00000005, 0x00000000, 0x00000000, 0x00000000,
    0x00000002, 0x00000021, 0x00040020, 0x0000002e, 0x00000000, 0x0000002d, 0x0004003b, 0x0000002e, 0x0000002f,
    0x00000000, 0x00090019, 0x00000030, 0x00000010, 0x00000001, 0x00000000, 0x00000000, 0x00000000, 0x00000001,
    0x00000000, 0x00040020, 0x00000031, 0x00000000, 0x00000030, 0x0004003b, 0x00000031, 0x00000032, 0x00000000,
    0x0002001a, 0x00000033, 0x00040020, 0x00000034, 0x00000000, 0x00000033, 0x0004003b, 0x00000034, 0x00000035,
    0x00000000, 0x00090019, 0x00000036, 0x00000010, 0x00000002, 0x00000000, 0x00000000, 0x00000000, 0x00000001,
    0x00000000, 0x0003001b, 0x00000037, 0x00000036, 0x0004002b, 0x00000006, 0x00000038, 0x00000006, 0x0004001c,
    0x00000039, 0x00000037, 0x00000038, 0x00040020, 0x0000003a, 0x00000000, 0x00000039, 0x0004003b, 0x0000003a,
    0x0000003b, 0x00000000, 0x0003001b, 0x0000003c, 0x00000030, 0x00040020, 0x0000003d, 0x00000000, 0x0000003c,
    0x0004003b, 0x0000003d, 0x0000003e, 0x00000000, 0x0003001e, 0x0000003f, 0x00000011, 0x0004001c, 0x00000040,
    0x0000003f, 0x00000008, 0x00040020, 0x00000041, 0x00000002, 0x00000040, 0x0004003b, 0x00000041, 0x00000042,
    0x00000002, 0x00050036, 0x00000002, 0x00000004, 0x00000000, 0x00000003, 0x000200f8, 0x00000005, 0x00060041,
    0x0000001c, 0x0000001d, 0x00000019, 0x0000001a, 0x0000001b, 0x0004003d, 0x00000010, 0x0000001e, 0x0000001d,
    0x0004006d, 0x00000006, 0x0000001f, 0x0000001e, 0x00060041, 0x00000020, 0x00000021, 0x0000000d, 0x0000000f,
    0x0000000f, 0x0003003e, 0x00000021, 0x0000001f, 0x000100fd, 0x00010038,
};

// glslangValidator -V --target-env vulkan1.0 -g0 of (SPIR-V 1.0 has no StorageBuffer storage class):
//   #version 450
//   layout(local_size_x = 16) in;
//   layout(std430, set = 0, binding = 1) buffer Values { uint values[]; };
//   void main() {}
const std::vector<uint32_t> kSpirv10Buffer = {
    0x07230203, 0x00010000, 0x0008000b, 0x0000000f, 0x00000000, 0x00020011, 0x00000001, 0x0006000b, 0x00000001,
    0x4c534c47, 0x6474732e, 0x3035342e, 0x00000000, 0x0003000e, 0x00000000, 0x00000001, 0x0005000f, 0x00000005,
    0x00000004, 0x6e69616d, 0x00000000, 0x00060010, 0x00000004, 0x00000011, 0x00000010, 0x00000001, 0x00000001,
    0x00040047, 0x0000000a, 0x0000000b, 0x00000019, 0x00040047, 0x0000000b, 0x00000006, 0x00000004, 0x00050048,
    0x0000000c, 0x00000000, 0x00000023, 0x00000000, 0x00030047, 0x0000000c, 0x00000003, 0x00040047, 0x0000000e,
    0x00000022, 0x00000000, 0x00040047, 0x0000000e, 0x00000021, 0x00000001, 0x00020013, 0x00000002, 0x00030021,
    0x00000003, 0x00000002, 0x00040015, 0x00000006, 0x00000020, 0x00000000, 0x00040017, 0x00000007, 0x00000006,
    0x00000003, 0x0004002b, 0x00000006, 0x00000008, 0x00000010, 0x0004002b, 0x00000006, 0x00000009, 0x00000001,
    0x0006002c, 0x00000007, 0x0000000a, 0x00000008, 0x00000009, 0x00000009, 0x0003001d, 0x0000000b, 0x00000006,
    0x0003001e, 0x0000000c, 0x0000000b, 0x00040020, 0x0000000d, 0x00000002, 0x0000000c, 0x0004003b, 0x0000000d,
    0x0000000e, 0x00000002, 0x00050036, 0x00000002, 0x00000004, 0x00000000, 0x00000003, 0x000200f8, 0x00000005,
    0x000100fd, 0x00010038,
};

// glslangValidator -V --target-env vulkan1.3 -g0 of (glslang sizes an unsized array by its largest
// constant index, so only a dynamically indexed one becomes an OpTypeRuntimeArray):
//   #version 460
//   #extension GL_EXT_nonuniform_qualifier : require
//   layout(set = 0, binding = 0) uniform sampler2D textures[];
//   layout(location = 0) flat in uint index;
//   layout(location = 0) out vec4 color;
//   void main() { color = texture(textures[nonuniformEXT(index)], vec2(0.0f)); }
const std::vector<uint32_t> kRuntimeArray = {
    0x07230203, 0x00010600, 0x0008000b, 0x0000001b, 0x00000000, 0x00020011, 0x00000001, 0x00020011, 0x000014b5,
    0x00020011, 0x000014b6, 0x00020011, 0x000014bb, 0x0006000b, 0x00000001, 0x4c534c47, 0x6474732e, 0x3035342e,
    0x00000000, 0x0003000e, 0x00000000, 0x00000001, 0x0008000f, 0x00000004, 0x00000004, 0x6e69616d, 0x00000000,
    0x00000009, 0x0000000e, 0x00000011, 0x00030010, 0x00000004, 0x00000007, 0x00040047, 0x00000009, 0x0000001e,
    0x00000000, 0x00040047, 0x0000000e, 0x00000022, 0x00000000, 0x00040047, 0x0000000e, 0x00000021, 0x00000000,
    0x00030047, 0x00000011, 0x0000000e, 0x00040047, 0x00000011, 0x0000001e, 0x00000000, 0x00030047, 0x00000013,
    0x000014b4, 0x00030047, 0x00000015, 0x000014b4, 0x00030047, 0x00000016, 0x000014b4, 0x00020013, 0x00000002,
    0x00030021, 0x00000003, 0x00000002, 0x00030016, 0x00000006, 0x00000020, 0x00040017, 0x00000007, 0x00000006,
    0x00000004, 0x00040020, 0x00000008, 0x00000003, 0x00000007, 0x0004003b, 0x00000008, 0x00000009, 0x00000003,
    0x00090019, 0x0000000a, 0x00000006, 0x00000001, 0x00000000, 0x00000000, 0x00000000, 0x00000001, 0x00000000,
    0x0003001b, 0x0000000b, 0x0000000a, 0x0003001d, 0x0000000c, 0x0000000b, 0x00040020, 0x0000000d, 0x00000000,
    0x0000000c, 0x0004003b, 0x0000000d, 0x0000000e, 0x00000000, 0x00040015, 0x0000000f, 0x00000020, 0x00000000,
    0x00040020, 0x00000010, 0x00000001, 0x0000000f, 0x0004003b, 0x00000010, 0x00000011, 0x00000001, 0x00040020,
    0x00000014, 0x00000000, 0x0000000b, 0x00040017, 0x00000017, 0x00000006, 0x00000002, 0x0004002b, 0x00000006,
    0x00000018, 0x00000000, 0x0005002c, 0x00000017, 0x00000019, 0x00000018, 0x00000018, 0x00050036, 0x00000002,
    0x00000004, 0x00000000, 0x00000003, 0x000200f8, 0x00000005, 0x0004003d, 0x0000000f, 0x00000012, 0x00000011,
    0x00040053, 0x0000000f, 0x00000013, 0x00000012, 0x00050041, 0x00000014, 0x00000015, 0x0000000e, 0x00000013,
    0x0004003d, 0x0000000b, 0x00000016, 0x00000015, 0x00050057, 0x00000007, 0x0000001a, 0x00000016, 0x00000019,
    0x0003003e, 0x00000009, 0x0000001a, 0x000100fd, 0x00010038,
};

std::vector<uint32_t> readSpirv(const std::string& name) {
    const std::string path = std::string(VCT_SOURCE_DIR) + "/spirv/" + name + ".spv";
    std::ifstream file(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    EXPECT_TRUE(file.good() || file.eof()) << "cannot read " << path;
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), words.size() * 4);
    return words;
}

ShaderReflection reflectFile(const std::string& name) { return reflectShader(readSpirv(name), name); }

ReflectedBinding binding(uint32_t set, uint32_t number, VkDescriptorType type, VkShaderStageFlags stages,
                         uint32_t count = 1) {
    ReflectedBinding b;
    b.set = set;
    b.binding = number;
    b.type = type;
    b.count = count;
    b.stages = stages;
    return b;
}

// Compares set, binding, type, count and stages, and prints the binding that differs. `expected`
// in any order: the reflection lists them by set and binding.
void expectBindings(const std::vector<ReflectedBinding>& actual, std::vector<ReflectedBinding> expected) {
    std::sort(expected.begin(), expected.end(), [](const ReflectedBinding& a, const ReflectedBinding& b) {
        return std::pair(a.set, a.binding) < std::pair(b.set, b.binding);
    });
    ASSERT_EQ(actual.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        SCOPED_TRACE("binding " + std::to_string(expected[i].binding) + " of set " + std::to_string(expected[i].set));
        EXPECT_EQ(actual[i].set, expected[i].set);
        EXPECT_EQ(actual[i].binding, expected[i].binding);
        EXPECT_EQ(actual[i].type, expected[i].type);
        EXPECT_EQ(actual[i].count, expected[i].count);
        EXPECT_EQ(actual[i].stages, expected[i].stages);
    }
}

// The message of the vct::Error that reflecting `words` throws, or a note that none was thrown.
std::string reflectionError(const std::vector<uint32_t>& words, const std::string& name) {
    try {
        reflectShader(words, name);
    } catch (const Error& error) {
        return error.what();
    }
    return "(no vct::Error)";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(SpirvReflect, InjectComputeShaderHasTheBindingsItsGlslDeclares) {
    // inject.comp.glsl: frame, lights, shadow views, two shadow maps, albedo and normal, the area
    // lights' triangles, the radiance level it writes, the gathered light it adds, the occupied-voxel
    // list and its count, the voxels' emission, the area lights' maps and the area lights' light it
    // keeps per voxel; one invocation per listed voxel, 64 to a workgroup.
    const ShaderReflection inject = reflectFile("inject.comp");
    EXPECT_EQ(inject.stage, kCompute);
    auto in = [](uint32_t number, VkDescriptorType type) { return binding(0, number, type, kCompute); };
    expectBindings(inject.bindings, {
                                        in(glsl::FRAME_BINDING, kUniformBuffer),
                                        in(glsl::LIGHTS_BINDING, kStorageBuffer),
                                        in(glsl::SHADOW_VIEWS_BINDING, kStorageBuffer),
                                        in(glsl::SUN_SHADOW_MAPS_BINDING, kCombined),
                                        in(glsl::LOCAL_SHADOW_MAPS_BINDING, kCombined),
                                        in(glsl::VOXEL_ALBEDO_BINDING, kStorageImage),
                                        in(glsl::VOXEL_NORMAL_BINDING, kStorageImage),
                                        in(glsl::EMITTER_TRIANGLES_BINDING, kStorageBuffer),
                                        in(glsl::VOXEL_RADIANCE_BINDING, kStorageImage),
                                        in(glsl::GATHERED_LIGHT_BINDING, kStorageImage),
                                        in(glsl::OCCUPIED_VOXELS_BINDING, kStorageBuffer),
                                        in(glsl::OCCUPIED_LIST_BINDING, kStorageBuffer),
                                        in(glsl::VOXEL_EMISSION_BINDING, kStorageImage),
                                        in(glsl::AREA_SHADOW_MAPS_BINDING, kCombined),
                                        in(glsl::AREA_LIGHT_CACHE_BINDING, kStorageBuffer),
                                    });
    EXPECT_EQ(inject.pushConstantBytes, 4u);  // uint addGathered
    EXPECT_EQ(inject.localSize[0], 64u);
    EXPECT_EQ(inject.localSize[1], 1u);
    EXPECT_EQ(inject.localSize[2], 1u);
}

TEST(SpirvReflect, BounceGatherComputeShaderHasTheBindingsItsGlslDeclares) {
    // bounce_gather.comp.glsl: frame, albedo and normal, the gathered light it writes, the radiance
    // volume, the occupied-voxel list and its count, directional_voxels.glsl's three images, the
    // surface planes and the sky's image.
    const ShaderReflection gather = reflectFile("bounce_gather.comp");
    EXPECT_EQ(gather.stage, kCompute);
    auto in = [](uint32_t number, VkDescriptorType type, uint32_t count = 1) {
        return binding(0, number, type, kCompute, count);
    };
    expectBindings(gather.bindings, {
                                        in(glsl::FRAME_BINDING, kUniformBuffer),
                                        in(glsl::VOXEL_ALBEDO_BINDING, kStorageImage),
                                        in(glsl::VOXEL_NORMAL_BINDING, kStorageImage),
                                        in(glsl::GATHERED_LIGHT_BINDING, kStorageImage),
                                        in(glsl::VOXEL_RADIANCE_BINDING, kCombined),
                                        in(glsl::OCCUPIED_VOXELS_BINDING, kStorageBuffer),
                                        in(glsl::OCCUPIED_LIST_BINDING, kStorageBuffer),
                                        in(glsl::DIRECTIONAL_VOXELS_BINDING, kCombined, 3),
                                        in(glsl::SURFACE_PLANES_BINDING, kCombined),
                                        in(glsl::SKY_BINDING, kCombined),
                                    });
    EXPECT_EQ(gather.pushConstantBytes, 8u);  // uint sliceCount, slicePhase
    EXPECT_EQ(gather.localSize[0], 64u);
}

TEST(SpirvReflect, ShadeFragmentShaderHasTheBindingsItsGlslDeclares) {
    const ShaderReflection shade = reflectFile("shade.frag");
    EXPECT_EQ(shade.stage, kFragment);
    auto in = [](uint32_t number, VkDescriptorType type, uint32_t count = 1) {
        return binding(0, number, type, kFragment, count);
    };
    expectBindings(shade.bindings, {
                                       in(glsl::FRAME_BINDING, kUniformBuffer),
                                       in(glsl::MATERIALS_BINDING, kStorageBuffer),
                                       in(glsl::LIGHTS_BINDING, kStorageBuffer),
                                       in(glsl::SHADOW_VIEWS_BINDING, kStorageBuffer),
                                       in(glsl::EMITTER_TRIANGLES_BINDING, kStorageBuffer),  // the area lights'
                                       in(glsl::LTC_TABLE_BINDING, kStorageBuffer),          // their GGX table
                                       in(glsl::SUN_SHADOW_MAPS_BINDING, kCombined),
                                       in(glsl::LOCAL_SHADOW_MAPS_BINDING, kCombined),
                                       in(glsl::AREA_SHADOW_MAPS_BINDING, kCombined),
                                       in(glsl::SUN_SHADOW_DEPTHS_BINDING, kCombined),
                                       in(glsl::LOCAL_SHADOW_DEPTHS_BINDING, kCombined),
                                       in(glsl::AREA_SHADOW_DEPTHS_BINDING, kCombined),
                                       in(glsl::G_POSITION_BINDING, kCombined),
                                       in(glsl::G_NORMAL_BINDING, kCombined),
                                       in(glsl::G_BASE_COLOR_BINDING, kCombined),
                                       in(glsl::G_EMISSIVE_BINDING, kCombined),
                                       in(glsl::VOXEL_RADIANCE_BINDING, kCombined),
                                       in(glsl::VOXEL_ALBEDO_BINDING, kCombined),
                                       in(glsl::VOXEL_NORMAL_BINDING, kCombined),
                                       in(glsl::DIRECTIONAL_VOXELS_BINDING, kCombined, 3),
                                       in(glsl::SURFACE_PLANES_BINDING, kCombined),
                                       in(glsl::DIFFUSE_SAMPLES_BINDING, kCombined),  // the reduced diffuse cones
                                       in(glsl::SKY_BINDING, kCombined),
                                   });
    EXPECT_EQ(shade.pushConstantBytes, 0u);
}

// The structs C++ fills and the shaders read byte for byte: each member's offset in the SPIR-V
// (the std140 uniform block's, the std430 buffers') is its offsetof in C++, and no member is
// missing from either. A member added to one side only, or a vec3 followed by a vec3, fails here.
struct MemberOffset {
    const char* name;
    size_t offset;
};
#define MEMBER(type, member) \
    MemberOffset { #member, offsetof(glsl::type, member) }

void expectSameLayout(const ShaderReflection& shader, const std::string& structName,
                      const std::vector<MemberOffset>& cpp) {
    const auto found = shader.structLayouts.find(structName);
    ASSERT_NE(found, shader.structLayouts.end()) << structName << " is not among the shader's laid-out structs";
    const std::vector<ReflectedMember>& spirv = found->second;
    ASSERT_EQ(spirv.size(), cpp.size()) << structName << ": members in the SPIR-V against the C++ list";
    for (size_t i = 0; i < cpp.size(); ++i) {
        EXPECT_EQ(spirv[i].name, cpp[i].name) << structName << " member " << i;
        EXPECT_EQ(spirv[i].offset, cpp[i].offset) << structName << "::" << cpp[i].name;
    }
}

TEST(SpirvReflect, TheSharedStructsHaveTheirCppOffsetsInTheShaders) {
    const ShaderReflection shade = reflectFile("shade.frag");
    expectSameLayout(shade, "FrameConstants",
                     {
                         MEMBER(FrameConstants, viewProjection),
                         MEMBER(FrameConstants, inverseViewProjection),
                         MEMBER(FrameConstants, grid),
                         MEMBER(FrameConstants, cameraPosition),
                         MEMBER(FrameConstants, lightCount),
                         MEMBER(FrameConstants, shadowViewCount),
                         MEMBER(FrameConstants, componentFlags),
                         MEMBER(FrameConstants, diffuseRingTurn),
                         MEMBER(FrameConstants, debugView),
                         MEMBER(FrameConstants, renderSize),
                         MEMBER(FrameConstants, inverseRenderSize),
                         MEMBER(FrameConstants, ambientFactor),
                         MEMBER(FrameConstants, shadowNormalOffset),
                         MEMBER(FrameConstants, pcfRadius),
                         MEMBER(FrameConstants, radianceScale),
                         MEMBER(FrameConstants, coneTanHalfAperture),
                         MEMBER(FrameConstants, coneStep),
                         MEMBER(FrameConstants, coneMaxDistance),
                         MEMBER(FrameConstants, coneStartOffset),
                         MEMBER(FrameConstants, aoFalloff),
                         MEMBER(FrameConstants, coneStopOpacity),
                         MEMBER(FrameConstants, diffuseCentreWeight),
                         MEMBER(FrameConstants, diffuseConeCount),
                         MEMBER(FrameConstants, environmentTurns),
                         MEMBER(FrameConstants, debugVoxelMip),
                         MEMBER(FrameConstants, diffuseDownscale),
                         MEMBER(FrameConstants, firstAreaLight),
                         MEMBER(FrameConstants, environment),
                         MEMBER(FrameConstants, specularConeMaxTan),
                         MEMBER(FrameConstants, diffuseBeam),
                         MEMBER(FrameConstants, diffuseBeamAzimuth),
                         MEMBER(FrameConstants, unused0),
                     });
    expectSameLayout(shade, "VoxelGridParams",
                     {
                         MEMBER(VoxelGridParams, origin),
                         MEMBER(VoxelGridParams, voxelSize),
                         MEMBER(VoxelGridParams, resolution),
                         MEMBER(VoxelGridParams, mipLevels),
                         MEMBER(VoxelGridParams, triangleCount),
                         MEMBER(VoxelGridParams, workItems),
                     });
    expectSameLayout(shade, "GpuMaterial",
                     {
                         MEMBER(GpuMaterial, baseColorFactor),
                         MEMBER(GpuMaterial, emission),
                         MEMBER(GpuMaterial, voxelEmission),
                         MEMBER(GpuMaterial, metallic),
                         MEMBER(GpuMaterial, roughness),
                         MEMBER(GpuMaterial, specularWeight),
                         MEMBER(GpuMaterial, baseColorTexture),
                         MEMBER(GpuMaterial, emissiveTexture),
                         MEMBER(GpuMaterial, metallicRoughnessTexture),
                         MEMBER(GpuMaterial, normalTexture),
                         MEMBER(GpuMaterial, normalScale),
                         MEMBER(GpuMaterial, occlusionTexture),
                         MEMBER(GpuMaterial, occlusionStrength),
                         MEMBER(GpuMaterial, alphaMode),
                         MEMBER(GpuMaterial, alphaCutoff),
                         MEMBER(GpuMaterial, baseColorTransform),
                         MEMBER(GpuMaterial, emissiveTransform),
                         MEMBER(GpuMaterial, metallicRoughnessTransform),
                         MEMBER(GpuMaterial, normalTransform),
                         MEMBER(GpuMaterial, occlusionTransform),
                     });
    expectSameLayout(shade, "GpuTextureTransform",
                     {
                         MEMBER(GpuTextureTransform, rowU),
                         MEMBER(GpuTextureTransform, rowV),
                     });
    expectSameLayout(shade, "GpuLight",
                     {
                         MEMBER(GpuLight, radiantIntensity),
                         MEMBER(GpuLight, positionRange),
                         MEMBER(GpuLight, direction),
                         MEMBER(GpuLight, spotShadow),
                         MEMBER(GpuLight, cascades),
                     });
    expectSameLayout(reflectFile("gbuffer.vert"), "GpuVertex",
                     {MEMBER(GpuVertex, positionU), MEMBER(GpuVertex, normalV), MEMBER(GpuVertex, texCoord1),
                      MEMBER(GpuVertex, tangent)});
    EXPECT_EQ(sizeof(glsl::FrameConstants) % 16, 0u) << "a std140 struct's size is a multiple of 16";
    EXPECT_EQ(sizeof(glsl::GpuMaterial) % 16, 0u) << "the std430 array stride of a struct with vec4s";
}
#undef MEMBER

TEST(SpirvReflect, VertexShadersAreVertexStage) {
    const ShaderReflection gbuffer = reflectFile("gbuffer.vert");
    EXPECT_EQ(gbuffer.stage, kVertex);
    expectBindings(gbuffer.bindings, {binding(0, glsl::FRAME_BINDING, kUniformBuffer, kVertex),
                                      binding(0, glsl::VERTICES_BINDING, kStorageBuffer, kVertex)});
    const ShaderReflection fullscreen = reflectFile("fullscreen.vert");
    EXPECT_EQ(fullscreen.stage, kVertex);
    EXPECT_TRUE(fullscreen.bindings.empty());
}

TEST(SpirvReflect, PushConstantBytesEndAtTheLastMember) {
    // voxelize.comp's push constants are the VoxelizeParams that C++ fills from the same header.
    EXPECT_EQ(reflectFile("voxelize.comp").pushConstantBytes, sizeof(glsl::VoxelizeParams));
    EXPECT_EQ(reflectFile("voxel_resolve.comp").pushConstantBytes, sizeof(glsl::VoxelizeParams));
    // The viewer's present pass: structs C++ fills from the same header (present.h).
    EXPECT_EQ(reflectFile("tonemap.frag").pushConstantBytes, sizeof(glsl::TonemapPush));
    EXPECT_EQ(reflectFile("grid_bounds.vert").pushConstantBytes, sizeof(glsl::GridBoundsPush));
    EXPECT_EQ(reflectFile("mips.comp").pushConstantBytes, 0u);
}

TEST(SpirvReflect, LocalSizeComesFromTheComputeShader) {
    const ShaderReflection probe = reflectFile("cone_probe.comp");  // local_size_x = 64
    EXPECT_EQ(probe.localSize[0], 64u);
    EXPECT_EQ(probe.localSize[1], 1u);
    EXPECT_EQ(probe.localSize[2], 1u);
    const ShaderReflection resolve = reflectFile("resolve.comp");  // 8 × 8
    EXPECT_EQ(resolve.localSize[0], 8u);
    EXPECT_EQ(resolve.localSize[1], 8u);
    EXPECT_EQ(resolve.localSize[2], 1u);
}

TEST(SpirvReflect, ArrayOfStorageBuffersIsOneBindingOfThatCount) {
    // voxel_resolve.comp: buffer Accumulation { uint values[]; } accumulation[ACCUM_CHANNELS].
    const ShaderReflection resolve = reflectFile("voxel_resolve.comp");
    const auto accumulation =
        std::find_if(resolve.bindings.begin(), resolve.bindings.end(),
                     [](const ReflectedBinding& b) { return b.binding == glsl::VOXEL_ACCUMULATION_BINDING; });
    ASSERT_NE(accumulation, resolve.bindings.end());
    EXPECT_EQ(accumulation->type, kStorageBuffer);
    EXPECT_EQ(accumulation->count, glsl::ACCUM_CHANNELS);
    EXPECT_FALSE(accumulation->countSpecId.has_value());
}

TEST(SpirvReflect, ArraySizedBySpecializationConstantSaysWhichOne) {
    // gbuffer.frag: layout(constant_id = TEXTURE_COUNT_CONSTANT_ID) const uint TEXTURE_COUNT = 1; sampler2D
    // colorTextures[TEXTURE_COUNT] in set 1. The layout must use the specialized count, so the reflection names
    // the constant.
    const ShaderReflection gbuffer = reflectFile("gbuffer.frag");
    ASSERT_EQ(gbuffer.bindings.size(), 3u);
    const ReflectedBinding& textures = gbuffer.bindings[2];
    EXPECT_EQ(textures.set, glsl::TEXTURES_SET);
    EXPECT_EQ(textures.binding, glsl::COLOR_TEXTURES_BINDING);
    EXPECT_EQ(textures.type, kCombined);
    EXPECT_EQ(textures.count, 1u);  // the constant's default
    ASSERT_TRUE(textures.countSpecId.has_value());
    EXPECT_EQ(*textures.countSpecId, glsl::TEXTURE_COUNT_CONSTANT_ID);
}

TEST(SpirvReflect, EveryDescriptorKindMapsToItsVulkanType) {
    const ShaderReflection shader = reflectShader(kEveryKind, "every_kind.comp");
    expectBindings(
        shader.bindings,
        {binding(0, 0, kUniformBuffer, kCompute), binding(0, 1, kStorageBuffer, kCompute),
         binding(0, 2, kStorageImage, kCompute), binding(0, 3, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, kCompute),
         binding(0, 4, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, kCompute),
         binding(0, 5, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, kCompute), binding(0, 6, VK_DESCRIPTOR_TYPE_SAMPLER, kCompute),
         binding(0, 12, kCombined, kCompute, 6),  // sampler3D volumes[6]
         binding(1, 3, kCombined, kCompute),      // declared, never read: still there
         binding(2, 0, kUniformBuffer, kCompute, 4)});
}

TEST(SpirvReflect, PushConstantSizeFollowsStridesAndRowMajorMatrices) {
    // mat4 at 0 (4 columns × stride 16), float[3] at 64 (stride 4), vec3 at 80, row_major mat2x3 at 96
    // (3 rows × stride 8): it ends at 120.
    EXPECT_EQ(reflectShader(kEveryKind, "every_kind.comp").pushConstantBytes, 120u);
}

TEST(SpirvReflect, LocalSizeFromLiteralsOrConstantIds) {
    const ShaderReflection spirv16 = reflectShader(kEveryKind, "every_kind.comp");  // OpExecutionModeId LocalSizeId
    EXPECT_EQ(spirv16.localSize[0], 8u);
    EXPECT_EQ(spirv16.localSize[1], 4u);
    EXPECT_EQ(spirv16.localSize[2], 2u);
    const ShaderReflection spirv10 = reflectShader(kSpirv10Buffer, "buffer_block.comp");  // OpExecutionMode LocalSize
    EXPECT_EQ(spirv10.localSize[0], 16u);
    EXPECT_EQ(spirv10.localSize[1], 1u);
    EXPECT_EQ(spirv10.localSize[2], 1u);
}

TEST(SpirvReflect, Spirv10BufferBlockIsAStorageBuffer) {
    // Before SPIR-V 1.3 a storage buffer is a Uniform variable whose struct is decorated BufferBlock.
    expectBindings(reflectShader(kSpirv10Buffer, "buffer_block.comp").bindings,
                   {binding(0, 1, kStorageBuffer, kCompute)});
}

TEST(SpirvReflect, RuntimeSizedDescriptorArrayIsRefused) {
    const std::string message = reflectionError(kRuntimeArray, "bindless.frag");
    EXPECT_TRUE(contains(message, "bindless.frag")) << message;
    EXPECT_TRUE(contains(message, "runtime-sized array")) << message;
    EXPECT_TRUE(contains(message, "set 0 binding 0")) << message;
}

TEST(SpirvReflect, MalformedWordsAreErrorsNamingTheShader) {
    struct Case {
        const char* what;
        std::vector<uint32_t> words;
        const char* problem;
    };
    std::vector<uint32_t> wrongMagic = kSpirv10Buffer;
    wrongMagic[0] = 0x03022307u;  // the magic number byte-swapped
    std::vector<uint32_t> truncated = kSpirv10Buffer;
    truncated.insert(truncated.end(), {(4u << 16) | 71u, 14u, 33u});  // an OpDecorate of 4 words with 3 left
    std::vector<uint32_t> zeroWordCount = kSpirv10Buffer;
    zeroWordCount.insert(zeroWordCount.begin() + 5, 0u);
    std::vector<uint32_t> smallBound = kSpirv10Buffer;
    smallBound[3] = 3;  // ids 3 and up are out of bound; the module uses ids up to 18
    const Case cases[] = {
        {"empty", {}, "too short"},
        {"header only", std::vector<uint32_t>(kSpirv10Buffer.begin(), kSpirv10Buffer.begin() + 4), "too short"},
        {"wrong magic", wrongMagic, "wrong magic"},
        {"truncated last instruction", truncated, "truncated"},
        {"word count 0", zeroWordCount, "word count 0"},
        {"id out of bound", smallBound, "out of the bound 3"},
    };
    for (const Case& c : cases) {
        const std::string message = reflectionError(c.words, "broken.comp");
        EXPECT_TRUE(contains(message, "broken.comp")) << c.what << ": " << message;
        EXPECT_TRUE(contains(message, c.problem)) << c.what << ": " << message;
    }
}

TEST(SpirvReflect, MergedStagesOrTheirStageFlags) {
    // gbuffer: the frame uniform buffer is read by both stages; vertices only by the vertex shader, materials
    // and textures only by the fragment shader, whose material index is the only push constant.
    const ShaderReflection pipeline =
        mergeStages({reflectFile("gbuffer.vert"), reflectFile("gbuffer.frag")}, "gbuffer pipeline");
    EXPECT_EQ(pipeline.stage, kVertex | kFragment);
    expectBindings(pipeline.bindings,
                   {binding(0, glsl::FRAME_BINDING, kUniformBuffer, kVertex | kFragment),
                    binding(0, glsl::VERTICES_BINDING, kStorageBuffer, kVertex),
                    binding(0, glsl::MATERIALS_BINDING, kStorageBuffer, kFragment),
                    binding(glsl::TEXTURES_SET, glsl::COLOR_TEXTURES_BINDING, kCombined, kFragment)});
    EXPECT_EQ(pipeline.pushConstantBytes, 4u);

    // The lighting pass: a vertex shader without descriptors and shade.frag's.
    const ShaderReflection shade = reflectFile("shade.frag");
    const ShaderReflection lighting = mergeStages({reflectFile("fullscreen.vert"), shade}, "lighting pipeline");
    EXPECT_EQ(lighting.stage, kVertex | kFragment);
    expectBindings(lighting.bindings, shade.bindings);
}

TEST(SpirvReflect, MergedStagesMustAgreeOnEachBinding) {
    ShaderReflection vertex;
    vertex.stage = kVertex;
    vertex.bindings = {binding(0, 3, kUniformBuffer, kVertex)};
    ShaderReflection fragment;
    fragment.stage = kFragment;
    fragment.bindings = {binding(0, 3, kStorageBuffer, kFragment)};
    try {
        mergeStages({vertex, fragment}, "debug pipeline");
        ADD_FAILURE() << "a uniform buffer and a storage buffer at one binding were merged";
    } catch (const Error& error) {
        const std::string message = error.what();
        EXPECT_TRUE(contains(message, "debug pipeline")) << message;
        EXPECT_TRUE(contains(message, "set 0 binding 3")) << message;
        EXPECT_TRUE(contains(message, "uniform buffer in the vertex stage")) << message;
        EXPECT_TRUE(contains(message, "storage buffer in the fragment stage")) << message;
    }
    fragment.bindings = {binding(0, 3, kUniformBuffer, kFragment, 2)};  // same type, another count
    EXPECT_THROW(mergeStages({vertex, fragment}, "debug pipeline"), Error);
}

}  // namespace
}  // namespace vct
