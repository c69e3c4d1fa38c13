// vct_pathtrace: renders the ground-truth image a VCT frame is measured against.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <thread>

#include "error.h"
#include "io/image_io.h"
#include "io/json_text.h"
#include "path_tracer.h"
#include "scene/default_camera.h"
#include "scene/default_light.h"
#include "scene/load.h"

namespace {

using vct::Error;
namespace pt = vct::pt;

constexpr const char* kUsage =
    "usage: vct_pathtrace --scene FILE|NAME --out FILE.pfm [options]\n"
    "  --width W --height H      image size (default 256 x 256)\n"
    "  --spp N                   samples per pixel (default 64)\n"
    "  --mode full|direct|indirect\n"
    "                            direct: emission seen by the camera + the light of punctual lights and\n"
    "                            emissive surfaces at the first hit;\n"
    "                            indirect: everything else; full: both (default)\n"
    "  --threads N               worker threads (default: all hardware threads)\n"
    "  --seed S                  random seed (default 1); images depend on it, not on --threads\n"
    "  --time-limit SEC          stop after the pass that exceeds SEC, with fewer samples\n"
    "  --max-depth N             surface interactions that gather light: 1 = direct light only, 2 adds\n"
    "                            one bounce of indirect light, N adds N - 1 (default: every bounce)\n"
    "  --environment R,G,B|FILE.hdr\n"
    "                            the sky: a uniform radiance or an equirectangular Radiance image, as in\n"
    "                            vct render (default black; a scene without light gets the default sun\n"
    "                            and sky, unless this names its sky, 0,0,0 included). The sky camera\n"
    "                            rays meet is direct light, the sky's light on\n"
    "                            surfaces indirect\n"
    "  --environment-rotation DEGREES\n"
    "                            turn the environment image about +Y, counter-clockwise seen from above\n"
    "  --camera-pos x,y,z --camera-target x,y,z --fov DEGREES\n"
    "                            override the scene's first camera (+Y up, vertical field of view)\n"
    "Writes FILE.pfm (linear radiance; .png also works) and FILE.json (spp, seconds, noise).\n";

struct Options {
    std::string scene;
    std::string out;
    pt::RenderSettings settings;
    std::optional<glm::vec3> cameraPosition, cameraTarget;
    std::optional<float> fovDegrees;
    std::optional<uint32_t> maxDepth;
    std::optional<glm::vec3> environment;
    std::string environmentImage;  // --environment FILE.hdr
    std::optional<float> environmentRotationDegrees;
};

template <typename T>
T parseNumber(const std::string& option, const std::string& text) {
    T value{};
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (error != std::errc() || stop != end) throw Error("option " + option + " expects a number, not '" + text + "'");
    return value;
}

glm::vec3 parseVector(const std::string& option, const std::string& text) {
    glm::vec3 v;
    size_t begin = 0;
    for (int i = 0; i < 3; ++i) {
        const size_t comma = i < 2 ? text.find(',', begin) : text.size();
        if (comma == std::string::npos) throw Error("option " + option + " expects x,y,z, not '" + text + "'");
        v[i] = parseNumber<float>(option, text.substr(begin, comma - begin));
        begin = comma + 1;
    }
    return v;
}

Options parseOptions(int argc, char** argv) {
    Options options;
    options.settings.width = options.settings.height = 256;
    options.settings.samplesPerPixel = 64;
    for (int i = 1; i < argc; ++i) {
        const std::string option = argv[i];
        if (option == "--help" || option == "-h") {
            std::fputs(kUsage, stdout);
            std::exit(0);
        }
        if (i + 1 >= argc) throw Error("option " + option + " needs a value (see --help)");
        const std::string value = argv[++i];
        pt::RenderSettings& s = options.settings;
        if (option == "--scene") options.scene = value;
        else if (option == "--out") options.out = value;
        else if (option == "--width") s.width = parseNumber<uint32_t>(option, value);
        else if (option == "--height") s.height = parseNumber<uint32_t>(option, value);
        else if (option == "--spp") s.samplesPerPixel = parseNumber<uint32_t>(option, value);
        else if (option == "--threads") s.threads = parseNumber<uint32_t>(option, value);
        else if (option == "--seed") s.seed = parseNumber<uint64_t>(option, value);
        else if (option == "--time-limit") s.timeLimitSeconds = parseNumber<double>(option, value);
        else if (option == "--max-depth") options.maxDepth = parseNumber<uint32_t>(option, value);
        else if (option == "--camera-pos") options.cameraPosition = parseVector(option, value);
        else if (option == "--camera-target") options.cameraTarget = parseVector(option, value);
        else if (option == "--fov") options.fovDegrees = parseNumber<float>(option, value);
        else if (option == "--environment" && vct::namesEnvironmentImage(value)) options.environmentImage = value;
        else if (option == "--environment") options.environment = parseVector(option, value);
        else if (option == "--environment-rotation")
            options.environmentRotationDegrees = parseNumber<float>(option, value);
        else if (option == "--mode") {
            if (value == "full") s.component = pt::Component::Full;
            else if (value == "direct") s.component = pt::Component::Direct;
            else if (value == "indirect") s.component = pt::Component::Indirect;
            else throw Error("option --mode expects full, direct or indirect, not '" + value + "'");
        } else {
            throw Error("unknown option '" + option + "' (see --help)");
        }
    }
    if (options.scene.empty() || options.out.empty()) throw Error("--scene and --out are required (see --help)");
    const pt::RenderSettings& s = options.settings;
    if (s.width == 0 || s.height == 0 || s.width > 16384 || s.height > 16384) {
        throw Error("the image size must be between 1 and 16384 pixels on each side");
    }
    if (s.samplesPerPixel == 0) throw Error("--spp must be at least 1");
    if (options.environment) vct::checkSkyRadiance(*options.environment);
    if (options.environmentRotationDegrees) {
        if (options.environmentImage.empty())
            throw Error("--environment-rotation turns an environment image: give --environment FILE.hdr too");
        if (!std::isfinite(*options.environmentRotationDegrees))
            throw Error("--environment-rotation must be a finite number of degrees");
    }
    if (options.fovDegrees && !(*options.fovDegrees > 0.0f && *options.fovDegrees < 180.0f)) {
        throw Error("--fov must be between 0 and 180 degrees");
    }
    return options;
}

// The scene's first camera, or the one vct render frames a scene without cameras from, with the
// command line's overrides.
vct::Camera chooseCamera(const vct::Scene& scene, const Options& options) {
    vct::Camera camera = scene.cameras.empty() ? vct::defaultCamera(scene.bounds()) : scene.cameras[0];
    if (options.cameraPosition) camera.position = *options.cameraPosition;
    if (options.cameraTarget) {
        if (glm::length(*options.cameraTarget - camera.position) <= 0.0f) {
            throw Error("--camera-target must differ from the camera position");
        }
        camera = pt::cameraLookingAt(camera.position, *options.cameraTarget, camera.yfov);
    }
    if (options.fovDegrees) camera.yfov = glm::radians(*options.fovDegrees);
    return camera;
}

// The sidecar's numbers; a non-finite one is written as 0 so readers always get a number.
std::string sidecarNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", std::isfinite(value) ? value : 0.0);
    return text;
}

std::string sidecarPath(const std::string& out) {
    const size_t dot = out.find_last_of('.');
    const size_t slash = out.find_last_of('/');
    const bool hasExtension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
    return (hasExtension ? out.substr(0, dot) : out) + ".json";
}

const char* modeName(pt::Component component) {
    return component == pt::Component::Full ? "full" : component == pt::Component::Direct ? "direct" : "indirect";
}

int run(int argc, char** argv) {
    Options options = parseOptions(argc, argv);
    vct::Scene scene = vct::loadScene(options.scene);
    if (options.environment) scene.environment = *options.environment;
    if (!options.environmentImage.empty())
        vct::useEnvironmentImage(
            scene, std::make_shared<const vct::EnvironmentMap>(vct::loadEnvironmentMap(options.environmentImage)));
    if (options.environmentRotationDegrees)
        scene.environmentRotation = glm::radians(*options.environmentRotationDegrees);
    // The light `vct render` gives a scene without any, unless --environment names the sky (black too).
    if (!options.environment && options.environmentImage.empty()) vct::addDefaultSunAndSkyIfUnlit(scene);
    for (const std::string& warning : scene.warnings) std::fprintf(stderr, "warning: %s\n", warning.c_str());
    options.settings.camera = chooseCamera(scene, options);
    pt::PathTracer tracer = pt::createPathTracer(scene);
    if (options.maxDepth) tracer.maxDepth = *options.maxDepth;
    const pt::RenderSettings& s = options.settings;
    const unsigned threads = s.threads > 0 ? s.threads : std::max(1u, std::thread::hardware_concurrency());

    const pt::RenderResult result = pt::render(tracer, s);
    vct::writeImage(options.out, result.image);
    const std::string json =
        "{\n  \"scene\": " + vct::jsonString(options.scene) + ",\n  \"mode\": \"" + modeName(s.component) +
        "\",\n  \"width\": " + std::to_string(s.width) + ",\n  \"height\": " + std::to_string(s.height) +
        ",\n  \"max_depth\": " + std::to_string(tracer.maxDepth) +
        ",\n  \"spp\": " + std::to_string(result.samplesPerPixel) +
        ",\n  \"spp_requested\": " + std::to_string(s.samplesPerPixel) + ",\n  \"seed\": " + std::to_string(s.seed) +
        ",\n  \"threads\": " + std::to_string(threads) + ",\n  \"seconds\": " + sidecarNumber(result.seconds) +
        ",\n  \"mean_luminance\": " + sidecarNumber(result.meanLuminance) +
        ",\n  \"mean_luminance_standard_error\": " + sidecarNumber(result.meanLuminanceStandardError) +
        ",\n  \"relative_noise\": " + sidecarNumber(result.relativeNoise) +
        ",\n  \"discarded_samples\": " + std::to_string(result.discardedSamples) + "\n}\n";
    vct::writeFileAtomically(sidecarPath(options.out), json);

    std::printf("%s: %ux%u, %u spp (%s), %.2f s on %u threads\n", options.scene.c_str(), s.width, s.height,
                result.samplesPerPixel, modeName(s.component), result.seconds, threads);
    std::printf("mean luminance %.6g ± %.2g; per-pixel relative noise %.3g %% (sqrt of relative MSE)\n",
                result.meanLuminance, result.meanLuminanceStandardError, 100.0 * result.relativeNoise);
    if (result.samplesPerPixel < 2) std::printf("(one sample per pixel: the noise cannot be estimated)\n");
    if (result.discardedSamples > 0) {
        std::printf("warning: %llu non-finite samples were discarded\n",
                    static_cast<unsigned long long>(result.discardedSamples));
    }
    std::printf("wrote %s and %s\n", options.out.c_str(), sidecarPath(options.out).c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "vct_pathtrace: %s\n", error.what());
        return 1;
    }
}
