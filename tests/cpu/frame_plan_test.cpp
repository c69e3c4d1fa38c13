// The frame plan: which passes a frame runs for what changed and the settings (render/frame_plan.h).
#include <gtest/gtest.h>

#include "render/frame_plan.h"

namespace vct {
namespace {

std::vector<std::string> names(const FramePlan& plan) {
    std::vector<std::string> result;
    for (Pass pass : plan.passes) result.push_back(passName(pass));
    return result;
}

using Names = std::vector<std::string>;

TEST(FramePlan, FirstFrameRunsEveryPassInPipelineOrder) {
    RenderSettings reducedDiffuse;
    reducedDiffuse.image.diffuseDownscale = 2;
    EXPECT_EQ(names(planFrame(StaleInputs{}, reducedDiffuse)), (Names{"shadow", "voxelize", "inject", "mips", "bounce",
                                                                      "gbuffer", "diffuse-cones", "shade", "resolve"}));
}

TEST(FramePlan, NothingChangedRunsOnlyTheImagePasses) {
    const StaleInputs nothing{.shadows = false, .voxels = false, .radiance = false, .view = false};
    EXPECT_EQ(names(planFrame(nothing, RenderSettings{})), (Names{"shade", "resolve"}));
}

TEST(FramePlan, OneSamplePerPixelHasNothingToResolve) {
    const StaleInputs nothing{.shadows = false, .voxels = false, .radiance = false, .view = false};
    RenderSettings settings;
    settings.image.supersample = 1;
    EXPECT_EQ(names(planFrame(nothing, settings)), (Names{"shade"})) << "the shading pass's image is the output";
    settings.image.supersample = 2;
    EXPECT_TRUE(planFrame(nothing, settings).runs(Pass::Resolve));
}

TEST(FramePlan, StillFramesToAverageAreResolvedAtOneSamplePerPixel) {
    const StaleInputs nothing{.shadows = false, .voxels = false, .radiance = false, .view = false};
    RenderSettings settings;
    settings.image.supersample = 1;
    settings.shading.diffuseConeTurns = 4;
    EXPECT_TRUE(planFrame(nothing, settings).runs(Pass::Resolve)) << "the resolve keeps the turns' mean";
    settings.shading.mode = RenderMode::Direct;
    EXPECT_FALSE(planFrame(nothing, settings).runs(Pass::Resolve)) << "no cones: every frame is the same image";
    settings.shading.mode = RenderMode::Full;
    settings.shading.diffuseConeCount = 1;
    EXPECT_FALSE(planFrame(nothing, settings).runs(Pass::Resolve)) << "one cone has no ring to turn";
}

TEST(FramePlan, OnlyAChangedViewRedrawsTheGBuffer) {
    const StaleInputs view{.shadows = false, .voxels = false, .radiance = false, .view = true};
    EXPECT_EQ(names(planFrame(view, RenderSettings{})), (Names{"gbuffer", "shade", "resolve"}));
    const StaleInputs light{.shadows = true, .voxels = false, .radiance = true, .view = false};
    EXPECT_FALSE(planFrame(light, RenderSettings{}).runs(Pass::GBuffer));
    EXPECT_FALSE(afterFrame(view, planFrame(view, RenderSettings{}), true).view);
}

TEST(FramePlan, AMovedLightRedrawsShadowsAndReinjectsWithoutRevoxelizing) {
    const StaleInputs light{.shadows = true, .voxels = false, .radiance = true, .view = false};
    EXPECT_EQ(names(planFrame(light, RenderSettings{})),
              (Names{"shadow", "inject", "mips", "bounce", "shade", "resolve"}));
}

TEST(FramePlan, NewVoxelsAreLitEvenWhenNoLightChanged) {
    const StaleInputs geometry{.shadows = false, .voxels = true, .radiance = false};
    const FramePlan plan = planFrame(geometry, RenderSettings{});
    EXPECT_TRUE(plan.runs(Pass::Voxelize));
    EXPECT_TRUE(plan.runs(Pass::Inject));
    EXPECT_TRUE(plan.runs(Pass::Mips));
}

TEST(FramePlan, DirectLightRunsNoVoxelPassAndKeepsThemStale) {
    RenderSettings direct;
    direct.shading.mode = RenderMode::Direct;
    const FramePlan plan = planFrame(StaleInputs{}, direct);
    EXPECT_EQ(names(plan), (Names{"shadow", "gbuffer", "shade", "resolve"}));
    const StaleInputs after = afterFrame(StaleInputs{}, plan, true);
    EXPECT_FALSE(after.shadows);
    EXPECT_TRUE(after.voxels) << "switching indirect light on later must voxelize then";
    EXPECT_TRUE(after.radiance);
}

TEST(FramePlan, ReducedDiffuseConesRunBetweenTheGBufferAndShadingWhenTheImageShowsThem) {
    RenderSettings settings;
    settings.image.diffuseDownscale = 2;
    const StaleInputs nothing{.shadows = false, .voxels = false, .radiance = false};
    EXPECT_EQ(names(planFrame(nothing, settings)), (Names{"gbuffer", "diffuse-cones", "shade", "resolve"}));
    settings.image.diffuseDownscale = 1;
    EXPECT_FALSE(planFrame(nothing, settings).runs(Pass::DiffuseCones)) << "shading traces them itself";
    settings.image.diffuseDownscale = 4;
    settings.shading.components.indirectDiffuse = false;
    EXPECT_FALSE(planFrame(nothing, settings).runs(Pass::DiffuseCones)) << "no diffuse light shown";
    settings.shading.ambientFactor = 0.1f;
    EXPECT_TRUE(planFrame(nothing, settings).runs(Pass::DiffuseCones)) << "the ambient term needs their occlusion";
    settings.shading.debugView = DebugView::VoxelAlbedo;
    EXPECT_FALSE(planFrame(nothing, settings).runs(Pass::DiffuseCones)) << "a debug view shows no light";
    settings.shading.debugView = DebugView::None;
    settings.shading.mode = RenderMode::Direct;
    EXPECT_FALSE(planFrame(nothing, settings).runs(Pass::DiffuseCones));
}

TEST(FramePlan, AmbientOcclusionReadsTheVoxelsOnlyWithAnAmbientTerm) {
    RenderSettings settings;
    settings.shading.components.indirectDiffuse = false;
    settings.shading.components.indirectSpecular = false;
    EXPECT_FALSE(planFrame(StaleInputs{}, settings).runs(Pass::Voxelize));
    settings.shading.ambientFactor = 0.1f;
    EXPECT_TRUE(planFrame(StaleInputs{}, settings).runs(Pass::Voxelize));
}

TEST(FramePlan, VoxelDebugViewsNeedTheVoxelsEvenInDirectMode) {
    RenderSettings settings;
    settings.shading.mode = RenderMode::Direct;
    settings.shading.debugView = DebugView::VoxelAlbedo;
    EXPECT_TRUE(planFrame(StaleInputs{}, settings).runs(Pass::Voxelize));
    settings.shading.debugView = DebugView::Normal;
    EXPECT_FALSE(planFrame(StaleInputs{}, settings).runs(Pass::Voxelize));
}

TEST(FramePlan, BouncesFollowEachInjectionUnlessThereIsOnlyOne) {
    RenderSettings settings;
    settings.resources.bounces = 1;
    EXPECT_FALSE(planFrame(StaleInputs{}, settings).runs(Pass::Bounce));
    settings.resources.bounces = 3;
    EXPECT_TRUE(planFrame(StaleInputs{}, settings).runs(Pass::Bounce));
    settings.resources.bounces = kConvergedBounces;
    EXPECT_TRUE(planFrame(StaleInputs{}, settings).runs(Pass::Bounce));
    const StaleInputs nothing{.shadows = false, .voxels = false, .radiance = false};
    EXPECT_FALSE(planFrame(nothing, settings).runs(Pass::Bounce));
}

TEST(FramePlan, ProgressiveBouncesInjectOncePerFrameUntilTheLightConverges) {
    RenderSettings settings;
    settings.shading.progressiveBounces = true;
    const FramePlan first = planFrame(StaleInputs{}, settings);
    EXPECT_TRUE(first.runs(Pass::Inject));
    EXPECT_FALSE(first.runs(Pass::Bounce)) << "one bounce per frame: the injection is it";
    // Not converged yet: the next frame, though nothing changed, bounces again.
    const StaleInputs settling = afterFrame(StaleInputs{}, first, false);
    EXPECT_TRUE(settling.bounces);
    EXPECT_EQ(names(planFrame(settling, settings)), (Names{"inject", "mips", "shade", "resolve"}));
    // Converged: still frames run no voxel pass.
    const StaleInputs settled = afterFrame(settling, planFrame(settling, settings), true);
    EXPECT_EQ(names(planFrame(settled, settings)), (Names{"shade", "resolve"}));
}

TEST(FramePlan, ProgressiveBouncesSpreadTheirConesOverSlicesOfABoundedSize) {
    RenderSettings settings;
    settings.shading.diffuseConeCount = 6;
    EXPECT_EQ(progressiveSlices(settings, 0), 1u);
    EXPECT_EQ(progressiveSlices(settings, kProgressiveGatherCones / 6), 1u);
    EXPECT_EQ(progressiveSlices(settings, kProgressiveGatherCones / 6 + 1), 2u);
    // Every slice traces at most the budget's cones, and the slices cover every voxel.
    for (uint32_t voxels : {1000u, 25000u, 100000u, 16777216u}) {
        const uint64_t slices = progressiveSlices(settings, voxels);
        EXPECT_LE((voxels + slices - 1) / slices * 6, uint64_t(kProgressiveGatherCones) + 6) << voxels;
    }
    settings.shading.progressiveSlices = 3;
    EXPECT_EQ(progressiveSlices(settings, 25000), 3u) << "a setting overrides the budget";
}

TEST(FramePlan, AfterAFullFrameNothingIsStale) {
    const FramePlan plan = planFrame(StaleInputs{}, RenderSettings{});
    EXPECT_EQ(afterFrame(StaleInputs{}, plan, true),
              (StaleInputs{.shadows = false, .voxels = false, .radiance = false, .bounces = false, .view = false}));
}

TEST(FramePlan, SkippedPassesAreTheRestInPipelineOrder) {
    const StaleInputs nothing{.shadows = false, .voxels = false, .radiance = false};
    const std::vector<Pass> skipped = planFrame(nothing, RenderSettings{}).skipped();
    EXPECT_EQ(skipped, (std::vector<Pass>{Pass::Shadow, Pass::Voxelize, Pass::Inject, Pass::Mips, Pass::Bounce,
                                          Pass::DiffuseCones}));
}

}  // namespace
}  // namespace vct
