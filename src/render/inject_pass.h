// Light injection: direct light (with shadow-map visibility) from punctual and area lights turned
// into the outgoing radiance of every occupied voxel, written to level 0 of the radiance volume; and the
// bounce, each voxel's cones gathering the light of the volume for the next injection to add.
#pragma once

#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "render/cone_tracing_pipeline.h"
#include "render/shadow_pass.h"
#include "render/sky_image.h"
#include "render/voxel_volumes.h"

namespace vct {

struct InjectPass {
    explicit InjectPass(GpuContext& context);

    // Writes level 0 of volumes.radiance from the scene voxels: the light sources' light reflected
    // once, plus (addGathered) what the last gather left in volumes.gatheredLight. Visible to the
    // mip pass after. The area lights' part is computed once and kept until forgetAreaLights().
    void record(VkCommandBuffer commands, VkBuffer frameConstants, const LightBuffers& lights,
                const ShadowPass& shadows, VoxelVolumes& volumes, bool addGathered);

    // New voxels (with room for the area lights' irradiance at `occupiedVoxels` of them; 0 where the
    // scene has no area lights), new area-light shadow maps, or other components shown: the next
    // injection computes the area lights' part anew. Not while commands that use the pass run.
    void forgetAreaLights(uint32_t occupiedVoxels);
    void forgetAreaLights() { forgetAreaLights(areaLightCapacity_); }

    // Every sliceCount-th occupied voxel from slicePhase gathers the light of the current
    // (mipmapped) volume through its diffuse cones into volumes.gatheredLight; {1, 0} is all.
    // occupiedVoxels is the voxelizer's count, read back: the dispatch covers the slice alone.
    struct Slice {
        uint32_t count = 1, phase = 0;
    };
    void recordGather(VkCommandBuffer commands, VkBuffer frameConstants, const VoxelVolumes& volumes,
                      const SkyImage& sky, Slice slice, uint32_t occupiedVoxels, bool skipEmptySpace);

    Pipeline pipeline;            // computes the area lights' part, and keeps it
    Pipeline cachedAreaPipeline;  // reads it
    ConeTracingComputePipeline gatherPipeline;

private:
    GpuContext& context_;
    Buffer areaLightCache_;  // three floats per occupied voxel
    uint32_t areaLightCapacity_ = 0;
    bool areaLightsCached_ = false;
};

// The scale that keeps the stored radiance inside float16's range whatever the scene's units:
// 1 / an upper estimate of any voxel's radiance (a light one voxel away, the brightest emitter).
float radianceStorageScale(const std::vector<Light>& lights, const Scene& scene, float voxelSize);

}  // namespace vct
