#include "render/voxel_volumes.h"

#include <algorithm>

#include "directional_chains.h"
#include "gpu/commands.h"
#include "gpu/pass_uses.h"
#include "render/voxel_grid_fit.h"

namespace vct {

std::vector<VoxelVolumeDesc> voxelVolumeDescs(const ResourceSettings& resources) {
    const uint32_t side = resources.voxelResolution, mips = voxelMipCount(side);
    const VkFormat half = VK_FORMAT_R16G16B16A16_SFLOAT;
    std::vector<VoxelVolumeDesc> descs = {
        {"voxel albedo and opacity", VK_FORMAT_R8G8B8A8_UNORM, 4, side, 1, 1, true},
        {"voxel normal and surface offset", half, 8, side, 1, 1, true},
        {"voxel emission", half, 8, side, 1, 1, true},
        {"voxel radiance", half, 8, side, mips, 1, false},
    };
    if (resources.anisotropicVoxels)
        for (const char* name : {"voxel radiance +x and -x", "voxel radiance +y and -y", "voxel radiance +z and -z"})
            descs.push_back({name, half, 8, side / 2, mips - 1, glsl::DIRECTIONAL_DEPTH_SIDES, false});
    if (resources.anisotropicVoxels)
        for (const char* name : {"surfaces leaving along +x and -x", "surfaces leaving along +y and -y",
                                 "surfaces leaving along +z and -z"})
            descs.push_back({name, VK_FORMAT_R32_UINT, 4, side / 2, mips - 1, 1, false});
    if (resources.bounces != 1) descs.push_back({"voxel gathered light", half, 8, side, 1, 1, false});
    if (resources.rayVisibility) descs.push_back({"surface planes", half, 8, side, mips, 1, false});
    return descs;
}

static uint64_t occupiedListBytes(uint32_t resolution) { return uint64_t(resolution) * resolution * resolution * 4; }

uint64_t voxelVolumeBytes(const ResourceSettings& resources, bool onlySceneVoxels) {
    // The occupied list is the light passes' work list: it counts with the light, not in the
    // voxelizer's share of the heap (checkVoxelizeMemory): half of lavapipe's 2 GiB heap, which a
    // 256³ grid of an opaque scene without emitters fills to 60 bytes a voxel of its 64.
    uint64_t bytes = onlySceneVoxels ? 0 : occupiedListBytes(resources.voxelResolution) + sizeof(glsl::WorkListHeader);
    for (const VoxelVolumeDesc& desc : voxelVolumeDescs(resources)) {
        if (onlySceneVoxels && !desc.sceneVoxels) continue;
        for (uint32_t level = 0; level < desc.mipLevels; ++level) {
            const uint64_t side = std::max(desc.side >> level, 1u);
            bytes += side * side * side * desc.depthSides * desc.texelBytes;
        }
    }
    return bytes;
}

static GpuImage makeVolume(GpuContext& context, const VoxelVolumeDesc& volume) {
    ImageDesc desc;
    desc.type = VK_IMAGE_TYPE_3D;
    desc.format = volume.format;
    desc.extent = {volume.side, volume.side, volume.side * volume.depthSides};
    desc.mipLevels = volume.mipLevels;
    // Written by storage, read by samplers, cleared and copied (creation and the tests clear and
    // fill them).
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                 VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    desc.debugName = volume.name;
    return GpuImage(context, desc);
}

VoxelVolumes::VoxelVolumes(GpuContext& context, const ResourceSettings& resources)
    : resolution(resources.voxelResolution), sampler(context, volumeSampler()) {
    const std::vector<VoxelVolumeDesc> descs = voxelVolumeDescs(resources);
    size_t next = 0;
    for (GpuImage* image : {&albedoOpacity, &normal, &emission, &radiance}) *image = makeVolume(context, descs[next++]);
    if (resources.anisotropicVoxels)
        for (int axis = 0; axis < 3; ++axis) directional.push_back(makeVolume(context, descs[next++]));
    if (resources.anisotropicVoxels)
        for (int axis = 0; axis < 3; ++axis) leavingSurfaces.push_back(makeVolume(context, descs[next++]));
    if (resources.bounces != 1) gatheredLight = makeVolume(context, descs[next++]);
    if (resources.rayVisibility) surfacePlanes = makeVolume(context, descs[next++]);
    occupiedVoxels = Buffer(context, occupiedListBytes(resolution),
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, false);
    // Written by the voxelizer (the count reset by a transfer), read by indirect dispatches.
    occupiedDispatch = Buffer(context, sizeof(glsl::WorkListHeader),
                              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                                  VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                              false);

    // Zero (no light yet: the first bounce gathers nothing; no voxel listed), then GENERAL.
    submitAndWait(context, [&](VkCommandBuffer commands) {
        const glsl::WorkListHeader none{0u, 1u, 1u, 0u};
        PassUses().use(occupiedDispatch, access::transferWrite).record(commands);
        vkCmdUpdateBuffer(commands, occupiedDispatch.buffer, 0, sizeof(none), &none);
        const VkClearColorValue zero{};
        const VkImageSubresourceRange everything{VK_IMAGE_ASPECT_COLOR_BIT, 0, VK_REMAINING_MIP_LEVELS, 0, 1};
        PassUses cleared, general;
        for (const GpuImage* image : images()) cleared.use(*image, access::transferWrite, Contents::Discard);
        cleared.record(commands);
        for (const GpuImage* image : images()) {
            vkCmdClearColorImage(commands, image->image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &everything);
            general.use(*image, access::computeRead);
        }
        general.record(commands);
    });
}

std::vector<VkImageView> VoxelVolumes::directionalViews() const {
    std::vector<VkImageView> views(3, radiance.view);
    for (size_t axis = 0; axis < directional.size(); ++axis) views[axis] = directional[axis].view;
    return views;
}

VkImageView VoxelVolumes::surfacePlanesView() const {
    return surfacePlanes.image != VK_NULL_HANDLE ? surfacePlanes.view : radiance.view;
}

std::vector<VkImageView> VoxelVolumes::lightLevelZeroViews() const {
    const VkImageView radianceLevelZero = radiance.mipViews.empty() ? radiance.view : radiance.mipViews[0];
    return {radianceLevelZero, gatheredLight.image != VK_NULL_HANDLE ? gatheredLight.view : radianceLevelZero};
}

std::vector<const GpuImage*> VoxelVolumes::tracedLight() const {
    std::vector<const GpuImage*> light = {&radiance};
    for (const GpuImage& chain : directional) light.push_back(&chain);
    if (surfacePlanes.image != VK_NULL_HANDLE) light.push_back(&surfacePlanes);
    return light;
}

std::vector<const GpuImage*> VoxelVolumes::images() const {
    std::vector<const GpuImage*> all = {&albedoOpacity, &normal, &emission, &radiance};
    for (const GpuImage& chain : directional) all.push_back(&chain);
    for (const GpuImage& flags : leavingSurfaces) all.push_back(&flags);
    if (gatheredLight.image != VK_NULL_HANDLE) all.push_back(&gatheredLight);
    if (surfacePlanes.image != VK_NULL_HANDLE) all.push_back(&surfacePlanes);
    return all;
}

uint64_t VoxelVolumes::allocatedBytes() const {
    uint64_t bytes = occupiedVoxels.size + occupiedDispatch.size;
    for (const GpuImage* image : images()) bytes += image->memorySize;
    return bytes;
}

}  // namespace vct
