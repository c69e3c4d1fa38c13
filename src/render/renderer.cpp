#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <functional>

#include <glm/gtc/matrix_transform.hpp>

#include "gpu/commands.h"
#include "gpu/vk_check.h"
#include "render/camera.h"
#include "render/frame_constants.h"
#include "render/frame_plan.h"
#include "render/renderer_limits.h"
#include "render/scene_analysis.h"
#include "render/sun_cascades.h"
#include "render/voxel_grid_fit.h"

namespace vct {

double FrameStats::gpuMilliseconds() const {
    double total = 0.0;
    for (const PassTime& pass : passes) total += pass.milliseconds;
    return total;
}

bool FrameStats::ran(const std::string& pass) const {
    for (Pass planned : plan.passes)
        if (passName(planned) == pass) return true;
    return false;
}

std::vector<std::string> FrameStats::skipped() const {
    std::vector<std::string> names;
    for (Pass pass : plan.skipped()) names.push_back(passName(pass));
    return names;
}

// Checks the settings against the device before the members below allocate anything.
static const RenderSettings& checkedSettings(const GpuContext& context, const Scene& scene,
                                             const RenderSettings& settings) {
    checkRendererLimits(context, scene, settings);
    return settings;
}

Renderer::Renderer(GpuContext& context, const Scene& scene, const RenderSettings& settings)
    : context_(context),
      settings_(checkedSettings(context, scene, settings)),
      camera_(scene.cameras.empty() ? defaultCamera(scene.bounds()) : scene.cameras.front()),
      lights_(scene.lights),
      frameConstants_(context, sizeof(glsl::FrameConstants), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true),
      bounceConvergence_(context),
      occupiedHeader_(context, sizeof(glsl::WorkListHeader), VK_BUFFER_USAGE_TRANSFER_DST_BIT, true),
      volumes_(std::make_unique<VoxelVolumes>(context, settings.resources)),
      injectPass_(context),
      mipsPass_(context),
      timer_(context) {
    setGeometry(scene);
    applyLights(lights_);
}

void Renderer::setGeometry(const Scene& scene) {
    if (sceneGpu_) vkDeviceWaitIdle(context_.device);
    checkSceneCanBeRendered(scene);
    sceneName_ = scene.name;
    SceneAnalysis analysis = analyzeScene(scene);
    facts_ = std::move(analysis.facts);
    const Scene& local = analysis.local;
    triangleBoxes_ = triangleBoxes(local);
    grid_ = fitVoxelGrid(facts_.bounds, settings_.resources.voxelResolution);
    environment_ = scene.environment;
    environmentRotation_ = scene.environmentRotation;
    sky_ = std::make_unique<SkyImage>(context_, facts_.sky(scene));
    sceneGpu_ = std::make_unique<SceneGpu>(context_, local);
    voxelizePass_ = std::make_unique<VoxelizePass>(context_, local, *sceneGpu_, grid_);
    resize(settings_.image);                             // the G-buffer pipeline depends on the scene's textures
    if (shadowPass_) shadowPass_->useScene(*sceneGpu_);  // and so does the alpha-tested shadow pipeline
    stale_.voxels = true;
    staleShadowArrays_ = kAllShadowArrays;  // every shadow map shows the old geometry
    if (shadowPass_) relight();             // shadow views are fitted to the scene's bounds
}

void Renderer::resize(const ImageSettings& image) {
    if (gbufferPass_) vkDeviceWaitIdle(context_.device);
    settings_.image = image;
    const uint32_t width = image.width, height = image.height;
    const uint32_t samplesWide = width * image.supersample, samplesHigh = height * image.supersample;
    gbufferPass_ = std::make_unique<GBufferPass>(context_, *sceneGpu_, samplesWide, samplesHigh);
    diffuseConesPass_ = image.diffuseDownscale > 1 ? std::make_unique<DiffuseConesPass>(
                                                         context_, samplesWide, samplesHigh, image.diffuseDownscale)
                                                   : nullptr;
    shadePass_ = std::make_unique<ShadePass>(context_, samplesWide, samplesHigh);
    resolvePass_.reset();
    createResolvePassIfNeeded();
    stale_.view = true;
}

void Renderer::createResolvePassIfNeeded() {
    if (resolvesImage(settings_) && !resolvePass_)
        resolvePass_ = std::make_unique<ResolvePass>(context_, settings_.image.width, settings_.image.height,
                                                     settings_.image.supersample);
}

void Renderer::setLights(const std::vector<Light>& lights) {
    if (lights != lights_) applyLights(lights);
}

void Renderer::relight() { applyLights(lights_); }

std::vector<Light> Renderer::withEnvironmentSun(const std::vector<Light>& lights) const {
    std::vector<Light> all = lights;
    if (!facts_.environmentSun) return all;
    const glm::vec3 illuminance = environment_ * facts_.environmentSun->illuminance;
    const float brightest = std::max({illuminance.r, illuminance.g, illuminance.b});
    if (!(brightest > 0.0f)) return all;
    // Turned about +Y with the image (equirectangular.h): a right-handed rotation.
    const glm::vec3 towards = facts_.environmentSun->towardsSun;
    const float c = std::cos(environmentRotation_), s = std::sin(environmentRotation_);
    Light sun;
    sun.name = "the environment image's sun";
    sun.type = LightType::Directional;
    sun.direction = -glm::vec3(towards.x * c + towards.z * s, towards.y, -towards.x * s + towards.z * c);
    sun.intensity = brightest;
    sun.color = illuminance / brightest;
    all.push_back(sun);
    return all;
}

void Renderer::applyLights(const std::vector<Light>& lights) {
    const std::vector<Light> all = withEnvironmentSun(lights);
    checkLightsCanBeRendered(all, sceneName_);
    lights_ = lights;
    shadowedLights_ = all;
    for (Light& light : shadowedLights_) light.position -= facts_.origin;
    layOutShadows(currentShadowLayout());
    // The brightest emitter stands in for the scene's materials in the storage scale.
    Scene emitters;
    Material brightest;
    // The sky stands beside the brightest emitter: light it bounces into a scene lit by nothing
    // else must fit in float16 as well.
    const glm::vec3 sky = environment_ * facts_.skyMean;
    brightest.emission = glm::vec3(std::max({facts_.brightestEmission, sky.r, sky.g, sky.b}));
    emitters.materials.push_back(brightest);
    radianceScale_ = radianceStorageScale(all, emitters, grid_.voxelSize);
    stale_.shadows = true;
    stale_.radiance = true;
}

void Renderer::layOutShadows(ShadowLayout layout) {
    const ShadowLayout previous = lightTable_.layout();
    lightTable_.upload(context_, std::move(layout));
    const ShadowLayout& now = lightTable_.layout();
    // New arrays only when the number of shadow maps changed, or the sun's cascades need more layers
    // than its array has (ShadowPass keeps room for all of them once there are any); otherwise the
    // maps are redrawn in place.
    const bool sunFits = shadowPass_ && now.sunLayers <= shadowPass_->sunMaps.desc.layers &&
                         previous.sunLayers - previous.sunCascadeLayers == now.sunLayers - now.sunCascadeLayers;
    if (!sunFits || previous.localLayers != now.localLayers || previous.areaLayers != now.areaLayers) {
        if (shadowPass_) vkDeviceWaitIdle(context_.device);
        shadowPass_ = std::make_unique<ShadowPass>(context_, now, settings_, *sceneGpu_);
    }
    // Only the maps whose views moved are redrawn: moving the sun in tile-room redrew its 48 lamp
    // cube faces every frame.
    staleShadowArrays_ |= changedShadowArrays(previous, now);
}

bool Renderer::castsSunCascades() const {
    return settings_.resources.sunCascades > 0 &&
           std::any_of(shadowedLights_.begin(), shadowedLights_.end(),
                       [](const Light& light) { return light.type == LightType::Directional; });
}

ShadowLayout Renderer::currentShadowLayout() const {
    if (!castsSunCascades()) return layoutShadows(shadowedLights_, facts_.areaLights, facts_.bounds, settings_);
    CascadeView view;
    view.camera = camera_;
    view.camera.position -= facts_.origin;
    view.aspect = float(settings_.image.width) / float(settings_.image.height);
    view.imageHeight = settings_.image.height;
    view.nearestGeometry = nearestBoxDistance(triangleBoxes_, view.camera.position);
    return layoutShadows(shadowedLights_, facts_.areaLights, facts_.bounds, settings_, &view);
}

void Renderer::refitSunCascades() {
    if (!castsSunCascades()) return;
    ShadowLayout layout = currentShadowLayout();
    if (changedShadowArrays(lightTable_.layout(), layout) == 0) return;
    layOutShadows(std::move(layout));
    stale_.shadows = true;  // the cascades' layers alone: the voxels' light stays as it is
}

void Renderer::setEnvironment(glm::vec3 environment) {
    environment_ = environment;
    relight();  // the storage scale may change with it, and the light converges again
}

void Renderer::setEnvironmentRotation(float radians) {
    if (radians == environmentRotation_) return;
    environmentRotation_ = radians;
    relight();  // the cones leaving the grid see another sky, and the image's sun turns with it
}

void Renderer::setShading(const ShadingSettings& shading) {
    // Other cones gather other light: the reduced diffuse light of the last frames no longer holds,
    // nor does the still frames' mean.
    if (shading != settings_.shading) {
        if (diffuseConesPass_) diffuseConesPass_->forgetHistory();
        framesAveraged_ = 0;
    }
    // Shadows or area lights switched on or off light the voxels differently, the area lights'
    // part included.
    if (voxelLightFlags(shading) != voxelLightFlags(settings_.shading)) {
        stale_.radiance = true;
        injectPass_.forgetAreaLights();
    }
    settings_.shading = shading;
    createResolvePassIfNeeded();
}

uint32_t Renderer::voxelLightFlags(const ShadingSettings& shading) {
    return componentFlags(effectiveComponents(shading)) & glsl::VOXEL_LIGHT_FLAGS;
}

glm::mat4 Renderer::cameraViewProjection() const {
    Camera local = camera_;
    local.position -= facts_.origin;
    const float aspect = float(gbufferPass_->width) / float(gbufferPass_->height);
    return cameraMatrices(local, aspect, facts_.bounds).viewProjection;
}

glm::mat4 Renderer::writeFrameConstants(const glm::mat4& cameraViewProjection) {
    const uint32_t width = gbufferPass_->width, height = gbufferPass_->height;
    glsl::FrameConstants constants{};
    constants.viewProjection = cameraViewProjection;
    // This still frame's samples moved within their squares (stillSampleOffset): a shift of the
    // clip space by the offset's share of the image, 2/width per sample. Once the mean is complete
    // the last frame's offset stays, so a still view draws nothing anew.
    const uint32_t stillFrame = std::min(framesAveraged_, stillFramesAveraged(settings_.shading) - 1);
    const glm::vec2 offset = stillSampleOffset(settings_.shading, stillFrame);
    if (offset != glm::vec2(0.0f))
        constants.viewProjection = glm::translate(glm::mat4(1.0f), glm::vec3(2.0f * offset.x / float(width),
                                                                             2.0f * offset.y / float(height), 0.0f)) *
                                   cameraViewProjection;
    constants.inverseViewProjection = glm::inverse(constants.viewProjection);
    constants.cameraPosition = camera_.position - facts_.origin;
    constants.lightCount = uint32_t(lightTable_.layout().lights.size());
    constants.firstAreaLight = lightTable_.layout().firstAreaLight;
    constants.shadowViewCount = uint32_t(lightTable_.layout().views.size());
    const ShadingSettings& shading = settings_.shading;
    constants.componentFlags = componentFlags(effectiveComponents(shading)) |
                               (shading.mode != RenderMode::Indirect ? glsl::SHOW_SKY : 0u) |
                               (settings_.resources.rayVisibility ? glsl::RAY_VISIBILITY : 0u) |
                               (settings_.resources.anisotropicVoxels ? glsl::ANISOTROPIC_VOXELS : 0u);
    constants.debugView = uint32_t(shading.debugView);
    constants.renderSize = glm::vec2(float(width), float(height));
    constants.inverseRenderSize = glm::vec2(1.0f / float(width), 1.0f / float(height));
    constants.ambientFactor = shading.ambientFactor;
    constants.shadowNormalOffset = shading.shadowNormalOffset;
    constants.pcfRadius = shading.pcfRadius;
    constants.radianceScale = radianceScale_;
    const float resolution = float(grid_.resolution);
    constants.grid = grid_;
    constants.coneTanHalfAperture = std::tan(glm::radians(0.5f * shading.diffuseConeAperture));
    constants.coneStep = shading.coneStep;
    constants.coneMaxDistance = shading.coneMaxDistance * resolution;
    // In world units (voxels of a 64³ grid over the same scene), so that a finer grid does not
    // start its cones nearer the surface and see light a coarser one skips; but never inside the
    // surface's own voxels, which a coarser grid's cones would otherwise start in.
    constants.coneStartOffset =
        std::max(shading.coneStartOffset * resolution / float(kConeStartGrid), shading.coneStartOffset);
    constants.aoFalloff = shading.aoFalloff / resolution;
    constants.coneStopOpacity = shading.coneStopOpacity;
    constants.diffuseCentreWeight = shading.diffuseCentreWeight;
    constants.diffuseConeCount = shading.diffuseConeCount;
    constants.specularConeMaxTan = float(std::tan(glm::radians(0.5 * double(shading.specularMaxAperture))));
    const uint32_t turns = diffuseRingTurns(shading);
    constants.diffuseRingTurn = float(ringTurn_ % turns) / float(turns);
    const DiffuseBeam beam = diffuseBeamOfTurn(shading, settings_.resources.rayVisibility, ringTurn_);
    constants.diffuseBeam = beam.beam;
    constants.diffuseBeamAzimuth = beam.azimuth;
    constants.debugVoxelMip = shading.debugVoxelMip;
    constants.diffuseDownscale = settings_.image.diffuseDownscale;
    constants.environment = glm::vec4(environment_, sky_->mapped() ? 1.0f : 0.0f);
    constants.environmentTurns = environmentTurns(environmentRotation_);
    std::memcpy(frameConstants_.mapped, &constants, sizeof(constants));
    return constants.viewProjection;
}

FrameStats Renderer::renderFrame() {
    const auto start = std::chrono::steady_clock::now();
    FrameStats stats;
    // The G-buffer holds the view alone: a frame whose camera did not move (a light steered, the
    // light settling) shades the last one's again.
    const glm::mat4 camera = cameraViewProjection();
    if (camera != cameraViewProjection_) stale_.view = true;
    cameraViewProjection_ = camera;
    if (stale_.view) refitSunCascades();  // a new view or image size
    stats.plan = planFrame(stale_, settings_);
    // A new view, light or geometry: the still frames' mean starts anew (new shading, in setShading).
    if (stale_.view || stats.plan.runs(Pass::Inject) || stats.plan.runs(Pass::Shadow)) framesAveraged_ = 0;
    // A still frame whose samples moved draws the G-buffer anew, in the same mean.
    const bool cameraStill = !stale_.view;
    const glm::mat4 viewProjection = writeFrameConstants(camera);
    if (viewProjection != gbufferViewProjection_ && !stale_.view) {
        stale_.view = true;
        stats.plan = planFrame(stale_, settings_);
    }
    gbufferViewProjection_ = viewProjection;
    const FramePlan& plan = stats.plan;
    const bool converging = settings_.resources.bounces == kConvergedBounces;
    const bool progressive = bouncesProgressively(settings_);
    // Each submission's passes are timed; a pass that runs in several (bounces) adds up.
    auto submit = [&](const std::function<void(VkCommandBuffer)>& record) {
        submitAndWait(context_, [&](VkCommandBuffer commands) {
            timer_.reset(commands);
            record(commands);
        });
        for (const PassTime& time : timer_.results()) {
            auto same = std::find_if(stats.passes.begin(), stats.passes.end(),
                                     [&](const PassTime& pass) { return pass.name == time.name; });
            if (same == stats.passes.end()) stats.passes.push_back(time);
            else same->milliseconds += time.milliseconds;
        }
    };
    auto run = [&](VkCommandBuffer commands, Pass pass, const std::function<void()>& record) {
        if (!plan.runs(pass)) return;
        timer_.begin(commands, passName(pass));
        record();
        timer_.end(commands);
    };

    // The area lights' light on the voxels is kept between injections while the voxels, the area
    // lights' maps and the switches that light them (setShading) stay as they were.
    if (plan.runs(Pass::Shadow) && (staleShadowArrays_ & shadowArrayBit(ShadowArray::Area)))
        injectPass_.forgetAreaLights();
    // The voxelizer's count of occupied voxels sizes the progressive slices: read between submissions.
    if (plan.runs(Pass::Shadow) || plan.runs(Pass::Voxelize))
        submit([&](VkCommandBuffer commands) {
            run(commands, Pass::Shadow, [&] {
                shadowPass_->record(commands, *sceneGpu_, lightTable_.layout(), lightTable_.buffers().shadowViews,
                                    staleShadowArrays_);
                staleShadowArrays_ = 0;
            });
            run(commands, Pass::Voxelize, [&] {
                voxelizePass_->record(commands, *sceneGpu_, *volumes_);
                recordOccupiedCount(commands);
            });
        });
    if (plan.runs(Pass::Voxelize)) {
        occupiedVoxels_ = static_cast<const glsl::WorkListHeader*>(occupiedHeader_.mapped)->count;
        injectPass_.forgetAreaLights(facts_.areaLights.empty() ? 0 : occupiedVoxels_);
    }
    const uint32_t slices = progressiveSlices(settings_, occupiedVoxels_);
    const InjectPass::Slice slice{slices, slicePhase_ % slices};
    stats.occupiedVoxels = occupiedVoxels_;
    stats.bounceSlices = progressive ? slices : 1;
    const bool sweepEnds = !progressive || slice.phase + 1 == slice.count;
    if (plan.runs(Pass::Inject))
        submit([&](VkCommandBuffer commands) {
            // Progressively converging (the viewer), the injection is itself a bounce: the light
            // sources' light plus what the cones gathered from the last frame's light (a slice of the
            // voxels gathers anew each frame), so a moved light starts from the old solution instead of
            // dropping to one bounce. Otherwise every frame that re-lights starts from the light
            // sources alone: the same inputs, the same image.
            run(commands, Pass::Inject, [&] {
                if (progressive)
                    injectPass_.recordGather(commands, frameConstants_.buffer, *volumes_, *sky_, slice, occupiedVoxels_,
                                             skipsEmptySpace());
                injectPass_.record(commands, frameConstants_.buffer, lightTable_.buffers(), *shadowPass_, *volumes_,
                                   progressive);
            });
            run(commands, Pass::Mips, [&] {
                mipsPass_.record(commands, *volumes_, settings_.resources.rayVisibility);
                if (converging && sweepEnds) bounceConvergence_.record(commands, volumes_->radiance);
            });
        });
    // Light converged anew from the light sources, or new voxels, is not the light of the last
    // frames' diffuse cones; a progressive bounce changes it by little, and reused light catches up
    // within a few frames.
    if (diffuseConesPass_ && (plan.runs(Pass::Voxelize) || (plan.runs(Pass::Inject) && !progressive)))
        diffuseConesPass_->forgetHistory();
    else if (diffuseConesPass_ && plan.runs(Pass::Inject)) diffuseConesPass_->lightChanged();
    bool converged = true;
    if (plan.runs(Pass::Inject)) {
        stats.bounces = 1;
        // Remembers this mean for the next bounce; only progressive bounces settle here, once a
        // whole sweep over the slices changed the light by less than the tolerance.
        if (converging) converged = sweepEnds && bounceConvergence_.settled() && progressive;
        if (progressive) slicePhase_ = (slice.phase + 1) % slice.count;
    }
    if (plan.runs(Pass::Bounce)) {
        const uint32_t more = converging ? kMaxBouncesPerFrame - 1 : settings_.resources.bounces - 1;
        for (uint32_t i = 0; i < more && !(converging && converged); ++i) {
            submit([&](VkCommandBuffer commands) {
                run(commands, Pass::Bounce, [&] {
                    injectPass_.recordGather(commands, frameConstants_.buffer, *volumes_, *sky_, {}, occupiedVoxels_,
                                             skipsEmptySpace());
                    injectPass_.record(commands, frameConstants_.buffer, lightTable_.buffers(), *shadowPass_, *volumes_,
                                       true);
                    mipsPass_.record(commands, *volumes_, settings_.resources.rayVisibility);
                    if (converging) bounceConvergence_.record(commands, volumes_->radiance);
                });
            });
            ++stats.bounces;
            if (converging) converged = bounceConvergence_.settled();
        }
    }
    submit([&](VkCommandBuffer commands) {
        run(commands, Pass::GBuffer, [&] { gbufferPass_->record(commands, *sceneGpu_, frameConstants_.buffer); });
        run(commands, Pass::DiffuseCones, [&] {
            diffuseConesPass_->record(commands, frameConstants_.buffer, *gbufferPass_, *volumes_, *sky_, viewProjection,
                                      cameraStill, skipsEmptySpace());
        });
        run(commands, Pass::Shade, [&] {
            const bool reducedDiffuse = plan.runs(Pass::DiffuseCones);
            const ShadeVariant variant{
                .debugViews = settings_.shading.debugView != DebugView::None,
                // A frame without indirect diffuse light (`--mode direct`) gets the variant without
                // the cone loop: inlined, it slowed lavapipe's shading of every pixel 2× (1280×720).
                .tracesDiffuseCones = !reducedDiffuse && needsDiffuseCones(settings_.shading),
                .tracesSpecularCone =
                    facts_.anySpecularMaterial && effectiveComponents(settings_.shading).indirectSpecular,
                .areaLights = !facts_.areaLights.empty() && settings_.shading.components.areaLights,
                .sunShadows = lightTable_.layout().sunLayers > 0,
                .localShadows = lightTable_.layout().localLayers > 0,
                .areaLightSpecular = facts_.anySpecularMaterial,
                .skipsEmptySpace = skipsEmptySpace(),
            };
            const ShadeInputs inputs{frameConstants_.buffer,
                                     sceneGpu_->materials.buffer,
                                     lightTable_.buffers(),
                                     reducedDiffuse ? &diffuseConesPass_->diffuse() : nullptr,
                                     variant,
                                     sky_.get()};
            shadePass_->record(commands, inputs, *gbufferPass_, *shadowPass_, *volumes_);
        });
        // Once every turn of the ring is in the mean, the resolved image stays as it is.
        if (!stillMeanComplete())
            run(commands, Pass::Resolve, [&] {
                const bool settled =
                    (!progressive || converged) && (!plan.runs(Pass::DiffuseCones) || diffuseConesPass_->settled());
                resolvePass_->record(commands, shadePass_->radiance, averageStillFrame(settled));
            });
    });
    stats.bouncesConverged = converged;
    diffuseReuseSettling_ = plan.runs(Pass::DiffuseCones) && !diffuseConesPass_->settled();
    if (plan.runs(Pass::DiffuseCones)) {
        stats.diffuseBlocksTraced = diffuseConesPass_->tracedRepresentatives();
        stats.diffuseSamplesTraced = diffuseConesPass_->tracedFallbackSamples();
    }
    stale_ = afterFrame(stale_, plan, converged);
    stats.cpuMilliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

float Renderer::averageStillFrame(bool settled) {
    const uint32_t frames = stillFramesAveraged(settings_.shading);
    if (!settled || frames == 1) {
        framesAveraged_ = 0;
        return 1.0f;
    }
    ++framesAveraged_;
    // The ring turns once each of its turns has had its share of the still frames (every frame
    // without still samples), and the next frame traces it at every sample: the reused light is
    // another turn's. Between turns only the samples move, and the reduced cones' light is reused.
    const uint32_t turns = diffuseRingTurns(settings_.shading);
    if (framesAveraged_ < frames && framesAveraged_ % (frames / turns) == 0) {
        ringTurn_ = (ringTurn_ + 1) % turns;
        if (diffuseConesPass_) diffuseConesPass_->forgetHistory();
    }
    return 1.0f / float(framesAveraged_);
}

FrameStats Renderer::renderSettled(uint32_t maxFrames) {
    FrameStats stats = renderFrame();
    for (; stats.settleFrames + 1 < maxFrames && settling(); ++stats.settleFrames)
        stats.settleGpuMilliseconds += renderFrame().gpuMilliseconds();
    return stats;
}

bool Renderer::skipsEmptySpace() const {
    return vct::skipsEmptySpace(settings_.shading, context_.isSoftwareRasterizer());
}

void Renderer::recordOccupiedCount(VkCommandBuffer commands) {
    copyForHost(commands, volumes_->occupiedDispatch, occupiedHeader_, {{0, 0, sizeof(glsl::WorkListHeader)}});
}

Image Renderer::readImage() {
    const uint32_t width = settings_.image.width, height = settings_.image.height;
    Buffer readback(context_, VkDeviceSize(width) * height * 4 * sizeof(float), VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    submitAndWait(context_, [&](VkCommandBuffer commands) {
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {width, height, 1};
        copyForHost(commands, output(), readback, region);
    });
    Image image;
    image.width = width;
    image.height = height;
    image.rgb.resize(size_t(width) * height * 3);
    const float* rgba = static_cast<const float*>(readback.mapped);
    for (size_t i = 0; i < size_t(width) * height; ++i)
        for (int c = 0; c < 3; ++c) image.rgb[i * 3 + c] = rgba[i * 4 + c];
    return image;
}

}  // namespace vct

namespace vct {

uint64_t Renderer::deviceMemoryBytes() const {
    uint64_t bytes = volumes_->allocatedBytes();
    for (const GpuImage* image : std::initializer_list<const GpuImage*>{
             &gbufferPass_->position, &gbufferPass_->normal, &gbufferPass_->baseColor, &gbufferPass_->emissive,
             &gbufferPass_->depth, &gbufferPass_->lastPosition, &gbufferPass_->lastNormal, &shadePass_->radiance,
             &shadowPass_->sunMaps, &shadowPass_->localMaps, &shadowPass_->areaMaps})
        bytes += image->memorySize;
    if (resolvePass_) bytes += resolvePass_->resolved.memorySize;
    if (diffuseConesPass_) bytes += diffuseConesPass_->memoryBytes();
    for (const GpuImage& texture : sceneGpu_->textures) bytes += texture.memorySize;
    for (const Buffer* buffer : std::initializer_list<const Buffer*>{
             &sceneGpu_->vertices, &sceneGpu_->indices, &sceneGpu_->triangleMaterials, &sceneGpu_->materials})
        bytes += buffer->size;
    for (const VoxelizePass::WorkChunk& chunk : voxelizePass_->workChunks) bytes += chunk.items.size;
    for (const Buffer& accumulation : voxelizePass_->accumulation) bytes += accumulation.size;
    return bytes;
}

}  // namespace vct
