#include "view/viewer.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>
#include <stb/stb_image_write.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>
#include <system_error>

#include "error.h"
#include "gpu/commands.h"
#include "gpu/timing.h"
#include "gpu/vk_check.h"
#include "render/camera.h"
#include "render/renderer.h"
#include "render/renderer_limits.h"
#include "scene/default_light.h"
#include "scene/load.h"
#include "view/controls.h"
#include "view/present_pass.h"
#include "view/recent_files.h"
#include "view/swapchain.h"
#include "view/ui.h"
#include "view/viewer_state.h"
#include "view/window.h"

namespace vct {
namespace {

bool sameCamera(const Camera& a, const Camera& b) {
    return a.position == b.position && a.forward == b.forward && a.up == b.up && a.yfov == b.yfov;
}

// Scenes with lights but no sun get one to steer, switched off (intensity 0), so that the viewer
// starts on the light `vct render` shows; the arrow keys aim it and the Lights panel turns it up.
// It shines from behind the camera and above, so it reaches into open boxes like the Cornell box.
// (Scenes without any light already have the default sun, default_light.h, as in `vct render`.)
size_t ensureSun(Scene& scene) {
    for (size_t i = 0; i < scene.lights.size(); ++i)
        if (scene.lights[i].type == LightType::Directional) return i;
    Light sun;
    sun.name = "viewer sun";
    sun.type = LightType::Directional;
    sun.intensity = 0.0f;
    const glm::vec3 forward = scene.cameras.empty() ? glm::vec3(0, 0, -1) : scene.cameras.front().forward;
    sun.direction = glm::normalize(glm::normalize(forward) + glm::vec3(0.0f, -0.7f, 0.0f));
    scene.lights.push_back(sun);
    return scene.lights.size() - 1;
}

float parseNumber(const ScriptEvent& event, size_t index) {
    try {
        return std::stof(event.arguments.at(index));
    } catch (const std::exception&) {
        throw Error("script, frame " + std::to_string(event.frame) + ": '" + event.action + "' needs numbers, not '" +
                    event.arguments.at(index) + "'");
    }
}

std::string timestampedScreenshotName() {
    const std::time_t now = std::time(nullptr);
    char name[64];
    std::strftime(name, sizeof name, "vct-%Y%m%d-%H%M%S.png", std::localtime(&now));
    return name;
}

class Viewer {
public:
    explicit Viewer(ViewerOptions options);
    int run();

private:
    bool loopIteration();
    void applyScript();
    void handleKeys(float seconds);
    void handleMouse(float seconds);
    void applyRequests();
    void applyLightEdits();
    void showScene();
    void rememberSceneFile(const std::string& name);
    bool loadScene(const std::string& name);
    void buildRenderer();
    void recreateSwapchain();
    void resizeRenderer();
    VkRect2D imageArea() const;
    VkExtent2D drawableExtent(VkExtent2D window) const;
    void drawFrame(bool drawUi, const std::string& screenshotPath);
    void writeScreenshot(const Buffer& pixels, VkExtent2D extent, const std::string& path);
    glsl::GridBoundsPush gridBoundsPush() const;
    UiFacts facts() const;
    void printFrameStats(const FrameStats& stats) const;
    void measureExposure(float seconds);
    void adaptExposure(float seconds);

    ViewerOptions options_;
    GlfwSession glfw_;
    Window window_;
    std::unique_ptr<GpuContext> context_;
    std::unique_ptr<Surface> surface_;
    std::unique_ptr<Swapchain> swapchain_;
    std::unique_ptr<PresentPass> presentPass_;
    std::unique_ptr<PresentCommands> presentCommands_;
    std::unique_ptr<GpuTimer> presentTimer_;
    std::unique_ptr<ImGuiSession> imgui_;
    std::unique_ptr<Renderer> renderer_;

    InputState input_;
    ViewerState state_;
    bool exposureMeasured_ = false;  // automatic exposure: targetExposure_ holds this scene's image's
    bool exposureStale_ = false;     // an image was rendered since targetExposure_ was measured
    float targetExposure_ = 1.0f;
    float secondsSinceExposureMeasure_ = 0.0f;  // the loop's seconds (a script's are 1/30 each)
    Scene scene_;
    SunControl shownSun_;  // the sun the renderer has
    Camera camera_;
    Camera lastRenderedCamera_;
    CameraControl cameraControl_;
    VkExtent2D requestedExtent_{};   // the swapchain's size: the window's, or what the device can draw
    VkExtent2D shownFramebuffer_{};  // the window's framebuffer size when the swapchain was made
    static constexpr uint64_t kSwapchainImagesAtMost = 4;
    bool swapchainStale_ = false;
    bool recentFilesWarned_ = false;  // the list could not be written: said once
    bool shownVsync_ = true;
    float shownRenderScale_ = 1.0f;
    VkRect2D shownImageArea_{};  // the part of the window the image was sized for
    bool imageStale_ = true;     // the renderer must run this frame
    bool quit_ = false;
    uint64_t iteration_ = 0;
    uint32_t framesDrawn_ = 0;
    size_t nextScriptEvent_ = 0;
    std::vector<std::pair<std::string, bool>> pendingScreenshots_;  // path, with UI
    std::chrono::steady_clock::time_point lastFrame_ = std::chrono::steady_clock::now();
};

Viewer::Viewer(ViewerOptions options)
    : options_(std::move(options)), window_(options_.settings.image.width, options_.settings.image.height) {
    installInputCallbacks(window_.handle, &input_);
    ContextOptions contextOptions = options_.context;
    uint32_t extensionCount = 0;
    const char** extensions = glfwGetRequiredInstanceExtensions(&extensionCount);
    if (!extensions) throw Error("cannot open a window: this Vulkan loader has no window-system surfaces");
    contextOptions.instanceExtensions.insert(contextOptions.instanceExtensions.end(), extensions,
                                             extensions + extensionCount);
    contextOptions.swapchain = true;
    context_ = std::make_unique<GpuContext>(contextOptions);
    context_->fenceTimeoutSeconds = options_.gpuTimeoutSeconds;
    surface_ = std::make_unique<Surface>(*context_, window_.handle);

    // On a software rasterizer the viewer starts on the `fast` preset at half the image area's size,
    // and says so: a 960×540 window moving through the Cornell box drew a frame in 58-65 ms (15-17
    // fps) on lavapipe, 2 cores.
    const bool software = context_->isSoftwareRasterizer();
    const bool softwarePreset = software && options_.softwareSettings.has_value();
    state_.settings = softwarePreset ? *options_.softwareSettings : options_.settings;
    state_.presetName = softwarePreset ? "fast" : options_.presetName;
    if (softwarePreset)
        state_.notice = "a software rasterizer (" + context_->deviceName() +
                        "): started on the fast preset at render scale 0.5, about 15 fps at 960x540; change them above";
    // The panel shows what the renderer does (settings.h).
    state_.settings.shading.skipEmptySpace = skipsEmptySpace(state_.settings.shading, software);
    state_.autoExposure = !options_.exposureStops.has_value();
    state_.exposureStops = options_.exposureStops.value_or(0.0f);
    state_.exposure = exposureFromStops(state_.exposureStops);
    state_.vsync = shownVsync_ = options_.vsync;
    state_.showHint = options_.showHint;
    state_.screenshotWithUi = options_.screenshotWithUi;
    // Software rasterizers shade a quarter of the pixels unless told otherwise.
    state_.renderScale = options_.renderScale > 0.0f ? options_.renderScale : (software ? 0.5f : 1.0f);
    recreateSwapchain();
    presentPass_ = std::make_unique<PresentPass>(*context_, swapchain_->format);
    presentPass_->createFramebuffers(*swapchain_);
    presentCommands_ = std::make_unique<PresentCommands>(*context_);
    presentTimer_ = std::make_unique<GpuTimer>(*context_, 2);
    imgui_ = std::make_unique<ImGuiSession>(*context_, window_.handle, *swapchain_, presentPass_->renderPass);

    scene_ = std::move(options_.scene);
    state_.sceneName = options_.sceneName;
    state_.warnings = scene_.warnings;  // printed on stderr by `vct view` already
    if (scene_.cameras.empty()) scene_.cameras.push_back(defaultCamera(scene_.bounds()));
    state_.sunIndex = ensureSun(scene_);
    buildRenderer();
    showScene();
    state_.recentFiles = readRecentFiles(recentFilesPath());
    rememberSceneFile(state_.sceneName);
    std::printf("vct view: %s, %zu triangles, on %s (%s)\n", state_.sceneName.c_str(), scene_.triangleCount(),
                context_->deviceName().c_str(), presentModeName(swapchain_->presentMode));
    if (softwarePreset) std::printf("vct view: %s\n", state_.notice.c_str());
}

// The largest window the viewer draws: each side within maxImageDimension2D, and the swapchain images
// and the render targets at the render scale within a quarter of the device's memory (lavapipe's
// 2 GiB: about 4000² at half scale). A larger window is asked to shrink, and is drawn at that size
// meanwhile; the scene is kept.
VkExtent2D Viewer::drawableExtent(VkExtent2D window) const {
    RenderSettings perPixel = state_.settings;
    perPixel.image.width = perPixel.image.height = std::max(1u, uint32_t(std::lround(1024 * state_.renderScale)));
    const uint64_t targetBytes = estimateRendererMemory(Scene{}, perPixel).imageTargets;
    const uint64_t bytesPerWindowPixel = kSwapchainImagesAtMost * 4 + targetBytes / (1024 * 1024) + 1;
    const uint64_t maxPixels = largestDeviceLocalHeap(context_->memoryProperties) / 4 / bytesPerWindowPixel;
    return fitWindowExtent(window, context_->properties.limits.maxImageDimension2D, maxPixels);
}

void Viewer::recreateSwapchain() {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_.handle, &width, &height);
    shownFramebuffer_ = {uint32_t(std::max(width, 1)), uint32_t(std::max(height, 1))};
    requestedExtent_ = drawableExtent(shownFramebuffer_);
    if (requestedExtent_.width != shownFramebuffer_.width || requestedExtent_.height != shownFramebuffer_.height) {
        state_.notice = "the window (" + std::to_string(shownFramebuffer_.width) + "x" +
                        std::to_string(shownFramebuffer_.height) + ") is larger than " + context_->deviceName() +
                        " can draw; drawn at " + std::to_string(requestedExtent_.width) + "x" +
                        std::to_string(requestedExtent_.height);
        std::printf("vct view: %s\n", state_.notice.c_str());
        glfwSetWindowSizeLimits(window_.handle, 1, 1, int(requestedExtent_.width), int(requestedExtent_.height));
        glfwSetWindowSize(window_.handle, int(requestedExtent_.width), int(requestedExtent_.height));
    }
    if (swapchain_) VK_CHECK(vkDeviceWaitIdle(context_->device));
    const VkSwapchainKHR previous = swapchain_ ? swapchain_->swapchain : VK_NULL_HANDLE;
    auto replacement =
        std::make_unique<Swapchain>(*context_, surface_->surface, requestedExtent_, state_.vsync, previous);
    swapchain_ = std::move(replacement);
    shownVsync_ = state_.vsync;
    swapchainStale_ = false;
    if (presentPass_) {
        if (swapchain_->format != presentPass_->format)
            throw Error("the window's image format changed; restart the viewer");
        presentPass_->createFramebuffers(*swapchain_);
    }
    if (imgui_) ImGui_ImplVulkan_SetMinImageCount(std::max(swapchain_->minImageCount, 2u));
    resizeRenderer();
}

// The image takes the window right of the docked settings, as an editor's viewport does, so the
// panel covers none of it; the aspect ratio follows. Collapsed or hidden settings leave the whole
// window to it, and so does a window where the image would get less than a third of the width
// (there the settings cover the image, and collapse with their title bar's arrow).
VkRect2D Viewer::imageArea() const {
    const VkExtent2D window = swapchain_->extent;
    const uint32_t panel = uint32_t(std::lround(std::max(state_.settingsWidth, 0.0f)));
    if (panel == 0 || panel >= window.width || 3 * (window.width - panel) < window.width) return {{0, 0}, window};
    return {{int32_t(panel), 0}, {window.width - panel, window.height}};
}

// The renderer draws at the image area's size × the render scale; the present pass scales it up.
void Viewer::resizeRenderer() {
    shownRenderScale_ = state_.renderScale;
    shownImageArea_ = imageArea();
    const VkExtent2D area = shownImageArea_.extent;
    state_.settings.image.width = std::max(1u, uint32_t(std::lround(area.width * state_.renderScale)));
    state_.settings.image.height = std::max(1u, uint32_t(std::lround(area.height * state_.renderScale)));
    if (renderer_) {
        renderer_->resize(state_.settings.image);  // the voxels are kept
        imageStale_ = true;
    }
}

void Viewer::buildRenderer() {
    if (renderer_) VK_CHECK(vkDeviceWaitIdle(context_->device));
    renderer_.reset();  // free the old voxels before allocating new ones
    renderer_ = std::make_unique<Renderer>(*context_, scene_, state_.settings);
    renderer_->setCamera(camera_);
    renderer_->setShading(state_.settings.shading);
    imageStale_ = true;
}

bool Viewer::loadScene(const std::string& name) {
    std::printf("loading %s\n", name.c_str());
    Scene loaded;
    try {
        LoadOptions options;
        options.bufferLimits = sceneBufferLimits(*context_);
        loaded = vct::loadScene(name, options);
    } catch (const Error& error) {
        state_.error = std::string(error.what()) + " (keeping " + state_.sceneName + ")";
        std::fprintf(stderr, "vct view: %s\n", state_.error.c_str());
        return false;
    }
    if (loaded.cameras.empty()) loaded.cameras.push_back(defaultCamera(loaded.bounds()));
    if (options_.environment) loaded.environment = *options_.environment;
    useEnvironmentImage(loaded, options_.environmentMap);
    loaded.environmentRotation = options_.environmentRotation;
    addDefaultSunAndSkyIfUnlit(loaded);  // as `vct render` would light it
    Scene previous = std::move(scene_);
    scene_ = std::move(loaded);
    const size_t previousSun = state_.sunIndex;
    state_.sunIndex = ensureSun(scene_);
    try {
        buildRenderer();
    } catch (const Error& error) {
        state_.error = std::string(error.what()) + " (keeping " + state_.sceneName + ")";
        scene_ = std::move(previous);
        state_.sunIndex = previousSun;
        buildRenderer();  // the panel's edits of the previous scene's lights return next frame
        return false;
    }
    state_.error.clear();
    state_.sceneName = name;
    for (const std::string& warning : scene_.warnings) std::fprintf(stderr, "warning: %s\n", warning.c_str());
    state_.warnings = scene_.warnings;
    showScene();
    rememberSceneFile(name);
    return true;
}

// A scene opened from a file (not a built-in name) goes first in the recent files, which are saved
// at once: the viewer may end by a crash of the driver or the window system.
void Viewer::rememberSceneFile(const std::string& name) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(name, error)) return;
    rememberRecentFile(state_.recentFiles, name);
    const std::string problem = writeRecentFiles(recentFilesPath(), state_.recentFiles);
    if (problem.empty() || recentFilesWarned_) return;
    recentFilesWarned_ = true;
    std::fprintf(stderr, "warning: %s\n", problem.c_str());
    state_.warnings.push_back(problem);
}

// The panels and the camera start from the scene the renderer was just built for.
void Viewer::showScene() {
    exposureMeasured_ = false;  // a new scene starts at its own exposure, not the last one's
    state_.lights = scene_.lights;
    state_.environment = scene_.environment;
    state_.skyImage = scene_.environmentMap ? scene_.environmentMap->name : std::string();
    state_.skyRotation = scene_.environmentRotation;
    state_.skyImageSun = renderer_ && renderer_->environmentSunLit();
    state_.materials = scene_.materials;
    state_.sceneSize = std::max(glm::length(scene_.bounds().extent()), 1e-3f);
    const Light& sun = scene_.lights.at(state_.sunIndex);
    state_.sun.setFromTravelDirection(sun.direction);
    state_.sun.intensity = sun.intensity;
    shownSun_ = state_.sun;
    camera_ = scene_.cameras.front();
    cameraControl_.reset(camera_, scene_.bounds());
    renderer_->setCamera(camera_);
}

void Viewer::applyScript() {
    while (nextScriptEvent_ < options_.script.size() && options_.script[nextScriptEvent_].frame <= iteration_) {
        const ScriptEvent& event = options_.script[nextScriptEvent_++];
        const std::vector<std::string>& a = event.arguments;
        if (event.action == "key") {
            const int key = keyFromName(a[0]);
            if (a[1] == "press") {
                input_.keysPressed.push_back(key);
            } else {
                input_.key(key, a[1] == "down");
            }
        } else if (event.action == "mouse") {
            input_.moveCursor(glm::vec2(parseNumber(event, 0), parseNumber(event, 1)));
        } else if (event.action == "button") {
            input_.buttons[a[0] == "left" ? GLFW_MOUSE_BUTTON_LEFT : GLFW_MOUSE_BUTTON_RIGHT] = a[1] == "down";
        } else if (event.action == "scroll") {
            input_.scroll += parseNumber(event, 0);
        } else if (event.action == "resize") {
            // X refuses a zero size (BadValue, which ends the process): a window resized to nothing
            // is minimised instead, and waits. Sizes past what X carries (2¹⁶) are kept to it.
            const double width = parseNumber(event, 0), height = parseNumber(event, 1);
            if (width < 1.0 || height < 1.0) glfwIconifyWindow(window_.handle);
            else {
                if (glfwGetWindowAttrib(window_.handle, GLFW_ICONIFIED)) glfwRestoreWindow(window_.handle);
                glfwSetWindowSize(window_.handle, int(std::min(width, 65535.0)), int(std::min(height, 65535.0)));
            }
        } else if (event.action == "iconify") {
            glfwIconifyWindow(window_.handle);
        } else if (event.action == "restore") {
            glfwRestoreWindow(window_.handle);
        } else if (event.action == "screenshot") {
            pendingScreenshots_.emplace_back(a[0], a.size() > 1);
        } else if (event.action == "drop") {
            input_.droppedFiles.push_back(a[0]);
        } else if (event.action == "type") {
            for (const char character : a[0]) ImGui::GetIO().AddInputCharacter(static_cast<unsigned char>(character));
        } else if (event.action == "light") {
            // What the scene panel's intensity field writes (the sun's is the sun control's).
            const float index = parseNumber(event, 0), intensity = parseNumber(event, 2);
            if (index < 0.0f || index >= float(state_.lights.size()) || index != std::floor(index))
                throw Error("script, frame " + std::to_string(event.frame) + ": the scene has no light " + a[0] +
                            " (it has " + std::to_string(state_.lights.size()) + ", counted from 0)");
            if (size_t(index) == state_.sunIndex) state_.sun.intensity = intensity;
            else state_.lights[size_t(index)].intensity = intensity;
        } else if (event.action == "sky") {
            // What the scene panel's sky radiance field writes.
            const glm::vec3 sky(parseNumber(event, 0), parseNumber(event, 1), parseNumber(event, 2));
            if (!glm::all(glm::greaterThanEqual(sky, glm::vec3(0.0f))))
                throw Error("script, frame " + std::to_string(event.frame) + ": a sky's radiance is not negative");
            state_.environment = sky;
        } else if (event.action == "quit") {
            quit_ = true;
        }
    }
}

void Viewer::handleKeys(float seconds) {
    for (int key : input_.keysPressed) {
        RenderSettings& settings = state_.settings;
        // Keys 1…8 toggle the components in componentTable()'s order.
        if (key >= GLFW_KEY_1 && size_t(key - GLFW_KEY_1) < componentTable().size()) {
            bool& shown = settings.shading.components.*componentTable()[size_t(key - GLFW_KEY_1)].member;
            shown = !shown;
        }
        switch (key) {
            case GLFW_KEY_F1:
            case GLFW_KEY_H: state_.showGuide = !state_.showGuide; break;
            case GLFW_KEY_TAB: state_.showPanels = !state_.showPanels; break;
            case GLFW_KEY_F2: state_.showProfiler = !state_.showProfiler; break;
            case GLFW_KEY_R: state_.requestCameraReset = true; break;
            case GLFW_KEY_O: state_.requestOrbitToggle = true; break;
            case GLFW_KEY_M: settings.shading.mode = RenderMode((uint32_t(settings.shading.mode) + 1) % 3); break;
            case GLFW_KEY_V:
                settings.shading.debugView = DebugView((uint32_t(settings.shading.debugView) + 1) % debugViewCount);
                break;
            case GLFW_KEY_LEFT_BRACKET:
                if (settings.shading.debugVoxelMip > 0) --settings.shading.debugVoxelMip;
                break;
            case GLFW_KEY_RIGHT_BRACKET:
                // The finest level is 0; the coarsest is the volume's last (the panels may be hidden).
                if (settings.shading.debugVoxelMip + 1 < renderer_->volumes().radiance.desc.mipLevels)
                    ++settings.shading.debugVoxelMip;
                break;
            case GLFW_KEY_L: state_.sun.animate = !state_.sun.animate; break;
            case GLFW_KEY_G: state_.showGridBounds = !state_.showGridBounds; break;
            case GLFW_KEY_F12:
            case GLFW_KEY_P: state_.requestScreenshot = true; break;
            case GLFW_KEY_ESCAPE: quit_ = true; break;
            default: break;
        }
    }
    const float degrees = 45.0f * seconds;
    if (input_.held(GLFW_KEY_LEFT)) state_.sun.azimuthDegrees -= degrees;
    if (input_.held(GLFW_KEY_RIGHT)) state_.sun.azimuthDegrees += degrees;
    if (input_.held(GLFW_KEY_UP)) state_.sun.elevationDegrees += degrees;
    if (input_.held(GLFW_KEY_DOWN)) state_.sun.elevationDegrees -= degrees;
}

void Viewer::handleMouse(float seconds) {
    const ImGuiIO& io = ImGui::GetIO();
    const bool keyboardFree = !io.WantCaptureKeyboard, mouseFree = !io.WantCaptureMouse;
    const bool ctrl = input_.held(GLFW_KEY_LEFT_CONTROL) || input_.held(GLFW_KEY_RIGHT_CONTROL);
    const bool left = input_.buttons[GLFW_MOUSE_BUTTON_LEFT], right = input_.buttons[GLFW_MOUSE_BUTTON_RIGHT];
    CameraInput camera;
    if (keyboardFree) {
        camera.forward = input_.held(GLFW_KEY_W);
        camera.back = input_.held(GLFW_KEY_S);
        camera.left = input_.held(GLFW_KEY_A);
        camera.right = input_.held(GLFW_KEY_D);
        camera.down = input_.held(GLFW_KEY_Q);
        camera.up = input_.held(GLFW_KEY_E);
        camera.fast = input_.held(GLFW_KEY_LEFT_SHIFT) || input_.held(GLFW_KEY_RIGHT_SHIFT);
    }
    camera.seconds = seconds;
    if (mouseFree) {
        if (ctrl && left) {
            // Drag right: the sun moves clockwise seen from above; drag up: it rises.
            state_.sun.azimuthDegrees += 0.3f * input_.cursorDelta.x;
            state_.sun.elevationDegrees -= 0.3f * input_.cursorDelta.y;
        } else if (right || (left && cameraControl_.mode() == CameraControl::Mode::Orbit)) {
            camera.drag = input_.cursorDelta;
        }
        camera.scroll = input_.scroll;
    }
    if (cameraControl_.update(camera, camera_)) renderer_->setCamera(camera_);
}

void Viewer::applyRequests() {
    for (const std::string& path : input_.droppedFiles) state_.requestedScene = path;
    input_.droppedFiles.clear();
    if (!state_.requestedScene.empty()) {
        const std::string name = state_.requestedScene;
        state_.requestedScene.clear();
        loadScene(name);
    }
    if (state_.requestCameraReset) {
        state_.requestCameraReset = false;
        camera_ = scene_.cameras.front();
        cameraControl_.reset(camera_, scene_.bounds());
        renderer_->setCamera(camera_);
    }
    if (state_.requestOrbitToggle) {
        state_.requestOrbitToggle = false;
        const bool orbit = cameraControl_.mode() != CameraControl::Mode::Orbit;
        cameraControl_.setMode(orbit ? CameraControl::Mode::Orbit : CameraControl::Mode::Fly, camera_);
        renderer_->setCamera(camera_);
    }
    state_.cameraIsOrbiting = cameraControl_.mode() == CameraControl::Mode::Orbit;
    state_.cameraSpeed = cameraControl_.speed();
    if (state_.requestScreenshot) {
        state_.requestScreenshot = false;
        pendingScreenshots_.emplace_back(timestampedScreenshotName(), state_.screenshotWithUi);
    }

    applyLightEdits();
    if (renderer_->settings().resources != state_.settings.resources) {
        const RenderSettings previous = renderer_->settings();
        try {
            const std::vector<Light> lights = renderer_->lights();
            buildRenderer();
            renderer_->setLights(lights);
        } catch (const Error& error) {
            state_.error = error.what();
            state_.settings = previous;
            buildRenderer();
        }
    }
    if (renderer_->settings().image != state_.settings.image) {
        renderer_->resize(state_.settings.image);
        imageStale_ = true;
    }
    if (renderer_->settings().shading != state_.settings.shading) {
        renderer_->setShading(state_.settings.shading);
        imageStale_ = true;
    }
    if (state_.vsync != shownVsync_) swapchainStale_ = true;
    if (state_.renderScale != shownRenderScale_) resizeRenderer();
}

// The sun steered by keys, mouse or panel, and the other lights edited in the panel, reach the
// renderer by one path: setLights re-injects light and redraws the shadow maps of the lights that
// moved; the voxels stay, and the bounces re-converge over the next frames.
void Viewer::applyLightEdits() {
    state_.sun.normalize();
    const SunControl& sun = state_.sun;
    Light& sunLight = state_.lights.at(state_.sunIndex);
    if (sun.azimuthDegrees != shownSun_.azimuthDegrees || sun.elevationDegrees != shownSun_.elevationDegrees ||
        sun.intensity != shownSun_.intensity) {
        sunLight.direction = sun.travelDirection();
        sunLight.intensity = sun.intensity;
        shownSun_ = sun;
    }
    if (state_.environment != renderer_->environment()) {
        renderer_->setEnvironment(state_.environment);
        imageStale_ = true;
    }
    if (state_.skyRotation != renderer_->environmentRotation()) {
        renderer_->setEnvironmentRotation(state_.skyRotation);
        imageStale_ = true;
    }
    if (state_.lights == renderer_->lights()) return;
    try {
        renderer_->setLights(state_.lights);
        imageStale_ = true;
    } catch (const Error& error) {
        // E.g. brighter than the voxels' float16 can hold: the renderer keeps its lights.
        state_.error = error.what();
        std::fprintf(stderr, "vct view: %s (the light is kept as it was)\n", error.what());
        state_.lights = renderer_->lights();
        state_.sun.intensity = state_.lights.at(state_.sunIndex).intensity;
        shownSun_ = state_.sun;
    }
}

UiFacts Viewer::facts() const {
    UiFacts facts;
    facts.deviceName = context_->deviceName();
    facts.presentMode = presentModeName(swapchain_->presentMode);
    facts.width = swapchain_->extent.width;
    facts.height = swapchain_->extent.height;
    facts.renderWidth = renderer_->settings().image.width;
    facts.renderHeight = renderer_->settings().image.height;
    facts.voxelResolution = renderer_->voxelGrid().resolution;
    facts.voxelMips = renderer_->volumes().radiance.desc.mipLevels;
    facts.deviceMemoryBytes = renderer_->deviceMemoryBytes();
    facts.triangles = scene_.triangleCount();
    facts.lights = renderer_->lights().size();
    return facts;
}

void Viewer::writeScreenshot(const Buffer& pixels, VkExtent2D extent, const std::string& path) {
    const bool bgra = swapchain_->format == VK_FORMAT_B8G8R8A8_UNORM;
    const uint8_t* source = static_cast<const uint8_t*>(pixels.mapped);
    std::vector<uint8_t> rgb(size_t(extent.width) * extent.height * 3);
    for (size_t i = 0; i < size_t(extent.width) * extent.height; ++i) {
        rgb[i * 3 + 0] = source[i * 4 + (bgra ? 2 : 0)];
        rgb[i * 3 + 1] = source[i * 4 + 1];
        rgb[i * 3 + 2] = source[i * 4 + (bgra ? 0 : 2)];
    }
    if (!stbi_write_png(path.c_str(), int(extent.width), int(extent.height), 3, rgb.data(), int(extent.width * 3)))
        throw Error("cannot write the screenshot '" + path + "'");
    state_.notice = "saved " + path;
    std::printf("saved %s (%ux%u)\n", path.c_str(), extent.width, extent.height);
}

// The voxel grid's box seen by the camera the image was rendered with, in the renderer's frame.
glsl::GridBoundsPush Viewer::gridBoundsPush() const {
    const glsl::VoxelGridParams& grid = renderer_->voxelGrid();
    Bounds box;
    box.min = grid.origin;
    box.max = box.min + float(grid.resolution) * grid.voxelSize;
    Camera camera = renderer_->camera();
    camera.position -= renderer_->sceneOrigin();
    const ImageSettings& image = renderer_->settings().image;
    glsl::GridBoundsPush push{};
    // The far plane fitted to the box rather than the scene: the grid's corners reach past the
    // scene's, and a line past the far plane would be cut.
    push.viewProjection = cameraMatrices(camera, float(image.width) / float(image.height), box).viewProjection;
    push.boxMin = glm::vec4(box.min, 1.0f);
    push.boxMax = glm::vec4(box.max, 1.0f);
    push.color = glm::vec4(1.0f, 0.8f, 0.1f, 1.0f);  // amber: apart from every colour the Cornell box has
    return push;
}

void Viewer::drawFrame(bool drawUi, const std::string& screenshotPath) {
    PresentCommands& frame = *presentCommands_;
    uint32_t imageIndex = 0;
    const VkResult acquired = vkAcquireNextImageKHR(context_->device, swapchain_->swapchain, UINT64_MAX,
                                                    frame.imageAcquired, VK_NULL_HANDLE, &imageIndex);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
        swapchainStale_ = true;
        return;
    }
    if (acquired != VK_SUBOPTIMAL_KHR) VK_CHECK(acquired);

    const bool capture = !screenshotPath.empty() && swapchain_->canCopyFrom;
    const VkExtent2D extent = swapchain_->extent;
    // With the UI, the whole window; without, the image alone (right of the open settings).
    const VkRect2D captured = drawUi ? VkRect2D{{0, 0}, extent} : shownImageArea_;
    Buffer pixels;
    if (capture)
        pixels = Buffer(*context_, VkDeviceSize(captured.extent.width) * captured.extent.height * 4,
                        VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);

    VK_CHECK(vkResetFences(context_->device, 1, &frame.fence));
    VK_CHECK(vkResetCommandBuffer(frame.commands, 0));
    VkCommandBufferBeginInfo beginInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(frame.commands, &beginInfo));
    presentTimer_->reset(frame.commands);
    presentTimer_->begin(frame.commands, "present");
    TonemapParams tonemap;
    tonemap.exposure = state_.exposure;
    tonemap.curve = state_.toneCurve;
    const DebugView view = renderer_->settings().shading.debugView;
    tonemap.toneCurve = view == DebugView::None || view == DebugView::VoxelRadiance;
    presentPass_->begin(frame.commands, imageIndex, extent, shownImageArea_, renderer_->output(), tonemap);
    if (state_.showGridBounds) presentPass_->drawGridBounds(frame.commands, gridBoundsPush());
    if (drawUi) ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), frame.commands);
    presentPass_->end(frame.commands);
    presentTimer_->end(frame.commands);
    if (capture) {
        const VkImage image = swapchain_->images[imageIndex];
        imageBarrier(frame.commands, image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                     VK_ACCESS_2_TRANSFER_READ_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageOffset = {captured.offset.x, captured.offset.y, 0};
        region.imageExtent = {captured.extent.width, captured.extent.height, 1};
        vkCmdCopyImageToBuffer(frame.commands, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, pixels.buffer, 1, &region);
        imageBarrier(frame.commands, image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                     VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                     VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE);
    }
    VK_CHECK(vkEndCommandBuffer(frame.commands));

    const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    const VkSemaphore renderFinished = swapchain_->renderFinished[imageIndex];
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &frame.imageAcquired;
    submit.pWaitDstStageMask = &waitStage;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &frame.commands;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &renderFinished;
    VK_CHECK(vkQueueSubmit(context_->queue, 1, &submit, frame.fence));

    VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    present.waitSemaphoreCount = 1;
    present.pWaitSemaphores = &renderFinished;
    present.swapchainCount = 1;
    present.pSwapchains = &swapchain_->swapchain;
    present.pImageIndices = &imageIndex;
    const VkResult presented = vkQueuePresentKHR(context_->queue, &present);
    if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR) swapchainStale_ = true;
    else VK_CHECK(presented);
    // Wait here: the acquire semaphore and command buffer are reused next frame, and the
    // renderer writes the image this pass read.
    waitForFence(*context_, frame.fence);
    const std::vector<PassTime> times = presentTimer_->results();
    if (!times.empty()) state_.history.presentMilliseconds = float(times.front().milliseconds);
    ++framesDrawn_;
    if (capture) writeScreenshot(pixels, captured.extent, screenshotPath);
    else if (!screenshotPath.empty()) state_.notice = "this window system cannot copy from its images";
}

// With --verbose, which passes each frame ran, so a test (or a user) can check what a change cost.
void Viewer::printFrameStats(const FrameStats& stats) const {
    std::printf("frame %llu: ran", static_cast<unsigned long long>(iteration_ - 1));
    for (Pass pass : stats.plan.passes) std::printf(" %s", passName(pass));
    std::printf("; skipped");
    for (const std::string& pass : stats.skipped()) std::printf(" %s", pass.c_str());
    std::printf("\n");
    std::fflush(stdout);
}

// Automatic exposure, as engines' eye adaptation: the exposure that puts a rendered image's
// log-average luminance at middle grey (display_transform.h), measured from the latest image at
// most every kExposureInterval seconds (reading it back costs a copy), at once on a new scene's
// first; the exposure follows it with a time constant of kExposureAdaptation seconds.
constexpr float kExposureInterval = 0.25f;
constexpr float kExposureAdaptation = 0.4f;

void Viewer::measureExposure(float seconds) {
    secondsSinceExposureMeasure_ += seconds;
    if (!state_.autoExposure || !exposureStale_) return;
    if (exposureMeasured_ && secondsSinceExposureMeasure_ < kExposureInterval) return;
    const DebugView view = renderer_->settings().shading.debugView;
    if (view != DebugView::None) return;  // the debug views hold colours or other quantities
    targetExposure_ = automaticExposure(renderer_->readImage());
    if (!exposureMeasured_) state_.exposure = targetExposure_;  // the first image starts exposed
    exposureMeasured_ = true;
    exposureStale_ = false;
    secondsSinceExposureMeasure_ = 0.0f;
}

void Viewer::adaptExposure(float seconds) {
    if (!state_.autoExposure) {
        state_.exposure = exposureFromStops(state_.exposureStops);
        exposureMeasured_ = false;
        return;
    }
    if (!exposureMeasured_) return;
    // In stops, so that brightening and darkening take the same time.
    const float blend = 1.0f - std::exp(-seconds / kExposureAdaptation);
    state_.exposure *= std::exp2(blend * std::log2(targetExposure_ / state_.exposure));
    state_.exposureStops = std::log2(state_.exposure);
}

// One pass of the main loop; false when the viewer should stop.
bool Viewer::loopIteration() {
    input_.beginFrame();
    glfwPollEvents();
    applyScript();
    ++iteration_;
    if (glfwWindowShouldClose(window_.handle) || quit_) return false;

    int width = 0, height = 0;
    glfwGetFramebufferSize(window_.handle, &width, &height);
    if (width == 0 || height == 0 || glfwGetWindowAttrib(window_.handle, GLFW_ICONIFIED)) {
        // Minimised: nothing to draw into. A script keeps counting frames, so it must not block.
        if (options_.script.empty()) glfwWaitEvents();
        else glfwWaitEventsTimeout(0.02);
        return true;
    }
    if (swapchainStale_ || uint32_t(width) != shownFramebuffer_.width || uint32_t(height) != shownFramebuffer_.height)
        recreateSwapchain();

    const auto now = std::chrono::steady_clock::now();
    const float wallSeconds = std::chrono::duration<float>(now - lastFrame_).count();
    lastFrame_ = now;
    // Scripts move by fixed steps so tests see the same images on fast and slow machines.
    const float seconds = options_.script.empty() ? std::min(wallSeconds, 1.0f) : 1.0f / 30.0f;

    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    if (!options_.script.empty()) {
        // A script's mouse is the only mouse: ImGui must see it where the camera sees it.
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = ImVec2(input_.cursor.x, input_.cursor.y);
        for (int button = 0; button < 3; ++button) io.MouseDown[button] = input_.buttons[button];
    }
    ImGui::NewFrame();
    if (!ImGui::GetIO().WantCaptureKeyboard) handleKeys(seconds);
    if (state_.sun.animate) state_.sun.azimuthDegrees += state_.sun.animateDegreesPerSecond * seconds;
    handleMouse(seconds);
    applyRequests();
    if (swapchainStale_) recreateSwapchain();

    const UiFacts uiFacts = facts();
    state_.settingsWidth = 0.0f;  // drawSettingsWindow sets it while the settings are open
    if (state_.showPanels) {
        drawStatusBar(state_);
        drawSettingsWindow(state_, uiFacts);
        drawProfilerWindow(state_, uiFacts);
    }
    if (state_.showGuide) drawGuideWindow(state_);
    drawWarningsWindow(state_);
    drawErrorWindow(state_);
    ImGui::Render();
    const VkRect2D area = imageArea();
    if (area.offset.x != shownImageArea_.offset.x || area.extent.width != shownImageArea_.extent.width ||
        area.extent.height != shownImageArea_.extent.height)
        resizeRenderer();  // the settings opened, closed or were hidden: the voxels stay

    if (imageStale_ || renderer_->settling() || options_.renderEveryFrame ||
        !sameCamera(renderer_->camera(), lastRenderedCamera_)) {
        const FrameStats stats = renderer_->renderFrame();
        lastRenderedCamera_ = renderer_->camera();
        imageStale_ = false;
        state_.history.add(wallSeconds * 1000.0f, stats);
        if (options_.verbose) printFrameStats(stats);
        exposureStale_ = true;
    } else {
        state_.history.add(wallSeconds * 1000.0f, FrameStats{});  // an empty plan: the image is reused
    }

    measureExposure(seconds);
    adaptExposure(seconds);
    const bool scriptedEnd = options_.frames > 0 && framesDrawn_ + 1 == options_.frames;
    std::string screenshot;
    bool withUi = state_.showPanels || state_.showGuide;
    if (scriptedEnd && !options_.screenshotPath.empty()) {
        screenshot = options_.screenshotPath;
        withUi = options_.screenshotWithUi;
    } else if (!pendingScreenshots_.empty()) {
        screenshot = pendingScreenshots_.front().first;
        withUi = pendingScreenshots_.front().second;
        pendingScreenshots_.erase(pendingScreenshots_.begin());
    }
    drawFrame(screenshot.empty() || withUi, screenshot);
    return !scriptedEnd;
}

int Viewer::run() {
    while (loopIteration()) {}
    VK_CHECK(vkDeviceWaitIdle(context_->device));
    std::printf("vct view: %u frames drawn\n", framesDrawn_);
    if (!context_->validationMessages().empty()) throw Error("the validation layer reported problems (see above)");
    return 0;
}

}  // namespace

int runViewer(ViewerOptions options) {
    Viewer viewer(std::move(options));
    return viewer.run();
}

}  // namespace vct
