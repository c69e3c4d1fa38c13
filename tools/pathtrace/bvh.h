// A bounding volume hierarchy over a Scene's triangles, for the reference path tracer.
//
// Built top-down with the binned surface area heuristic (Wald 2007, "On fast Construction of
// SAH-based Bounding Volume Hierarchies"); nodes are stored depth first, so a node's left child
// follows it and only the right child's index is kept. Triangles are tested with the watertight
// algorithm of Woop, Benthin and Wald (JCGT 2013), so rays do not slip through shared edges.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace vct::pt {

struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, 1.0f};  // need not be unit length; t is in its units
    float tMax = 3.4e38f;
};

struct RayHit {
    float t = 0.0f;
    float b1 = 0.0f;  // barycentric weights of the triangle's 2nd and 3rd vertex
    float b2 = 0.0f;
    uint32_t triangle = 0;  // index into Scene::triangleMaterials
};

struct TrianglePositions {
    glm::vec3 p0, p1, p2;
};

// One ray against one triangle, both faces; a hit needs 0 < t < ray.tMax.
std::optional<RayHit> intersectTriangle(const Ray& ray, const TrianglePositions& triangle);

struct BvhNode {
    glm::vec3 min;
    uint32_t rightOrFirst;  // interior: index of the right child; leaf: first entry in Bvh::triangles
    glm::vec3 max;
    uint32_t count;  // 0 for an interior node, else the number of triangles in the leaf
};

struct Bvh {
    std::vector<BvhNode> nodes;                // nodes[0] is the root
    std::vector<TrianglePositions> triangles;  // in leaf order
    std::vector<uint32_t> triangleIds;         // the Scene's index of each entry of `triangles`
    // 1 where a hit on the entry may not count: its material is MASK or BLEND, or single-sided (a
    // camera ray passes its back). Only such hits are put to a HitFilter, so a scene of opaque
    // two-sided materials is traversed as fast as without one.
    std::vector<uint8_t> filtered;
};

// Asked about each hit on a filtered triangle (RayHit::triangle set): false lets the ray pass
// through it, as through a cut-out (glTF alphaMode) or a back face. Empty: every hit counts.
using HitFilter = std::function<bool(const RayHit&)>;

// Zero-area triangles are left out: no ray can hit them.
Bvh buildBvh(const Scene& scene);

std::optional<RayHit> closestHit(const Bvh& bvh, const Ray& ray, const HitFilter& filter = {});
// True when anything lies on the ray between 0 and tMax (shadow rays).
bool anyHit(const Bvh& bvh, const Ray& ray, const HitFilter& filter = {});

}  // namespace vct::pt
