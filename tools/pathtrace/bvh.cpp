#include "bvh.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <limits>

namespace vct::pt {
namespace {

constexpr int kBinCount = 16;
constexpr uint32_t kMaxLeafSize = 8;
constexpr float kTraversalCost = 1.0f;  // relative to one triangle test
// Below this depth the SAH chooses; deeper, splits are at the median, which keeps the tree
// (and so the traversal stack) shallow whatever the geometry.
constexpr uint32_t kMaxSahDepth = 64;
constexpr int kTraversalStackSize = 128;

struct Aabb {
    glm::vec3 min{FLT_MAX};
    glm::vec3 max{-FLT_MAX};

    void grow(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void grow(const Aabb& b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    float halfArea() const {
        const glm::vec3 e = max - min;
        return e.x < 0.0f ? 0.0f : e.x * e.y + e.y * e.z + e.z * e.x;
    }
};

struct BuildPrimitive {
    Aabb bounds;
    glm::vec3 centroid;
    uint32_t id;
};

struct Builder {
    std::vector<BuildPrimitive> primitives;
    std::vector<BvhNode> nodes;

    // Builds the subtree over primitives[begin, end) and returns its node index.
    uint32_t build(uint32_t begin, uint32_t end, uint32_t depth) {
        const uint32_t nodeIndex = uint32_t(nodes.size());
        nodes.push_back({});
        Aabb bounds, centroids;
        for (uint32_t i = begin; i < end; ++i) {
            bounds.grow(primitives[i].bounds);
            centroids.grow(primitives[i].centroid);
        }
        nodes[nodeIndex].min = bounds.min;
        nodes[nodeIndex].max = bounds.max;

        const uint32_t count = end - begin;
        uint32_t middle = count <= 2 ? end : splitPoint(begin, end, bounds, centroids, depth);
        if (middle == end) {
            nodes[nodeIndex].rightOrFirst = begin;
            nodes[nodeIndex].count = count;
            return nodeIndex;
        }
        build(begin, middle, depth + 1);  // the left child is nodeIndex + 1
        const uint32_t right = build(middle, end, depth + 1);
        nodes[nodeIndex].rightOrFirst = right;
        nodes[nodeIndex].count = 0;
        return nodeIndex;
    }

    // Partitions primitives[begin, end) and returns where the right half starts, or `end` for a leaf.
    uint32_t splitPoint(uint32_t begin, uint32_t end, const Aabb& bounds, const Aabb& centroids, uint32_t depth) {
        const uint32_t count = end - begin;
        int bestAxis = -1, bestBin = 0;
        float bestCost = FLT_MAX;
        for (int axis = 0; axis < 3 && depth < kMaxSahDepth; ++axis) {
            const float extent = centroids.max[axis] - centroids.min[axis];
            if (!(extent > 0.0f)) continue;
            std::array<Aabb, kBinCount> binBounds;
            std::array<uint32_t, kBinCount> binCounts{};
            for (uint32_t i = begin; i < end; ++i) {
                const int bin = binOf(primitives[i].centroid[axis], centroids.min[axis], extent);
                binBounds[bin].grow(primitives[i].bounds);
                ++binCounts[bin];
            }
            // SAH (Wald 2007): cost of a split after bin i ∝ area(left)·n(left) + area(right)·n(right).
            std::array<float, kBinCount> rightCost{};
            Aabb rightBounds;
            uint32_t rightCount = 0;
            for (int i = kBinCount - 1; i > 0; --i) {
                rightBounds.grow(binBounds[i]);
                rightCount += binCounts[i];
                rightCost[i] = rightBounds.halfArea() * float(rightCount);
            }
            Aabb leftBounds;
            uint32_t leftCount = 0;
            for (int i = 0; i < kBinCount - 1; ++i) {
                leftBounds.grow(binBounds[i]);
                leftCount += binCounts[i];
                if (leftCount == 0 || leftCount == count) continue;
                const float cost = leftBounds.halfArea() * float(leftCount) + rightCost[i + 1];
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestBin = i;
                }
            }
        }

        const float leafCost = float(count) * bounds.halfArea();
        const float splitCost = kTraversalCost * bounds.halfArea() + bestCost;
        if (bestAxis >= 0 && (splitCost < leafCost || count > kMaxLeafSize)) {
            const float extent = centroids.max[bestAxis] - centroids.min[bestAxis];
            auto middle =
                std::partition(primitives.begin() + begin, primitives.begin() + end, [&](const BuildPrimitive& p) {
                    return binOf(p.centroid[bestAxis], centroids.min[bestAxis], extent) <= bestBin;
                });
            return uint32_t(middle - primitives.begin());
        }
        if (count <= kMaxLeafSize) return end;
        // No useful SAH split (coincident centroids, or too deep): halve along the widest axis.
        const glm::vec3 extent = centroids.max - centroids.min;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        const uint32_t middle = begin + count / 2;
        std::nth_element(
            primitives.begin() + begin, primitives.begin() + middle, primitives.begin() + end,
            [axis](const BuildPrimitive& a, const BuildPrimitive& b) { return a.centroid[axis] < b.centroid[axis]; });
        return middle;
    }

    static int binOf(float value, float min, float extent) {
        const int bin = int(float(kBinCount) * (value - min) / extent);
        return std::clamp(bin, 0, kBinCount - 1);
    }
};

// The per-ray constants of the watertight test (Woop et al. 2013, section 3) and of the slab test.
struct PreparedRay {
    glm::vec3 origin;
    int kx, ky, kz;    // axes permuted so that z is the dominant direction component
    float sx, sy, sz;  // shear that maps the ray direction to +z
    glm::vec3 inverseDirection;
};

PreparedRay prepare(const Ray& ray) {
    PreparedRay r;
    r.origin = ray.origin;
    const glm::vec3 d = ray.direction;
    const glm::vec3 a = glm::abs(d);
    r.kz = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    r.kx = (r.kz + 1) % 3;
    r.ky = (r.kx + 1) % 3;
    if (d[r.kz] < 0.0f) std::swap(r.kx, r.ky);  // keeps the winding, so the sign tests below hold
    r.sx = d[r.kx] / d[r.kz];
    r.sy = d[r.ky] / d[r.kz];
    r.sz = 1.0f / d[r.kz];
    for (int i = 0; i < 3; ++i) {
        // A tiny stand-in for zero keeps (bound − origin)·inverse free of 0·∞ = NaN.
        const float component = std::abs(d[i]) > 1e-30f ? d[i] : std::copysign(1e-30f, d[i]);
        r.inverseDirection[i] = 1.0f / component;
    }
    return r;
}

std::optional<RayHit> intersect(const PreparedRay& r, const TrianglePositions& tri, float tMax) {
    const glm::vec3 a = tri.p0 - r.origin, b = tri.p1 - r.origin, c = tri.p2 - r.origin;
    const float ax = a[r.kx] - r.sx * a[r.kz], ay = a[r.ky] - r.sy * a[r.kz];
    const float bx = b[r.kx] - r.sx * b[r.kz], by = b[r.ky] - r.sy * b[r.kz];
    const float cx = c[r.kx] - r.sx * c[r.kz], cy = c[r.ky] - r.sy * c[r.kz];
    // Scaled barycentrics: 2D edge functions of the sheared triangle.
    float u = cx * by - cy * bx;
    float v = ax * cy - ay * cx;
    float w = bx * ay - by * ax;
    if (u == 0.0f || v == 0.0f || w == 0.0f) {
        // On an edge in float: decide in double so neighbouring triangles agree (section 3.1).
        u = float(double(cx) * double(by) - double(cy) * double(bx));
        v = float(double(ax) * double(cy) - double(ay) * double(cx));
        w = float(double(bx) * double(ay) - double(by) * double(ax));
    }
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return std::nullopt;
    float det = u + v + w;
    if (det == 0.0f) return std::nullopt;
    float t = u * (r.sz * a[r.kz]) + v * (r.sz * b[r.kz]) + w * (r.sz * c[r.kz]);
    if (det < 0.0f) {
        det = -det;
        t = -t;
    }
    if (!(t > 0.0f) || !(t < tMax * det)) return std::nullopt;
    const float inverseDet = 1.0f / det;
    RayHit hit;
    hit.t = t * inverseDet;
    hit.b1 = std::abs(v) * inverseDet;
    hit.b2 = std::abs(w) * inverseDet;
    return hit;
}

// Slab test; the far distance is scaled by 1 + 2γ₃ so that rounding never culls a box the ray
// touches (Ize 2013, "Robust BVH Ray Traversal").
bool hitsBox(const PreparedRay& r, const BvhNode& node, float tMax, float& tEnter) {
    constexpr float kUnitRoundoff = 0.5f * FLT_EPSILON;
    constexpr float kGamma3 = 3.0f * kUnitRoundoff / (1.0f - 3.0f * kUnitRoundoff);
    constexpr float kRobustScale = 1.0f + 2.0f * kGamma3;
    const glm::vec3 t0 = (node.min - r.origin) * r.inverseDirection;
    const glm::vec3 t1 = (node.max - r.origin) * r.inverseDirection;
    const glm::vec3 tNear = glm::min(t0, t1), tFar = glm::max(t0, t1);
    tEnter = std::max(std::max(tNear.x, tNear.y), std::max(tNear.z, 0.0f));
    const float tExit = std::min(std::min(tFar.x, tFar.y), tFar.z) * kRobustScale;
    return tEnter <= std::min(tExit, tMax);
}

// Depth-first traversal, nearer child first; stops at the first hit when `anyHitOnly`.
std::optional<RayHit> traverse(const Bvh& bvh, const Ray& ray, bool anyHitOnly, const HitFilter& filter) {
    if (bvh.nodes.empty()) return std::nullopt;
    const PreparedRay r = prepare(ray);
    float tMax = ray.tMax;
    std::optional<RayHit> best;
    float tEnter;
    if (!hitsBox(r, bvh.nodes[0], tMax, tEnter)) return std::nullopt;
    std::array<uint32_t, kTraversalStackSize> stack;
    int stackSize = 0;
    uint32_t nodeIndex = 0;
    for (;;) {
        const BvhNode& node = bvh.nodes[nodeIndex];
        if (node.count > 0) {
            for (uint32_t i = node.rightOrFirst; i < node.rightOrFirst + node.count; ++i) {
                std::optional<RayHit> hit = intersect(r, bvh.triangles[i], tMax);
                if (!hit) continue;
                hit->triangle = bvh.triangleIds[i];
                if (bvh.filtered[i] && filter && !filter(*hit)) continue;
                best = hit;
                tMax = hit->t;
                if (anyHitOnly) return best;
            }
        } else {
            uint32_t near = nodeIndex + 1, far = node.rightOrFirst;
            float tNear, tFar;
            bool hitNear = hitsBox(r, bvh.nodes[near], tMax, tNear);
            bool hitFar = hitsBox(r, bvh.nodes[far], tMax, tFar);
            if (hitNear && hitFar) {
                if (tFar < tNear) std::swap(near, far);
                stack[stackSize++] = far;
                nodeIndex = near;
                continue;
            }
            if (hitNear || hitFar) {
                nodeIndex = hitNear ? near : far;
                continue;
            }
        }
        if (stackSize == 0) return best;
        nodeIndex = stack[--stackSize];
    }
}

}  // namespace

std::optional<RayHit> intersectTriangle(const Ray& ray, const TrianglePositions& triangle) {
    return intersect(prepare(ray), triangle, ray.tMax);
}

Bvh buildBvh(const Scene& scene) {
    Builder builder;
    for (uint32_t id = 0; id < scene.triangleCount(); ++id) {
        const glm::vec3 p0 = scene.vertices[scene.indices[3 * id + 0]].position;
        const glm::vec3 p1 = scene.vertices[scene.indices[3 * id + 1]].position;
        const glm::vec3 p2 = scene.vertices[scene.indices[3 * id + 2]].position;
        if (!(glm::length(glm::cross(p1 - p0, p2 - p0)) > 0.0f)) continue;
        BuildPrimitive primitive;
        primitive.bounds.grow(p0);
        primitive.bounds.grow(p1);
        primitive.bounds.grow(p2);
        primitive.centroid = (p0 + p1 + p2) / 3.0f;
        primitive.id = id;
        builder.primitives.push_back(primitive);
    }
    Bvh bvh;
    if (builder.primitives.empty()) return bvh;
    builder.nodes.reserve(2 * builder.primitives.size());
    builder.build(0, uint32_t(builder.primitives.size()), 0);
    bvh.nodes = std::move(builder.nodes);
    for (const BuildPrimitive& primitive : builder.primitives) {
        const uint32_t* index = &scene.indices[3 * primitive.id];
        bvh.triangles.push_back(
            {scene.vertices[index[0]].position, scene.vertices[index[1]].position, scene.vertices[index[2]].position});
        bvh.triangleIds.push_back(primitive.id);
        const Material& material = scene.materials[scene.triangleMaterials[primitive.id]];
        bvh.filtered.push_back(material.alphaMode != AlphaMode::Opaque || !material.doubleSided ? 1 : 0);
    }
    return bvh;
}

std::optional<RayHit> closestHit(const Bvh& bvh, const Ray& ray, const HitFilter& filter) {
    return traverse(bvh, ray, false, filter);
}

bool anyHit(const Bvh& bvh, const Ray& ray, const HitFilter& filter) {
    return traverse(bvh, ray, true, filter).has_value();
}

}  // namespace vct::pt
