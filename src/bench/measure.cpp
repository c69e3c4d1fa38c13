#include "bench/measure.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <numeric>
#include <regex>
#include <sstream>

#include "error.h"
#include "render/renderer.h"

namespace vct::bench {
namespace {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const size_t middle = values.size() / 2;
    return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

bool finite(const Image& image) {
    return std::all_of(image.rgb.begin(), image.rgb.end(), [](float v) { return std::isfinite(v); });
}

// A number from a flat JSON object such as the path tracer's sidecar; −1 when it is not there.
double jsonNumber(const std::string& path, const std::string& key) {
    std::ifstream file(path);
    if (!file) return -1.0;
    std::stringstream text;
    text << file.rdbuf();
    std::smatch match;
    const std::string content = text.str();
    if (!std::regex_search(content, match, std::regex("\"" + key + "\"\\s*:\\s*([-+0-9.eE]+)"))) return -1.0;
    return std::stod(match[1].str());
}

}  // namespace

// The lights as they are on even frames, and on odd ones with the first one moved a little: 1 mm
// for a point or spot light, 0.1° for a sun. Its shadow maps are then redrawn, as in the viewer
// while the user steers it (re-setting the same lights redraws none). Area lights move only with
// the geometry.
std::vector<Light> nudgedOnOddFrames(std::vector<Light> lights, uint32_t frame) {
    if (lights.empty() || frame % 2 == 0) return lights;
    Light& light = lights.front();
    if (light.type == LightType::Directional) {
        const float angle = 0.00175f;
        const glm::vec3 d = light.direction;
        light.direction = glm::vec3(std::cos(angle) * d.x + std::sin(angle) * d.z, d.y,
                                    -std::sin(angle) * d.x + std::cos(angle) * d.z);
    } else {
        light.position.x += 0.001f;
    }
    return lights;
}

// The light change of frame `frame` (nudgedOnOddFrames). Where that leaves the lights as they are
// (a first frame, or a scene lit by emissive surfaces alone) the light converges again all the
// same, as a change makes it: Renderer::setLights would do nothing.
void changeLights(Renderer& renderer, const std::vector<Light>& steady, uint32_t frame) {
    const std::vector<Light> lights = nudgedOnOddFrames(steady, frame);
    if (lights == renderer.lights()) renderer.relight();
    else renderer.setLights(lights);
}

FrameTiming medianTiming(const std::vector<FrameStats>& frames) {
    FrameTiming timing;
    std::vector<double> gpu, cpu;
    std::vector<std::string> order;  // pass names in the order they ran
    std::map<std::string, std::vector<double>> perPass;
    for (const FrameStats& frame : frames) {
        gpu.push_back(frame.gpuMilliseconds());
        cpu.push_back(frame.cpuMilliseconds);
        for (const PassTime& pass : frame.passes) {
            if (!perPass.count(pass.name)) order.push_back(pass.name);
            perPass[pass.name].push_back(pass.milliseconds);
        }
    }
    timing.gpuMilliseconds = median(gpu);
    timing.cpuMilliseconds = median(cpu);
    for (const std::string& name : order) timing.passes.push_back({name, median(perPass[name])});
    return timing;
}

std::optional<References> loadReferences(const std::string& directory, const std::string& scene, uint32_t width,
                                         uint32_t height) {
    const std::string base = directory + "/" + scene;
    if (!std::filesystem::exists(base + "-direct.pfm") || !std::filesystem::exists(base + "-indirect.pfm"))
        return std::nullopt;
    References references;
    references.direct = readPfm(base + "-direct.pfm");
    references.indirect = readPfm(base + "-indirect.pfm");
    if (references.direct.width != width || references.direct.height != height || references.indirect.width != width ||
        references.indirect.height != height)
        return std::nullopt;
    references.full = std::filesystem::exists(base + "-full.pfm") ? readPfm(base + "-full.pfm")
                                                                  : addImages(references.direct, references.indirect);
    const std::string oneBounce = base + "-indirect-1bounce.pfm";
    if (std::filesystem::exists(oneBounce)) {
        Image image = readPfm(oneBounce);
        if (image.width == width && image.height == height) references.indirectOneBounce = std::move(image);
    }
    references.directNoise = jsonNumber(base + "-direct.json", "relative_noise");
    references.indirectNoise = jsonNumber(base + "-indirect.json", "relative_noise");
    references.directSpp = uint32_t(std::max(0.0, jsonNumber(base + "-direct.json", "spp")));
    references.indirectSpp = uint32_t(std::max(0.0, jsonNumber(base + "-indirect.json", "spp")));
    return references;
}

std::vector<Measurement> measureScene(GpuContext& context, const Scene& scene,
                                      const std::vector<BenchSetting>& settings, const References* references,
                                      const MeasureOptions& options) {
    // Settings that share a Renderer run one after another; results go back in the caller's order.
    std::vector<size_t> order(settings.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::vector<size_t> group(settings.size());
    for (size_t i = 0; i < settings.size(); ++i) {
        group[i] = i;
        for (size_t j = 0; j < i; ++j)
            if (sameRenderer(settings[j].settings, settings[i].settings)) {
                group[i] = group[j];
                break;
            }
    }
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return group[a] < group[b]; });

    std::vector<Measurement> results(settings.size());
    std::unique_ptr<Renderer> renderer;
    double voxelizeMilliseconds = 0.0;
    for (size_t index : order) {
        const BenchSetting& setting = settings[index];
        if (!renderer || !sameRenderer(renderer->settings(), setting.settings)) {
            renderer.reset();  // one Renderer's memory at a time
            renderer = std::make_unique<Renderer>(context, scene, setting.settings);
            const FrameStats first = renderer->renderFrame();  // everything runs: the warm-up
            voxelizeMilliseconds = 0.0;
            for (const PassTime& pass : first.passes)
                if (pass.name == "voxelize") voxelizeMilliseconds = pass.milliseconds;
            for (uint32_t i = 0; i < options.warmupFrames; ++i) renderer->renderFrame();
        }
        Measurement& m = results[index];
        m.scene = scene.name;
        m.setting = setting;
        m.voxelizeMilliseconds = voxelizeMilliseconds;

        ShadingSettings shading = setting.settings.shading;
        shading.mode = RenderMode::Full;
        renderer->setShading(shading);
        // Light changes first: the first one also re-lights the voxels with this setting's cones
        // (a second bounce gathers with them), so the static frames after it show this setting.
        std::vector<FrameStats> frames;
        const std::vector<Light> steady = renderer->lights();
        for (uint32_t i = 0; i < options.frames; ++i) {
            changeLights(*renderer, steady, i);
            frames.push_back(renderer->renderFrame());
        }
        m.lightChangeFrame = medianTiming(frames);
        if (options.frames % 2 == 0) {  // the last change left the light moved: the images need it back
            renderer->setLights(steady);
            renderer->renderFrame();
        }
        m.bounces = frames.back().bounces;
        m.bouncesConverged = frames.back().bouncesConverged;
        // The image a still viewer converges to (the reused diffuse light traced anew, the ring's
        // turns averaged), then the frames of a still view.
        const auto settleStart = std::chrono::steady_clock::now();
        m.settleFrames = 0;
        for (; renderer->settling() && m.settleFrames < Renderer::kMaxSettleFrames; ++m.settleFrames)
            renderer->renderFrame();
        m.settleMilliseconds =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - settleStart).count();

        frames.clear();
        for (uint32_t i = 0; i < options.frames; ++i) frames.push_back(renderer->renderFrame());
        m.staticFrame = medianTiming(frames);
        // Wall time: a light change spans a submission per bounce, and lavapipe's timestamps miss
        // part of the compute work in them (the bounces' gather: 41 ms a bounce by its timestamps,
        // 560 ms by the clock on the Cornell box at 64³).
        const double relight = m.lightChangeFrame.cpuMilliseconds - m.staticFrame.cpuMilliseconds;
        m.bounceMilliseconds = m.bounces > 0 ? std::max(relight, 0.0) / m.bounces : 0.0;
        m.fullImage = renderer->readImage();
        m.deviceMemoryBytes = renderer->deviceMemoryBytes();

        shading.mode = RenderMode::Direct;
        renderer->setShading(shading);
        renderer->renderSettled();
        const Image direct = renderer->readImage();
        shading.mode = RenderMode::Indirect;
        renderer->setShading(shading);
        renderer->renderSettled();
        const Image indirect = renderer->readImage();
        shading.mode = RenderMode::Full;
        renderer->setShading(shading);

        // The viewer's frame while a light moves: the light sources' light re-injected and one
        // progressive bounce, gathered for a slice of the voxels (last: it leaves the light
        // unconverged, and the next setting starts with a light change).
        if (setting.settings.resources.bounces == kConvergedBounces) {
            ShadingSettings moving = shading;
            moving.progressiveBounces = true;
            renderer->setShading(moving);
            frames.clear();
            for (uint32_t i = 0; i < options.frames; ++i) {
                changeLights(*renderer, steady, i + 1);  // the light moves every frame
                frames.push_back(renderer->renderFrame());
            }
            m.lightMovingFrame = medianTiming(frames);
            m.bounceSlices = frames.back().bounceSlices;
            renderer->setShading(shading);
        }

        const Camera still = renderer->camera();
        Camera walking = still;
        const float step = std::min(5.0f / 30.0f, 0.02f * glm::length(scene.bounds().extent()));
        frames.clear();
        for (uint32_t i = 0; i < options.frames; ++i) {
            walking.position += glm::normalize(walking.forward) * step;
            renderer->setCamera(walking);
            frames.push_back(renderer->renderFrame());
            m.cameraMovingWorstMilliseconds = std::max(m.cameraMovingWorstMilliseconds, frames.back().cpuMilliseconds);
        }
        m.cameraMovingFrame = medianTiming(frames);
        renderer->setCamera(still);
        renderer->renderFrame();  // the next setting's light change starts from the still view

        m.imagesFinite = finite(m.fullImage) && finite(direct) && finite(indirect);
        if (references) {
            m.errors =
                ModeErrors{compareImages(m.fullImage, references->full), compareImages(direct, references->direct),
                           compareImages(indirect, references->indirect),
                           shadowedLuminanceRatio(indirect, references->indirect, references->direct)};
        }
        if (options.onMeasured) options.onMeasured(m);
    }
    return results;
}

}  // namespace vct::bench
