#include "render/shadow_pass.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

#include "bindings.h"
#include "gpu/commands.h"
#include "gpu/pass_uses.h"
#include "lights.h"
#include "render/camera.h"

namespace vct {
namespace {

constexpr VkFormat kShadowFormat = VK_FORMAT_D32_SFLOAT;

glsl::ShadowView perspectiveView(glm::vec3 eye, glm::vec3 forward, float fov, float znear, float zfar,
                                 ShadowArray array, uint32_t layer, uint32_t size) {
    glsl::ShadowView view{};
    view.viewProjection = glm::perspective(fov, 1.0f, znear, zfar) * lookAlong(eye, forward, glm::vec3(0, 1, 0));
    // World size of one texel at distance 1 from the light.
    view.params = glm::vec4(float(array), float(layer), 2.0f * std::tan(0.5f * fov) / float(size), 1.0f);
    view.depthRange = glm::vec4(znear, zfar, 1.0f, 0.0f);
    return view;
}

// The bit of a redraw set (ShadowArraySet) that redraws `view`: its array's, or a sun's cascade's
// own.
ShadowArraySet redrawnWith(const ShadowLayout& layout, const glsl::ShadowView& view) {
    const uint32_t array = uint32_t(view.params.x), layer = uint32_t(view.params.y);
    const uint32_t firstCascade = layout.sunLayers - layout.sunCascadeLayers;
    const bool cascade = array == uint32_t(ShadowArray::Sun) && layer >= firstCascade;
    const uint32_t index = (layer - firstCascade) * layout.cascadesPerLayer + uint32_t(view.depthRange.w);
    return cascade ? sunCascadeBit(index) : shadowArrayBit(ShadowArray(array));
}

}  // namespace

ShadowLayout layoutShadows(const std::vector<Light>& lights, const std::vector<AreaLight>& areaLights,
                           const Bounds& sceneBounds, const RenderSettings& settings, const CascadeView* cascadeView) {
    ShadowLayout layout;
    const glm::vec3 center = sceneBounds.center();
    const float radius = std::max(0.5f * glm::length(sceneBounds.extent()), 1e-6f);
    // A perspective view's depth range: to the scene's farthest corner, near relative to it only
    // (itself at least 1e-5), so a scene scaled by a power of two gets the same depth mapping and
    // the same shadows.
    auto farthestCorner = [&](const glm::vec3& eye) {
        float farthest = 0.0f;
        for (int corner = 0; corner < 8; ++corner)
            farthest = std::max(farthest, glm::distance(eye, sceneBounds.corner(corner)));
        return std::max(farthest * 1.01f, 1e-5f);
    };
    auto addCube = [&](const glm::vec3& eye, ShadowArray array) {
        const float zfar = farthestCorner(eye);
        uint32_t& layers = array == ShadowArray::Area ? layout.areaLayers : layout.localLayers;
        const uint32_t size =
            array == ShadowArray::Area ? settings.resources.areaShadowMapSize : settings.resources.localShadowMapSize;
        // Faces a little wider than 90° so the PCF kernel near a face edge stays inside the face.
        const float margin = 1.0f + 2.0f * (settings.shading.pcfRadius + 1.0f) / float(size);
        const float fov = 2.0f * std::atan(margin);
        const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        for (const glm::vec3& axis : axes)
            layout.views.push_back(perspectiveView(eye, axis, fov, zfar * 1e-4f, zfar, array, layers++, size));
    };
    for (const Light& light : lights) {
        glsl::GpuLight gpu{};
        gpu.radiantIntensity = glm::vec4(light.color * light.intensity, float(uint32_t(light.type)));
        gpu.positionRange = glm::vec4(light.position, light.range);
        gpu.direction = glm::vec4(glm::normalize(light.direction), 0.0f);
        gpu.spotShadow = glm::vec4(light.innerConeAngle, light.outerConeAngle, float(layout.views.size()), 0.0f);

        if (light.type == LightType::Directional) {
            // An orthographic box around the scene's bounding sphere, looking along the light.
            const glm::vec3 eye = center - glm::normalize(light.direction) * (2.0f * radius);
            glsl::ShadowView view{};
            view.viewProjection = glm::ortho(-radius, radius, -radius, radius, radius * 0.5f, radius * 3.5f) *
                                  lookAlong(eye, light.direction, glm::vec3(0, 1, 0));
            view.params = glm::vec4(0.0f, float(layout.sunLayers++),
                                    2.0f * radius / float(settings.resources.sunShadowMapSize), 0.0f);
            view.depthRange = glm::vec4(0.0f, 0.0f, 1.0f, 0.0f);  // the whole layer
            layout.views.push_back(view);
            gpu.spotShadow.w = 1.0f;
        } else if (light.type == LightType::Spot) {
            const float zfar = farthestCorner(light.position);
            const float fov = std::min(2.0f * light.outerConeAngle * 1.05f + 0.02f, glm::radians(170.0f));
            layout.views.push_back(perspectiveView(light.position, light.direction, fov, zfar * 1e-4f, zfar,
                                                   ShadowArray::Local, layout.localLayers++,
                                                   settings.resources.localShadowMapSize));
            gpu.spotShadow.w = 1.0f;
        } else {
            addCube(light.position, ShadowArray::Local);
            gpu.spotShadow.w = 6.0f;
        }
        layout.lights.push_back(gpu);
    }
    layout.firstAreaLight = uint32_t(layout.lights.size());
    for (const AreaLight& light : areaLights) {
        glsl::GpuLight gpu{};
        gpu.radiantIntensity = glm::vec4(light.meanRadiance, float(glsl::LIGHT_AREA));
        // The cube's eye sits just in front of the surface, clear of it and of what it is mounted on.
        const glm::vec3 eye = light.centroid + light.normal * std::max(1e-3f * radius, 1e-2f * light.radius);
        gpu.positionRange = glm::vec4(eye, light.radius);
        gpu.direction = glm::vec4(light.normal, light.area);
        gpu.spotShadow = glm::vec4(float(layout.emitterTriangles.size()), float(light.triangles.size()),
                                   float(layout.views.size()), 6.0f);
        addCube(eye, ShadowArray::Area);
        for (const EmitterTriangle& triangle : light.triangles)
            layout.emitterTriangles.push_back({glm::vec4(triangle.corners[0], triangle.radiance.r),
                                               glm::vec4(triangle.corners[1], triangle.radiance.g),
                                               glm::vec4(triangle.corners[2], triangle.radiance.b)});
        layout.lights.push_back(gpu);
    }
    // The suns' cascades, in layers after every scene-fitted map (the camera moves them alone), as
    // many to a layer as its tiles of their size.
    const uint32_t sunSize = settings.resources.sunShadowMapSize;
    const uint32_t cascadeSize = cascadeView ? cascadeMapSize(cascadeView->imageHeight, sunSize) : sunSize;
    layout.cascadesPerLayer = (sunSize / cascadeSize) * (sunSize / cascadeSize);
    const uint32_t firstCascadeLayer = layout.sunLayers;
    uint32_t cascades = 0;
    const std::vector<float> distances =
        cascadeView ? cascadeDistances(*cascadeView, 2.0f * radius / float(sunSize), settings.resources.sunCascades)
                    : std::vector<float>{};
    for (size_t i = 0; i < lights.size() && !distances.empty(); ++i) {
        if (lights[i].type != LightType::Directional) continue;
        layout.lights[i].cascades = glm::vec4(float(layout.views.size()), float(distances.size()), 0.0f, 0.0f);
        float nearDistance = 0.0f;
        for (float farDistance : distances) {
            glsl::ShadowView view =
                cascadeShadowView(lights[i].direction, *cascadeView, nearDistance, farDistance, sceneBounds,
                                  cascadeSize, sunSize, cascades % layout.cascadesPerLayer);
            view.params.x = float(ShadowArray::Sun);
            view.params.y = float(firstCascadeLayer + cascades / layout.cascadesPerLayer);
            layout.views.push_back(view);
            ++cascades;
            nearDistance = farDistance;
        }
    }
    layout.sunCascadeLayers = (cascades + layout.cascadesPerLayer - 1) / layout.cascadesPerLayer;
    layout.sunLayers += layout.sunCascadeLayers;
    return layout;
}

uint32_t mostSunLayers(const ShadowLayout& layout, const RenderSettings& settings) {
    const uint32_t suns = layout.sunLayers - layout.sunCascadeLayers;  // a scene-fitted map each
    const uint32_t cascades = suns * settings.resources.sunCascades;
    const uint32_t layerSize = settings.resources.sunShadowMapSize;
    const uint32_t tilesPerSide = layerSize / cascadeMapSize(settings.image.height, layerSize);
    const uint32_t perLayer = tilesPerSide * tilesPerSide;
    return suns + (cascades + perLayer - 1) / perLayer;
}

ShadowPass::ShadowPass(GpuContext& context, const ShadowLayout& layout, const RenderSettings& settings,
                       const SceneGpu& scene)
    : context_(context) {
    auto makeArray = [&](uint32_t layers, uint32_t size, const char* name) {
        ImageDesc desc;
        desc.format = kShadowFormat;
        desc.extent = layers > 0 ? VkExtent3D{size, size, 1} : VkExtent3D{1, 1, 1};
        desc.layers = std::max(layers, 1u);
        desc.arrayView = true;
        desc.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
        desc.debugName = name;
        return GpuImage(context, desc);
    };
    // Once a sun has cascades, room for as many as the camera may come to need: a camera moving
    // nearer to geometry adds cascades without a new array (a stall) each time.
    const uint32_t sunLayers = layout.sunCascadeLayers > 0 ? mostSunLayers(layout, settings) : layout.sunLayers;
    sunMaps = makeArray(sunLayers, settings.resources.sunShadowMapSize, "sun shadow maps");
    localMaps = makeArray(layout.localLayers, settings.resources.localShadowMapSize, "local shadow maps");
    areaMaps = makeArray(layout.areaLayers, settings.resources.areaShadowMapSize, "area light shadow maps");

    VkSamplerCreateInfo samplerInfo = linearClampSampler();
    samplerInfo.compareEnable = VK_TRUE;
    samplerInfo.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;  // 1 = the surface is not behind the stored depth
    compareSampler = Sampler(context, samplerInfo);

    GraphicsPipelineDesc desc;
    desc.vertexShader = "shadow.vert";
    desc.depthFormat = kShadowFormat;
    desc.depthTest = true;
    pipeline = createGraphicsPipeline(context, desc);
    useScene(scene);
}

void ShadowPass::useScene(const SceneGpu& scene) {
    alphaPipeline = Pipeline();
    if (scene.alphaTestedRanges.empty()) return;
    GraphicsPipelineDesc desc;
    desc.vertexShader = "shadow_alpha.vert";
    desc.fragmentShader = "shadow_alpha.frag";
    desc.depthFormat = kShadowFormat;
    desc.depthTest = true;
    // The texture array's size, as in the G-buffer.
    desc.fragmentSpecialization = specializationConstants({{glsl::TEXTURE_COUNT_CONSTANT_ID, scene.textureCount()}});
    alphaPipeline = createGraphicsPipeline(context_, desc, {scene.textureSetLayout});
}

ShadowArraySet changedShadowArrays(const ShadowLayout& before, const ShadowLayout& after) {
    // Views by the bit that redraws them: each array, and each sun cascade apart.
    using ViewsByBit = std::array<std::vector<glsl::ShadowView>, 32>;
    auto viewsByBit = [](const ShadowLayout& layout) {
        ViewsByBit views;
        for (const glsl::ShadowView& view : layout.views)
            views[std::countr_zero(redrawnWith(layout, view))].push_back(view);
        return views;
    };
    const ViewsByBit a = viewsByBit(before), b = viewsByBit(after);
    const uint32_t layers[kShadowArrayCount][2] = {
        {before.sunLayers - before.sunCascadeLayers, after.sunLayers - after.sunCascadeLayers},
        {before.localLayers, after.localLayers},
        {before.areaLayers, after.areaLayers}};
    ShadowArraySet changed = 0;
    for (uint32_t array = 0; array < kShadowArrayCount; ++array)
        if (layers[array][0] != layers[array][1]) changed |= 1u << array;
    for (uint32_t bit = 0; bit < 32; ++bit)
        if (a[bit].size() != b[bit].size() ||
            std::memcmp(a[bit].data(), b[bit].data(), a[bit].size() * sizeof(glsl::ShadowView)) != 0)
            changed |= 1u << bit;
    return changed;
}

void ShadowPass::record(VkCommandBuffer commands, const SceneGpu& scene, const ShadowLayout& layout,
                        VkBuffer viewsBuffer, ShadowArraySet redraw) {
    GpuImage* arrays[kShadowArrayCount] = {&sunMaps, &localMaps, &areaMaps};
    redraw |= kAllShadowArrays & ~drawn;                                         // a new array has no maps yet
    if (redraw & shadowArrayBit(ShadowArray::Sun)) redraw |= kSunCascadeLayers;  // the sun moved
    // The redrawn arrays are drawn into after the passes that sampled them; the passes that sample
    // them next declare so.
    PassUses drawing;
    for (uint32_t array = 0; array < kShadowArrayCount; ++array) {
        const bool cascades = array == uint32_t(ShadowArray::Sun) && (redraw & kSunCascadeLayers) != 0;
        if ((redraw & (1u << array)) != 0 || cascades) drawing.use(*arrays[array], access::depthAttachment);
    }
    drawing.record(commands);

    // Opaque materials need no fragment shader; alpha-tested ones (if any) switch to the second
    // pipeline after them in every layer, and back for the next layer.
    const bool alphaTested = !scene.alphaTestedRanges.empty() && alphaPipeline.pipeline != VK_NULL_HANDLE;
    auto bindOpaque = [&] {
        vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.pipeline);
        DescriptorPush()
            .buffer(glsl::VERTICES_BINDING, scene.vertices.buffer)
            .buffer(glsl::SHADOW_VIEWS_BINDING, viewsBuffer)
            .push(context_, commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    };
    bindOpaque();
    vkCmdBindIndexBuffer(commands, scene.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
    bool opaqueBound = true;

    // Unused arrays (no light of that kind) are cleared once so they sample as "lit".
    // A view covering a tile of its layer (a sun's cascade) is cleared and drawn there alone.
    auto renderLayer = [&](GpuImage& maps, uint32_t layer, int viewIndex) {
        const uint32_t size = maps.desc.extent.width;
        VkRect2D area{{0, 0}, {size, size}};
        if (viewIndex >= 0) {
            const glsl::ShadowView& view = layout.views[size_t(viewIndex)];
            const glm::vec2 corner = glsl::shadowTileCorner(view) * float(size);
            const uint32_t covered = uint32_t(std::lround(view.depthRange.z * float(size)));
            area = {{int32_t(std::lround(corner.x)), int32_t(std::lround(corner.y))}, {covered, covered}};
        }
        VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        depth.imageView = maps.layerViews[layer];
        depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
        depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        depth.clearValue.depthStencil = {1.0f, 0};
        VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
        rendering.renderArea = area;
        rendering.layerCount = 1;
        rendering.pDepthAttachment = &depth;
        vkCmdBeginRendering(commands, &rendering);
        if (viewIndex >= 0 && scene.indexCount > 0) {
            const VkViewport viewport{0.0f, 0.0f, float(size), float(size), 0.0f, 1.0f};
            const VkRect2D scissor = area;
            vkCmdSetViewport(commands, 0, 1, &viewport);
            vkCmdSetScissor(commands, 0, 1, &scissor);
            const uint32_t index = uint32_t(viewIndex);
            if (!opaqueBound) bindOpaque();
            opaqueBound = true;
            vkCmdPushConstants(commands, pipeline.layout, VK_SHADER_STAGE_ALL, 0, sizeof(index), &index);
            for (const SceneGpu::IndexRun& run : scene.opaqueRuns)
                vkCmdDrawIndexed(commands, run.indexCount, 1, run.firstIndex, 0, 0);
            if (alphaTested) {
                vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, alphaPipeline.pipeline);
                DescriptorPush()
                    .buffer(glsl::VERTICES_BINDING, scene.vertices.buffer)
                    .buffer(glsl::SHADOW_VIEWS_BINDING, viewsBuffer)
                    .buffer(glsl::MATERIALS_BINDING, scene.materials.buffer)
                    .push(context_, commands, VK_PIPELINE_BIND_POINT_GRAPHICS, alphaPipeline);
                vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, alphaPipeline.layout,
                                        glsl::TEXTURES_SET, 1, &scene.textureSet, 0, nullptr);
                opaqueBound = false;
                for (const SceneGpu::MaterialRange& range : scene.alphaTestedRanges) {
                    const uint32_t viewAndMaterial[2] = {index, range.material};
                    vkCmdPushConstants(commands, alphaPipeline.layout, VK_SHADER_STAGE_ALL, 0, sizeof(viewAndMaterial),
                                       viewAndMaterial);
                    vkCmdDrawIndexed(commands, range.indexCount, 1, range.firstIndex, 0, 0);
                }
            }
        }
        vkCmdEndRendering(commands);
    };
    for (size_t i = 0; i < layout.views.size(); ++i) {
        const glsl::ShadowView& view = layout.views[i];
        if ((redraw & redrawnWith(layout, view)) != 0)
            renderLayer(*arrays[uint32_t(view.params.x)], uint32_t(view.params.y), int(i));
    }
    const uint32_t layers[kShadowArrayCount] = {layout.sunLayers, layout.localLayers, layout.areaLayers};
    for (uint32_t array = 0; array < kShadowArrayCount; ++array)
        if ((redraw & (1u << array)) != 0 && layers[array] == 0) renderLayer(*arrays[array], 0, -1);

    drawn |= redraw & kAllShadowArrays;
}

}  // namespace vct
