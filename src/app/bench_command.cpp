// vct bench: error against the path-traced references and GPU time, over a matrix of settings.
// Writes bench.csv, bench.json and bench.svg (error against time, Pareto front, presets) into
// --out-dir, and prints a table with one line per setting; then measures the common VCT failure
// modes (leaking, drift with resolution, flicker) into failure_modes.json, and the side-by-side
// with an OpenGL VCT (bench/comparison.h) into comparison.json. See README, "Benchmark".
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "app/commands.h"
#include "app/options.h"
#include "app/progress_line.h"
#include "app/scene_setup.h"
#include "bench/comparison.h"
#include "bench/failure_report.h"
#include "bench/matrix.h"
#include "bench/measure.h"
#include "bench/report.h"
#include "error.h"
#include "io/output_paths.h"
#include "io/temporary_files.h"
#include "render/camera.h"
#include "render/presets.h"
#include "render/renderer_limits.h"
#include "scene/default_light.h"
#include "scene/load.h"

namespace vct {
namespace {

std::vector<Option> benchOptions() {
    std::vector<Option> options = {
        {"scenes", "A,B", "built-in scenes or glTF files (default: every built-in scene)"},
        {"out-dir", "DIR", "where bench.csv, bench.json and bench.svg go (default bench-results)"},
        {"preset", "NAME", "measure just that preset (" + presetNameList() + ")"},
        {"quick", "", "two cheap settings, for tests (no failure modes)"},
        {"no-failure-modes", "", "skip the leak, shell, closed-block, resolution-drift and flicker measurements"},
        {"comparison", "", "measure only the side-by-side with an OpenGL VCT (1280x720 cornell-sun)"},
        {"no-comparison", "", "skip that side-by-side"},
        {"frames", "N", "measured frames per setting; medians are reported (default 3)"},
        {"warmup", "N", "frames before measuring (default 1)"},
        {"reference-dir", "DIR", "SCENE-direct.pfm and SCENE-indirect.pfm (default assets/reference)"},
    };
    for (const char* shared : {"width", "height", "device", "validate", "gpu-timeout"})
        options.push_back(sharedOption(shared));
    return options;
}

// The references' size.
RenderSettings benchDefaults() { return RenderSettings{.image = {.width = 128, .height = 128}}; }

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> items;
    std::istringstream stream(text);
    for (std::string item; std::getline(stream, item, ',');)
        if (!item.empty()) items.push_back(item);
    return items;
}

std::string sceneFileName(const std::string& scene) {
    return std::filesystem::path(scene).stem().string();  // "cornell" or "model" for "dir/model.glb"
}

}  // namespace

int runBench(const std::vector<std::string>& rawArguments) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<Option> rows = benchOptions();
    const Arguments arguments = parseArguments(rawArguments, rows);
    if (answerHelpOrVersion(arguments, "vct bench [options]", rows, benchDefaults())) return 0;
    // Every argument, scene and folder is checked before the device opens and anything is measured.
    // Only the image size comes from the options: the matrix sets everything else.
    const RenderSettings imageSettings = renderSettingsFromArguments(arguments, rows, benchDefaults());
    const std::vector<bench::BenchSetting> matrix =
        arguments.has("preset")  ? bench::presetMatrix(arguments.text("preset", ""), imageSettings)
        : arguments.has("quick") ? bench::quickMatrix(imageSettings)
                                 : bench::defaultMatrix(imageSettings);
    const std::vector<std::string> scenes =
        arguments.has("scenes") ? splitList(arguments.text("scenes", "")) : builtinSceneNames();
    if (scenes.empty()) throw Error("--scenes names no scene");
    for (const std::string& name : scenes) checkSceneName(name, "--scenes");
    const std::string referenceDir = arguments.text("reference-dir", std::string(VCT_SOURCE_DIR) + "/assets/reference");
    if (arguments.has("reference-dir") && !std::filesystem::is_directory(referenceDir))
        throw Error("--reference-dir '" + referenceDir + "' is not a folder");
    bench::MeasureOptions options;
    options.frames = arguments.unsignedInt("frames", 3, 1, 1000);
    options.warmupFrames = arguments.unsignedInt("warmup", 1, 0, 1000);
    const float gpuTimeout = arguments.number("gpu-timeout", 120.0f, 0.1f, 1e6f);
    const std::string outDir = arguments.text("out-dir", "bench-results");
    prepareOutputFolder(outDir);

    ProgressLine progress("vct bench");
    progress.setStage("opening the device");
    GpuContext context(contextOptionsFromArguments(arguments));
    context.fenceTimeoutSeconds = gpuTimeout;
    bench::RunInfo info;
    info.device = context.deviceName();
    info.width = imageSettings.image.width;
    info.height = imageSettings.image.height;
    info.frames = options.frames;
    info.warmupFrames = options.warmupFrames;
    // The run's files are written together at the end (temporary_files.h): an interrupted run leaves
    // the previous run's set as it was, never new bench files beside an old failure_modes.json.
    std::vector<std::pair<std::string, std::string>> outputs;
    const auto writeOutputs = [&] {
        progress.setStage("writing the results");
        writeFilesAtomically(outputs);
        progress.hideWhile([&] {
            for (const auto& output : outputs) std::printf("wrote %s\n", output.first.c_str());
        });
        outputs.clear();
    };
    const auto measureComparison = [&] {
        progress.setStage("the side-by-side with an OpenGL VCT");
        const std::optional<bench::References> references =
            bench::loadReferences(referenceDir, "cornell-sun", imageSettings.image.width, imageSettings.image.height);
        const bench::ComparisonReport report =
            bench::measureComparison(context, references ? &*references : nullptr, imageSettings.image.width,
                                     imageSettings.image.height, options);
        outputs.emplace_back(outDir + "/comparison.json", bench::comparisonJson(report));
        progress.hideWhile([&] { std::printf("\n%s", bench::comparisonText(report).c_str()); });
    };
    if (arguments.has("comparison")) {
        measureComparison();
        writeOutputs();
        progress.finish();
        if (!context.validationMessages().empty()) throw Error("the validation layer reported problems (see above)");
        return 0;
    }

    // Every scene loads before the first is measured: a broken file fails the run at once.
    std::vector<Scene> loadedScenes;
    for (size_t i = 0; i < scenes.size(); ++i) {
        progress.setStage("loading " + scenes[i]);
        LoadOptions loadOptions;
        loadOptions.bufferLimits = sceneBufferLimits(context);
        Scene scene = loadScene(scenes[i], loadOptions);
        addDefaultSunAndSkyIfUnlit(scene);
        progress.hideWhile([&] {
            for (const std::string& warning : scene.warnings) std::fprintf(stderr, "warning: %s\n", warning.c_str());
        });
        if (scene.cameras.empty()) scene.cameras.push_back(defaultCamera(scene.bounds()));
        loadedScenes.push_back(std::move(scene));
    }

    progress.hideWhile([&] {
        std::printf("vct bench: %zu settings × %zu scenes at %ux%u on %s\n", matrix.size(), scenes.size(),
                    imageSettings.image.width, imageSettings.image.height, info.device.c_str());
    });

    const size_t total = matrix.size() * scenes.size();
    size_t measured = 0;
    std::string sceneStage;
    options.onMeasured = [&](const bench::Measurement& m) {
        progress.hideWhile([&] {
            std::printf("  %-16s %-34s %8.1f ms static %8.1f ms light (%u bounces, %.0f ms each)", m.scene.c_str(),
                        m.setting.label.c_str(), m.staticFrame.gpuMilliseconds, m.lightChangeFrame.cpuMilliseconds,
                        m.bounces, m.bounceMilliseconds);
            if (m.lightMovingFrame)
                std::printf(" %7.1f ms moving light (1/%u bounce)", m.lightMovingFrame->cpuMilliseconds,
                            m.bounceSlices);
            std::printf(" %7.1f ms moving camera", m.cameraMovingFrame.cpuMilliseconds);
            if (m.errors)
                std::printf("   relMSE full %.4f direct %.4f indirect %.4f   ind.lum %.2f shadow %.2f",
                            m.errors->full.relMse, m.errors->direct.relMse, m.errors->indirect.relMse,
                            m.errors->indirect.luminanceRatio, m.errors->shadowedIndirectRatio);
            std::printf("%s\n", m.imagesFinite ? "" : "   NON-FINITE PIXELS");
        });
        ++measured;
        progress.setStage(sceneStage + ", " + std::to_string(measured) + " of " + std::to_string(total) + " measured");
    };
    std::vector<bench::Measurement> measurements;
    for (size_t i = 0; i < scenes.size(); ++i) {
        const std::string& name = scenes[i];
        const Scene& scene = loadedScenes[i];
        const std::optional<bench::References> references = bench::loadReferences(
            referenceDir, sceneFileName(name), imageSettings.image.width, imageSettings.image.height);
        if (references) info.references[scene.name] = *references;
        if (!references)
            progress.hideWhile([&] {
                std::printf("  %s: no %ux%u reference in %s, so no error is reported\n", name.c_str(),
                            imageSettings.image.width, imageSettings.image.height, referenceDir.c_str());
            });
        sceneStage = name + " (scene " + std::to_string(i + 1) + " of " + std::to_string(scenes.size()) + ")";
        progress.setStage(sceneStage + ", " + std::to_string(measured) + " of " + std::to_string(total) + " measured");
        for (bench::Measurement& m :
             bench::measureScene(context, scene, matrix, references ? &*references : nullptr, options)) {
            m.fullImage = {};  // not kept: only the numbers are written
            measurements.push_back(std::move(m));
        }
    }
    info.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    const std::vector<bench::SettingSummary> summary = bench::summarize(measurements);
    outputs.emplace_back(outDir + "/bench.csv", bench::toCsv(measurements));
    outputs.emplace_back(outDir + "/bench.json", bench::toJson(measurements, summary, info));
    outputs.emplace_back(outDir + "/bench.svg", bench::toSvg(summary, info));
    progress.hideWhile([&] {
        std::printf(
            "\nover all scenes: times are means, relMSE (full, direct, indirect light), ind.lum (indirect\n"
            "luminance / reference) and shadow (the same where the reference's direct light is under a\n"
            "tenth of its mean) geometric means\n%s",
            bench::summaryTable(summary).c_str());
        std::printf("measured in %.0f s\n", info.seconds);
    });
    if (!arguments.has("quick") && !arguments.has("no-failure-modes")) {
        // With the preset being measured, else `balanced`.
        const std::string presetName = arguments.text("preset", "balanced");
        const std::optional<RenderSettings> preset = findRenderPreset(presetName);
        RenderSettings settings = preset ? *preset : RenderSettings{};
        settings.image.width = imageSettings.image.width;
        settings.image.height = imageSettings.image.height;
        progress.setStage("the failure modes");
        std::vector<bench::OneBounceTruth> truths;
        for (const Scene& scene : loadedScenes) {
            const auto references = info.references.find(scene.name);
            if (references != info.references.end() && references->second.indirectOneBounce)
                truths.push_back({&scene, &*references->second.indirectOneBounce});
        }
        const auto sunRoom = info.references.find("sun-room");
        const bench::FailureModeReport report = bench::measureFailureModes(
            context, settings, truths, sunRoom != info.references.end() ? &sunRoom->second.indirect : nullptr);
        outputs.emplace_back(outDir + "/failure_modes.json", bench::failureModesJson(report));
        // What each room's camera saw beside each kind of wall on a voxel boundary, to look at.
        for (const bench::FailureModeReport::Leak& leak : report.leaks)
            if (leak.wallOffsetVoxels == 0.0f)
                for (const auto& [room, image] :
                     {std::pair{"lit", &leak.measurement.litRoom}, std::pair{"dark", &leak.measurement.darkRoom}})
                    outputs.emplace_back(
                        outDir + "/leak-" + bench::sharedWallName(leak.wall) + "-" + room + "-room.pfm",
                        pfmBytes(*image));
        progress.hideWhile([&] { std::printf("\n%s", bench::failureModesText(report).c_str()); });
        for (const bench::ResolutionLuminance& r : report.drift)
            if (!r.finite) {
                writeOutputs();  // what was measured, with the failure modes that show the problem
                throw Error("the failure-mode run gave non-finite pixels at " + std::to_string(r.voxelResolution) +
                            "³ voxels");
            }
    }
    if (!arguments.has("quick") && !arguments.has("preset") && !arguments.has("scenes") &&
        !arguments.has("no-comparison"))
        measureComparison();
    writeOutputs();
    progress.finish();
    for (const bench::Measurement& m : measurements)
        if (!m.imagesFinite)
            throw Error("scene '" + m.scene + "', setting '" + m.setting.label + "' gave non-finite pixels");
    if (!context.validationMessages().empty()) throw Error("the validation layer reported problems (see above)");
    return 0;
}

}  // namespace vct
