#include "scene/area_lights.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <unordered_map>

#include "luminance.h"
#include "scene/material_textures.h"

namespace vct {
namespace {

struct Emitter {
    EmitterTriangle triangle;
    float area;
    glm::vec3 frontNormal;  // unit
};

using glsl::luminance;

// Disjoint sets over the emitters, for the surfaces their shared vertices join.
struct DisjointSets {
    std::vector<size_t> parent;
    explicit DisjointSets(size_t count) : parent(count) { std::iota(parent.begin(), parent.end(), size_t(0)); }
    size_t root(size_t i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    }
    void join(size_t a, size_t b) { parent[root(a)] = root(b); }
};

// 10 bits per axis of a position inside the bounds, interleaved: nearby points get nearby codes.
uint32_t mortonCode(const glm::vec3& position, const Bounds& bounds) {
    const glm::vec3 extent = glm::max(bounds.extent(), glm::vec3(1e-20f));
    const glm::vec3 unit = glm::clamp((position - bounds.min) / extent, 0.0f, 1.0f);
    uint32_t code = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const uint32_t cell = std::min(uint32_t(unit[axis] * 1024.0f), 1023u);
        for (uint32_t bit = 0; bit < 10; ++bit) code |= ((cell >> bit) & 1u) << (3 * bit + uint32_t(axis));
    }
    return code;
}

std::vector<Emitter> emissiveTriangles(const Scene& scene, std::vector<uint32_t>& sourceTriangle) {
    std::vector<Emitter> emitters;
    for (size_t t = 0; t < scene.triangleCount(); ++t) {
        const Material& material = scene.materials[scene.triangleMaterials[t]];
        if (!(std::max({material.emission.r, material.emission.g, material.emission.b}) > 0.0f)) continue;
        const Vertex* v[3] = {&scene.vertices[scene.indices[3 * t]], &scene.vertices[scene.indices[3 * t + 1]],
                              &scene.vertices[scene.indices[3 * t + 2]]};
        // The emissive texture's mean over the triangle's own coordinates, so a model whose one texture
        // atlas glows in a few places gets lights there and nowhere else; holes emit nothing.
        const glm::vec3 radiance = emittedRadianceOverTriangle(scene, material, v);
        if (!(std::max({radiance.r, radiance.g, radiance.b}) > 0.0f)) continue;
        Emitter emitter;
        emitter.triangle.radiance = radiance;
        for (int i = 0; i < 3; ++i) emitter.triangle.corners[i] = v[i]->position;
        const glm::vec3 n = glm::cross(v[1]->position - v[0]->position, v[2]->position - v[0]->position);
        emitter.area = 0.5f * glm::length(n);
        if (!(emitter.area > 0.0f) || !std::isfinite(emitter.area)) continue;
        emitter.frontNormal = n / (2.0f * emitter.area);
        // The front is where the vertex normals point (as for the G-buffer and the path tracer).
        if (glm::dot(n, v[0]->normal + v[1]->normal + v[2]->normal) < 0.0f) {
            std::swap(emitter.triangle.corners[1], emitter.triangle.corners[2]);
            emitter.frontNormal = -emitter.frontNormal;
        }
        emitters.push_back(emitter);
        sourceTriangle.push_back(uint32_t(t));
    }
    return emitters;
}

// The rectangle in the group's plane that bounds it, oriented along its spread, glowing with the
// group's power spread evenly; none if the group is not flat (a triangle off the mean plane by more
// than 1 % of its size, or turned more than 8° from it).
std::optional<std::vector<EmitterTriangle>> boundingRectangle(const std::vector<const Emitter*>& members,
                                                              const AreaLight& light) {
    float size = 0.0f;
    for (const Emitter* e : members)
        for (const glm::vec3& corner : e->triangle.corners)
            size = std::max(size, glm::distance(corner, light.centroid));
    for (const Emitter* e : members) {
        if (glm::dot(e->frontNormal, light.normal) < 0.99f) return std::nullopt;
        for (const glm::vec3& corner : e->triangle.corners)
            if (std::abs(glm::dot(corner - light.centroid, light.normal)) > 0.01f * size) return std::nullopt;
    }
    // Axes: the principal direction of the triangles' centres in the plane, and its perpendicular.
    const glm::vec3 helper = std::abs(light.normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 u = glm::normalize(glm::cross(light.normal, helper));
    const glm::vec3 v = glm::cross(light.normal, u);
    float uu = 0.0f, uv = 0.0f, vv = 0.0f;
    for (const Emitter* e : members) {
        const glm::vec3 d =
            (e->triangle.corners[0] + e->triangle.corners[1] + e->triangle.corners[2]) / 3.0f - light.centroid;
        uu += e->area * glm::dot(d, u) * glm::dot(d, u);
        uv += e->area * glm::dot(d, u) * glm::dot(d, v);
        vv += e->area * glm::dot(d, v) * glm::dot(d, v);
    }
    const float angle = 0.5f * std::atan2(2.0f * uv, uu - vv);
    const glm::vec3 axisU = std::cos(angle) * u + std::sin(angle) * v;
    const glm::vec3 axisV = glm::cross(light.normal, axisU);
    glm::vec2 low(1e30f), high(-1e30f);
    glm::vec3 power(0.0f);
    for (const Emitter* e : members) {
        power += e->area * e->triangle.radiance;
        for (const glm::vec3& corner : e->triangle.corners) {
            const glm::vec2 p(glm::dot(corner - light.centroid, axisU), glm::dot(corner - light.centroid, axisV));
            low = glm::min(low, p);
            high = glm::max(high, p);
        }
    }
    const float area = (high.x - low.x) * (high.y - low.y);
    if (!(area > 0.0f)) return std::nullopt;
    auto at = [&](float a, float b) { return light.centroid + axisU * a + axisV * b; };
    // Wound so that cross(b − a, c − a) = axisU × axisV = the front normal.
    const glm::vec3 radiance = power / area;
    return std::vector<EmitterTriangle>{{{at(low.x, low.y), at(high.x, low.y), at(high.x, high.y)}, radiance},
                                        {{at(low.x, low.y), at(high.x, high.y), at(low.x, high.y)}, radiance}};
}

AreaLight makeLight(const std::vector<const Emitter*>& members, size_t triangleBudget) {
    AreaLight light;
    glm::vec3 weightedNormal(0.0f);
    float power = 0.0f;
    for (const Emitter* e : members) {
        light.area += e->area;
        light.centroid += e->area * (e->triangle.corners[0] + e->triangle.corners[1] + e->triangle.corners[2]) / 3.0f;
        weightedNormal += e->area * e->frontNormal;
        power += e->area * luminance(e->triangle.radiance);
    }
    light.centroid /= light.area;
    const float normalLength = glm::length(weightedNormal);
    if (normalLength > 1e-6f * light.area) light.normal = weightedNormal / normalLength;

    if (members.size() <= triangleBudget) {
        for (const Emitter* e : members) light.triangles.push_back(e->triangle);
    } else if (std::optional<std::vector<EmitterTriangle>> rectangle = boundingRectangle(members, light)) {
        light.triangles = *rectangle;
        light.approximation = AreaLight::Approximation::BoundingRectangle;
    } else {
        // The brightest triangles (by power) stand in for the rest, which lend them their power.
        std::vector<const Emitter*> kept = members;
        std::stable_sort(kept.begin(), kept.end(), [](const Emitter* a, const Emitter* b) {
            return a->area * luminance(a->triangle.radiance) > b->area * luminance(b->triangle.radiance);
        });
        kept.resize(triangleBudget);
        float keptPower = 0.0f;
        for (const Emitter* e : kept) keptPower += e->area * luminance(e->triangle.radiance);
        const float scale = keptPower > 0.0f ? power / keptPower : 1.0f;
        for (const Emitter* e : kept)
            light.triangles.push_back({{e->triangle.corners[0], e->triangle.corners[1], e->triangle.corners[2]},
                                       e->triangle.radiance * scale});
        light.approximation = AreaLight::Approximation::BrightestTriangles;
    }
    light.sourceTriangles = members.size();
    float keptArea = 0.0f;
    for (const EmitterTriangle& triangle : light.triangles) {
        const float area = 0.5f * glm::length(glm::cross(triangle.corners[1] - triangle.corners[0],
                                                         triangle.corners[2] - triangle.corners[0]));
        light.meanRadiance += area * triangle.radiance;
        keptArea += area;
        for (const glm::vec3& corner : triangle.corners)
            light.radius = std::max(light.radius, glm::distance(corner, light.centroid));
    }
    light.meanRadiance /= keptArea;
    return light;
}

}  // namespace

std::vector<AreaLight> findAreaLights(const Scene& scene) {
    std::vector<uint32_t> sourceTriangle;
    const std::vector<Emitter> emitters = emissiveTriangles(scene, sourceTriangle);
    if (emitters.empty()) return {};

    // Triangles of one material that share a vertex form one surface.
    DisjointSets sets(emitters.size());
    std::unordered_map<uint64_t, size_t> firstWithVertex;
    for (size_t i = 0; i < emitters.size(); ++i) {
        const uint32_t t = sourceTriangle[i];
        for (int corner = 0; corner < 3; ++corner) {
            const uint64_t key = (uint64_t(scene.triangleMaterials[t]) << 32) | scene.indices[3 * t + corner];
            const auto [it, inserted] = firstWithVertex.emplace(key, i);
            if (!inserted) sets.join(i, it->second);
        }
    }
    std::unordered_map<size_t, std::vector<const Emitter*>> byRoot;
    std::vector<std::vector<const Emitter*>> groups;
    for (size_t i = 0; i < emitters.size(); ++i) byRoot[sets.root(i)].push_back(&emitters[i]);
    // In the emitters' order, so that the lights do not depend on the hash map's.
    std::vector<size_t> roots;
    for (size_t i = 0; i < emitters.size(); ++i)
        if (sets.root(i) == i) roots.push_back(i);
    for (size_t root : roots) groups.push_back(std::move(byRoot[root]));

    // Too many surfaces: neighbours in space merge, along a Morton curve cut into equal runs.
    if (groups.size() > kMaxAreaLights) {
        const Bounds bounds = scene.bounds();
        std::vector<std::pair<uint32_t, size_t>> order;
        for (size_t g = 0; g < groups.size(); ++g) {
            glm::vec3 centre(0.0f);
            for (const Emitter* e : groups[g]) centre += e->triangle.corners[0];
            order.emplace_back(mortonCode(centre / float(groups[g].size()), bounds), g);
        }
        std::stable_sort(order.begin(), order.end());
        std::vector<std::vector<const Emitter*>> merged(kMaxAreaLights);
        for (size_t k = 0; k < order.size(); ++k) {
            std::vector<const Emitter*>& run = merged[k * kMaxAreaLights / order.size()];
            run.insert(run.end(), groups[order[k].second].begin(), groups[order[k].second].end());
        }
        groups = std::move(merged);
    }

    std::vector<AreaLight> lights;
    const size_t budget = kMaxAreaLightTriangles / groups.size();
    for (const std::vector<const Emitter*>& group : groups) lights.push_back(makeLight(group, budget));
    return lights;
}

}  // namespace vct
