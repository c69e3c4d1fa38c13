#include "bench/comparison.h"

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "io/json_text.h"
#include "scene/load.h"

namespace vct::bench {
namespace {

constexpr float kStepDegrees = 1.0f;  // how far the camera orbits, or the sun turns, each frame

glm::vec3 turnedAboutY(glm::vec3 v, float degrees) {
    return glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0.0f, 1.0f, 0.0f)) *
                     glm::vec4(v, 0.0f));
}

std::string timingJson(const FrameTiming& timing) {
    std::string json = "{\"gpu_ms\": " + jsonNumber(timing.gpuMilliseconds) +
                       ", \"cpu_ms\": " + jsonNumber(timing.cpuMilliseconds) + ", \"passes_ms\": {";
    for (size_t i = 0; i < timing.passes.size(); ++i)
        json += std::string(i ? ", " : "") + jsonString(timing.passes[i].name) + ": " +
                jsonNumber(timing.passes[i].milliseconds);
    return json + "}}";
}

std::string errorJson(const ImageError& error) {
    return "{\"relmse\": " + jsonNumber(error.relMse) + ", \"luminance_ratio\": " + jsonNumber(error.luminanceRatio) +
           "}";
}

}  // namespace

RenderSettings comparisonSettings() {
    RenderSettings settings;
    settings.image = {.width = 1280, .height = 720, .supersample = 1, .diffuseDownscale = 4};
    settings.resources = {.voxelResolution = 128, .sunShadowMapSize = 4096};
    settings.shading.diffuseConeCount = 6;
    settings.shading.diffuseConeAperture = 60.0f;
    settings.shading.coneStep = 1.0f;
    settings.shading.progressiveBounces = true;
    return settings;
}

ComparisonReport measureComparison(GpuContext& context, const References* references, uint32_t referenceWidth,
                                   uint32_t referenceHeight, const MeasureOptions& options) {
    const Scene scene = loadScene("cornell-sun");
    const RenderSettings settings = comparisonSettings();
    ComparisonReport report;
    report.setting = settingLabel(settings);
    report.width = settings.image.width;
    report.height = settings.image.height;
    report.frames = options.frames;
    {
        // Converge the light first, all bounces in the first frame, then run as the viewer does (one
        // bounce a frame): the camera's frames are those of a viewer whose light has settled. Settling
        // progressively, a slice of a bounce a frame, takes a 128³ grid hundreds of frames, and the
        // frames measured before it ended re-injected the light and rebuilt the mips each time.
        RenderSettings converging = settings;
        converging.shading.progressiveBounces = false;
        Renderer renderer(context, scene, converging);
        for (uint32_t i = 0; i < 1 + options.warmupFrames; ++i) renderer.renderFrame();
        renderer.setShading(settings.shading);
        const glm::vec3 target = 0.5f * (scene.bounds().min + scene.bounds().max);
        std::vector<FrameStats> frames;
        // New shading settings trace every block of the reduced diffuse cones once; the frames
        // after reuse a viewer's share of them, as every frame of a moving camera does.
        for (uint32_t i = 0; i < 1 + options.frames; ++i) {
            Camera camera = renderer.camera();
            camera.position = target + turnedAboutY(camera.position - target, kStepDegrees);
            camera.forward = turnedAboutY(camera.forward, kStepDegrees);
            camera.up = turnedAboutY(camera.up, kStepDegrees);
            renderer.setCamera(camera);
            const FrameStats stats = renderer.renderFrame();
            if (i > 0) frames.push_back(stats);
        }
        report.cameraMoving = medianTiming(frames);
        frames.clear();
        for (uint32_t i = 0; i < options.frames; ++i) {
            std::vector<Light> lights = renderer.lights();
            for (Light& light : lights) light.direction = turnedAboutY(light.direction, kStepDegrees);
            renderer.setLights(lights);
            frames.push_back(renderer.renderFrame());
        }
        report.sunMoving = medianTiming(frames);
    }
    if (references) {
        // The same settings where the references are, the light converged as `vct render` does.
        RenderSettings small = settings;
        small.image.width = referenceWidth;
        small.image.height = referenceHeight;
        small.shading.progressiveBounces = false;
        MeasureOptions quiet = options;
        quiet.onMeasured = nullptr;
        const std::vector<Measurement> measured =
            measureScene(context, scene, {{settingLabel(small), "", small}}, references, quiet);
        report.errors = measured.front().errors;
    }
    return report;
}

std::string comparisonText(const ComparisonReport& report) {
    char text[1024];
    int length = std::snprintf(
        text, sizeof text,
        "side by side with the OpenGL VCT of issue 13 (cornell-sun %ux%u, %s; theirs: about 380 ms a frame):\n"
        "  camera moving: %.1f ms GPU, %.1f ms wall a frame\n"
        "  sun moving:    %.1f ms GPU, %.1f ms wall a frame (one bounce a frame)\n",
        report.width, report.height, report.setting.c_str(), report.cameraMoving.gpuMilliseconds,
        report.cameraMoving.cpuMilliseconds, report.sunMoving.gpuMilliseconds, report.sunMoving.cpuMilliseconds);
    if (report.errors && length > 0 && size_t(length) < sizeof text)
        std::snprintf(text + length, sizeof text - size_t(length),
                      "  at the references' size: relMSE full %.4f, indirect %.4f; indirect luminance %.2f × "
                      "path-traced\n",
                      report.errors->full.relMse, report.errors->indirect.relMse,
                      report.errors->indirect.luminanceRatio);
    return text;
}

std::string comparisonJson(const ComparisonReport& report) {
    std::string json = "{\n  \"scene\": \"cornell-sun\", \"setting\": " + jsonString(report.setting) +
                       ", \"width\": " + std::to_string(report.width) +
                       ", \"height\": " + std::to_string(report.height) +
                       ", \"frames\": " + std::to_string(report.frames) + ",\n  \"opengl_reference_ms\": 380" +
                       ",\n  \"camera_moving\": " + timingJson(report.cameraMoving) +
                       ",\n  \"sun_moving\": " + timingJson(report.sunMoving);
    if (report.errors)
        json += ",\n  \"error\": {\"full\": " + errorJson(report.errors->full) +
                ", \"direct\": " + errorJson(report.errors->direct) +
                ", \"indirect\": " + errorJson(report.errors->indirect) + "}";
    return json + "\n}\n";
}

}  // namespace vct::bench
