#include "gpu/pipelines.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "gpu/spirv_reflect.h"
#include "gpu/vk_check.h"

namespace vct {

std::string spirvDirectory() {
    if (const char* fromEnvironment = std::getenv("VCT_SPIRV_DIR")) return fromEnvironment;
    std::error_code error;
    const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error) {
        for (std::filesystem::path folder = executable.parent_path(); !folder.empty() && folder != folder.root_path();
             folder = folder.parent_path()) {
            if (std::filesystem::exists(folder / "spirv" / "gbuffer.vert.spv")) return (folder / "spirv").string();
        }
    }
    return std::string(VCT_SOURCE_DIR) + "/spirv";
}

ShaderCode loadShader(const std::string& name) {
    const std::string path = spirvDirectory() + "/" + name + ".spv";
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    if (!file) throw Error("cannot open the shader '" + path + "' (set VCT_SPIRV_DIR to the spirv/ folder)");
    const std::streamsize size = file.tellg();
    if (size <= 0 || size % 4 != 0) throw Error("the shader '" + path + "' is not SPIR-V");
    std::vector<uint32_t> code(size_t(size) / 4);
    file.seekg(0);
    file.read(reinterpret_cast<char*>(code.data()), size);
    if (!file || code[0] != 0x07230203u) throw Error("the shader '" + path + "' is not SPIR-V");
    return {name, std::move(code)};
}

VkShaderModule createShaderModule(GpuContext& context, const ShaderCode& code) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = code.words.size() * sizeof(uint32_t);
    info.pCode = code.words.data();
    VkShaderModule module = VK_NULL_HANDLE;
    VK_CHECK(vkCreateShaderModule(context.device, &info, nullptr, &module));
    return module;
}

ShaderLayout createShaderLayout(GpuContext& context, const std::vector<ShaderCode>& stageCode,
                                const std::vector<VkDescriptorSetLayout>& laterSets) {
    std::vector<ShaderReflection> stages;
    std::string pipelineName;
    for (const ShaderCode& code : stageCode) {
        stages.push_back(reflectShader(code.words, code.name));
        pipelineName += (pipelineName.empty() ? "" : " + ") + code.name;
    }
    const ShaderReflection merged = mergeStages(stages, pipelineName);
    ShaderLayout result;
    result.name = pipelineName;
    std::vector<VkDescriptorSetLayoutBinding> setZero;
    for (const ReflectedBinding& binding : merged.bindings) {
        if (binding.set > laterSets.size())
            throw Error(pipelineName + ": uses descriptor set " + std::to_string(binding.set) + " but only " +
                        std::to_string(laterSets.size() + 1) + " set layouts were given");
        if (binding.set != 0) continue;
        if (binding.countSpecId)
            throw Error(pipelineName + ": set 0 binding " + std::to_string(binding.binding) +
                        " is sized by a specialization constant, which a push-descriptor set cannot follow");
        setZero.push_back({binding.binding, binding.type, binding.count, binding.stages, nullptr});
        result.setZero.push_back(binding);
    }
    VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setInfo.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
    setInfo.bindingCount = uint32_t(setZero.size());
    setInfo.pBindings = setZero.data();
    VK_CHECK(vkCreateDescriptorSetLayout(context.device, &setInfo, nullptr, &result.setLayout));

    std::vector<VkDescriptorSetLayout> sets = {result.setLayout};
    sets.insert(sets.end(), laterSets.begin(), laterSets.end());
    // One range for every stage: the passes push with VK_SHADER_STAGE_ALL.
    const VkPushConstantRange range{VK_SHADER_STAGE_ALL, 0, merged.pushConstantBytes};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = uint32_t(sets.size());
    info.pSetLayouts = sets.data();
    info.pushConstantRangeCount = merged.pushConstantBytes > 0 ? 1 : 0;
    info.pPushConstantRanges = &range;
    const VkResult created = vkCreatePipelineLayout(context.device, &info, nullptr, &result.layout);
    if (created != VK_SUCCESS) vkDestroyDescriptorSetLayout(context.device, result.setLayout, nullptr);
    VK_CHECK(created);
    return result;
}

namespace {

// Entry i of `values` as constant_id i; `values` must outlive it.
struct Specialization {
    explicit Specialization(const std::vector<uint32_t>& values) {
        for (uint32_t id = 0; id < values.size(); ++id)
            entries.push_back({id, id * uint32_t(sizeof(uint32_t)), sizeof(uint32_t)});
        info = {uint32_t(entries.size()), entries.data(), values.size() * sizeof(uint32_t), values.data()};
    }
    const VkSpecializationInfo* get() const { return entries.empty() ? nullptr : &info; }
    Specialization(const Specialization&) = delete;
    Specialization& operator=(const Specialization&) = delete;
    std::vector<VkSpecializationMapEntry> entries;
    VkSpecializationInfo info{};
};

}  // namespace

Pipeline createComputePipeline(GpuContext& context, const std::string& shaderName,
                               const std::vector<VkDescriptorSetLayout>& laterSets,
                               const std::vector<uint32_t>& specialization) {
    const ShaderCode code = loadShader(shaderName);
    const ShaderLayout layout = createShaderLayout(context, {code}, laterSets);
    VkShaderModule module = createShaderModule(context, code);
    const Specialization constants(specialization);
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module;
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = constants.get();
    info.layout = layout.layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    const VkResult result = vkCreateComputePipelines(context.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
    vkDestroyShaderModule(context.device, module, nullptr);
    Pipeline owned(context, pipeline, layout);  // frees the layouts if the check throws
    VK_CHECK(result);
    return owned;
}

// `code` holds the vertex shader, then the fragment shader if there is one.
static VkPipeline createGraphicsPipeline(GpuContext& context, VkPipelineLayout layout, const GraphicsPipelineDesc& desc,
                                         const std::vector<ShaderCode>& code) {
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    std::vector<VkShaderModule> modules;
    auto addStage = [&](VkShaderStageFlagBits stage, const ShaderCode& stageCode) {
        modules.push_back(createShaderModule(context, stageCode));
        VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        info.stage = stage;
        info.module = modules.back();
        info.pName = "main";
        stages.push_back(info);
    };
    addStage(VK_SHADER_STAGE_VERTEX_BIT, code[0]);
    if (code.size() > 1) addStage(VK_SHADER_STAGE_FRAGMENT_BIT, code[1]);
    const Specialization constants(desc.fragmentSpecialization);
    if (stages.size() > 1) stages[1].pSpecializationInfo = constants.get();

    // Vertices are pulled from storage buffers by gl_VertexIndex: no vertex input state.
    VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    VkPipelineInputAssemblyStateCreateInfo inputAssembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    inputAssembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = desc.cullMode;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth.depthTestEnable = desc.depthTest;
    depth.depthWriteEnable = desc.depthTest;
    depth.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    std::vector<VkPipelineColorBlendAttachmentState> blends(desc.colorFormats.size());
    for (auto& blend : blends)
        blend.colorWriteMask =
            VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = uint32_t(blends.size());
    blend.pAttachments = blends.data();
    std::vector<VkDynamicState> dynamicStates = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    if (desc.dynamicCullMode) dynamicStates.push_back(VK_DYNAMIC_STATE_CULL_MODE);
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = uint32_t(dynamicStates.size());
    dynamic.pDynamicStates = dynamicStates.data();
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = uint32_t(desc.colorFormats.size());
    rendering.pColorAttachmentFormats = desc.colorFormats.data();
    rendering.depthAttachmentFormat = desc.depthFormat;

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, &rendering};
    info.stageCount = uint32_t(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &vertexInput;
    info.pInputAssemblyState = &inputAssembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
    info.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    const VkResult result = vkCreateGraphicsPipelines(context.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
    for (VkShaderModule module : modules) vkDestroyShaderModule(context.device, module, nullptr);
    VK_CHECK(result);
    return pipeline;
}

Pipeline createGraphicsPipeline(GpuContext& context, const GraphicsPipelineDesc& desc,
                                const std::vector<VkDescriptorSetLayout>& laterSets) {
    std::vector<ShaderCode> code = {loadShader(desc.vertexShader)};
    if (!desc.fragmentShader.empty()) code.push_back(loadShader(desc.fragmentShader));
    const ShaderLayout layout = createShaderLayout(context, code, laterSets);
    Pipeline owned(context, VK_NULL_HANDLE, layout);  // frees the layouts on a throw
    owned.pipeline = createGraphicsPipeline(context, layout.layout, desc, code);
    return owned;
}

VkWriteDescriptorSet& DescriptorPush::addWrite(uint32_t binding, VkDescriptorType type, uint32_t count) {
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstBinding = binding;
    write.descriptorCount = count;
    write.descriptorType = type;
    writes_.push_back(write);
    return writes_.back();
}

DescriptorPush& DescriptorPush::buffer(uint32_t binding, VkBuffer buffer, VkDescriptorType type) {
    buffers_.at(bufferCount_) = {buffer, 0, VK_WHOLE_SIZE};
    addWrite(binding, type, 1).pBufferInfo = &buffers_[bufferCount_++];
    return *this;
}

DescriptorPush& DescriptorPush::buffers(uint32_t binding, const std::vector<VkBuffer>& elements) {
    const size_t first = bufferCount_;
    for (VkBuffer element : elements) buffers_.at(bufferCount_++) = {element, 0, VK_WHOLE_SIZE};
    addWrite(binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, uint32_t(elements.size())).pBufferInfo = &buffers_[first];
    return *this;
}

DescriptorPush& DescriptorPush::storageImage(uint32_t binding, VkImageView view) {
    images_.at(imageCount_) = {VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL};
    addWrite(binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1).pImageInfo = &images_[imageCount_++];
    return *this;
}

DescriptorPush& DescriptorPush::storageImages(uint32_t binding, const std::vector<VkImageView>& views) {
    const size_t first = imageCount_;
    for (VkImageView view : views) images_.at(imageCount_++) = {VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL};
    addWrite(binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, uint32_t(views.size())).pImageInfo = &images_[first];
    return *this;
}

DescriptorPush& DescriptorPush::sampledImage(uint32_t binding, VkImageView view, VkSampler sampler,
                                             VkImageLayout layout) {
    images_.at(imageCount_) = {sampler, view, layout};
    addWrite(binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1).pImageInfo = &images_[imageCount_++];
    return *this;
}

DescriptorPush& DescriptorPush::sampledImages(uint32_t binding, const std::vector<VkImageView>& views,
                                              VkSampler sampler, VkImageLayout layout) {
    const size_t first = imageCount_;
    for (VkImageView view : views) images_.at(imageCount_++) = {sampler, view, layout};
    addWrite(binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, uint32_t(views.size())).pImageInfo = &images_[first];
    return *this;
}

namespace {

// The write's slot, type and array elements are among what the shaders declare.
void checkWrite(const VkWriteDescriptorSet& write, const Pipeline& pipeline) {
    const std::string where = pipeline.name + ": binding " + std::to_string(write.dstBinding);
    auto declared = std::find_if(pipeline.setZero.begin(), pipeline.setZero.end(),
                                 [&](const ReflectedBinding& b) { return b.binding == write.dstBinding; });
    if (declared == pipeline.setZero.end())
        throw Error(where + " is written as a " + descriptorTypeName(write.descriptorType) +
                    ", but its shaders declare no such binding");
    if (declared->type != write.descriptorType)
        throw Error(where + " is a " + descriptorTypeName(declared->type) + " in its shaders, written as a " +
                    descriptorTypeName(write.descriptorType));
    if (write.dstArrayElement + write.descriptorCount > declared->count)
        throw Error(where + " holds " + std::to_string(declared->count) + " descriptor(s), written with " +
                    std::to_string(write.dstArrayElement + write.descriptorCount));
}

}  // namespace

void DescriptorPush::push(GpuContext& context, VkCommandBuffer commands, VkPipelineBindPoint bindPoint,
                          const Pipeline& pipeline) {
    for (const VkWriteDescriptorSet& write : writes_) checkWrite(write, pipeline);
    context.cmdPushDescriptorSet(commands, bindPoint, pipeline.layout, 0, uint32_t(writes_.size()), writes_.data());
}

}  // namespace vct

namespace vct {

Pipeline::~Pipeline() {
    if (!device_) return;
    vkDestroyPipeline(device_, pipeline, nullptr);
    vkDestroyPipelineLayout(device_, layout, nullptr);
    vkDestroyDescriptorSetLayout(device_, setLayout, nullptr);
}

Pipeline& Pipeline::operator=(Pipeline&& other) noexcept {
    std::swap(pipeline, other.pipeline);
    std::swap(layout, other.layout);
    std::swap(setLayout, other.setLayout);
    std::swap(name, other.name);
    std::swap(setZero, other.setZero);
    std::swap(device_, other.device_);
    return *this;
}

Sampler::Sampler(GpuContext& context, const VkSamplerCreateInfo& info) : device_(context.device) {
    VK_CHECK(vkCreateSampler(device_, &info, nullptr, &sampler));
}

Sampler::~Sampler() {
    if (device_) vkDestroySampler(device_, sampler, nullptr);
}

Sampler& Sampler::operator=(Sampler&& other) noexcept {
    std::swap(sampler, other.sampler);
    std::swap(device_, other.device_);
    return *this;
}

VkSamplerCreateInfo nearestClampSampler() {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = VK_FILTER_NEAREST;
    info.minFilter = VK_FILTER_NEAREST;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.maxLod = VK_LOD_CLAMP_NONE;
    return info;
}

VkSamplerCreateInfo linearClampSampler() {
    VkSamplerCreateInfo info = nearestClampSampler();
    info.magFilter = VK_FILTER_LINEAR;
    info.minFilter = VK_FILTER_LINEAR;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
    return info;
}

VkSamplerCreateInfo volumeSampler() {
    VkSamplerCreateInfo info = linearClampSampler();
    info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
    info.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
    return info;
}

std::vector<uint32_t> specializationConstants(std::initializer_list<std::pair<uint32_t, uint32_t>> byId) {
    std::vector<uint32_t> constants;
    for (const auto& [id, value] : byId) {
        if (id >= constants.size()) constants.resize(id + 1, 0u);
        constants[id] = value;
    }
    return constants;
}

}  // namespace vct
