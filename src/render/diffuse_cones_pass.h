// The diffuse cones at a reduced resolution (ImageSettings::diffuseDownscale): one G-buffer sample
// per block traces them, or takes the last frame's light where it was (a quarter of the blocks
// trace anew each frame), every sample blends the nearest along its own surface, and the samples
// where that fails take their own light of the last frame in the same way or trace their own
// cones, from a work list (shaders_glsl/reduced_diffuse.glsl). Only created when the downscale is above 1.
#pragma once

#include <glm/glm.hpp>

#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "render/cone_tracing_pipeline.h"
#include "render/gbuffer_pass.h"
#include "render/sky_image.h"
#include "render/voxel_volumes.h"

namespace vct {

struct DiffuseConesPass {
    // `samplesWide` × `samplesHigh` is the G-buffer's size; the reduced image is that / downscale,
    // rounded up.
    DiffuseConesPass(GpuContext& context, uint32_t samplesWide, uint32_t samplesHigh, uint32_t downscale);

    // Writes diffuse(), which the shading pass samples.
    // `viewProjection` is the G-buffer's: the next frame finds this frame's light through it.
    // `cameraStill`: the camera did not move since the last frame, though the samples may have
    // (ShadingSettings::stillSamples): the reused light still counts towards settled().
    void record(VkCommandBuffer commands, VkBuffer frameConstants, const GBufferPass& gbuffer,
                const VoxelVolumes& volumes, const SkyImage& sky, const glm::mat4& viewProjection, bool cameraStill,
                bool skipEmptySpace);
    // The light the last frames gathered no longer holds (the voxels' light was recomputed, or the
    // cones changed): the next frame traces every block.
    void forgetHistory() { haveHistory_ = false; }
    // The voxels' light changed by a progressive bounce: the light reused from the last frames
    // lags it until every block has traced again.
    void lightChanged() { stillFrames_ = 0; }
    // Whether the last frame is the image that tracing every block anew would give: each block and
    // edge sample traced since the view and the voxels' light last changed.
    bool settled() const { return stillFrames_ + 1 >= kRefreshPeriod; }

    // The last recorded frame's light per sample (RGBA32F, scene units: a sun's light can exceed
    // float16): Σ wᵢ Lᵢ of the diffuse cones and their weighted occlusion.
    const GpuImage& diffuse() const { return samples[(frameCount_ + 1) % 2]; }
    // After the recorded commands ran: the representatives that traced their cones, and the
    // samples that traced their own.
    uint32_t tracedRepresentatives() const;
    uint32_t tracedFallbackSamples() const;
    uint64_t memoryBytes() const;  // of its images

    // What one frame leaves for the next, per representative: its light (RGBA32F, as diffuse()),
    // where it was (xyz, w 1 on a surface) and which way it faced.
    struct Reduced {
        GpuImage light;
        GpuImage positions;
        GpuImage normals;
    };
    Reduced reduced[2];      // this frame's and the last one's, alternately
    GpuImage samples[2];     // per sample, this frame's and the last one's: what diffuse() returns
    Buffer tracedSamples;    // the representatives that trace this frame, packed 16 bits a coordinate
    Buffer tracedList;       // glsl::WorkListHeader over them
    Buffer edgeSamples;      // the samples that could not be upsampled
    Buffer edgeList;         // glsl::WorkListHeader over them
    Buffer fallbackSamples;  // the samples that trace their own cones
    Buffer fallbackList;     // glsl::WorkListHeader over them
    Buffer listHeaders;      // host-visible copies of both headers, for the counts above
    Sampler pointSampler;
    Pipeline reprojectPipeline, upsamplePipeline, edgeHistoryPipeline;
    ConeTracingComputePipeline traceListPipeline;

private:
    GpuContext& context_;
    uint32_t downscale_;
    uint32_t frameCount_ = 0;  // frames recorded: picks the refresh phase and this frame's reduced[]
    static constexpr uint32_t kRefreshPeriod = 4;  // frames in which every block traces once (2×2 pattern)
    uint32_t stillFrames_ = 0;  // frames since the view or the light last changed, not counting that one
    bool haveHistory_ = false;
    uint64_t lastGBufferFrame_ = 0;  // GBufferPass::recorded when this pass last ran
    glm::mat4 lastViewProjection_{1.0f};
};

}  // namespace vct
