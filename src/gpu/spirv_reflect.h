// The descriptor bindings, push-constant size and workgroup size of a shader, read from its SPIR-V
// words (the way zeux/niagara's shaders.cpp parses decorations), so that pipeline code can build its
// descriptor set layouts from the shaders instead of from hand-written lists that drift from the GLSL.
// Only Vulkan's enums are used: no device is needed, and the CPU tests link it.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vct {

struct ReflectedBinding {
    uint32_t set = 0;
    uint32_t binding = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
    uint32_t count = 1;  // array size (1 for a non-array)
    // Set when the array size is a specialization constant (layout(constant_id = N)): count is then its
    // default, and a pipeline that specializes it must use its own value for the layout.
    std::optional<uint32_t> countSpecId;
    VkShaderStageFlags stages = 0;
};

// A member of a struct with an explicit layout (a uniform or storage block's, or a struct inside
// one): its name from the module's debug names (OpMemberName) and its byte offset.
struct ReflectedMember {
    std::string name;
    uint32_t offset = 0;
};

struct ShaderReflection {
    VkShaderStageFlags stage = 0;            // from the OpEntryPoint execution models
    std::vector<ReflectedBinding> bindings;  // sorted by (set, binding)
    // The laid-out structs by their names (OpName), members in declaration order: what the C++
    // mirror of a shared struct is checked against. Empty where the module has no debug names.
    std::map<std::string, std::vector<ReflectedMember>> structLayouts;
    uint32_t pushConstantBytes = 0;     // end of the last push-constant member (offset + size); 0 if none
    uint32_t localSize[3] = {1, 1, 1};  // compute: OpExecutionMode LocalSize or LocalSizeId
};

// "storage image", "uniform buffer", …: for error messages.
const char* descriptorTypeName(VkDescriptorType type);

// Reflects every descriptor variable the module declares (glslang keeps unused ones too). `name` is used
// only in error messages. Malformed SPIR-V (wrong magic, a truncated instruction, word count 0, an id out
// of bound) and descriptors this renderer does not use (runtime arrays, acceleration structures, ...)
// throw vct::Error naming the shader and the problem.
ShaderReflection reflectShader(const std::vector<uint32_t>& words, const std::string& name);

// The bindings of several stages of one pipeline: the same (set, binding) must agree on type and count
// (else vct::Error naming the pipeline and both stages); stage flags are OR-ed, push-constant bytes the max.
ShaderReflection mergeStages(const std::vector<ShaderReflection>& stages, const std::string& pipelineName);

}  // namespace vct
