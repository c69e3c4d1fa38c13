// VoxelVolumes: the one owner of the voxel images, and the memory estimate the device checks use.
#include <cstdio>

#include "gpu_test.h"
#include "render/renderer_limits.h"
#include "render/voxel_volumes.h"
#include "render/voxelize_pass.h"

namespace vct {
namespace {

using test::gpu;
using test::GpuTest;

class VoxelVolumesTest : public GpuTest {};

TEST_F(VoxelVolumesTest, EstimateIsWhatTheDeviceAllocates) {
    // The estimate counts texels; a device may pad each level, so it may allocate a little more,
    // but never less, and the padding must stay small next to the volume.
    for (const ResourceSettings resources :
         {ResourceSettings{.voxelResolution = 32, .anisotropicVoxels = false}, ResourceSettings{.voxelResolution = 32},
          ResourceSettings{.voxelResolution = 64, .bounces = 2}, ResourceSettings{.voxelResolution = 128}}) {
        const VoxelVolumes volumes(gpu(), resources);
        const uint64_t estimate = voxelVolumeBytes(resources), allocated = volumes.allocatedBytes();
        std::printf("[ volumes ] %u³ %s, %u bounce(s): estimate %llu, allocated %llu bytes\n",
                    resources.voxelResolution, resources.anisotropicVoxels ? "anisotropic" : "isotropic",
                    resources.bounces, static_cast<unsigned long long>(estimate),
                    static_cast<unsigned long long>(allocated));
        EXPECT_LE(estimate, allocated);
        EXPECT_LE(double(allocated), 1.02 * double(estimate)) << resources.voxelResolution;  // lavapipe: 0.7 % at 32³
        EXPECT_EQ(volumes.images().size(), voxelVolumeDescs(resources).size());
    }
}

TEST_F(VoxelVolumesTest, OnlyWhatTheSettingsNeedIsCreated) {
    const VoxelVolumes isotropic(gpu(), {.voxelResolution = 32, .anisotropicVoxels = false, .bounces = 1});
    EXPECT_TRUE(isotropic.directional.empty());
    EXPECT_EQ(isotropic.gatheredLight.image, VK_NULL_HANDLE) << "one bounce needs no second target";
    const VoxelVolumes twoBounces(gpu(), {.voxelResolution = 32, .bounces = 2});
    EXPECT_EQ(twoBounces.directional.size(), 3u) << "an image per axis";
    EXPECT_EQ(twoBounces.directional[0].desc.extent.width, 16u) << "the chains start at the grid's level 1";
    EXPECT_EQ(twoBounces.directional[0].desc.extent.depth, 48u) << "two chains and the empty third between them";
    EXPECT_NE(twoBounces.gatheredLight.image, VK_NULL_HANDLE);
    EXPECT_EQ(twoBounces.surfacePlanes.image, VK_NULL_HANDLE) << "the planes are ray visibility's";
    const VoxelVolumes rays(gpu(), {.voxelResolution = 32, .rayVisibility = true});
    EXPECT_NE(rays.surfacePlanes.image, VK_NULL_HANDLE);
    EXPECT_EQ(rays.surfacePlanes.desc.mipLevels, rays.radiance.desc.mipLevels) << "read at the radiance's levels";
}

TEST_F(VoxelVolumesTest, TheRendererMemoryEstimateCountsTheVolumesOnce) {
    // The renderer's voxel estimate is the volumes plus the voxelizer's accumulation buffers.
    Scene empty;
    RenderSettings settings;
    settings.resources = {.voxelResolution = 64, .bounces = 2};
    EXPECT_EQ(estimateRendererMemory(empty, settings).voxels,
              voxelVolumeBytes(settings.resources) + voxelizeAccumulationBytes(64));
}

}  // namespace
}  // namespace vct
