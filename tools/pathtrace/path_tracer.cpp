#include "path_tracer.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <thread>

#include "bsdf.h"
#include "error.h"
#include "lights.h"
#include "luminance.h"
#include "normal_map.h"
#include "scene/material_textures.h"

namespace vct::pt {
namespace {

constexpr uint32_t kRouletteStartDepth = 3;
constexpr uint32_t kSamplesPerPass = 4;
constexpr double kRelativeNoiseEpsilon = 0.01;         // keeps black pixels from dividing by zero
constexpr uint64_t kPixelOffsetStream = ~uint64_t(0);  // a stream no sample index reaches

using glsl::luminance;

bool isBlack(const glm::vec3& c) { return c.x <= 0.0f && c.y <= 0.0f && c.z <= 0.0f; }

LinearTexture decodeTexture(const Texture& texture) {
    LinearTexture linear;
    if (texture.width == 0 || texture.height == 0 ||
        texture.rgba8.size() < size_t(texture.width) * texture.height * 4) {
        linear.width = linear.height = 1;
        linear.texels = {glm::vec3(1.0f)};  // a missing image leaves the factor alone
        linear.alpha = {1.0f};
        return linear;
    }
    std::array<float, 256> table;  // colour textures are sRGB-encoded, data textures linear
    for (int i = 0; i < 256; ++i) table[i] = texture.srgb ? srgbToLinear(float(i) / 255.0f) : float(i) / 255.0f;
    linear.width = texture.width;
    linear.height = texture.height;
    linear.wrapS = texture.wrapS;
    linear.wrapT = texture.wrapT;
    linear.nearestMagnification = texture.nearestMagnification;
    linear.texels.resize(size_t(texture.width) * texture.height);
    linear.alpha.resize(linear.texels.size());
    for (size_t i = 0; i < linear.texels.size(); ++i) {
        const uint8_t* texel = &texture.rgba8[4 * i];
        linear.texels[i] = glm::vec3(table[texel[0]], table[texel[1]], table[texel[2]]);
        linear.alpha[i] = float(texel[3]) / 255.0f;  // alpha is linear in every format
    }
    return linear;
}

// Bilinear filtering (nearest where the sampler magnifies so), wrapped as the texture's sampler
// says; uv (0, 0) is the image's top-left corner and texel centres lie at (i + ½) / size. Many
// paths average over each pixel, so no mip level is needed: the pixel's mean is the filtered one.
template <typename T>
T sampleTexels(const LinearTexture& texture, const std::vector<T>& texels, float u, float v) {
    if (!std::isfinite(u) || !std::isfinite(v)) return texels[0];
    auto at = [&](double ix, double iy) {
        return texels[size_t(wrapTexel(iy, texture.height, texture.wrapT)) * texture.width +
                      wrapTexel(ix, texture.width, texture.wrapS)];
    };
    const double x = double(u) * texture.width, y = double(v) * texture.height;
    if (texture.nearestMagnification) return at(std::floor(x), std::floor(y));
    const double x0 = std::floor(x - 0.5), y0 = std::floor(y - 0.5);
    const float tx = float(x - 0.5 - x0), ty = float(y - 0.5 - y0);
    return glm::mix(glm::mix(at(x0, y0), at(x0 + 1.0, y0), tx), glm::mix(at(x0, y0 + 1.0), at(x0 + 1.0, y0 + 1.0), tx),
                    ty);
}

glm::vec3 sampleTexture(const LinearTexture& texture, float u, float v) {
    return sampleTexels(texture, texture.texels, u, v);
}

// A point on a triangle, normals unit and as authored (not yet turned towards any viewer).
struct TrianglePoint {
    glm::vec3 position;
    glm::vec3 geometricNormal;       // from the counter-clockwise winding
    glm::vec3 shadingNormal;         // interpolated vertex normal
    glm::vec2 texCoord0, texCoord1;  // both sets, interpolated
    glm::vec4 tangent;               // the file's TANGENT, interpolated (0 without one)
    const Vertex* corners[3];
};

TrianglePoint pointOnTriangle(const Scene& scene, uint32_t triangle, float b1, float b2) {
    const Vertex& v0 = scene.vertices[scene.indices[3 * triangle + 0]];
    const Vertex& v1 = scene.vertices[scene.indices[3 * triangle + 1]];
    const Vertex& v2 = scene.vertices[scene.indices[3 * triangle + 2]];
    const float b0 = 1.0f - b1 - b2;
    TrianglePoint point;
    point.position = b0 * v0.position + b1 * v1.position + b2 * v2.position;
    point.texCoord0 = b0 * glm::vec2(v0.u, v0.v) + b1 * glm::vec2(v1.u, v1.v) + b2 * glm::vec2(v2.u, v2.v);
    point.texCoord1 = b0 * v0.uv1 + b1 * v1.uv1 + b2 * v2.uv1;
    point.tangent = b0 * v0.tangent + b1 * v1.tangent + b2 * v2.tangent;
    const glm::vec3 cross = glm::cross(v1.position - v0.position, v2.position - v0.position);
    const float crossLength = glm::length(cross);
    const glm::vec3 shading = b0 * v0.normal + b1 * v1.normal + b2 * v2.normal;
    const float shadingLength = glm::length(shading);
    point.geometricNormal = crossLength > 0.0f ? cross / crossLength : glm::vec3(0.0f, 0.0f, 1.0f);
    point.shadingNormal =
        shadingLength > 1e-12f && std::isfinite(shadingLength) ? shading / shadingLength : point.geometricNormal;
    point.corners[0] = &v0;
    point.corners[1] = &v1;
    point.corners[2] = &v2;
    return point;
}

glm::vec2 texCoordOf(const glsl::GpuTextureTransform& transform, const Vertex& vertex) {
    return glsl::transformedTexCoord(transform, glm::vec2(vertex.u, vertex.v), vertex.uv1);
}

// ∂position/∂u and ∂position/∂v at the point, u and v the texture's own (after `transform`): the
// file's tangent frame where it has one for the texture (normal_map.h), else the triangle's, from its
// texture coordinates; zero where those are degenerate.
glsl::TextureAxes textureAxes(const TrianglePoint& point, const glsl::GpuTextureTransform& transform) {
    if (glsl::tangentServes(point.tangent, transform))
        return glsl::axesOfTangent(point.shadingNormal, point.tangent, transform);
    const glm::vec3 p0 = point.corners[0]->position;
    const glm::vec3 e1 = point.corners[1]->position - p0, e2 = point.corners[2]->position - p0;
    const glm::vec2 uv0 = texCoordOf(transform, *point.corners[0]);
    const glm::vec2 uv1 = texCoordOf(transform, *point.corners[1]) - uv0;
    const glm::vec2 uv2 = texCoordOf(transform, *point.corners[2]) - uv0;
    return glsl::axesFromSteps(e1, e2, uv1, uv2);
}

bool hasTexture(const PathTracer& tracer, const TextureReference& reference) {
    return reference.index >= 0 && size_t(reference.index) < tracer.textures.size();
}

// The material texture `reference` at the point, read through `transform`; white without one.
glm::vec3 textureAt(const PathTracer& tracer, const TextureReference& reference,
                    const glsl::GpuTextureTransform& transform, const TrianglePoint& point) {
    if (!hasTexture(tracer, reference)) return glm::vec3(1.0f);
    const glm::vec2 uv = glsl::transformedTexCoord(transform, point.texCoord0, point.texCoord1);
    return sampleTexture(tracer.textures[size_t(reference.index)], uv.x, uv.y);
}

float triangleArea(const Scene& scene, uint32_t triangle) {
    const glm::vec3 p0 = scene.vertices[scene.indices[3 * triangle + 0]].position;
    const glm::vec3 p1 = scene.vertices[scene.indices[3 * triangle + 1]].position;
    const glm::vec3 p2 = scene.vertices[scene.indices[3 * triangle + 2]].position;
    return 0.5f * glm::length(glm::cross(p1 - p0, p2 - p0));
}

// The radiance the triangle's material emits at the point: emission × the emissive texture.
glm::vec3 emissionAt(const PathTracer& tracer, uint32_t triangle, const TrianglePoint& point) {
    const uint32_t material = tracer.scene->triangleMaterials[triangle];
    return tracer.scene->materials[material].emission * textureAt(tracer,
                                                                  tracer.scene->materials[material].emissiveTexture,
                                                                  tracer.textureTransforms[material].emissive, point);
}

EmitterTable buildEmitterTable(const Scene& scene) {
    EmitterTable table;
    table.areaPdf.assign(scene.triangleCount(), 0.0f);
    std::vector<double> powers;
    double total = 0.0;
    // With an emissive texture, its mean stands in for the texels a triangle covers: the choice
    // stays unbiased (a texture whose mean is 0 is black everywhere), only less well matched.
    std::vector<float> materialLuminance;
    for (const Material& material : scene.materials)
        materialLuminance.push_back(luminance(voxelEmission(scene, material)));
    for (uint32_t triangle = 0; triangle < scene.triangleCount(); ++triangle) {
        const double power =
            double(triangleArea(scene, triangle)) * materialLuminance[scene.triangleMaterials[triangle]];
        if (!(power > 0.0) || !std::isfinite(power)) continue;
        table.triangles.push_back(triangle);
        powers.push_back(power);
        total += power;
    }
    double running = 0.0;
    for (size_t i = 0; i < powers.size(); ++i) {
        running += powers[i];
        table.cdf.push_back(float(running / total));
        const uint32_t triangle = table.triangles[i];
        table.areaPdf[triangle] = float(powers[i] / total / double(triangleArea(scene, triangle)));
    }
    if (!table.cdf.empty()) table.cdf.back() = 1.0f;
    return table;
}

// Wächter and Binder, "A Fast and Robust Method for Avoiding Self-Intersection" (Ray Tracing
// Gems, ch. 6): moves p off its surface along n by a few ulps, in proportion to |p|.
glm::vec3 offsetRayOrigin(const glm::vec3& p, const glm::vec3& n) {
    constexpr float kOrigin = 1.0f / 32.0f, kFloatScale = 1.0f / 65536.0f, kIntScale = 256.0f;
    glm::vec3 result;
    for (int i = 0; i < 3; ++i) {
        const int64_t offset = int64_t(kIntScale * n[i]);
        const int64_t bits = int64_t(std::bit_cast<int32_t>(p[i])) + (p[i] < 0.0f ? -offset : offset);
        const float shifted = std::bit_cast<float>(uint32_t(bits));
        result[i] = std::abs(p[i]) < kOrigin ? p[i] + kFloatScale * n[i] : shifted;
    }
    return result;
}

// A hit as the integrator sees it: normals turned towards the viewer (all surfaces are two-sided).
struct SurfacePoint {
    glm::vec3 position;
    glm::vec3 geometricNormal;
    glm::vec3 shadingNormal;
    glm::vec3 toViewer;
    glm::vec3 emission;  // zero unless the viewer faces the emitting front side
    SurfaceMaterial material;
};

SurfacePoint surfaceAt(const PathTracer& tracer, const RayHit& hit, const glm::vec3& rayDirection) {
    const Scene& scene = *tracer.scene;
    const TrianglePoint point = pointOnTriangle(scene, hit.triangle, hit.b1, hit.b2);
    const uint32_t materialIndex = scene.triangleMaterials[hit.triangle];
    const Material& material = scene.materials[materialIndex];
    const MaterialTextureTransforms& transforms = tracer.textureTransforms[materialIndex];
    SurfacePoint s;
    s.position = point.position;
    s.toViewer = -rayDirection;
    // The side is the interpolated normal's; a normal texture tilts the normal of that side.
    const bool frontFace = glm::dot(point.shadingNormal, s.toViewer) > 0.0f;
    glm::vec3 shadingNormal = point.shadingNormal;
    if (hasTexture(tracer, material.normalTexture)) {
        const glm::vec3 texel = textureAt(tracer, material.normalTexture, transforms.normal, point);
        const glsl::TextureAxes axes = textureAxes(point, transforms.normal);
        shadingNormal = glsl::normalFromTexture(shadingNormal, axes.alongU, axes.alongV, texel, material.normalScale);
    }
    s.shadingNormal = frontFace ? shadingNormal : -shadingNormal;
    s.geometricNormal =
        glm::dot(point.geometricNormal, s.toViewer) >= 0.0f ? point.geometricNormal : -point.geometricNormal;
    s.emission = frontFace ? emissionAt(tracer, hit.triangle, point) : glm::vec3(0.0f);
    const glm::vec3 baseColor =
        glm::vec3(material.baseColorFactor) * textureAt(tracer, material.baseColorTexture, transforms.baseColor, point);
    s.material.baseColor = glm::clamp(baseColor, 0.0f, 1.0f);
    // glTF: blue scales metallic, green roughness.
    const glm::vec3 metallicRoughnessTexel =
        textureAt(tracer, material.metallicRoughnessTexture, transforms.metallicRoughness, point);
    const glm::vec2 metallicRoughness = glm::vec2(material.metallic, material.roughness) *
                                        glm::vec2(metallicRoughnessTexel.b, metallicRoughnessTexel.g);
    s.material.metallic = std::clamp(metallicRoughness.x, 0.0f, 1.0f);
    s.material.roughness = std::clamp(metallicRoughness.y, 0.0f, 1.0f);
    s.material.specularWeight = std::clamp(material.specularWeight, 0.0f, 1.0f);
    return s;
}

// f(V, L)·(N·L) towards L, zero when L leaves the viewer's side of the surface.
glm::vec3 reflectedTowards(const SurfacePoint& s, const glm::vec3& L) {
    const float NdotL = glm::dot(s.shadingNormal, L);
    if (glm::dot(s.geometricNormal, L) <= 0.0f || NdotL <= 0.0f) return glm::vec3(0.0f);
    return evaluateBsdf(s.material, s.shadingNormal, s.toViewer, L) * NdotL;
}

Ray spawnRay(const SurfacePoint& s, const glm::vec3& direction) {
    const glm::vec3 side = glm::dot(s.geometricNormal, direction) >= 0.0f ? s.geometricNormal : -s.geometricNormal;
    return Ray{offsetRayOrigin(s.position, side), direction, FLT_MAX};
}

// Whether a ray stops at a hit on an alpha-tested triangle (glTF alphaMode), from the base colour's
// alpha there (factor × texture, read as the base colour is): MASK where it reaches the cutoff;
// BLEND with probability alpha, stochastic transmission, whose mean lets 1 − alpha of the light
// through (the renderer's screen-door pattern, alpha_coverage.h, averaged over a pixel).
// The triangle's coverage at barycentric (b1, b2): coverageOfAlpha of its base colour's alpha there.
float coverageAt(const PathTracer& tracer, uint32_t triangle, float b1, float b2) {
    const Scene& scene = *tracer.scene;
    const uint32_t materialIndex = scene.triangleMaterials[triangle];
    const Material& material = scene.materials[materialIndex];
    float alpha = material.baseColorFactor.a;
    if (hasTexture(tracer, material.baseColorTexture)) {
        const float b0 = 1.0f - b1 - b2;
        const Vertex* v[3];
        for (uint32_t corner = 0; corner < 3; ++corner)
            v[corner] = &scene.vertices[scene.indices[3 * triangle + corner]];
        const glm::vec2 texCoord0 =
            b0 * glm::vec2(v[0]->u, v[0]->v) + b1 * glm::vec2(v[1]->u, v[1]->v) + b2 * glm::vec2(v[2]->u, v[2]->v);
        const glm::vec2 texCoord1 = b0 * v[0]->uv1 + b1 * v[1]->uv1 + b2 * v[2]->uv1;
        const glm::vec2 uv =
            glsl::transformedTexCoord(tracer.textureTransforms[materialIndex].baseColor, texCoord0, texCoord1);
        const LinearTexture& texture = tracer.textures[size_t(material.baseColorTexture.index)];
        alpha *= sampleTexels(texture, texture.alpha, uv.x, uv.y);
    }
    return coverageOfAlpha(material, alpha);
}

bool stopsRay(const PathTracer& tracer, const RayHit& hit, Rng& rng) {
    const float coverage = coverageAt(tracer, hit.triangle, hit.b1, hit.b2);
    if (tracer.scene->materials[tracer.scene->triangleMaterials[hit.triangle]].alphaMode == AlphaMode::Blend)
        return rng.uniform() < coverage;
    return coverage > 0.0f;
}

HitFilter alphaFilter(const PathTracer& tracer, Rng& rng) {
    return [&tracer, &rng](const RayHit& hit) { return stopsRay(tracer, hit, rng); };
}

// What the camera's ray meets: as alphaFilter, and it passes the back of a single-sided surface
// (glTF doubleSided false: back faces culled), as the renderer's G-buffer does. Paths and shadow
// rays meet both sides of every surface, as the renderer's voxels and shadow maps do.
HitFilter cameraFilter(const PathTracer& tracer, const glm::vec3& direction, Rng& rng) {
    return [&tracer, direction, &rng](const RayHit& hit) {
        const Scene& scene = *tracer.scene;
        if (!scene.materials[scene.triangleMaterials[hit.triangle]].doubleSided) {
            const uint32_t* corner = &scene.indices[3 * hit.triangle];
            const glm::vec3 p0 = scene.vertices[corner[0]].position, p1 = scene.vertices[corner[1]].position,
                            p2 = scene.vertices[corner[2]].position;
            if (glm::dot(glm::cross(p1 - p0, p2 - p0), direction) > 0.0f) return false;  // its back
        }
        return stopsRay(tracer, hit, rng);
    };
}

// Nothing between s and `target` (itself offset off its own surface by the caller, or a light).
bool unoccluded(const PathTracer& tracer, const SurfacePoint& s, const glm::vec3& target, Rng& rng) {
    Ray ray = spawnRay(s, glm::normalize(target - s.position));
    const glm::vec3 toTarget = target - ray.origin;
    const float distance = glm::length(toTarget);
    if (!(distance > 0.0f)) return true;
    ray.direction = toTarget / distance;
    ray.tMax = distance;
    return !anyHit(tracer.bvh, ray, alphaFilter(tracer, rng));
}

// The sky seen along `direction`: Scene::environment, times the environment image where there is one.
glm::vec3 skyRadiance(const Scene& scene, const glm::vec3& direction) {
    return scene.environmentMap
               ? scene.environment * environmentRadiance(*scene.environmentMap, direction, scene.environmentRotation)
               : scene.environment;
}

// Light from the punctual lights, by KHR_lights_punctual's falloff (shaders_glsl/lights.h).
glm::vec3 punctualLight(const PathTracer& tracer, const SurfacePoint& s, Rng& rng) {
    glm::vec3 sum(0.0f);
    for (const Light& light : tracer.scene->lights) {
        glm::vec3 L;
        glm::vec3 irradiance = light.color * light.intensity;  // at normal incidence
        if (light.type == LightType::Directional) {
            L = -glm::normalize(light.direction);
        } else {
            const glm::vec3 toLight = light.position - s.position;
            const float distance = glm::length(toLight);
            if (!(distance > 0.0f)) continue;
            L = toLight / distance;
            irradiance *= glsl::rangeAttenuation(distance, light.range) / (distance * distance);
            if (light.type == LightType::Spot) {
                irradiance *= glsl::spotAttenuation(glm::normalize(light.direction), -L, light.innerConeAngle,
                                                    light.outerConeAngle);
            }
        }
        const glm::vec3 reflected = reflectedTowards(s, L) * irradiance;
        if (isBlack(reflected) || !std::isfinite(L.x + L.y + L.z)) continue;
        const bool visible = light.type == LightType::Directional
                                 ? !anyHit(tracer.bvh, spawnRay(s, L), alphaFilter(tracer, rng))
                                 : unoccluded(tracer, s, light.position, rng);
        if (visible) sum += reflected;
    }
    return sum;
}

// Next-event estimation towards one point on one emissive triangle, MIS-weighted against BRDF
// sampling. Density per unit solid angle: p_area · d² / |cosθ_light| (PBRT-v3 §14.2.2).
glm::vec3 emissiveLight(const PathTracer& tracer, const SurfacePoint& s, Rng& rng) {
    const EmitterTable& emitters = tracer.emitters;
    const float uPick = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
    if (emitters.triangles.empty()) return glm::vec3(0.0f);
    const uint32_t triangle = emitters.triangles[pickFromCdf(emitters.cdf, uPick)];
    // Uniform point on the triangle (PBRT-v3 §13.6.5).
    const float root = std::sqrt(u1);
    const float b1 = u2 * root, b2 = 1.0f - root;
    const TrianglePoint light = pointOnTriangle(*tracer.scene, triangle, b1, b2);

    const glm::vec3 toLight = light.position - s.position;
    const float distanceSquared = glm::dot(toLight, toLight);
    if (!(distanceSquared > 0.0f)) return glm::vec3(0.0f);
    const glm::vec3 L = toLight / std::sqrt(distanceSquared);
    if (glm::dot(light.shadingNormal, L) >= 0.0f) return glm::vec3(0.0f);  // its back face
    const float cosLight = std::abs(glm::dot(light.geometricNormal, L));
    if (cosLight < 1e-6f) return glm::vec3(0.0f);
    const glm::vec3 reflected = reflectedTowards(s, L);
    if (isBlack(reflected)) return glm::vec3(0.0f);
    const glm::vec3 lightSide =
        glm::dot(light.geometricNormal, L) < 0.0f ? light.geometricNormal : -light.geometricNormal;
    if (!unoccluded(tracer, s, offsetRayOrigin(light.position, lightSide), rng)) return glm::vec3(0.0f);

    const float lightPdf = emitters.areaPdf[triangle] * distanceSquared / cosLight;
    const float weight = powerHeuristic(lightPdf, bsdfPdf(s.material, s.shadingNormal, s.toViewer, L));
    // A MASK emitter's holes emit nothing, a BLEND one's emission counts by its alpha: what the rays
    // that pass through them with 1 − alpha see on average.
    return reflected * emissionAt(tracer, triangle, light) * (coverageAt(tracer, triangle, b1, b2) * weight / lightPdf);
}

// Next-event estimation towards the environment image: a direction drawn by its luminance
// (sky_sampling.h), MIS-weighted against BRDF sampling, which finds the sky where a path escapes.
glm::vec3 skyLight(const PathTracer& tracer, const SurfacePoint& s, Rng& rng) {
    const float uCell = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
    const std::optional<SkySample> sample = sampleSky(tracer.sky, uCell, u1, u2);
    if (!sample || glm::dot(s.geometricNormal, sample->direction) <= 0.0f) return glm::vec3(0.0f);
    const glm::vec3 reflected = reflectedTowards(s, sample->direction);
    if (isBlack(reflected)) return glm::vec3(0.0f);
    if (anyHit(tracer.bvh, spawnRay(s, sample->direction), alphaFilter(tracer, rng))) return glm::vec3(0.0f);
    const float weight =
        powerHeuristic(sample->pdf, bsdfPdf(s.material, s.shadingNormal, s.toViewer, sample->direction));
    return reflected * skyRadiance(*tracer.scene, sample->direction) * (weight / sample->pdf);
}

// Where in its pixel sample number `sample` looks: Roberts' R2 sequence (2018, "The Unreasonable
// Effectiveness of Quasirandom Sequences"), shifted by a random offset per pixel (Cranley-Patterson
// rotation). Every prefix covers the pixel evenly, so a time-limited render stays unbiased, and each
// sample is still uniform over the pixel.
glm::vec2 pixelJitter(const glm::dvec2& offset, uint32_t sample) {
    constexpr double kPlastic = 1.32471795724474602596;  // x³ = x + 1
    const glm::dvec2 point = offset + double(sample) * glm::dvec2(1.0 / kPlastic, 1.0 / (kPlastic * kPlastic));
    return glm::vec2(glm::min(glm::fract(point), glm::dvec2(0.99999994)));
}

}  // namespace

PathTracer createPathTracer(const Scene& scene) {
    const size_t triangles = scene.triangleCount();
    if (scene.indices.size() % 3 != 0 || scene.triangleMaterials.size() != triangles) {
        throw Error("scene '" + scene.name + "' has " + std::to_string(scene.indices.size()) + " indices and " +
                    std::to_string(scene.triangleMaterials.size()) + " triangle materials, which do not match");
    }
    for (uint32_t index : scene.indices) {
        if (index >= scene.vertices.size()) throw Error("scene '" + scene.name + "' indexes a missing vertex");
    }
    for (uint32_t material : scene.triangleMaterials) {
        if (material >= scene.materials.size()) throw Error("scene '" + scene.name + "' names a missing material");
    }
    PathTracer tracer;
    tracer.scene = &scene;
    tracer.bvh = buildBvh(scene);
    for (const Texture& texture : scene.textures) tracer.textures.push_back(decodeTexture(texture));
    for (const Material& material : scene.materials)
        tracer.textureTransforms.push_back(
            {textureTransform(material.baseColorTexture), textureTransform(material.metallicRoughnessTexture),
             textureTransform(material.normalTexture), textureTransform(material.emissiveTexture)});
    tracer.emitters = buildEmitterTable(scene);
    tracer.sky = buildSkyDistribution(scene);
    return tracer;
}

glm::vec3 tracePath(const PathTracer& tracer, Ray ray, Component component, Rng& rng) {
    const bool wantDirect = component != Component::Indirect;
    const bool wantIndirect = component != Component::Direct;
    glm::vec3 radiance(0.0f), throughput(1.0f);
    float previousBsdfPdf = 0.0f;
    // One interaction past maxDepth: emission that BRDF sampling finds there belongs to the light
    // the last gathering vertex received (its other half is that vertex's light sampling).
    for (uint32_t depth = 1; depth <= tracer.maxDepth + 1; ++depth) {
        const std::optional<RayHit> hit = closestHit(
            tracer.bvh, ray, depth == 1 ? cameraFilter(tracer, ray.direction, rng) : alphaFilter(tracer, rng));
        if (!hit) {
            // The sky: seen by the camera it is direct light, as an emitter seen is; on a surface
            // it is indirect light, which is where the renderer's cones gather it. Found here by BRDF
            // sampling, weighed against the light sampling of an environment image (skyLight).
            if (depth == 1 ? wantDirect : wantIndirect) {
                const float skyWeight = depth > 1 && tracer.sampleSky && !tracer.sky.empty()
                                            ? powerHeuristic(previousBsdfPdf, skyPdf(tracer.sky, ray.direction))
                                            : 1.0f;
                radiance += throughput * skyRadiance(*tracer.scene, ray.direction) * skyWeight;
            }
            break;
        }
        const SurfacePoint s = surfaceAt(tracer, *hit, ray.direction);
        const bool gathers = depth <= tracer.maxDepth;

        // Direct light is what reaches the camera from a light after at most one reflection: the
        // emission it sees, and the light of punctual and emissive sources at the first hit (found
        // there by light sampling, or one step later by BRDF sampling).
        if (!isBlack(s.emission)) {
            if (depth == 1) {
                if (wantDirect) radiance += throughput * s.emission;
            } else if (depth == 2 ? wantDirect : wantIndirect) {
                // Reached by BRDF sampling: weigh against the light sampling that could have found it.
                const float cosLight = std::abs(glm::dot(s.geometricNormal, ray.direction));
                const float lightPdf = tracer.sampleEmitters && cosLight > 0.0f
                                           ? tracer.emitters.areaPdf[hit->triangle] * hit->t * hit->t / cosLight
                                           : 0.0f;
                radiance += throughput * s.emission * powerHeuristic(previousBsdfPdf, lightPdf);
            }
        }
        if (!gathers) break;
        if (depth == 1 ? wantDirect : wantIndirect) {
            radiance += throughput * punctualLight(tracer, s, rng);
            if (tracer.sampleEmitters) radiance += throughput * emissiveLight(tracer, s, rng);
        }
        if (wantIndirect && tracer.sampleSky && !tracer.sky.empty()) radiance += throughput * skyLight(tracer, s, rng);
        // Direct light alone goes one step further only to find emitters by BRDF sampling.
        if (!wantIndirect && !(depth == 1 && !tracer.emitters.triangles.empty())) break;

        const float uLobe = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        const std::optional<BsdfSample> sample = sampleBsdf(s.material, s.shadingNormal, s.toViewer, uLobe, u1, u2);
        if (!sample || glm::dot(s.geometricNormal, sample->direction) <= 0.0f) break;
        throughput *= sample->weight;
        previousBsdfPdf = sample->pdf;

        // Russian roulette (PBRT-v3 §13.7): survivors are divided by the survival probability.
        const float uRoulette = rng.uniform();
        if (depth >= kRouletteStartDepth) {
            const float survival = std::min(0.95f, std::max(throughput.x, std::max(throughput.y, throughput.z)));
            if (!(uRoulette < survival)) break;
            throughput /= survival;
        }
        ray = spawnRay(s, sample->direction);
    }
    return radiance;
}

Camera cameraLookingAt(const glm::vec3& position, const glm::vec3& target, float yfov) {
    Camera camera;
    camera.name = "command line camera";
    camera.position = position;
    camera.forward = glm::normalize(target - position);
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    camera.yfov = yfov;
    return camera;
}

Ray cameraRay(const Camera& camera, uint32_t width, uint32_t height, float x, float y) {
    const glm::vec3 forward = glm::normalize(camera.forward);
    glm::vec3 right = glm::cross(forward, camera.up);
    if (glm::length(right) < 1e-6f) right = glm::cross(forward, glm::vec3(0.0f, 0.0f, 1.0f));
    if (glm::length(right) < 1e-6f) right = glm::cross(forward, glm::vec3(1.0f, 0.0f, 0.0f));
    right = glm::normalize(right);
    const glm::vec3 up = glm::cross(right, forward);
    const float tanHalfFov = std::tan(0.5f * camera.yfov);
    const float aspect = float(width) / float(height);
    const float px = (2.0f * x / float(width) - 1.0f) * tanHalfFov * aspect;
    const float py = (1.0f - 2.0f * y / float(height)) * tanHalfFov;
    return Ray{camera.position, glm::normalize(forward + px * right + py * up), FLT_MAX};
}

RenderResult render(const PathTracer& tracer, const RenderSettings& settings) {
    const uint32_t width = settings.width, height = settings.height;
    if (width == 0 || height == 0 || settings.samplesPerPixel == 0) {
        throw Error("the image size and the samples per pixel must be positive");
    }
    const uint32_t threadCount =
        settings.threads > 0 ? settings.threads : std::max(1u, std::thread::hardware_concurrency());
    const size_t pixelCount = size_t(width) * height;
    std::vector<glm::dvec3> sums(pixelCount, glm::dvec3(0.0));
    std::vector<double> luminanceSums(pixelCount, 0.0), luminanceSquares(pixelCount, 0.0);
    std::atomic<uint64_t> discarded{0};
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };

    // Passes of a few samples, so a time limit can stop between them; within a pass, threads
    // take whole rows. Each pixel is only touched by one thread at a time, in sample order.
    uint32_t done = 0;
    while (done < settings.samplesPerPixel) {
        const uint32_t end = std::min(settings.samplesPerPixel, done + kSamplesPerPass);
        std::atomic<uint32_t> nextRow{0};
        auto work = [&] {
            for (uint32_t y = nextRow++; y < height; y = nextRow++) {
                for (uint32_t x = 0; x < width; ++x) {
                    const size_t pixel = size_t(y) * width + x;
                    Rng pixelRng = Rng::forSample(settings.seed, pixel, kPixelOffsetStream);
                    const glm::dvec2 offset(pixelRng.uniform(), pixelRng.uniform());
                    for (uint32_t sample = done; sample < end; ++sample) {
                        Rng rng = Rng::forSample(settings.seed, pixel, sample);
                        const glm::vec2 jitter = pixelJitter(offset, sample);
                        const Ray ray =
                            cameraRay(settings.camera, width, height, float(x) + jitter.x, float(y) + jitter.y);
                        glm::vec3 radiance = tracePath(tracer, ray, settings.component, rng);
                        if (!std::isfinite(radiance.x + radiance.y + radiance.z)) {
                            ++discarded;
                            radiance = glm::vec3(0.0f);
                        }
                        sums[pixel] += glm::dvec3(radiance);
                        const double lum = luminance(radiance);
                        luminanceSums[pixel] += lum;
                        luminanceSquares[pixel] += lum * lum;
                    }
                }
            }
        };
        std::vector<std::thread> workers;
        for (uint32_t i = 1; i < threadCount; ++i) workers.emplace_back(work);
        work();
        for (std::thread& worker : workers) worker.join();
        done = end;
        if (settings.timeLimitSeconds > 0.0 && elapsed() >= settings.timeLimitSeconds) break;
    }

    RenderResult result;
    result.samplesPerPixel = done;
    result.seconds = elapsed();
    result.discardedSamples = discarded;
    result.image.width = width;
    result.image.height = height;
    result.image.rgb.resize(pixelCount * 3);
    result.luminanceVariance.resize(pixelCount);
    const double n = done;
    double luminanceTotal = 0.0, varianceTotal = 0.0, relativeVarianceTotal = 0.0;
    for (size_t pixel = 0; pixel < pixelCount; ++pixel) {
        const glm::dvec3 mean = sums[pixel] / n;
        for (int c = 0; c < 3; ++c) result.image.rgb[3 * pixel + c] = float(mean[c]);
        // Unbiased sample variance of the luminance, divided by n: the variance of the pixel's mean.
        const double meanLuminance = luminanceSums[pixel] / n;
        const double sampleVariance =
            done > 1 ? std::max(0.0, luminanceSquares[pixel] / n - meanLuminance * meanLuminance) * n / (n - 1.0) : 0.0;
        result.luminanceVariance[pixel] = float(sampleVariance / n);
        luminanceTotal += meanLuminance;
        varianceTotal += sampleVariance / n;
        relativeVarianceTotal += sampleVariance / n / (meanLuminance * meanLuminance + kRelativeNoiseEpsilon);
    }
    result.meanLuminance = luminanceTotal / double(pixelCount);
    result.meanLuminanceStandardError = std::sqrt(varianceTotal) / double(pixelCount);
    result.relativeNoise = std::sqrt(relativeVarianceTotal / double(pixelCount));
    return result;
}

}  // namespace vct::pt
