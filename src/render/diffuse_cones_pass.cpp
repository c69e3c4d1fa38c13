#include "render/diffuse_cones_pass.h"

#include <array>

#include "bindings.h"
#include "gpu/commands.h"
#include "gpu/pass_uses.h"
#include "surface_planes.h"
#include "work_list.h"

namespace vct {
namespace {

GpuImage image(GpuContext& context, uint32_t width, uint32_t height, const char* name) {
    ImageDesc desc;
    desc.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    desc.extent = {width, height, 1};
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    desc.debugName = name;
    return GpuImage(context, desc);
}

// Reset by a transfer each frame, and copied out for the frame's statistics.
Buffer listHeader(GpuContext& context) {
    return Buffer(context, sizeof(glsl::WorkListHeader),
                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                      VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                  false);
}

}  // namespace

DiffuseConesPass::DiffuseConesPass(GpuContext& context, uint32_t samplesWide, uint32_t samplesHigh, uint32_t downscale)
    : traceListPipeline(context, "diffuse_trace_list.comp"), context_(context), downscale_(downscale) {
    const uint32_t reducedWide = (samplesWide + downscale - 1) / downscale;
    const uint32_t reducedHigh = (samplesHigh + downscale - 1) / downscale;
    for (Reduced& frame : reduced)
        frame = {image(context, reducedWide, reducedHigh, "reduced diffuse cones"),
                 image(context, reducedWide, reducedHigh, "reduced diffuse representatives"),
                 image(context, reducedWide, reducedHigh, "reduced diffuse representatives' normals")};
    for (GpuImage& perSample : samples)
        perSample = image(context, samplesWide, samplesHigh, "diffuse cones per sample");
    tracedSamples = Buffer(context, VkDeviceSize(reducedWide) * reducedHigh * sizeof(uint32_t),
                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
    tracedList = listHeader(context);
    edgeSamples = Buffer(context, VkDeviceSize(samplesWide) * samplesHigh * sizeof(uint32_t),
                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
    edgeList = listHeader(context);
    fallbackSamples = Buffer(context, VkDeviceSize(samplesWide) * samplesHigh * sizeof(uint32_t),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
    fallbackList = listHeader(context);
    listHeaders = Buffer(context, 2 * sizeof(glsl::WorkListHeader), VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    pointSampler = Sampler(context, nearestClampSampler());
    reprojectPipeline = createComputePipeline(context, "diffuse_reproject.comp");
    upsamplePipeline = createComputePipeline(context, "diffuse_upsample.comp");
    edgeHistoryPipeline = createComputePipeline(context, "diffuse_edge_history.comp");
}

void DiffuseConesPass::record(VkCommandBuffer commands, VkBuffer frameConstants, const GBufferPass& gbuffer,
                              const VoxelVolumes& volumes, const SkyImage& sky, const glm::mat4& viewProjection,
                              bool cameraStill, bool skipEmptySpace) {
    const VkSampler volumeSampler = volumes.sampler.sampler, point = pointSampler.sampler;
    const Reduced& now = reduced[frameCount_ % 2];
    const Reduced& last = reduced[(frameCount_ + 1) % 2];
    const uint32_t reducedWidth = now.light.desc.extent.width, reducedHeight = now.light.desc.extent.height;
    const GpuImage& nowSamples = samples[frameCount_ % 2];
    const GpuImage& lastSamples = samples[(frameCount_ + 1) % 2];
    // This pass's last frame saw the G-buffer's last images if the G-buffer was drawn once since,
    // its current ones if it was not drawn (the view did not move); otherwise there is no history.
    const bool gbufferRedrawn = gbuffer.recorded != lastGBufferFrame_;
    if (gbufferRedrawn && gbuffer.recorded != lastGBufferFrame_ + 1) haveHistory_ = false;
    lastGBufferFrame_ = gbuffer.recorded;
    const GpuImage& lastGBufferPosition = gbufferRedrawn ? gbuffer.lastPosition : gbuffer.position;
    const GpuImage& lastGBufferNormal = gbufferRedrawn ? gbuffer.lastNormal : gbuffer.normal;
    const std::array<const GpuImage*, 3> nowImages{&now.light, &now.positions, &now.normals};

    // The lists start empty, once the last frame's dispatches have read them.
    PassUses()
        .use(tracedList, access::transferWrite)
        .use(edgeList, access::transferWrite)
        .use(fallbackList, access::transferWrite)
        .record(commands);
    const glsl::WorkListHeader empty{0u, 1u, 1u, 0u};
    vkCmdUpdateBuffer(commands, tracedList.buffer, 0, sizeof(empty), &empty);
    vkCmdUpdateBuffer(commands, edgeList.buffer, 0, sizeof(empty), &empty);
    vkCmdUpdateBuffer(commands, fallbackList.buffer, 0, sizeof(empty), &empty);

    const uint32_t groupLimit = context_.properties.limits.maxComputeWorkGroupCount[0];
    struct {  // diffuse_reproject.comp's Push block
        glm::mat4 lastViewProjection;
        uint32_t groupLimit, refreshPhase, haveHistory;
    } const reuse{lastViewProjection_, groupLimit, frameCount_ % kRefreshPeriod, haveHistory_ ? 1u : 0u};
    // Steps 2 and 4: the listed samples' cones, into `target`'s texels, a representative's at its block.
    auto traceListed = [&](const GpuImage& target, uint32_t targetDownscale, const Buffer& listed, const Buffer& list) {
        const Pipeline& traceList = traceListPipeline.get(skipEmptySpace);
        PassUses uses;
        for (const GpuImage* light : volumes.tracedLight()) uses.use(*light, access::computeRead);
        uses.use(volumes.normal, access::computeRead)
            .use(gbuffer.position, access::computeSampled)
            .use(gbuffer.normal, access::computeSampled)
            .use(target, access::computeWrite)
            .use(listed, access::computeRead)
            .use(list, access::computeRead | access::indirectArguments)
            .record(commands);
        vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, traceList.pipeline);
        DescriptorPush()
            .sampledImages(glsl::DIRECTIONAL_VOXELS_BINDING, volumes.directionalViews(), volumeSampler,
                           VK_IMAGE_LAYOUT_GENERAL)
            .buffer(glsl::FRAME_BINDING, frameConstants, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
            .storageImage(glsl::LISTED_TARGET_BINDING, target.view)
            .buffer(glsl::LISTED_SAMPLES_BINDING, listed.buffer)
            .buffer(glsl::LISTED_SAMPLES_LIST_BINDING, list.buffer)
            .sampledImage(glsl::G_POSITION_BINDING, gbuffer.position.view, point)
            .sampledImage(glsl::G_NORMAL_BINDING, gbuffer.normal.view, point)
            .sampledImage(glsl::VOXEL_RADIANCE_BINDING, volumes.radiance.view, volumeSampler, VK_IMAGE_LAYOUT_GENERAL)
            .sampledImage(glsl::VOXEL_NORMAL_BINDING, volumes.normal.view, volumeSampler, VK_IMAGE_LAYOUT_GENERAL)
            .sampledImage(glsl::SURFACE_PLANES_BINDING, volumes.surfacePlanesView(), volumeSampler,
                          VK_IMAGE_LAYOUT_GENERAL)
            .sampledImage(glsl::SKY_BINDING, sky.view(), sky.sampler())
            .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, traceList);
        vkCmdPushConstants(commands, traceList.layout, VK_SHADER_STAGE_ALL, 0, sizeof(targetDownscale),
                           &targetDownscale);
        vkCmdDispatchIndirect(commands, list.buffer, 0);
    };

    // 1. The representatives: the last frame's light where it holds, the rest listed.
    PassUses reprojecting;
    for (const GpuImage* image : nowImages) reprojecting.use(*image, access::computeWrite, Contents::Discard);
    for (const GpuImage* image : {&last.light, &last.positions, &last.normals, &gbuffer.position, &gbuffer.normal})
        reprojecting.use(*image, access::computeSampled);
    reprojecting.use(tracedSamples, access::computeWrite).use(tracedList, access::computeWrite).record(commands);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, reprojectPipeline.pipeline);
    DescriptorPush()
        .buffer(glsl::FRAME_BINDING, frameConstants, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
        .storageImage(glsl::REDUCED_LIGHT_BINDING, now.light.view)
        .buffer(glsl::TRACED_SAMPLES_BINDING, tracedSamples.buffer)
        .buffer(glsl::TRACED_LIST_BINDING, tracedList.buffer)
        .storageImage(glsl::REDUCED_POSITIONS_BINDING, now.positions.view)
        .storageImage(glsl::REDUCED_NORMALS_BINDING, now.normals.view)
        .sampledImage(glsl::G_POSITION_BINDING, gbuffer.position.view, point)
        .sampledImage(glsl::G_NORMAL_BINDING, gbuffer.normal.view, point)
        .sampledImage(glsl::LAST_REDUCED_LIGHT_BINDING, last.light.view, point)
        .sampledImage(glsl::LAST_REDUCED_POSITIONS_BINDING, last.positions.view, point)
        .sampledImage(glsl::LAST_REDUCED_NORMALS_BINDING, last.normals.view, point)
        .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, reprojectPipeline);
    vkCmdPushConstants(commands, reprojectPipeline.layout, VK_SHADER_STAGE_ALL, 0, sizeof(reuse), &reuse);
    vkCmdDispatch(commands, (reducedWidth + 7) / 8, (reducedHeight + 7) / 8, 1);

    // 2. The listed representatives' cones.
    traceListed(now.light, downscale_, tracedSamples, tracedList);

    // 3. Every sample upsampled, or listed.
    PassUses upsampling;
    for (const GpuImage* image : nowImages) upsampling.use(*image, access::computeSampled);
    upsampling.use(gbuffer.position, access::computeSampled)
        .use(gbuffer.normal, access::computeSampled)
        .use(nowSamples, access::computeWrite, Contents::Discard)
        .use(edgeSamples, access::computeWrite)
        .use(edgeList, access::computeWrite)
        .record(commands);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, upsamplePipeline.pipeline);
    DescriptorPush()
        .buffer(glsl::FRAME_BINDING, frameConstants, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
        .storageImage(glsl::DIFFUSE_SAMPLES_BINDING, nowSamples.view)
        .buffer(glsl::EDGE_SAMPLES_BINDING, edgeSamples.buffer)
        .buffer(glsl::EDGE_LIST_BINDING, edgeList.buffer)
        .sampledImage(glsl::G_POSITION_BINDING, gbuffer.position.view, point)
        .sampledImage(glsl::G_NORMAL_BINDING, gbuffer.normal.view, point)
        .sampledImage(glsl::REDUCED_LIGHT_BINDING, now.light.view, point)
        .sampledImage(glsl::REDUCED_POSITIONS_BINDING, now.positions.view, point)
        .sampledImage(glsl::REDUCED_NORMALS_BINDING, now.normals.view, point)
        .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, upsamplePipeline);
    vkCmdPushConstants(commands, upsamplePipeline.layout, VK_SHADER_STAGE_ALL, 0, sizeof(reuse), &reuse);
    // One invocation per cell between four representatives, from the one before the first.
    const uint32_t cellsWide = reducedWidth + 1, cellsHigh = reducedHeight + 1;
    vkCmdDispatch(commands, (cellsWide + 7) / 8, (cellsHigh + 7) / 8, 1);

    // 3b. The listed samples' own light of the last frame, or listed again to trace.
    PassUses()
        .use(nowSamples, access::computeWrite)
        .use(fallbackSamples, access::computeWrite)
        .use(fallbackList, access::computeWrite)
        .use(edgeSamples, access::computeRead)
        .use(edgeList, access::computeRead | access::indirectArguments)
        .use(gbuffer.position, access::computeSampled)
        .use(gbuffer.normal, access::computeSampled)
        .use(lastSamples, access::computeSampled)
        .use(lastGBufferPosition, access::computeSampled)
        .use(lastGBufferNormal, access::computeSampled)
        .record(commands);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, edgeHistoryPipeline.pipeline);
    DescriptorPush()
        .buffer(glsl::FRAME_BINDING, frameConstants, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
        .storageImage(glsl::DIFFUSE_SAMPLES_BINDING, nowSamples.view)
        .buffer(glsl::FALLBACK_SAMPLES_BINDING, fallbackSamples.buffer)
        .buffer(glsl::FALLBACK_LIST_BINDING, fallbackList.buffer)
        .buffer(glsl::EDGE_SAMPLES_BINDING, edgeSamples.buffer)
        .buffer(glsl::EDGE_LIST_BINDING, edgeList.buffer)
        .sampledImage(glsl::G_POSITION_BINDING, gbuffer.position.view, point)
        .sampledImage(glsl::G_NORMAL_BINDING, gbuffer.normal.view, point)
        .sampledImage(glsl::LAST_DIFFUSE_SAMPLES_BINDING, lastSamples.view, point)
        .sampledImage(glsl::LAST_G_POSITION_BINDING, lastGBufferPosition.view, point)
        .sampledImage(glsl::LAST_G_NORMAL_BINDING, lastGBufferNormal.view, point)
        .push(context_, commands, VK_PIPELINE_BIND_POINT_COMPUTE, edgeHistoryPipeline);
    vkCmdPushConstants(commands, edgeHistoryPipeline.layout, VK_SHADER_STAGE_ALL, 0, sizeof(reuse), &reuse);
    vkCmdDispatchIndirect(commands, edgeList.buffer, 0);

    // 4. The listed samples' own cones, into the texels step 3 left.
    traceListed(nowSamples, 1u, fallbackSamples, fallbackList);

    // The lists' counts, for the frame's statistics.
    constexpr VkDeviceSize header = sizeof(glsl::WorkListHeader);
    copyForHost(commands, tracedList, listHeaders, {{0, 0, header}});
    copyForHost(commands, fallbackList, listHeaders, {{0, header, header}});

    if (!haveHistory_) stillFrames_ = kRefreshPeriod;  // every block traced: settled at once
    else if (!cameraStill) stillFrames_ = 0;
    else ++stillFrames_;
    haveHistory_ = true;
    lastViewProjection_ = viewProjection;
    ++frameCount_;
}

uint64_t DiffuseConesPass::memoryBytes() const {
    uint64_t bytes = 0;
    for (const Reduced& frame : reduced)
        bytes += frame.light.memorySize + frame.positions.memorySize + frame.normals.memorySize;
    for (const GpuImage& perSample : samples) bytes += perSample.memorySize;
    for (const Buffer* list : {&tracedSamples, &edgeSamples, &fallbackSamples}) bytes += list->size;
    return bytes;
}

uint32_t DiffuseConesPass::tracedRepresentatives() const {
    return static_cast<const glsl::WorkListHeader*>(listHeaders.mapped)[0].count;
}

uint32_t DiffuseConesPass::tracedFallbackSamples() const {
    return static_cast<const glsl::WorkListHeader*>(listHeaders.mapped)[1].count;
}

}  // namespace vct
