// The frame: orders the passes, decides which can be skipped, and hands back the image.
//
//   shadow maps → G-buffer → full-screen shading → resolve (supersample average)
//
// Shadow maps are redrawn only when a light or the geometry changed.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "gpu/context.h"
#include "gpu/resources.h"
#include "gpu/timing.h"
#include "io/image_io.h"
#include "render/gbuffer_pass.h"
#include "render/resolve_pass.h"
#include "render/scene_gpu.h"
#include "render/settings.h"
#include "render/shade_pass.h"
#include "render/shadow_pass.h"
#include "scene/scene.h"

namespace vct {

struct FrameStats {
    std::vector<PassTime> passes;      // GPU time of each pass that ran this frame
    std::vector<std::string> skipped;  // passes skipped because nothing they depend on changed
    double cpuMilliseconds = 0.0;      // recording + submission + wait, on the CPU clock

    double gpuMilliseconds() const;
    bool ran(const std::string& pass) const;
};

class Renderer {
public:
    Renderer(GpuContext& context, const Scene& scene, const RenderSettings& settings);

    void setCamera(const Camera& camera) { camera_ = camera; }
    const Camera& camera() const { return camera_; }
    void setLights(const std::vector<Light>& lights);
    const std::vector<Light>& lights() const { return lights_; }
    const RenderSettings& settings() const { return settings_; }
    // Changes that keep the image size (component toggles, ambient, mode).
    void setShadingSettings(const RenderSettings& settings);

    // Records, submits and waits for one frame.
    FrameStats renderFrame();
    // The last frame's image: linear radiance, width × height, top row first.
    Image readImage();

private:
    void writeFrameConstants();

    GpuContext& context_;
    RenderSettings settings_;
    Bounds sceneBounds_;
    Camera camera_;
    std::vector<Light> lights_;
    bool shadowsDirty_ = true;

    SceneGpu sceneGpu_;
    ShadowLayout shadowLayout_;
    Buffer frameConstants_;
    Buffer lightsBuffer_;
    Buffer shadowViewsBuffer_;
    std::unique_ptr<ShadowPass> shadowPass_;
    GBufferPass gbufferPass_;
    ShadePass shadePass_;
    ResolvePass resolvePass_;
    GpuTimer timer_;
};

}  // namespace vct
