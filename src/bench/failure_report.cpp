#include "bench/failure_report.h"

#include <algorithm>
#include <cstdio>

#include "bench/matrix.h"
#include "io/json_text.h"
#include "scene/load.h"

namespace vct::bench {
namespace {

std::string format(const char* pattern, auto... values) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, values...);
    return text;
}

// (max − min) / mean of the measured luminances.
double spread(const std::vector<ResolutionLuminance>& drift) {
    if (drift.empty()) return 0.0;
    double lowest = drift[0].meanLuminance, highest = lowest, sum = 0.0;
    for (const ResolutionLuminance& r : drift) {
        lowest = std::min(lowest, r.meanLuminance);
        highest = std::max(highest, r.meanLuminance);
        sum += r.meanLuminance;
    }
    return sum > 0.0 ? (highest - lowest) / (sum / double(drift.size())) : 0.0;
}

}  // namespace

FailureModeReport measureFailureModes(GpuContext& context, const RenderSettings& settings,
                                      const std::vector<OneBounceTruth>& truths, const Image* sunRoomIndirect) {
    FailureModeReport report;
    report.setting = settingLabel(settings);

    // The fitted grid gives the leak measurement its voxel size (the two rooms span 2 m along x).
    const float voxel = twoRoomVoxelSize(settings.resources.voxelResolution);
    for (SharedWall wall : kSharedWalls)
        for (float offset : {0.0f, 1.0f / 3.0f, -0.5f})
            report.leaks.push_back({wall, offset, measureLightLeak(context, settings, offset * voxel, wall)});
    for (float thickness : {1.0f, 2.0f, 4.0f})
        report.thickWalls.push_back(
            {thickness,
             measureLightLeak(context, settings, makeTwoRoomScene(0.0f, SharedWall::TwoFaces, thickness * voxel))});
    if (sunRoomIndirect) report.shelledRoomIndirect = measureShelledRoomIndirect(context, settings, *sunRoomIndirect);
    report.insideBlock = measureInsideClosedBlock(context, settings);

    const Scene cornell = loadScene("cornell");
    RenderSettings indirect = settings;
    indirect.shading.mode = RenderMode::Indirect;
    // The first bounce, against its own truth: converging at 256³ would take minutes on lavapipe,
    // and each later bounce repeats the first one's error.
    RenderSettings firstBounce = indirect;
    firstBounce.resources.bounces = 1;
    report.drift = measureResolutionDrift(context, cornell, firstBounce, {32, 64, 128, 256});

    report.selfIllumination = measureSelfIllumination(context, settings);
    report.flickerFull = measureFlicker(context, cornell, settings, 0.001f, 0.001f);
    report.flickerIndirect = measureFlicker(context, cornell, indirect, 0.001f, 0.001f);
    for (const OneBounceTruth& truth : truths) {
        report.firstBounces.push_back(
            {truth.scene->name, measureFirstBounce(context, *truth.scene, settings, *truth.reference)});
        if (truth.scene->name == "cornell") report.driftReference = meanLuminance(*truth.reference);
    }
    return report;
}

std::string failureModesText(const FailureModeReport& report) {
    std::string text = "failure modes (" + report.setting + "):\n";
    for (const FailureModeReport::Leak& leak : report.leaks)
        text += format(
            "  leak, %s wall %+.2f voxel into its voxel: dark room %.4f of the lit room (truth 0), lit room %.3f\n",
            sharedWallName(leak.wall), double(leak.wallOffsetVoxels), leak.measurement.leakRatio(),
            leak.measurement.litRoomLuminance);
    for (const FailureModeReport::ThickWall& wall : report.thickWalls)
        text +=
            format("  leak, two faces %.0f voxel(s) apart: dark room %.4f of the lit room (truth 0), lit room %.3f\n",
                   double(wall.thicknessVoxels), wall.measurement.leakRatio(), wall.measurement.litRoomLuminance);
    if (report.shelledRoomIndirect)
        text += format("  sun room in a sunlit shell %.2f m out: indirect light %.3f × the sun room's (truth 1)\n",
                       double(kShellGap), *report.shelledRoomIndirect);
    text += format("  camera inside a closed block: %.4f of the room's light (truth 0), direct %.4f\n",
                   report.insideBlock.ratio(), report.insideBlock.insideDirect);
    for (const ResolutionLuminance& r : report.drift) {
        text += format("  Cornell first bounce at %3u³: mean luminance %.4f", r.voxelResolution, r.meanLuminance);
        if (report.driftReference > 0.0)
            text += format(" (%.3f × path-traced one bounce)", r.meanLuminance / report.driftReference);
        text += r.finite ? "\n" : "  NON-FINITE PIXELS\n";
    }
    text += format("  spread over resolutions (max − min) / mean: %.3f\n", spread(report.drift));
    text += format("  self-illumination, lone sunlit plane: indirect %.4f of its direct light (truth 0)\n",
                   report.selfIllumination.ratio());
    text += format(
        "  flicker, 1 mm steps (relative L1 change): full camera %.4f light %.4f, indirect camera %.4f "
        "light %.4f\n",
        report.flickerFull.cameraChange, report.flickerFull.lightChange, report.flickerIndirect.cameraChange,
        report.flickerIndirect.lightChange);
    for (const FailureModeReport::SceneFirstBounce& scene : report.firstBounces)
        text += format("  first bounce, %s: %.3f × its path-traced one bounce, relMSE %.4f%s\n", scene.scene.c_str(),
                       scene.firstBounce.error.luminanceRatio, scene.firstBounce.error.relMse,
                       scene.firstBounce.finite ? "" : "  NON-FINITE PIXELS");
    return text;
}

std::string failureModesJson(const FailureModeReport& report) {
    std::string json = "{\n  \"setting\": " + jsonString(report.setting) + ",\n  \"leak\": [";
    for (size_t i = 0; i < report.leaks.size(); ++i) {
        const FailureModeReport::Leak& leak = report.leaks[i];
        json += std::string(i ? "," : "") + "\n    {\"wall\": " + jsonString(sharedWallName(leak.wall)) +
                ", \"wall_offset_voxels\": " + jsonNumber(leak.wallOffsetVoxels) +
                ", \"lit_room\": " + jsonNumber(leak.measurement.litRoomLuminance) +
                ", \"dark_room\": " + jsonNumber(leak.measurement.darkRoomLuminance) +
                ", \"ratio\": " + jsonNumber(leak.measurement.leakRatio()) + "}";
    }
    json += "\n  ],\n  \"thick_walls\": [";
    for (size_t i = 0; i < report.thickWalls.size(); ++i) {
        const FailureModeReport::ThickWall& wall = report.thickWalls[i];
        json += std::string(i ? "," : "") + "\n    {\"thickness_voxels\": " + jsonNumber(wall.thicknessVoxels) +
                ", \"lit_room\": " + jsonNumber(wall.measurement.litRoomLuminance) +
                ", \"dark_room\": " + jsonNumber(wall.measurement.darkRoomLuminance) +
                ", \"ratio\": " + jsonNumber(wall.measurement.leakRatio()) + "}";
    }
    json += "\n  ],";
    if (report.shelledRoomIndirect)
        json += "\n  \"shelled_room\": {\"gap_m\": " + jsonNumber(kShellGap) +
                ", \"indirect_over_truth\": " + jsonNumber(*report.shelledRoomIndirect) + "},";
    json += "\n  \"inside_closed_block\": {\"usual\": " + jsonNumber(report.insideBlock.usualLuminance) +
            ", \"inside\": " + jsonNumber(report.insideBlock.insideLuminance) +
            ", \"inside_direct\": " + jsonNumber(report.insideBlock.insideDirect) +
            ", \"ratio\": " + jsonNumber(report.insideBlock.ratio()) + "},";
    json +=
        "\n  \"resolution_drift\": {\n    \"scene\": \"cornell\", \"mode\": \"indirect, first bounce\", "
        "\"reference_luminance\": " +
        jsonNumber(report.driftReference) + ", \"spread\": " + jsonNumber(spread(report.drift)) +
        ",\n    \"resolutions\": [";
    for (size_t i = 0; i < report.drift.size(); ++i) {
        const ResolutionLuminance& r = report.drift[i];
        json += std::string(i ? "," : "") + "\n      {\"voxels\": " + std::to_string(r.voxelResolution) +
                ", \"luminance\": " + jsonNumber(r.meanLuminance) + ", \"finite\": " + (r.finite ? "true" : "false") +
                "}";
    }
    json +=
        "\n    ]\n  },\n  \"self_illumination\": {\"direct\": " + jsonNumber(report.selfIllumination.directLuminance) +
        ", \"indirect\": " + jsonNumber(report.selfIllumination.indirectLuminance) +
        ", \"ratio\": " + jsonNumber(report.selfIllumination.ratio()) + "},";
    json +=
        "\n  \"flicker\": {\"step_m\": 0.001, \"full\": {\"camera\": " + jsonNumber(report.flickerFull.cameraChange) +
        ", \"light\": " + jsonNumber(report.flickerFull.lightChange) +
        "}, \"indirect\": {\"camera\": " + jsonNumber(report.flickerIndirect.cameraChange) +
        ", \"light\": " + jsonNumber(report.flickerIndirect.lightChange) + "}},";
    json += "\n  \"first_bounce\": [";
    for (size_t i = 0; i < report.firstBounces.size(); ++i) {
        const FailureModeReport::SceneFirstBounce& scene = report.firstBounces[i];
        json += std::string(i ? "," : "") + "\n    {\"scene\": " + jsonString(scene.scene) +
                ", \"luminance_ratio\": " + jsonNumber(scene.firstBounce.error.luminanceRatio) +
                ", \"relmse\": " + jsonNumber(scene.firstBounce.error.relMse) +
                ", \"finite\": " + (scene.firstBounce.finite ? "true" : "false") + "}";
    }
    json += "\n  ]\n}\n";
    return json;
}

}  // namespace vct::bench
