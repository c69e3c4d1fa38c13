// The reference path tracer: unidirectional path tracing with next-event estimation, the
// renderer's own BRDF (shaders_glsl/brdf.h) and light falloff (shaders_glsl/lights.h).
//
// Model, shared with the GPU renderer so their images can be compared:
// - Every surface reflects on both sides: the shading normal is flipped towards the viewer.
//   Reflection must also stay on the viewer's side of the geometric normal (no light through
//   a surface when the shading normal bends away from it). A single-sided material (glTF
//   doubleSided false) is not seen from behind by the camera's rays, as back-face culling hides it
//   on screen; paths and shadow rays meet both of its sides, as the renderer's voxels and shadow
//   maps do.
// - Emission (Material::emission × the sRGB-decoded emissive texture, radiance) leaves only the
//   front face: the side the interpolated vertex normal points to.
// - Base colour = baseColorFactor.rgb × the sRGB-decoded texture, bilinear, repeat wrap. Its alpha
//   (factor × texture) is the coverage of glTF's alphaMode: a MASK surface is not there where it is
//   below alphaCutoff, a BLEND surface stops a ray with probability alpha (stochastic transmission),
//   for camera, path and shadow rays alike; an emissive triangle emits where it is there (its
//   holes emit nothing, its BLEND parts by their alpha), as the renderer's area lights do.
// - Each texture is read at the texture-coordinate set its material names, through its
//   KHR_texture_transform (shaders_glsl/texture_transform.h, as on the GPU). The occlusion texture
//   is ignored: paths find the occlusion it stands for themselves.
// - Punctual lights (KHR_lights_punctual, no photometric factor) are delta lights, reached only
//   by next-event estimation. Emissive triangles are sampled by area, chosen with probability
//   ∝ area × luminance(emission), and combined with BRDF sampling by the power heuristic. So is an
//   environment image, sampled by its luminance (sky_sampling.h); a uniform sky is left to BRDF
//   sampling, which finds it without noise.
//
// Components: `Direct` is the emission the camera sees plus the punctual lights' light at the
// first hit; `Indirect` is everything else; `Full` is their sum.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "bvh.h"
#include "io/image_io.h"
#include "sampling.h"
#include "scene/scene.h"
#include "sky_sampling.h"
#include "texture_transform.h"

namespace vct::pt {

enum class Component { Full, Direct, Indirect };

struct LinearTexture {
    uint32_t width = 0, height = 0;
    std::vector<glm::vec3> texels;  // linear RGB, top row first
    std::vector<float> alpha;       // the same texels' alpha (coverage, glTF alphaMode)
    TextureWrap wrapS = TextureWrap::Repeat, wrapT = TextureWrap::Repeat;
    bool nearestMagnification = false;
};

// Emissive triangles and the distribution they are sampled with.
struct EmitterTable {
    std::vector<uint32_t> triangles;
    std::vector<float> cdf;      // cumulative probability per entry of `triangles`
    std::vector<float> areaPdf;  // per Scene triangle: P(chosen) / area, 0 for the non-emissive
};

// Where a material's textures are read (material_textures.h's textureTransform, computed once).
struct MaterialTextureTransforms {
    glsl::GpuTextureTransform baseColor, metallicRoughness, normal, emissive;
};

// Everything the integrator needs; the Scene must outlive it.
struct PathTracer {
    const Scene* scene = nullptr;
    Bvh bvh;
    std::vector<LinearTexture> textures;
    std::vector<MaterialTextureTransforms> textureTransforms;  // one per Scene material
    EmitterTable emitters;
    // Surface interactions that gather light, as PBRT counts them: 1 = direct light only, 2 adds
    // one bounce of indirect light, N adds N − 1 bounces. The default is a safety net: Russian
    // roulette ends paths long before, so the image holds every bounce.
    uint32_t maxDepth = 64;
    // false: emissive surfaces are found by BRDF sampling alone, an independent (noisier) estimator
    // that the tests hold the MIS one against.
    bool sampleEmitters = true;
    // The environment image's light sampling (sky_sampling.h); false: the sky is found by BRDF
    // sampling alone, as the tests' independent estimator.
    SkyDistribution sky;
    bool sampleSky = true;
};

PathTracer createPathTracer(const Scene& scene);

// The radiance arriving along the camera's `ray` (unit direction) from the chosen component.
glm::vec3 tracePath(const PathTracer& tracer, Ray ray, Component component, Rng& rng);

struct RenderSettings {
    uint32_t width = 64;
    uint32_t height = 64;
    uint32_t samplesPerPixel = 16;
    Component component = Component::Full;
    uint64_t seed = 1;
    uint32_t threads = 0;           // 0 = all hardware threads
    double timeLimitSeconds = 0.0;  // 0 = none; otherwise stop after the pass that passes it
    Camera camera;
};

struct RenderResult {
    Image image;  // mean radiance per pixel
    // Estimated variance of each pixel's mean luminance, from its samples' spread as if they were
    // independent: an upper bound, since the pixel positions are stratified.
    std::vector<float> luminanceVariance;
    uint32_t samplesPerPixel = 0;  // fewer than asked when the time limit stopped the render
    double seconds = 0.0;
    double meanLuminance = 0.0;
    double meanLuminanceStandardError = 0.0;  // of meanLuminance, from the per-pixel variances
    // sqrt of the mean over pixels of σ²/(μ² + 0.01), σ the standard error and μ the mean of a pixel's
    // luminance: the relative MSE of denoising papers (e.g. Rousselle et al. 2011), which a few very
    // bright pixels do not dominate.
    double relativeNoise = 0.0;
    uint64_t discardedSamples = 0;  // non-finite path results (a bug if ever non-zero)
};

// A camera at `position` looking at `target`, +Y up, vertical field of view in radians.
Camera cameraLookingAt(const glm::vec3& position, const glm::vec3& target, float yfov);

// The primary ray through image position (x, y) in pixels, (0, 0) the top-left corner.
Ray cameraRay(const Camera& camera, uint32_t width, uint32_t height, float x, float y);

// Renders the image; each sample's random numbers depend only on (seed, pixel, sample index), so
// the result does not depend on the number of threads.
RenderResult render(const PathTracer& tracer, const RenderSettings& settings);

}  // namespace vct::pt
