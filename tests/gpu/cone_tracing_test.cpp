// The cone tracer and the mip chain on synthetic radiance volumes with known answers, apart
// from voxelization and light injection (Crassin et al. 2011, sections 3–4).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <memory>
#include <random>

#include <glm/gtc/packing.hpp>

#include "bindings.h"
#include "gpu/commands.h"
#include "gpu/pass_uses.h"
#include "gpu/pipelines.h"
#include "gpu/readback.h"
#include "gpu_test.h"
#include "gpu_types.h"
#include "render/cone_tracing_pipeline.h"
#include "render/mips_pass.h"
#include "render/sky_image.h"
#include "render/voxel_grid_fit.h"
#include "render/voxel_volumes.h"
#include "sampling.h"

namespace vct::test {
namespace {

constexpr uint32_t kResolution = 64;

struct Probe {
    glm::vec4 origin;
    glm::vec4 direction;
};

// A radiance volume filled from the CPU (level 0), with its mips built by the real MipsPass,
// and a compute pipeline that traces probe cones through it.
class ConeTracing : public GpuTest {
protected:
    void SetUp() override {
        GpuTest::SetUp();
        // The renderer's own volumes (level 0 + mips, six directional chains); level 0 is filled here.
        volumes = std::make_unique<VoxelVolumes>(gpu(), ResourceSettings{.voxelResolution = kResolution});
        voxels.assign(size_t(kResolution) * kResolution * kResolution, glm::vec4(0.0f));
        // The grid spans [0, 64]³ in world units: one voxel = one unit.
        grid.origin = glm::vec3(0.0f, 0.0f, 0.0f);
        grid.voxelSize = 1.0f;
        grid.resolution = kResolution;
        grid.mipLevels = voxelMipCount(kResolution);
    }

    const GpuImage& volume() const { return volumes->radiance; }

    glm::vec4& voxel(int x, int y, int z) { return voxels[size_t(x) + kResolution * (size_t(y) + kResolution * z)]; }
    glm::vec4& normalAt(int x, int y, int z) {
        if (normals.empty()) normals.assign(voxels.size(), glm::vec4(0.0f));
        return normals[size_t(x) + kResolution * (size_t(y) + kResolution * z)];
    }

    // Uploads a level-0 volume (RGBA16F) from the CPU into `image`.
    void upload(VkCommandBuffer commands, Buffer& staging, const GpuImage& image,
                const std::vector<glm::vec4>& values) {
        std::vector<uint16_t> halves;
        for (const glm::vec4& v : values)
            for (int c = 0; c < 4; ++c) halves.push_back(glm::packHalf1x16(v[c]));
        staging = Buffer(gpu(), halves.size() * 2, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
        std::memcpy(staging.mapped, halves.data(), halves.size() * 2);
        PassUses().use(image, access::transferWrite).record(commands);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {kResolution, kResolution, kResolution};
        vkCmdCopyBufferToImage(commands, staging.buffer, image.image, access::transferWrite.layout, 1, &region);
    }

    // Uploads level 0 (and the voxels' normals: zero unless a test sets them, which makes every
    // voxel two-sided for the directional mips) and builds the mips on the GPU.
    void buildVolume() {
        if (normals.empty()) normals.assign(voxels.size(), glm::vec4(0.0f));
        Buffer radianceStaging, normalStaging;
        MipsPass mips(gpu());
        submitAndWait(gpu(), [&](VkCommandBuffer commands) {
            upload(commands, radianceStaging, volume(), voxels);
            upload(commands, normalStaging, volumes->normal, normals);
            mips.record(commands, *volumes, rayVisibility);
        });
    }

    glsl::FrameConstants frameConstants() const {
        glsl::FrameConstants frame{};
        frame.grid = grid;
        frame.coneTanHalfAperture = std::tan(glm::radians(0.5f * diffuseAperture));
        frame.coneStep = coneStep;
        frame.coneMaxDistance = coneMaxDistance;
        frame.coneStartOffset = 1.0f;
        frame.aoFalloff = aoFalloff;
        frame.coneStopOpacity = stopOpacity;
        frame.diffuseCentreWeight = 0.25f;
        frame.radianceScale = 1.0f;
        frame.diffuseConeCount = 6;
        frame.componentFlags =
            (rayVisibility ? glsl::RAY_VISIBILITY : 0u) | (anisotropic ? glsl::ANISOTROPIC_VOXELS : 0u);
        ShadingSettings shading;
        shading.diffuseConeTurns = coneTurns;
        const DiffuseBeam beam = diffuseBeamOfTurn(shading, rayVisibility, turn);
        frame.diffuseRingTurn = float(turn) / float(coneTurns);
        frame.diffuseBeam = beam.beam;
        frame.diffuseBeamAzimuth = beam.azimuth;
        return frame;
    }

    std::vector<glm::vec4> trace(const std::vector<Probe>& probes) {
        GpuContext& context = gpu();
        const glsl::FrameConstants constants = frameConstants();
        Buffer frame(context, sizeof(constants), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
        std::memcpy(frame.mapped, &constants, sizeof(constants));
        Buffer probeBuffer(context, probes.size() * sizeof(Probe), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true);
        std::memcpy(probeBuffer.mapped, probes.data(), probes.size() * sizeof(Probe));
        Buffer results(context, probes.size() * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true);
        // Made once per variant: lavapipe compiles it in about half a second.
        std::unique_ptr<Pipeline>& made = probePipelines[skipEmptySpace ? 1 : 0];
        if (!made)
            made = std::make_unique<Pipeline>(
                createComputePipeline(context, "cone_probe.comp", {}, coneTracingSpecialization(skipEmptySpace)));
        const Pipeline& pipeline = *made;
        const SkyImage sky(context, nullptr);  // the uniform sky of frame.environment
        const uint32_t count = uint32_t(probes.size());
        submitAndWait(context, [&](VkCommandBuffer commands) {
            PassUses uses;
            for (const GpuImage* light : volumes->tracedLight()) uses.use(*light, access::computeRead);
            uses.record(commands);
            vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline);
            DescriptorPush()
                .sampledImages(glsl::DIRECTIONAL_VOXELS_BINDING, volumes->directionalViews(), volumes->sampler.sampler,
                               VK_IMAGE_LAYOUT_GENERAL)
                .buffer(glsl::FRAME_BINDING, frame.buffer, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
                .sampledImage(glsl::VOXEL_RADIANCE_BINDING, volume().view, volumes->sampler.sampler,
                              VK_IMAGE_LAYOUT_GENERAL)
                .buffer(glsl::CONE_PROBES_BINDING, probeBuffer.buffer)
                .buffer(glsl::CONE_PROBE_RESULTS_BINDING, results.buffer)
                .sampledImage(glsl::SKY_BINDING, sky.view(), sky.sampler())
                .push(context, commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
            vkCmdPushConstants(commands, pipeline.layout, VK_SHADER_STAGE_ALL, 0, sizeof(count), &count);
            vkCmdDispatch(commands, (count + 63) / 64, 1, 1);
        });
        const glm::vec4* mapped = static_cast<const glm::vec4*>(results.mapped);
        return std::vector<glm::vec4>(mapped, mapped + count);
    }

    std::unique_ptr<VoxelVolumes> volumes;
    std::unique_ptr<Pipeline> probePipelines[2];  // cone_probe.comp without and with empty-space skipping
    std::vector<glm::vec4> voxels;
    std::vector<glm::vec4> normals;  // per voxel: mean normal (xyz), as the voxelizer writes it
    glsl::VoxelGridParams grid{};
    float coneStep = 0.5f;
    float coneMaxDistance = 2.0f * kResolution;  // voxels
    float diffuseAperture = 60.0f;               // degrees, each of the diffuse set's cones
    float stopOpacity = 0.95f;
    float aoFalloff = 0.0f;
    bool skipEmptySpace = true;
    bool anisotropic = true;     // the renderer's default
    bool rayVisibility = false;  // ResourceSettings::rayVisibility, off by default
    uint32_t coneTurns = 1;      // ShadingSettings::diffuseConeTurns
    uint32_t turn = 0;           // the turn of them the probes trace
};

TEST_F(ConeTracing, MipsEqualCpuDownsampleWithinFloat16Rounding) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (glm::vec4& v : voxels) {
        const float opacity = unit(random) < 0.3f ? 1.0f : 0.0f;
        v = glm::vec4(unit(random), unit(random), unit(random), 1.0f) * opacity;
    }
    buildVolume();
    std::vector<glm::vec4> expected = voxels;
    for (uint32_t level = 1, size = kResolution / 2; size >= 1; ++level, size /= 2) {
        std::vector<glm::vec4> coarser(size_t(size) * size * size);
        const uint32_t finer = size * 2;
        for (uint32_t z = 0; z < size; ++z)
            for (uint32_t y = 0; y < size; ++y)
                for (uint32_t x = 0; x < size; ++x) {
                    glm::vec4 sum(0.0f);
                    for (int c = 0; c < 8; ++c)
                        sum += expected[(2 * x + (c & 1)) +
                                        finer * ((2 * y + ((c >> 1) & 1)) + finer * (2 * z + (c >> 2)))];
                    coarser[x + size * (y + size * z)] = sum * 0.125f;
                }
        expected = coarser;
        const std::vector<glm::vec4> actual = readImage3D(gpu(), volume(), level);
        ASSERT_EQ(actual.size(), expected.size());
        for (size_t i = 0; i < actual.size(); ++i)
            for (int c = 0; c < 4; ++c)  // each level rounds to float16 once more: allow a few ulps
                ASSERT_NEAR(actual[i][c], expected[i][c], 4e-3f * std::max(expected[i][c], 0.25f))
                    << "level " << level << " texel " << i;
        if (size == 1) break;
    }
}

TEST_F(ConeTracing, EmptyGridGivesNoLightAndNoOcclusion) {
    buildVolume();
    const std::vector<glm::vec4> results =
        trace({{glm::vec4(16, 16, 16, 1), glm::vec4(0, 1, 0, 0)},
               {glm::vec4(3, 5, 7, 0), glm::vec4(glm::normalize(glm::vec3(1, 1, 1)), 0.5f)}});
    for (const glm::vec4& result : results) EXPECT_EQ(result, glm::vec4(0.0f));
}

TEST_F(ConeTracing, OpaqueWallInFrontGivesFullOcclusion) {
    // An opaque black wall filling everything from y = 20 up (thin walls are the light-leaking
    // case, measured by the benchmark).
    for (int z = 0; z < int(kResolution); ++z)
        for (int x = 0; x < int(kResolution); ++x)
            for (int y = 20; y < int(kResolution); ++y) voxel(x, y, z) = glm::vec4(0, 0, 0, 1);
    stopOpacity = 1.0f;
    buildVolume();
    // Three voxels below the wall, facing it: every diffuse cone (the 60° ones too) meets the wall
    // far from the grid's edges, and so does a narrow cone along the normal.
    const std::vector<glm::vec4> results = trace(
        {{glm::vec4(32, 17, 32, 1), glm::vec4(0, 1, 0, 0)}, {glm::vec4(32, 17, 32, 0), glm::vec4(0, 1, 0, 0.05f)}});
    EXPECT_GT(results[0].a, 0.97f) << "diffuse cones";
    EXPECT_GT(results[1].a, 0.99f) << "narrow cone";
    EXPECT_EQ(glm::vec3(results[0]), glm::vec3(0.0f));
}

// A closed box, walls two voxels thick, every wall voxel radiating L. Every cone must end on a
// wall, so the exact gathered radiance is L (the weights sum to 1) and the irradiance πL.
class EmittingEnclosure : public ConeTracing {
protected:
    const glm::vec3 radiance{0.5f, 1.0f, 2.0f};
    void buildEnclosure() {
        for (int z = 2; z < 30; ++z)
            for (int y = 2; y < 30; ++y)
                for (int x = 2; x < 30; ++x) {
                    const bool inside = x >= 4 && x < 28 && y >= 4 && y < 28 && z >= 4 && z < 28;
                    if (!inside) voxel(x, y, z) = glm::vec4(radiance, 1.0f);
                }
    }
    std::vector<glm::vec4> gather() {
        buildEnclosure();
        buildVolume();
        std::vector<Probe> probes;
        for (glm::vec3 normal : {glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), glm::normalize(glm::vec3(1, 1, 0)),
                                 glm::normalize(glm::vec3(1, -2, 3))})
            probes.push_back({glm::vec4(16, 16, 16, 1), glm::vec4(normal, 0)});
        return trace(probes);
    }
    // A black floor facing up (one-sided voxels, as the voxelizer writes a surface) in the box, lying on
    // the box's bottom wall as a room's floor lies on its slab: `slab` is that wall's radiance. The
    // cones start 1.5 voxels above the floor, as the renderer starts them (coneStartOffset at 64³);
    // the floor's surface runs through its voxels' centres (y = 4.5).
    std::vector<glm::vec4> gatherOnABlackFloor(glm::vec3 slab) {
        buildEnclosure();
        for (int z = 2; z < 30; ++z)
            for (int x = 2; x < 30; ++x)
                for (int y = 2; y < 4; ++y) voxel(x, y, z) = glm::vec4(slab, 1.0f);
        for (int z = 4; z < 28; ++z)
            for (int x = 4; x < 28; ++x) {
                voxel(x, 4, z) = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
                normalAt(x, 4, z) = glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
            }
        buildVolume();
        std::vector<Probe> probes;
        for (glm::vec2 at : {glm::vec2(16, 16), glm::vec2(8, 20), glm::vec2(22, 9)})
            probes.push_back({glm::vec4(at.x, 6.0f, at.y, 2), glm::vec4(0, 1, 0, 1.5f)});
        return trace(probes);
    }
};

TEST_F(EmittingEnclosure, AnisotropicVoxelsGatherTheRadianceAtEveryStepSize) {
    // 60° cones sample coarse texels that blend the wall with the empty space beyond it; the
    // directional mips make the texel behind an opaque one opaque too, so a cone that reaches a
    // wall stops in it whatever its step (0.68 / 0.71 / 0.84 L at steps 0.25 / 0.5 / 1 without).
    for (float step : {0.25f, 0.5f, 1.0f}) {
        coneStep = step;
        voxels.assign(voxels.size(), glm::vec4(0.0f));
        for (const glm::vec4& result : gather()) {
            for (int c = 0; c < 3; ++c) {
                EXPECT_GE(result[c], 0.95f * radiance[c]) << "step " << step;
                EXPECT_LE(result[c], 1.0f * radiance[c]) << "step " << step;
                EXPECT_NEAR(result[c] / result.a, radiance[c], 0.01f * radiance[c]) << "colour";
            }
        }
    }
}

TEST_F(EmittingEnclosure, AConeInAnyDirectionEndsOnAWall) {
    // Single cones from inside the box, 400 directions spread over the sphere: each must end on a
    // wall and gather L, the narrow cones of the balanced preset (40°) as well as the default 60°.
    // The box's low walls lie in the grid's outermost coarse texels, as a room's walls do. Measured
    // (mean, least): 40° 0.969 / 0.906, 60° 1.000 / 1.000; before samples inside the grid stopped
    // blending those texels with the transparent border, 0.926 / 0.871 and 0.963 / 0.926. The
    // bounds keep what was reached; the narrow cones still lose up to a tenth in some directions.
    buildEnclosure();
    buildVolume();
    struct Bound {
        float aperture, mean, least;
    };
    for (const Bound bound : {Bound{40.0f, 0.96f, 0.90f}, Bound{60.0f, 0.99f, 0.99f}}) {
        const float aperture = bound.aperture;
        std::vector<Probe> probes;
        for (int i = 0; i < 400; ++i) {
            const float z = 1.0f - 2.0f * (float(i) + 0.5f) / 400.0f, r = std::sqrt(1.0f - z * z);
            const float azimuth = float(i) * 2.39996f;  // the golden angle
            const glm::vec3 direction(r * std::cos(azimuth), r * std::sin(azimuth), z);
            probes.push_back(
                {glm::vec4(16.2f, 16.1f, 15.9f, 0), glm::vec4(direction, std::tan(glm::radians(0.5f * aperture)))});
        }
        double sum = 0.0;
        float least = 1.0f;
        for (const glm::vec4& result : trace(probes)) {
            sum += result.g / radiance.g;
            least = std::min(least, result.g / radiance.g);
        }
        const double mean = sum / double(probes.size());
        std::printf("[ enclosure ] %.0f° cones: mean %.3f L, least %.3f L\n", aperture, mean, least);
        EXPECT_GE(mean, bound.mean) << aperture << "° cones";
        EXPECT_GE(least, bound.least) << aperture << "° cones";
        EXPECT_LE(mean, 1.0 + 1e-3) << aperture << "° cones";
    }
}

TEST_F(EmittingEnclosure, ABlackFloorGathersTheWallsLightNotItsOwnVoxels) {
    // A point on the floor must see the emitting walls and ceiling, blocked neither by the floor's
    // own voxels (self-occlusion) nor by the dark slab under it. Measured 0.944 / 0.963 / 0.989 L.
    // Until the directional chains stopped carrying opacity across a surface that cones leave
    // (mips_anisotropic.comp), the slab's opacity stood in front of the floor and this gathered
    // 0.76 L; the test then passed at 0.93 only because the slab emitted L and the floor saw it.
    // The target is 0.95 L: the cones 30-40° off the normal still lose a few percent where
    // they meet the walls near the floor.
    for (const glm::vec4& result : gatherOnABlackFloor(glm::vec3(0.0f)))
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(result[c], 0.94f * radiance[c]);
            EXPECT_LE(result[c], 1.0f * radiance[c]);
        }
}

TEST_F(EmittingEnclosure, AFloorsConesDoNotSeeWhatLiesBehindIt) {
    // The same floor on a slab that emits like the walls: nothing of the slab may reach the cones.
    const std::vector<glm::vec4> overDark = gatherOnABlackFloor(glm::vec3(0.0f));
    voxels.assign(voxels.size(), glm::vec4(0.0f));
    normals.assign(normals.size(), glm::vec4(0.0f));
    const std::vector<glm::vec4> overBright = gatherOnABlackFloor(radiance);
    ASSERT_EQ(overDark.size(), overBright.size());
    for (size_t i = 0; i < overDark.size(); ++i)
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(overBright[i][c], overDark[i][c], 0.01f * radiance[c]) << "probe " << i;
}

TEST_F(EmittingEnclosure, IsotropicVoxelsLetWideConesSeeThroughThinWalls) {
    // The reason anisotropic voxels are the default: averaging opacity over a coarse texel makes
    // a two-voxel wall 2/texel opaque, so 60° cones gather only about a fifth of L (measured 0.21).
    anisotropic = false;
    for (const glm::vec4& result : gather()) {
        EXPECT_LT(result.g, 0.3f * radiance.g);
        EXPECT_NEAR(result.g / result.a, radiance.g, 0.01f * radiance.g) << "colour";
    }
}

TEST_F(ConeTracing, ResultDoesNotDependOnTheStepSize) {
    // A wall 4 voxels thick of radiance 1: opacity correction makes coarse and fine steps agree.
    for (int z = 0; z < int(kResolution); ++z)
        for (int x = 0; x < int(kResolution); ++x)
            for (int y = 20; y < 24; ++y) voxel(x, y, z) = glm::vec4(1, 1, 1, 1) * (y < 22 ? 0.5f : 1.0f);
    buildVolume();
    const Probe probe{glm::vec4(16, 8, 16, 0), glm::vec4(0, 1, 0, 0.2f)};
    coneStep = 0.25f;
    const glm::vec4 fine = trace({probe})[0];
    coneStep = 1.0f;
    const glm::vec4 coarse = trace({probe})[0];
    EXPECT_GT(fine.r, 0.1f);
    EXPECT_NEAR(coarse.r, fine.r, 0.1f * fine.r);
    EXPECT_NEAR(coarse.a, fine.a, 0.1f);
}

TEST_F(ConeTracing, SkippingEmptySpaceChangesNothing) {
    for (int z = 10; z < 14; ++z)
        for (int y = 24; y < 28; ++y)
            for (int x = 10; x < 14; ++x) voxel(x, y, z) = glm::vec4(2, 1, 0.5f, 1);
    buildVolume();
    std::vector<Probe> probes;
    for (int i = 0; i < 16; ++i)
        probes.push_back({glm::vec4(12 + 0.1f * i, 4, 12, float(i % 2)),
                          glm::vec4(glm::normalize(glm::vec3(0.02f * i, 1, 0)), 0.3f)});
    skipEmptySpace = false;
    const std::vector<glm::vec4> marched = trace(probes);
    skipEmptySpace = true;
    const std::vector<glm::vec4> skipped = trace(probes);
    for (size_t i = 0; i < probes.size(); ++i) {
        EXPECT_GT(marched[i].a, 0.0f) << "probe " << i << " should reach the block";
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(skipped[i][c], marched[i][c], 0.05f * marched[i][c] + 1e-4f);
    }
}

// A wall at the cone's maximum distance is met, wherever the cone's growing steps fall: the last
// step lands on the maximum distance. (A step from short of it that went past ended the march
// unsampled: a cone from the Cornell floor stopped 40 voxels below the ceiling at 256³.)
TEST_F(ConeTracing, AConeMeetsAWallAtItsMaximumDistance) {
    for (int z = 0; z < int(kResolution); ++z)
        for (int x = 0; x < int(kResolution); ++x)
            for (int y = 60; y < 62; ++y) voxel(x, y, z) = glm::vec4(1, 1, 1, 1);
    buildVolume();
    // From y = 4 the wall's near face is 56 voxels away; a 0.3 cone steps ~8 voxels there.
    const std::vector<glm::vec4> results = [&] {
        std::vector<glm::vec4> all;
        for (float reach = 56.0f; reach <= 58.0f; reach += 0.25f) {
            coneMaxDistance = reach;
            const std::vector<glm::vec4> one = trace({{glm::vec4(32, 4, 32, 0), glm::vec4(0, 1, 0, 0.3f)}});
            all.push_back(one[0]);
        }
        return all;
    }();
    // Measured: 0.80-0.82 with the last step on the maximum distance; 0.70 at every reach when
    // the march stopped at the sample before it (46.6 voxels out, its footprint grazing the wall).
    for (size_t i = 0; i < results.size(); ++i)
        EXPECT_GT(results[i].a, 0.75f) << "maximum distance " << 56.0f + 0.25f * float(i) << ": the wall was missed";
}

// The two directional chains of an axis share one image, the −z chain two thirds of the way along
// its z (directional_chains.h). A wide cone marching out through the grid's +z face, its footprint
// still overlapping the grid, samples far past the face; unclamped, its coarse samples there
// reached through the empty third into the −z chain and saw a wall that lies behind it.
TEST_F(ConeTracing, AConeLeavingThroughAFaceSeesNothingOfTheOtherDirectionsChain) {
    for (int x = 0; x < int(kResolution); ++x)
        for (int y = 0; y < int(kResolution); ++y) {
            voxel(x, y, 0) = glm::vec4(1, 1, 1, 1);  // a lit wall at the −z face, facing +z
            normalAt(x, y, 0) = glm::vec4(0, 0, 1, 0);
        }
    buildVolume();
    // Along +z the wall is seen from behind (transparent), and nothing else is there.
    const std::vector<glm::vec4> away = trace({{glm::vec4(32, 32, 60, 0), glm::vec4(0, 0, 1, 2.0f)}});
    EXPECT_LT(glm::length(glm::vec3(away[0])), 1e-4f) << "a cone along +z met the wall behind it";
    // The wall is there for a cone that faces it: the test would pass on an empty volume otherwise.
    const std::vector<glm::vec4> towards = trace({{glm::vec4(32, 32, 30, 0), glm::vec4(0, 0, -1, 0.3f)}});
    EXPECT_GT(towards[0].r, 0.5f);
}

// Cones leaving a floor towards a wall: what they gather changes smoothly as their origin slides
// along the floor. Near their surface the cones sample levels finer than their footprint (the
// self-clearance); steps as long as the footprint then skipped whole texels, so the one-voxel wall
// was met more or less fully by where the steps fell, and every wall in the Cornell box showed the
// voxel grid as stripes.
TEST_F(ConeTracing, WhatConesGatherDoesNotStripeWithTheVoxelGrid) {
    for (int z = 0; z < int(kResolution); ++z) {
        for (int x = 0; x < int(kResolution); ++x) {
            voxel(x, 7, z) = glm::vec4(0, 0, 0, 1);  // a black floor, lit from above
            normalAt(x, 7, z) = glm::vec4(0, 1, 0, 0);
        }
        for (int y = 8; y < int(kResolution); ++y) voxel(44, y, z) = glm::vec4(1, 1, 1, 1);  // a glowing wall
    }
    buildVolume();
    std::vector<Probe> probes;
    const float height = 1.5f;  // the renderer's start offset above the floor's voxels
    for (float x = 12.0f; x <= 28.0f; x += 0.25f)
        probes.push_back({glm::vec4(x, 8.0f + height, 32.5f, 2.0f), glm::vec4(0, 1, 0, height)});
    const std::vector<glm::vec4> results = trace(probes);
    // The gathered light grows as the origin nears the wall; a stripe is a bump on that curve:
    // how far each value lies from the mean of its neighbours a voxel either side.
    float worst = 0.0f;
    for (size_t i = 4; i + 4 < results.size(); ++i) {
        const float neighbours = 0.5f * (results[i - 4].r + results[i + 4].r);
        worst = std::max(worst, std::abs(results[i].r - neighbours) / neighbours);
    }
    std::printf("[ stripes ] largest bump %.4f\n", worst);
    // Measured: 0.068 with steps of the footprint's length (flat, then kinked: the wall met in
    // jumps), 0.020 with steps of at most two texels of the finer level (the rest is the curve's own
    // bend near the wall and the footprint's width, which the finer level does not filter).
    EXPECT_LT(worst, 0.035f);
}

// A closed box (inner faces at 4 and 28 voxels, walls two voxels thick, its low walls in the grid's
// outermost coarse texels as a room's are) whose faces are opaque surfaces facing in, one of them
// emitting radiance 1 and the rest black: what a cone or the diffuse set gathers can be compared
// with the exact share of its solid angle, or of the cosine-weighted hemisphere, that meets that
// face (Monte Carlo on the CPU, 40 000 rays, ±0.005).
class BoxWithOneEmittingFace : public ConeTracing {
protected:
    enum Face { MinusX, PlusX, Floor, Ceiling, MinusZ, PlusZ };
    static constexpr int kInnerLow = 4, kInnerHigh = 28, kWall = 2;  // voxels
    static constexpr float kLow = float(kInnerLow), kHigh = float(kInnerHigh);

    void build(Face emitting) {
        voxels.assign(voxels.size(), glm::vec4(0.0f));
        normals.assign(voxels.size(), glm::vec4(0.0f));
        for (int z = kInnerLow - kWall; z < kInnerHigh + kWall; ++z)
            for (int y = kInnerLow - kWall; y < kInnerHigh + kWall; ++y)
                for (int x = kInnerLow - kWall; x < kInnerHigh + kWall; ++x) {
                    const glm::ivec3 v(x, y, z);
                    if (glm::all(glm::greaterThanEqual(v, glm::ivec3(kInnerLow))) &&
                        glm::all(glm::lessThan(v, glm::ivec3(kInnerHigh))))
                        continue;
                    const Face face = y < kInnerLow     ? Floor
                                      : y >= kInnerHigh ? Ceiling
                                      : x < kInnerLow   ? MinusX
                                      : x >= kInnerHigh ? PlusX
                                      : z < kInnerLow   ? MinusZ
                                                        : PlusZ;
                    voxel(x, y, z) = face == emitting ? glm::vec4(1.0f) : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
                    normalAt(x, y, z) = glm::vec4(inwardNormal(face), 0.0f);
                }
        buildVolume();
    }
    static glm::vec3 inwardNormal(Face face) {
        glm::vec3 n(0.0f);
        n[int(face) / 2] = int(face) % 2 == 0 ? 1.0f : -1.0f;
        return n;
    }
    // The face a ray from inside the box meets first.
    static Face faceMet(glm::vec3 from, glm::vec3 direction) {
        float nearest = 1e30f;
        Face met = Floor;
        for (int axis = 0; axis < 3; ++axis) {
            if (std::abs(direction[axis]) < 1e-7f) continue;
            const bool up = direction[axis] > 0.0f;
            const float t = ((up ? kHigh : kLow) - from[axis]) / direction[axis];
            if (t > 0.0f && t < nearest) {
                nearest = t;
                met = Face(2 * axis + (up ? 1 : 0));
            }
        }
        return met;
    }
    // The six cones (0.25 along the normal, 0.15 each around it) against the cosine-weighted share
    // of the hemisphere that meets the emitting face, over nine surface points and faces: the mean
    // |ln(gathered / truth)| for cones of `aperture` degrees, averaged over `turns` turns of the ring.
    double diffuseSetLogError(float aperture, uint32_t turns = 1) {
        struct Case {
            const char* name;
            glm::vec3 surface;
            Face onFace, emitting;
        };
        const Case cases[] = {
            {"floor's middle, ceiling", {16.2f, kLow, 15.9f}, Floor, Ceiling},
            {"floor's middle, a wall", {16.2f, kLow, 15.9f}, Floor, PlusX},
            {"floor by a wall, that wall", {6.0f, kLow, 15.9f}, Floor, MinusX},
            {"floor by a wall, the far wall", {6.0f, kLow, 15.9f}, Floor, PlusX},
            {"floor by a wall, ceiling", {6.0f, kLow, 15.9f}, Floor, Ceiling},
            {"wall's middle, floor", {kLow, 16.1f, 15.9f}, MinusX, Floor},
            {"wall's foot, floor", {kLow, 6.0f, 15.9f}, MinusX, Floor},
            {"wall's top, floor", {kLow, 26.0f, 15.9f}, MinusX, Floor},
            {"wall's middle, the wall across", {kLow, 16.1f, 15.9f}, MinusX, PlusX},
        };
        diffuseAperture = aperture;
        double logError = 0.0;
        for (const Case& c : cases) {
            build(c.emitting);
            const glm::vec3 normal = inwardNormal(c.onFace);
            // The cones leave the surface 1.5 voxels out, as the renderer's do at 64³.
            glm::vec4 gathered(0.0f);
            coneTurns = turns;
            for (turn = 0; turn < turns; ++turn)
                gathered += trace({Probe{glm::vec4(c.surface + 1.5f * normal, 2.0f), glm::vec4(normal, 1.5f)}})[0] /
                            float(turns);
            const float truth = shareMeeting(c.emitting, c.surface, normal, -1.0f);
            std::printf("[ diffuse set ] %.0f°%s, %-30s %.3f, truth %.3f (%.2f×)\n", aperture,
                        rayVisibility ? " rays" : "", c.name, gathered.r, truth, gathered.r / truth);
            EXPECT_GT(gathered.r, 0.0f) << aperture << "°, " << c.name;
            logError += std::abs(std::log(std::max(gathered.r, 1e-6f) / truth));
        }
        const double meanLogError = logError / double(std::size(cases));
        std::printf("[ diffuse set ] %.0f°%s: mean |ln(gathered / truth)| %.3f\n", aperture,
                    rayVisibility ? " rays" : "", meanLogError);
        return meanLogError;
    }

    // The share of rays meeting `face`: uniform over a cone of half-angle `halfAngle` around
    // `axis`, or (halfAngle < 0) cosine-weighted over the hemisphere around it. The path tracer's
    // basis, generator and cosine warp (tools/pathtrace/sampling.h).
    static float shareMeeting(Face face, glm::vec3 from, glm::vec3 axis, float halfAngle) {
        const pt::Frame frame = pt::Frame::around(axis);
        const float cosMax = std::cos(halfAngle);
        int met = 0;
        const int rays = 40000;
        for (int i = 0; i < rays; ++i) {
            pt::Rng random = pt::Rng::forSample(7, 0, uint64_t(i));
            const float u1 = random.uniform(), u2 = random.uniform();
            glm::vec3 local = pt::sampleCosineHemisphere(u1, u2);
            if (halfAngle >= 0.0f) {
                const float cosTheta = 1.0f - u1 * (1.0f - cosMax), sinTheta = std::sqrt(1.0f - cosTheta * cosTheta);
                const float phi = 2.0f * pt::kPi * u2;
                local = glm::vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
            }
            if (faceMet(from, frame.toWorld(local)) == face) ++met;
        }
        return float(met) / float(rays);
    }
};
class BoxWithOneEmittingFaceGuard : public BoxWithOneEmittingFace {};

TEST_F(BoxWithOneEmittingFaceGuard, ASingleConeSeesTheFloorAsMuchAsItsSolidAngleMeetsIt) {
    // 40° cones (the balanced preset's) from the box's middle, turned from straight down to level.
    // Measured: 0.62 / 0.61 / 0.58 / 0.54 / 0.40 / 0.27 / 0.13 / 0.04 / 0.02 / 0.02 against truths
    // 1 / 1 / 1 / 0.91 / 0.64 / 0.32 / 0.06 / 0 / 0 / 0. A cone looking straight at the floor ends
    // at opacity 0.69: the floor lies in the grid's outermost coarse texels, where a sample is read
    // half a coarser texel inside the grid (cone_tracing.glsl), i.e. off the floor (without that
    // inset: 0.73 at opacity 0.78, though the box whose walls all emit gathers less), and trilinear
    // filtering halves an opaque texel's opacity half a texel from it. With the directional chains
    // storing optical depth instead (tried, not kept), these read 0.99 / 0.99 / 0.98 / 0.88 / 0.60 /
    // 0.26 / 0.05 / 0 / 0 / 0. The bounds are regression guards at today's figures; the target is
    // the truth, as ray visibility's diffuse set meets it within 10 % (below).
    build(Floor);
    const glm::vec3 origin(16.2f, 16.1f, 15.9f);
    const float halfAngle = glm::radians(20.0f);
    std::vector<Probe> probes;
    std::vector<float> truths;
    for (int degrees = 0; degrees <= 90; degrees += 10) {
        const float t = glm::radians(float(degrees));
        const glm::vec3 direction(std::sin(t), -std::cos(t), 0.0f);
        probes.push_back({glm::vec4(origin, 0.0f), glm::vec4(direction, std::tan(halfAngle))});
        truths.push_back(shareMeeting(Floor, origin, direction, halfAngle));
    }
    const std::vector<glm::vec4> results = trace(probes);
    for (size_t i = 0; i < probes.size(); ++i) {
        std::printf("[ one cone ] %2zu0° from straight down: %.3f (opacity %.3f), truth %.3f\n", i, results[i].r,
                    results[i].a, truths[i]);
        EXPECT_LE(results[i].r, truths[i] + 0.08f) << i * 10 << "°: more than the floor's share of the cone";
        if (truths[i] >= 0.5f) {
            EXPECT_GE(results[i].r, 0.55f * truths[i]) << i * 10 << "° (regression guard)";
        }
    }
}

TEST_F(BoxWithOneEmittingFaceGuard, WithTheMipsAloneTheDiffuseConesWeighEachFaceAsTheCosineDoes) {
    // The six cones (0.25 along the normal, 0.15 each around it at one aperture from it) against the
    // cosine-weighted share of the hemisphere that meets the emitting face: the quadrature the
    // indirect light rests on, apart from voxelization, injection and bounces. For 60° cones those
    // weights are the cosine's shares of a cap of 30° and of the ring around it: measured 0.83–1.05×
    // the truth where a face fills much of the hemisphere, 1.24 and 1.67× where it lies at the
    // horizon and the ring cones' footprints reach it (mean |ln ratio| 0.17). For 40° cones they
    // are not: the cones cover a third of the hemisphere and leave out its last 30° above the
    // horizon (a quarter of the cosine), so a face across from the surface counts 1.37–1.67× and a
    // face low on its horizon 0.26–0.29× (mean |ln ratio| 0.50). That is the Cornell box's pattern
    // at `balanced`: the ceiling and the top of the walls too bright, the floor by the blocks too
    // dark, cancelling in the mean. The bounds are regression guards at today's figures; the target,
    // 0.10, is ray visibility's (below).
    for (float aperture : {40.0f, 60.0f})
        EXPECT_LE(diffuseSetLogError(aperture), aperture == 60.0f ? 0.20 : 0.55)
            << aperture << "° (regression guard; target 0.10)";
}

TEST_F(BoxWithOneEmittingFace, WithRayVisibilityTheDiffuseConesWeighEachFaceAsTheCosineDoes) {
    // The same with ray visibility: each cone's five beams stop where their rays meet a face, and
    // the ring stands at 56°, where the set integrates the cosine exactly. Measured 0.89–1.16× the
    // truth on every face, mean |ln ratio| 0.078 (40°) and 0.077 (60°). Target: within 10 % on
    // average at either aperture.
    rayVisibility = true;
    for (float aperture : {40.0f, 60.0f}) EXPECT_LE(diffuseSetLogError(aperture), 0.10) << aperture << "°";
}

TEST_F(BoxWithOneEmittingFace, WithRayVisibilityOneBeamATurnWeighsEachFaceAsTheFiveBeamsDo) {
    // `walls` traces one of each cone's five beams a turn over 16 turns of the ring
    // (diffuseBeamOfTurn), a fifth of the five beams' work a frame: their mean must integrate the
    // cosine as the five beams do. Measured mean |ln ratio| 0.034 (the five beams of one turn: 0.080).
    // Target: within 10 % on average, as the five.
    rayVisibility = true;
    EXPECT_LE(diffuseSetLogError(60.0f, 16), 0.10);
}

}  // namespace
}  // namespace vct::test
