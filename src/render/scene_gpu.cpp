#include "render/scene_gpu.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <numeric>
#include <string>
#include <tuple>

#include "alpha_coverage.h"
#include "bindings.h"
#include "error.h"
#include "gpu/commands.h"
#include "gpu/vk_check.h"
#include "gpu_types.h"
#include "render/texture_upload.h"
#include "scene/material_textures.h"
#include "scene/scene_limits.h"

namespace vct {
namespace {

static_assert(sizeof(Vertex) == sizeof(glsl::GpuVertex), "Vertex must match GpuVertex");
static_assert(uint32_t(AlphaMode::Opaque) == glsl::ALPHA_OPAQUE && uint32_t(AlphaMode::Mask) == glsl::ALPHA_MASK &&
                  uint32_t(AlphaMode::Blend) == glsl::ALPHA_BLEND,
              "AlphaMode must match GpuMaterial::alphaMode");

// Storage buffers are never empty (Vulkan forbids it) and hold at least one element.
template <typename T>
Buffer uploadArray(GpuContext& context, const std::vector<T>& values, VkBufferUsageFlags usage) {
    std::vector<T> padded = values;
    if (padded.empty()) padded.resize(1);
    return uploadBuffer(context, padded.data(), padded.size() * sizeof(T), usage);
}

VkSamplerAddressMode addressMode(TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::ClampToEdge: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        case TextureWrap::MirroredRepeat: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
        case TextureWrap::Repeat: break;
    }
    return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Every texture transform's numbers are finite.
bool finiteMapping(const Material& material) {
    for (const TextureReference* texture :
         {&material.baseColorTexture, &material.emissiveTexture, &material.metallicRoughnessTexture,
          &material.normalTexture, &material.occlusionTexture})
        if (!finite(glm::vec3(texture->offset, texture->rotation)) || !std::isfinite(texture->scale.x) ||
            !std::isfinite(texture->scale.y))
            return false;
    return true;
}

}  // namespace

void checkSceneCanBeRendered(const Scene& scene) {
    const auto fail = [&](const std::string& problem) { throw Error("scene '" + scene.name + "': " + problem); };
    for (size_t i = 0; i < scene.vertices.size(); ++i) {
        const Vertex& vertex = scene.vertices[i];
        if (!finite(vertex.position) || !finite(vertex.normal) || !std::isfinite(vertex.u) ||
            !std::isfinite(vertex.v) || !std::isfinite(vertex.uv1.x) || !std::isfinite(vertex.uv1.y) ||
            !finite(glm::vec3(vertex.tangent)) || !std::isfinite(vertex.tangent.w))
            fail("vertex " + std::to_string(i) + " holds a value that is not a finite number");
    }
    if (scene.indices.size() % 3 != 0) fail("the index count is not a multiple of 3");
    for (size_t i = 0; i < scene.indices.size(); ++i)
        if (scene.indices[i] >= scene.vertices.size())
            fail("index " + std::to_string(i) + " names vertex " + std::to_string(scene.indices[i]) + " of " +
                 std::to_string(scene.vertices.size()));
    if (scene.triangleMaterials.size() != scene.triangleCount())
        fail("there are " + std::to_string(scene.triangleMaterials.size()) + " triangle materials for " +
             std::to_string(scene.triangleCount()) + " triangles");
    for (size_t i = 0; i < scene.triangleMaterials.size(); ++i)
        if (scene.triangleMaterials[i] >= scene.materials.size())
            fail("triangle " + std::to_string(i) + " names material " + std::to_string(scene.triangleMaterials[i]) +
                 ", which does not exist");
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& material = scene.materials[i];
        const glm::vec4 color = material.baseColorFactor;
        if (!finite(glm::vec3(color)) || !std::isfinite(color.a) || !finite(material.emission) ||
            !std::isfinite(material.metallic) || !std::isfinite(material.roughness) ||
            !std::isfinite(material.specularWeight) || !std::isfinite(material.normalScale) ||
            !std::isfinite(material.occlusionStrength) || !std::isfinite(material.alphaCutoff) ||
            !finiteMapping(material))
            fail("material " + std::to_string(i) + " ('" + material.name +
                 "') holds a value that is not a finite number");
    }
}

void checkLightsCanBeRendered(const std::vector<Light>& lights, const std::string& sceneName) {
    for (size_t i = 0; i < lights.size(); ++i) {
        const Light& light = lights[i];
        const std::string name = "scene '" + sceneName + "': light " + std::to_string(i) + " ('" + light.name + "')";
        if (!finite(light.color) || !std::isfinite(light.intensity) || !finite(light.position) ||
            !finite(light.direction) || !std::isfinite(light.range) || !std::isfinite(light.innerConeAngle) ||
            !std::isfinite(light.outerConeAngle))
            throw Error(name + " holds a value that is not a finite number");
        if (light.intensity < 0.0f || light.color.r < 0.0f || light.color.g < 0.0f || light.color.b < 0.0f)
            throw Error(name + " has a negative intensity or colour");
        const double brightest = double(light.intensity) * std::max({light.color.r, light.color.g, light.color.b});
        if (brightest > kBrightestRepresentable) {
            char text[160];
            std::snprintf(text, sizeof text,
                          ": its intensity times its colour is %g, brighter than this renderer "
                          "represents (%g)",
                          brightest, kBrightestRepresentable);
            throw Error(name + text);
        }
    }
}

SceneGpu::SceneGpu(GpuContext& context, const Scene& scene) : context_(context) {
    const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    vertices = uploadArray(context, scene.vertices, storage);
    triangleCount = uint32_t(scene.triangleCount());
    indexCount = triangleCount * 3;

    // A stable sort by material keeps each material's triangles in file order.
    std::vector<uint32_t> order(triangleCount);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return scene.triangleMaterials[a] < scene.triangleMaterials[b]; });
    std::vector<uint32_t> sortedIndices(indexCount);
    std::vector<uint32_t> sortedMaterials(triangleCount);
    for (uint32_t i = 0; i < triangleCount; ++i) {
        const uint32_t triangle = order[i];
        sortedMaterials[i] = scene.triangleMaterials[triangle];
        for (uint32_t corner = 0; corner < 3; ++corner)
            sortedIndices[i * 3 + corner] = scene.indices[triangle * 3 + corner];
        if (materialRanges.empty() || materialRanges.back().material != sortedMaterials[i])
            materialRanges.push_back({sortedMaterials[i], i * 3, 0});
        materialRanges.back().indexCount += 3;
    }
    for (MaterialRange& range : materialRanges) {
        range.alphaTested = scene.materials[range.material].alphaMode != AlphaMode::Opaque;
        range.doubleSided = scene.materials[range.material].doubleSided;
        if (range.alphaTested) alphaTestedRanges.push_back(range);
        else if (!opaqueRuns.empty() && opaqueRuns.back().firstIndex + opaqueRuns.back().indexCount == range.firstIndex)
            opaqueRuns.back().indexCount += range.indexCount;
        else opaqueRuns.push_back({range.firstIndex, range.indexCount});
    }
    indices = uploadArray(context, sortedIndices, storage | VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    triangleMaterials = uploadArray(context, sortedMaterials, storage);

    std::vector<glsl::GpuMaterial> gpuMaterials;
    for (const Material& material : scene.materials) {
        glsl::GpuMaterial gpu{};
        gpu.baseColorFactor = material.baseColorFactor;
        gpu.emission = glm::vec4(material.emission, 0.0f);
        gpu.voxelEmission = glm::vec4(voxelEmission(scene, material), voxelCoverage(scene, material));
        gpu.metallic = material.metallic;
        gpu.roughness = material.roughness;
        gpu.specularWeight = material.specularWeight;
        gpu.baseColorTexture = material.baseColorTexture.index;
        gpu.emissiveTexture = material.emissiveTexture.index;
        gpu.metallicRoughnessTexture = material.metallicRoughnessTexture.index;
        gpu.normalTexture = material.normalTexture.index;
        gpu.normalScale = material.normalScale;
        gpu.occlusionTexture = material.occlusionTexture.index;
        gpu.occlusionStrength = material.occlusionStrength;
        gpu.alphaMode = uint32_t(material.alphaMode);
        gpu.alphaCutoff = material.alphaCutoff;
        gpu.baseColorTransform = textureTransform(material.baseColorTexture);
        gpu.emissiveTransform = textureTransform(material.emissiveTexture);
        gpu.metallicRoughnessTransform = textureTransform(material.metallicRoughnessTexture);
        gpu.normalTransform = textureTransform(material.normalTexture);
        gpu.occlusionTransform = textureTransform(material.occlusionTexture);
        gpuMaterials.push_back(gpu);
    }
    materials = uploadArray(context, gpuMaterials, storage);

    // One sampler per kind of glTF sampler the textures use (they are few: wrap modes × filters).
    std::map<std::tuple<TextureWrap, TextureWrap, bool>, VkSampler> samplerOf;
    std::vector<VkSampler> textureSamplers;
    const auto samplerFor = [&](TextureWrap wrapS, TextureWrap wrapT, bool nearestMagnification) {
        const auto key = std::tuple{wrapS, wrapT, nearestMagnification};
        if (const auto known = samplerOf.find(key); known != samplerOf.end()) return known->second;
        VkSamplerCreateInfo info = linearClampSampler();  // trilinear through the mip chain
        info.addressModeU = addressMode(wrapS);
        info.addressModeV = addressMode(wrapT);
        if (nearestMagnification) info.magFilter = VK_FILTER_NEAREST;
        samplers.emplace_back(context, info);
        return samplerOf[key] = samplers.back().sampler;
    };
    for (const Texture& texture : scene.textures) {
        textures.push_back(uploadTexture(context, texture.width, texture.height, texture.rgba8.data(), texture.srgb));
        textureSamplers.push_back(samplerFor(texture.wrapS, texture.wrapT, texture.nearestMagnification));
    }
    if (textures.empty()) {
        const uint8_t white[4] = {255, 255, 255, 255};
        textures.push_back(uploadTexture(context, 1, 1, white, true));
        textureSamplers.push_back(samplerFor(TextureWrap::Repeat, TextureWrap::Repeat, false));
    }

    // The texture array changes size with the scene, so it lives in a classic descriptor set.
    // The G-buffer reads it per pixel, the voxelizer per voxel.
    VkDescriptorSetLayoutBinding binding{glsl::COLOR_TEXTURES_BINDING, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                         textureCount(), VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT,
                                         nullptr};
    VkDescriptorSetLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    layoutInfo.bindingCount = 1;
    layoutInfo.pBindings = &binding;
    VK_CHECK(vkCreateDescriptorSetLayout(context.device, &layoutInfo, nullptr, &textureSetLayout));
    VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2 * textureCount()};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.maxSets = 2;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &poolSize;
    VK_CHECK(vkCreateDescriptorPool(context.device, &poolInfo, nullptr, &texturePool));
    const VkDescriptorSetLayout layouts[2] = {textureSetLayout, textureSetLayout};
    VkDescriptorSetAllocateInfo allocateInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    allocateInfo.descriptorPool = texturePool;
    allocateInfo.descriptorSetCount = 2;
    allocateInfo.pSetLayouts = layouts;
    VkDescriptorSet sets[2];
    VK_CHECK(vkAllocateDescriptorSets(context.device, &allocateInfo, sets));
    textureSet = sets[0];
    voxelTextureSet = sets[1];

    // The voxelizer reads base colour and emissive textures only, which glTF stores in sRGB; the
    // linear ones are the white fallback in its set. lavapipe 22.3 (LLVM 15) compiles a read for
    // every texture bound to the array, and crashed compiling a compute shader's filtered read of
    // a linear RGBA8 texture.
    const bool anyLinear =
        std::any_of(scene.textures.begin(), scene.textures.end(), [](const Texture& texture) { return !texture.srgb; });
    if (anyLinear) {
        const uint8_t white[4] = {255, 255, 255, 255};
        voxelFallbackTexture = uploadTexture(context, 1, 1, white, true);
    }
    std::vector<VkDescriptorImageInfo> imageInfos, voxelImageInfos;
    for (size_t i = 0; i < textures.size(); ++i) {
        imageInfos.push_back({textureSamplers[i], textures[i].view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
        const bool linear = i < scene.textures.size() && !scene.textures[i].srgb;
        voxelImageInfos.push_back(linear ? VkDescriptorImageInfo{textureSamplers[i], voxelFallbackTexture.view,
                                                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}
                                         : imageInfos.back());
    }
    VkWriteDescriptorSet writes[2];
    for (int i = 0; i < 2; ++i) {
        writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        writes[i].dstSet = sets[i];
        writes[i].dstBinding = glsl::COLOR_TEXTURES_BINDING;
        writes[i].descriptorCount = textureCount();
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        writes[i].pImageInfo = i == 0 ? imageInfos.data() : voxelImageInfos.data();
    }
    vkUpdateDescriptorSets(context.device, 2, writes, 0, nullptr);
}

SceneGpu::~SceneGpu() {
    vkDestroyDescriptorPool(context_.device, texturePool, nullptr);
    vkDestroyDescriptorSetLayout(context_.device, textureSetLayout, nullptr);
}

}  // namespace vct
