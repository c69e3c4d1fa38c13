#include "scene/area_lights.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

#include "scene/material_textures.h"

namespace vct {
namespace {

struct Emitter {
    EmitterTriangle triangle;
    float area;
    glm::vec3 frontNormal;  // unit
};

float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

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
    std::vector<glm::vec3> materialRadiance;
    for (const Material& material : scene.materials) materialRadiance.push_back(voxelEmission(scene, material));
    std::vector<Emitter> emitters;
    for (size_t t = 0; t < scene.triangleCount(); ++t) {
        const glm::vec3 radiance = materialRadiance[scene.triangleMaterials[t]];
        if (!(std::max({radiance.r, radiance.g, radiance.b}) > 0.0f)) continue;
        const Vertex* v[3] = {&scene.vertices[scene.indices[3 * t]], &scene.vertices[scene.indices[3 * t + 1]],
                              &scene.vertices[scene.indices[3 * t + 2]]};
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

    // The brightest triangles (by power) stand in for the rest, which lend them their power.
    std::vector<const Emitter*> kept = members;
    std::stable_sort(kept.begin(), kept.end(), [](const Emitter* a, const Emitter* b) {
        return a->area * luminance(a->triangle.radiance) > b->area * luminance(b->triangle.radiance);
    });
    light.droppedTriangles = kept.size() > triangleBudget ? kept.size() - triangleBudget : 0;
    kept.resize(std::min(kept.size(), triangleBudget));
    float keptPower = 0.0f, keptArea = 0.0f;
    for (const Emitter* e : kept) keptPower += e->area * luminance(e->triangle.radiance);
    const float scale = keptPower > 0.0f ? power / keptPower : 1.0f;
    for (const Emitter* e : kept) {
        EmitterTriangle triangle = e->triangle;
        triangle.radiance *= scale;
        light.triangles.push_back(triangle);
        light.meanRadiance += e->area * triangle.radiance;
        keptArea += e->area;
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
