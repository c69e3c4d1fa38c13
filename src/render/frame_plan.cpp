#include "render/frame_plan.h"

#include <algorithm>

namespace vct {

const char* passName(Pass pass) {
    switch (pass) {
        case Pass::Shadow: return "shadow";
        case Pass::Voxelize: return "voxelize";
        case Pass::Inject: return "inject";
        case Pass::Mips: return "mips";
        case Pass::Bounce: return "bounce";
        case Pass::GBuffer: return "gbuffer";
        case Pass::DiffuseCones: return "diffuse-cones";
        case Pass::Shade: return "shade";
        case Pass::Resolve: return "resolve";
    }
    return "?";
}

bool FramePlan::runs(Pass pass) const { return std::find(passes.begin(), passes.end(), pass) != passes.end(); }

std::vector<Pass> FramePlan::skipped() const {
    std::vector<Pass> skipped;
    for (Pass pass : kPipelineOrder)
        if (!runs(pass)) skipped.push_back(pass);
    return skipped;
}

FramePlan planFrame(const StaleInputs& stale, const RenderSettings& settings) {
    const bool voxelsRead = needsVoxels(settings.shading);
    const bool voxelize = voxelsRead && stale.voxels;
    const uint32_t bounces = settings.resources.bounces;
    const bool progressive = bouncesProgressively(settings);
    const bool inject = voxelsRead && (stale.radiance || voxelize || (progressive && stale.bounces));
    FramePlan plan;
    for (Pass pass : kPipelineOrder) {
        bool run = true;
        if (pass == Pass::Shadow) run = stale.shadows;
        if (pass == Pass::GBuffer) run = stale.view;
        if (pass == Pass::Voxelize) run = voxelize;
        if (pass == Pass::Inject || pass == Pass::Mips) run = inject;
        if (pass == Pass::Bounce) run = inject && bounces != 1 && !progressive;
        if (pass == Pass::DiffuseCones)
            run = settings.image.diffuseDownscale > 1 && needsDiffuseCones(settings.shading);
        if (pass == Pass::Resolve) run = resolvesImage(settings);
        if (run) plan.passes.push_back(pass);
    }
    return plan;
}

StaleInputs afterFrame(const StaleInputs& stale, const FramePlan& plan, bool converged) {
    StaleInputs after = stale;
    if (plan.runs(Pass::Shadow)) after.shadows = false;
    if (plan.runs(Pass::Voxelize)) after.voxels = false;
    if (plan.runs(Pass::GBuffer)) after.view = false;
    if (plan.runs(Pass::Inject)) {
        after.radiance = false;
        after.bounces = !converged;
    }
    return after;
}

}  // namespace vct
