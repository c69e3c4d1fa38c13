// The frame: records the passes the frame plan (render/frame_plan.h) picks, in pipeline order,
//
//   shadow maps → voxelize → inject light → mips (→ bounce) → G-buffer → full-screen shading
//   (direct light and cone tracing) → resolve (supersample average, with supersamples)
//
// and hands back the image. What did not change is not redone.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "gpu/context.h"
#include "gpu/resources.h"
#include "gpu/timing.h"
#include "io/image_io.h"
#include "render/bounce_convergence.h"
#include "render/diffuse_cones_pass.h"
#include "render/frame_plan.h"
#include "render/gbuffer_pass.h"
#include "render/inject_pass.h"
#include "render/light_table.h"
#include "render/mips_pass.h"
#include "render/resolve_pass.h"
#include "render/scene_analysis.h"
#include "render/scene_gpu.h"
#include "render/settings.h"
#include "render/shade_pass.h"
#include "render/shadow_pass.h"
#include "render/sky_image.h"
#include "render/voxel_volumes.h"
#include "render/voxelize_pass.h"
#include "scene/environment_sun.h"
#include "scene/scene.h"

namespace vct {

struct FrameStats {
    FramePlan plan;                // the passes this frame ran (none: the viewer reused its image)
    std::vector<PassTime> passes;  // their GPU times, where the device has timestamp queries
    double cpuMilliseconds = 0.0;  // recording + submission + wait, on the CPU clock
    uint32_t bounces = 0;          // bounce iterations this frame ran (the injection is the first)
    bool bouncesConverged = true;  // the voxels' light changed by less than kBounceTolerance
    uint32_t occupiedVoxels = 0;   // voxels the last voxelization listed (the light passes' work)
    uint32_t bounceSlices = 1;     // a progressive bounce gathers for one of these slices a frame
    // Reduced diffuse cones (DiffuseConesPass): blocks whose representative traced anew (the others
    // reused the last frame's light), and samples that traced their own.
    uint32_t diffuseBlocksTraced = 0;
    uint32_t diffuseSamplesTraced = 0;
    // Renderer::renderSettled: the frames it rendered after this one until the image settled, and
    // their GPU time together.
    uint32_t settleFrames = 0;
    double settleGpuMilliseconds = 0.0;

    double gpuMilliseconds() const;
    bool ran(const std::string& pass) const;
    std::vector<std::string> skipped() const;  // the passes the plan left out, in pipeline order
};

class Renderer {
public:
    Renderer(GpuContext& context, const Scene& scene, const RenderSettings& settings);

    void setCamera(const Camera& camera) { camera_ = camera; }
    const Camera& camera() const { return camera_; }
    // New lights: their shadow maps are redrawn and the light converges again on the next frames.
    // The same lights again change nothing (the viewer and the bench set them every frame).
    void setLights(const std::vector<Light>& lights);
    // The light converges again from its sources, as after a light change (the bench times that
    // where a scene has no light to move: its emissive surfaces are geometry).
    void relight();
    // New geometry (moved vertices, changed transforms or a new scene): re-uploaded, and the voxels
    // and shadow maps are rebuilt on the next frame. Lights and camera stay as they are.
    void setGeometry(const Scene& scene);
    const std::vector<Light>& lights() const { return lights_; }
    // The sky's radiance (Scene::environment), or the factor on its environment image; a change
    // converges the light again, as setLights.
    void setEnvironment(glm::vec3 environment);
    glm::vec3 environment() const { return environment_; }
    // How far the environment image is turned about +Y (Scene::environmentRotation); a change
    // converges the light again.
    void setEnvironmentRotation(float radians);
    float environmentRotation() const { return environmentRotation_; }
    // Whether the environment image holds a sun, lit as a directional light (environment_sun.h).
    bool environmentSunLit() const { return facts_.environmentSun.has_value(); }
    const RenderSettings& settings() const { return settings_; }
    // Changes that need no new images or voxels (a new image size is resize(); new resources
    // need a new Renderer).
    void setShading(const ShadingSettings& shading);

    // A new image size or supersampling (a resized window): only the image-sized passes are rebuilt.
    void resize(const ImageSettings& image);

    // Records, submits and waits for one frame.
    FrameStats renderFrame();
    // Progressive bounces have not converged yet, the reduced diffuse cones' reused light has not
    // all been traced anew since the view or the light changed, or the still frames (whose cones
    // turned, ShadingSettings::diffuseConeTurns, and whose samples moved, stillSamples) are not all
    // in the image's mean: the next frame changes the image even if nothing else does.
    bool settling() const {
        return stale_.bounces || diffuseReuseSettling_ ||
               (stillFramesAveraged(settings_.shading) > 1 && !stillMeanComplete());
    }
    // Frames renderSettled() and `vct bench` wait at most for the image to settle.
    static constexpr uint32_t kMaxSettleFrames = 64;
    // Renders frames until the image settles (at most `maxFrames`): the image a still viewer
    // converges to, as `vct render` and `vct bench` show it. Returns the first frame's stats, with
    // the frames after it counted in settleFrames.
    FrameStats renderSettled(uint32_t maxFrames = kMaxSettleFrames);
    // The last frame's image: linear radiance, width × height, top row first.
    Image readImage();

    // The GPU's positions (G-buffer, voxel grid, shadow views) are relative to this point, the
    // centre of the scene's bounds: world = local + sceneOrigin().
    glm::vec3 sceneOrigin() const { return facts_.origin; }
    const glsl::VoxelGridParams& voxelGrid() const { return grid_; }  // in the local frame
    const VoxelVolumes& volumes() const { return *volumes_; }
    // The last frame's image (RGBA32F, width × height; declare its use, gpu/pass_uses.h): the resolved one, or at one
    // sample per pixel the shading pass's own, e.g. for a viewer to tone-map onto its swapchain.
    const GpuImage& output() const { return resolvesImage(settings_) ? resolvePass_->resolved : shadePass_->radiance; }
    // Device memory held by the renderer's images and buffers, in bytes.
    uint64_t deviceMemoryBytes() const;

private:
    void applyLights(const std::vector<Light>& lights);
    // Holds `layout` in the light table, with shadow arrays large enough for it, and marks the maps
    // whose views moved for the next shadow pass.
    void layOutShadows(ShadowLayout layout);
    // Whether a sun casts shadows through cascades (ResourceSettings::sunCascades).
    bool castsSunCascades() const;
    // The lights' shadow views, with the suns' cascades fitted to the camera and the image as they
    // are now (the nearest geometry is looked for only where a sun has cascades).
    ShadowLayout currentShadowLayout() const;
    // After the camera moved or the image was resized: new cascades where they changed, redrawn on
    // the next frame.
    void refitSunCascades();
    // The resolve pass where resolvesImage() asks for one and there is none yet.
    void createResolvePassIfNeeded();
    // This frame's share of the resolved mean (ResolvePass::record); counts the frame into it and
    // turns the ring for the next one where `settled` (its image will not change by itself).
    float averageStillFrame(bool settled);
    // Every turn of the ring is in the mean (with turns to average).
    bool stillMeanComplete() const {
        const uint32_t turns = stillFramesAveraged(settings_.shading);
        return turns > 1 && framesAveraged_ >= turns;
    }
    // `lights` and, where the environment image has a sun, that sun as a directional light, turned
    // and scaled as the sky is now.
    std::vector<Light> withEnvironmentSun(const std::vector<Light>& lights) const;

    glm::mat4 cameraViewProjection() const;  // the camera's, as the G-buffer's size shapes it
    // Returns the view-projection it wrote: the camera's, with this still frame's samples moved.
    glm::mat4 writeFrameConstants(const glm::mat4& cameraViewProjection);
    // The components the voxels' light depends on (glsl::VOXEL_LIGHT_FLAGS) as `shading` shows them.
    static uint32_t voxelLightFlags(const ShadingSettings& shading);
    // The shading settings' empty-space skipping, or the device's default (settings.h).
    bool skipsEmptySpace() const;
    // Copies the occupied list's header to occupiedHeader_: its count sizes the progressive slices.
    void recordOccupiedCount(VkCommandBuffer commands);

    GpuContext& context_;
    RenderSettings settings_;
    std::string sceneName_;  // for messages
    SceneFacts facts_;       // the scene's frame (local = world − facts_.origin), area lights, sun, sky mean
    Camera camera_;
    std::vector<Light> lights_;
    std::vector<Light> shadowedLights_;  // lights_ and the environment's sun, in the local frame
    std::vector<Bounds> triangleBoxes_;  // of the scene's triangles, local: the camera's nearest geometry
    glm::vec3 environment_{0.0f};        // Scene::environment
    float environmentRotation_ = 0.0f;   // Scene::environmentRotation
    std::unique_ptr<SkyImage> sky_;      // Scene::environmentMap without its sun, or the placeholder
    StaleInputs stale_;
    glm::mat4 cameraViewProjection_{0.0f};                 // the last frame's camera
    glm::mat4 gbufferViewProjection_{0.0f};                // ... with its samples moved, as the G-buffer holds it
    ShadowArraySet staleShadowArrays_ = kAllShadowArrays;  // shadow arrays to redraw at the next shadow pass
    float radianceScale_ = 1.0f;
    glsl::VoxelGridParams grid_;

    std::unique_ptr<SceneGpu> sceneGpu_;
    LightTable lightTable_;  // the lights and shadow views as the shaders read them
    Buffer frameConstants_;
    BounceConvergence bounceConvergence_;
    bool diffuseReuseSettling_ = false;  // see settling()
    // The still frames in the resolved image's mean, and the turn of the diffuse ring the next frame
    // traces (of stillFramesAveraged()); a change to the shading or the image size starts anew.
    uint32_t framesAveraged_ = 0;
    uint32_t ringTurn_ = 0;
    uint32_t slicePhase_ = 0;  // the occupied voxels' slice the next progressive bounce gathers for
    Buffer occupiedHeader_;    // host-visible copy of the occupied list's header, made after voxelizing
    uint32_t occupiedVoxels_ = 0;
    std::unique_ptr<ShadowPass> shadowPass_;
    std::unique_ptr<VoxelVolumes> volumes_;  // sized by the settings' resources, kept across scenes
    std::unique_ptr<VoxelizePass> voxelizePass_;
    InjectPass injectPass_;
    MipsPass mipsPass_;
    // Sized by the image: rebuilt by resize() without touching the voxels or shadow maps.
    std::unique_ptr<GBufferPass> gbufferPass_;
    std::unique_ptr<DiffuseConesPass> diffuseConesPass_;  // only when the diffuse cones run reduced
    std::unique_ptr<ShadePass> shadePass_;
    std::unique_ptr<ResolvePass> resolvePass_;
    GpuTimer timer_;
};

}  // namespace vct
