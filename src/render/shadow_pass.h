// Shadow maps for every light: a sun gets an orthographic map fitted to the scene (and, where the
// camera needs finer ones, cascades fitted to its view: sun_cascades.h), a spot a perspective map
// over its cone, a point light six perspective maps (cube faces), and an area light
// (an emissive surface) a cube seen from just in front of its centre.
#pragma once

#include <algorithm>
#include <vector>

#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "gpu_types.h"
#include "render/scene_gpu.h"
#include "render/settings.h"
#include "render/sun_cascades.h"
#include "scene/area_lights.h"
#include "scene/scene.h"

namespace vct {

// The shadow views of all lights, and the lights in GPU form pointing at their views: the punctual
// lights first, then the area lights, whose triangles follow in one array.
struct ShadowLayout {
    std::vector<glsl::ShadowView> views;
    std::vector<glsl::GpuLight> lights;  // the punctual lights, then from firstAreaLight on the area lights
    uint32_t firstAreaLight = 0;
    std::vector<glsl::GpuEmitterTriangle> emitterTriangles;
    uint32_t sunLayers = 0;  // the scene-fitted maps, then the cascades (the last sunCascadeLayers)
    uint32_t sunCascadeLayers = 0;
    uint32_t cascadesPerLayer = 1;  // the tiles of a cascade layer (glsl::shadowTileCorner)
    uint32_t localLayers = 0;
    uint32_t areaLayers = 0;
};

// ShadowView::params.x: which array a view's map is a layer of.
enum class ShadowArray : uint32_t { Sun = 0, Local = 1, Area = 2 };
inline constexpr uint32_t kShadowArrayCount = 3;

// A set of shadow arrays, one bit per ShadowArray.
using ShadowArraySet = uint32_t;
inline constexpr ShadowArraySet shadowArrayBit(ShadowArray array) { return 1u << uint32_t(array); }
inline constexpr ShadowArraySet kAllShadowArrays = (1u << kShadowArrayCount) - 1u;
// Beside the arrays, a bit for each of the suns' cascades (the camera moved: the scene-fitted maps
// and the voxels' light stay as they are), the last bit for any beyond.
inline constexpr ShadowArraySet kSunCascadeLayers = ~kAllShadowArrays;
inline constexpr ShadowArraySet sunCascadeBit(uint32_t cascade) {
    return 1u << std::min(kShadowArrayCount + cascade, 31u);
}

// The arrays whose views differ between two layouts: those must be redrawn. Area lights' views
// depend on the geometry alone, so moving the sun leaves their cubes as they are; a sun's cascades
// (kSunCascadeLayers) follow the camera, which leaves its scene-fitted map as it is, and only
// those whose view moved are redrawn: a cascade's texel grid is fixed in the world, so a small
// step moves the finest ones alone.
ShadowArraySet changedShadowArrays(const ShadowLayout& before, const ShadowLayout& after);

// The sun array's layers at most, whatever the camera: the scene-fitted maps and every sun's
// ResourceSettings::sunCascades, as tiles for the settings' image height (the memory a renderer
// may come to hold until it is resized).
uint32_t mostSunLayers(const ShadowLayout& layout, const RenderSettings& settings);

// The buffers that describe a ShadowLayout to the shaders.
struct LightBuffers {
    VkBuffer lights;            // glsl::GpuLight
    VkBuffer shadowViews;       // glsl::ShadowView
    VkBuffer emitterTriangles;  // glsl::GpuEmitterTriangle (at least one element, unused without area lights)
};

// With `cascadeView`, each sun also gets the cascades that view needs (at most
// ResourceSettings::sunCascades), finest first: GpuLight::cascades points at them.
ShadowLayout layoutShadows(const std::vector<Light>& lights, const std::vector<AreaLight>& areaLights,
                           const Bounds& sceneBounds, const RenderSettings& settings,
                           const CascadeView* cascadeView = nullptr);

struct ShadowPass {
    ShadowPass(GpuContext& context, const ShadowLayout& layout, const RenderSettings& settings, const SceneGpu& scene);

    // Makes the pipeline that draws `scene`'s alpha-tested materials (it reads their textures), or
    // none when every material is opaque. Call it when the scene changes, with the GPU idle.
    void useScene(const SceneGpu& scene);

    // Renders the views of the arrays in `redraw` (and of any never drawn) into their layers, and
    // leaves those arrays ready for sampling; the others keep their maps.
    void record(VkCommandBuffer commands, const SceneGpu& scene, const ShadowLayout& layout, VkBuffer viewsBuffer,
                ShadowArraySet redraw);

    // Both arrays exist even when unused (1×1) so the shading pass can always bind them.
    GpuImage sunMaps;
    GpuImage localMaps;
    GpuImage areaMaps;
    Sampler compareSampler;
    Pipeline pipeline;         // depth only: opaque materials
    Pipeline alphaPipeline;    // MASK and BLEND materials: discards where the base colour's alpha says
    ShadowArraySet drawn = 0;  // arrays drawn at least once

private:
    GpuContext& context_;
};

}  // namespace vct
