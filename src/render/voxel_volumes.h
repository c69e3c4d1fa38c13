// Every 3D image of the voxel data, owned in one place with its format: what the voxelizer writes
// (albedo and opacity, normal, emission, and the list of occupied voxels), the light injected into
// it (radiance with its mip chain), the directional chains of anisotropic voxels and the next
// bounce's target. Each image is cleared at creation and lives in GENERAL, where storage writes and
// sampled reads alike use it (a read-back's copy moves it out until the next pass); the passes
// declare their uses of it (gpu/pass_uses.h).
#pragma once

#include <vector>

#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "render/settings.h"

namespace vct {

struct VoxelVolumeDesc {
    const char* name;
    VkFormat format;
    uint32_t texelBytes;
    uint32_t side;  // of level 0
    uint32_t mipLevels;
    uint32_t depthSides;  // its depth, in sides: 3 where two directional chains share an image
    bool sceneVoxels;     // written by the voxelizer (the rest hold light)
};

// The volumes `resources` call for, in the order VoxelVolumes holds them.
std::vector<VoxelVolumeDesc> voxelVolumeDescs(const ResourceSettings& resources);
// Their texels' bytes, every level, and (not among the scene voxels) the occupied-voxel list's:
// the renderer's one estimate of its voxel data's memory.
uint64_t voxelVolumeBytes(const ResourceSettings& resources, bool onlySceneVoxels = false);

struct VoxelVolumes {
    VoxelVolumes(GpuContext& context, const ResourceSettings& resources);

    uint32_t resolution;
    GpuImage albedoOpacity;  // RGBA8 UNORM: mean linear base colour, opacity
    GpuImage normal;         // RGBA16F: mean unit normal (not renormalized), surface offset (voxel_resolve.comp)
    GpuImage emission;       // RGBA16F: mean emission (scene units), opacity
    // RGBA16F with the full mip chain: radiance × scale premultiplied by opacity, and opacity.
    GpuImage radiance;
    // Anisotropic voxels: the chains for rays along +x and −x, +y and −y, +z and −z, from the grid's
    // level 1 down (level 0 is shared), an image per axis; empty when the voxels are isotropic. Each
    // image is three sides deep: the +axis chain fills its first third along z, the −axis chain its
    // last, and the empty third between them reads as the space outside the grid (directional_chains.h).
    // A cone then reads its three chains with three fetches: with an image per direction, lavapipe
    // fetched from both of an axis's images and kept one (a converged bounce 294 -> 199 ms, README).
    std::vector<GpuImage> directional;
    // R32_UINT, one per axis and level of the directional chains: bit 0 where a texel holds a
    // surface that cones leave along +axis (its front faces +axis, so rays along +axis see it from
    // behind), bit 1 the same for −axis. The chains' "opaque hides what lies behind it" stops
    // there (mips_anisotropic.comp).
    std::vector<GpuImage> leavingSurfaces;
    // RGBA16F (bounces ≠ 1): the light each voxel reflects of what its cones last gathered, scaled
    // as the radiance; the injection adds it for the next bounce.
    GpuImage gatheredLight;
    // RGBA16F with the full mip chain, with ray visibility only: the lit surfaces' planes
    // (shaders_glsl/surface_planes.h), which tell a cone's sample on which side of them it lies.
    GpuImage surfacePlanes;
    Sampler sampler;  // trilinear between mips, transparent black outside the grid
    // The occupied voxels (voxel_grid.h): a uint each, room for every voxel of the grid; and their
    // count with the indirect dispatch over them (glsl::WorkListHeader).
    Buffer occupiedVoxels;
    Buffer occupiedDispatch;

    // The three views of the directional array binding (the isotropic volume stands in when the
    // voxels are isotropic; the shaders then never sample it).
    std::vector<VkImageView> directionalViews() const;
    // The surface planes' view; without ray visibility the radiance volume stands in (the shaders
    // then never sample it).
    VkImageView surfacePlanesView() const;
    // The light cones sample: the radiance, its directional chains and the surface planes that exist.
    std::vector<const GpuImage*> tracedLight() const;
    // Every image above that exists, in voxelVolumeDescs() order.
    std::vector<const GpuImage*> images() const;
    // The two level-0 images of light (radiance, then the gathered light or radiance again where
    // there is none): the voxelizer zeroes them where a voxel is empty.
    std::vector<VkImageView> lightLevelZeroViews() const;
    // What the images' memory requirements asked for, and the occupied-voxel buffers.
    uint64_t allocatedBytes() const;
};

}  // namespace vct
