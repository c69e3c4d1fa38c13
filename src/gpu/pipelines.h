// Shader modules loaded from spirv/, pipelines, and push-descriptor set layouts.
#pragma once

#include <vulkan/vulkan.h>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "gpu/context.h"
#include "gpu/spirv_reflect.h"

namespace vct {

// The folder holding the compiled shaders: $VCT_SPIRV_DIR, else spirv/ beside the build folder
// of the executable, else the source tree's spirv/.
std::string spirvDirectory();

// A shader's SPIR-V, read once: its layout is reflected from it and its module made from it.
struct ShaderCode {
    std::string name;  // e.g. "gbuffer.frag", for errors
    std::vector<uint32_t> words;
};

// Reads spirv/NAME.spv (e.g. "gbuffer.frag"); a missing or malformed file is a vct::Error.
ShaderCode loadShader(const std::string& name);
VkShaderModule createShaderModule(GpuContext& context, const ShaderCode& code);

// Bindings come from the shaders' SPIR-V (gpu/spirv_reflect.h), never from a list in C++: set 0
// is a push-descriptor set holding every binding the stages declare, sets 1, 2, … are
// `laterSets` (owned by the caller, e.g. the scene's texture array), and one push-constant range
// covers the stages' push-constant blocks.
struct ShaderLayout {
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;  // set 0
    std::string name;                                  // the shaders', "a.vert + a.frag"
    std::vector<ReflectedBinding> setZero;             // set 0's bindings, as the shaders declare them
};
ShaderLayout createShaderLayout(GpuContext& context, const std::vector<ShaderCode>& stages,
                                const std::vector<VkDescriptorSetLayout>& laterSets = {});

struct GraphicsPipelineDesc {
    std::string vertexShader;
    std::string fragmentShader;  // empty = depth only
    std::vector<VkFormat> colorFormats;
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;
    bool depthTest = false;
    VkCullModeFlags cullMode = VK_CULL_MODE_NONE;
    bool dynamicCullMode = false;  // set per draw with vkCmdSetCullMode instead (core in Vulkan 1.3)
    // The fragment shader's specialization constants: element i is constant_id i (a uint, or a
    // bool as VkBool32); empty leaves the shader's defaults.
    std::vector<uint32_t> fragmentSpecialization;
};

// Collects descriptor writes for one vkCmdPushDescriptorSetKHR call.
class Pipeline;

class DescriptorPush {
public:
    DescriptorPush& buffer(uint32_t binding, VkBuffer buffer,
                           VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    DescriptorPush& storageImage(uint32_t binding, VkImageView view);
    DescriptorPush& sampledImage(uint32_t binding, VkImageView view, VkSampler sampler,
                                 VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    // Array bindings: element i of `binding` gets item i.
    DescriptorPush& buffers(uint32_t binding, const std::vector<VkBuffer>& buffers);
    DescriptorPush& storageImages(uint32_t binding, const std::vector<VkImageView>& views);
    DescriptorPush& sampledImages(uint32_t binding, const std::vector<VkImageView>& views, VkSampler sampler,
                                  VkImageLayout layout);
    // Each write is checked against the bindings the pipeline's shaders declare (its slot, type and
    // array size): a mismatch throws an Error naming the shaders and the binding, where the
    // validation layer would report it only when enabled, and the driver might read garbage.
    void push(GpuContext& context, VkCommandBuffer commands, VkPipelineBindPoint bindPoint, const Pipeline& pipeline);

private:
    VkWriteDescriptorSet& addWrite(uint32_t binding, VkDescriptorType type, uint32_t count);
    // Stable addresses: the writes point into these until push().
    std::vector<VkDescriptorBufferInfo> buffers_ = std::vector<VkDescriptorBufferInfo>(32);
    std::vector<VkDescriptorImageInfo> images_ = std::vector<VkDescriptorImageInfo>(32);
    std::vector<VkWriteDescriptorSet> writes_;
    size_t bufferCount_ = 0, imageCount_ = 0;
};

}  // namespace vct

namespace vct {

// A pipeline with its layout and (push-descriptor) set layout, destroyed together.
class Pipeline {
public:
    Pipeline() = default;
    // Takes ownership of `shaderLayout`'s layouts.
    Pipeline(GpuContext& context, VkPipeline createdPipeline, const ShaderLayout& shaderLayout)
        : pipeline(createdPipeline),
          layout(shaderLayout.layout),
          setLayout(shaderLayout.setLayout),
          name(shaderLayout.name),
          setZero(shaderLayout.setZero),
          device_(context.device) {}
    ~Pipeline();
    Pipeline(Pipeline&& other) noexcept { *this = std::move(other); }
    Pipeline& operator=(Pipeline&& other) noexcept;

    VkPipeline pipeline = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    std::string name;                       // its shaders', for errors
    std::vector<ReflectedBinding> setZero;  // the bindings its shaders declare in set 0

private:
    VkDevice device_ = VK_NULL_HANDLE;
};

// Specialization constants named by id (shaders_glsl/bindings.h) as the pipelines take them:
// element i is constant_id i (a uint, or a bool as VkBool32); ids not named are 0.
std::vector<uint32_t> specializationConstants(std::initializer_list<std::pair<uint32_t, uint32_t>> byId);

// A compute pipeline with its layout read from the shader (createShaderLayout), `laterSets` as its
// sets 1, 2, … and `specialization` its constants (element i is constant_id i, a uint or VkBool32).
Pipeline createComputePipeline(GpuContext& context, const std::string& shaderName,
                               const std::vector<VkDescriptorSetLayout>& laterSets = {},
                               const std::vector<uint32_t>& specialization = {});
// A graphics pipeline for dynamic rendering, with dynamic viewport and scissor, and its layout read
// from its shaders.
Pipeline createGraphicsPipeline(GpuContext& context, const GraphicsPipelineDesc& desc,
                                const std::vector<VkDescriptorSetLayout>& laterSets = {});

// A sampler destroyed with its owner.
class Sampler {
public:
    Sampler() = default;
    Sampler(GpuContext& context, const VkSamplerCreateInfo& info);
    ~Sampler();
    Sampler(Sampler&& other) noexcept { *this = std::move(other); }
    Sampler& operator=(Sampler&& other) noexcept;
    VkSampler sampler = VK_NULL_HANDLE;

private:
    VkDevice device_ = VK_NULL_HANDLE;
};

VkSamplerCreateInfo nearestClampSampler();
VkSamplerCreateInfo linearClampSampler();
// Trilinear, transparent black outside: for voxel volumes, where outside the grid is empty space.
VkSamplerCreateInfo volumeSampler();

}  // namespace vct
