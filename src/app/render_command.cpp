// vct render: one image, written as linear radiance (.pfm) or tone-mapped sRGB (.png).
#include <chrono>
#include <cmath>
#include <cstdio>

#include "app/commands.h"
#include "app/options.h"
#include "app/progress_line.h"
#include "app/scene_setup.h"
#include "error.h"
#include "io/display_transform.h"
#include "io/output_paths.h"
#include "render/presets.h"
#include "render/renderer.h"
#include "render/renderer_limits.h"

namespace vct {

static std::vector<Option> renderOptions() {
    std::vector<Option> options = {
        {"out", "FILE.pfm|FILE.png", "linear radiance (.pfm) or a tone-mapped sRGB image (.png)"},
        {"exposure", "EV",
         "PNG only: a fixed exposure, radiance × 2^EV (default: automatic, the image's "
         "log-average luminance at middle grey)"},
        {"tone-curve", "pbr-neutral|aces", "PNG only: Khronos PBR Neutral or ACES filmic (default pbr-neutral)"},
        {"frames", "N", "render N frames, keep the last (default 1)"},
    };
    options.insert(options.end(), sharedOptions().begin(), sharedOptions().end());
    return options;
}

int runRender(const std::vector<std::string>& rawArguments) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<Option> options = renderOptions();
    const Arguments arguments = parseArguments(rawArguments, options);
    const RenderSettings defaults = *findRenderPreset(kDefaultPreset);
    if (answerHelpOrVersion(arguments, "vct render --out FILE.pfm|FILE.png [options]", options, defaults,
                            presetsHelp()))
        return 0;
    // Every argument and the output path first: a mistake is reported at once, not after the
    // scene has loaded and rendered (half a minute on lavapipe).
    if (!arguments.has("out")) throw Error("render needs --out FILE.pfm or FILE.png");
    const std::string outPath = arguments.text("out", "");
    checkOutputFile(outPath, {".pfm", ".png"});
    const bool fixedExposure = arguments.has("exposure");
    const float exposureStops = arguments.number("exposure", 0.0f, -64.0f, 64.0f);
    DisplayTransform display;
    if (arguments.has("tone-curve")) {
        const std::optional<ToneCurve> curve = parseToneCurve(arguments.text("tone-curve", ""));
        if (!curve)
            throw Error("--tone-curve must be pbr-neutral or aces, not '" + arguments.text("tone-curve", "") + "'");
        display.curve = *curve;
    }
    const uint32_t frames = arguments.unsignedInt("frames", 1, 1, 100000);
    const float gpuTimeout = arguments.number("gpu-timeout", 120.0f, 0.1f, 1e6f);
    const RenderSettings settings = renderSettingsFromArguments(arguments, options, defaults);
    checkSceneArguments(arguments);

    ProgressLine progress("vct render");
    progress.setStage("opening the device");
    // The device first: the scene is checked against its buffer limits while it loads.
    GpuContext context(contextOptionsFromArguments(arguments));
    context.fenceTimeoutSeconds = gpuTimeout;
    progress.setStage("loading the scene");
    const Scene scene = loadSceneFromArguments(arguments, sceneBufferLimits(context));
    progress.hideWhile([&] {
        printSceneWarnings(scene);
        std::printf("scene %s: %zu triangles, %zu lights, on %s\n", scene.name.c_str(), scene.triangleCount(),
                    scene.lights.size(), context.deviceName().c_str());
    });

    progress.setStage("preparing the passes");
    Renderer renderer(context, scene, settings);
    FrameStats stats;
    for (uint32_t frame = 0; frame < frames; ++frame) {
        progress.setStage(frames == 1 ? std::string("rendering")
                                      : "frame " + std::to_string(frame + 1) + " of " + std::to_string(frames));
        // The last frame waits for the image to settle, as a still viewer's does: its passes are
        // listed, the frames after it (still samples, turns, settling light) counted.
        stats = frame + 1 < frames ? renderer.renderFrame() : renderer.renderSettled();
    }
    progress.setStage("writing " + outPath);
    const Image image = renderer.readImage();
    display.exposure = fixedExposure ? exposureFromStops(exposureStops) : automaticExposure(image);
    writeImage(outPath, image, display);
    progress.finish();

    for (const PassTime& pass : stats.passes)
        std::printf("  %-10s %8.3f ms GPU\n", pass.name.c_str(), pass.milliseconds);
    for (const std::string& pass : stats.skipped()) std::printf("  %-10s  skipped\n", pass.c_str());
    if (stats.bounces > 0)
        std::printf("  light: %u bounce%s over %u occupied voxels, %s\n", stats.bounces, stats.bounces == 1 ? "" : "s",
                    stats.occupiedVoxels, stats.bouncesConverged ? "converged" : "not converged yet");
    if (stats.settleFrames > 0)
        std::printf("  then %u frame%s until the image settled, %.3f ms GPU together\n", stats.settleFrames,
                    stats.settleFrames == 1 ? "" : "s", stats.settleGpuMilliseconds);
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("wrote %s (%ux%u, %s) in %.2f s; frame %.3f ms GPU\n", outPath.c_str(), image.width, image.height,
                renderModeName(settings.shading.mode), total, stats.gpuMilliseconds());
    if (!endsWithIgnoringCase(outPath, ".pfm"))
        std::printf("  exposure %+.2f EV (%s), %s tone curve\n", std::log2(display.exposure),
                    fixedExposure ? "fixed" : "automatic", toneCurveName(display.curve));
    if (!context.validationMessages().empty()) throw Error("the validation layer reported problems (see above)");
    return 0;
}

}  // namespace vct
