#include "render/voxelize_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/material_textures.h"
#include "voxelize.h"

namespace vct {

glm::dvec3 toGridCoordinates(const glsl::VoxelGridParams& grid, const glm::vec3& world) {
    return (glm::dvec3(world) - glm::dvec3(grid.origin)) / double(grid.voxelSize);
}

TriangleD gridTriangle(const Scene& scene, const glsl::VoxelGridParams& grid, size_t triangle) {
    TriangleD result;
    for (size_t corner = 0; corner < 3; ++corner)
        result[corner] = toGridCoordinates(grid, scene.vertices[scene.indices[triangle * 3 + corner]].position);
    return result;
}

TriangleD setBackTriangle(const TriangleD& triangle) {
    const glm::dvec3 normal = glm::normalize(glm::cross(triangle[1] - triangle[0], triangle[2] - triangle[0]));
    const glm::dvec3 setback = -double(glsl::voxelizationSetback(glm::vec3(normal))) * normal;
    return {triangle[0] + setback, triangle[1] + setback, triangle[2] + setback};
}

bool isDegenerateTriangle(const Scene& scene, size_t triangle) {
    const glm::dvec3 p0(scene.vertices[scene.indices[triangle * 3 + 0]].position);
    const glm::dvec3 p1(scene.vertices[scene.indices[triangle * 3 + 1]].position);
    const glm::dvec3 p2(scene.vertices[scene.indices[triangle * 3 + 2]].position);
    const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
    return n.x == 0.0 && n.y == 0.0 && n.z == 0.0;
}

namespace {

// Gap along `axis` (unnormalized) between the triangle (relative to the box centre) and the box.
double gapOnAxis(const glm::dvec3& axis, const TriangleD& v, double halfSize) {
    const double length = glm::length(axis);
    if (length == 0.0) return -std::numeric_limits<double>::infinity();
    const double p0 = glm::dot(axis, v[0]), p1 = glm::dot(axis, v[1]), p2 = glm::dot(axis, v[2]);
    const double radius = halfSize * (std::abs(axis.x) + std::abs(axis.y) + std::abs(axis.z));
    const double gap = std::max(std::min({p0, p1, p2}) - radius, -radius - std::max({p0, p1, p2}));
    return gap / length;
}

}  // namespace

double triangleBoxSeparation(const TriangleD& triangle, const glm::dvec3& boxCenter, double halfSize) {
    const TriangleD v = {triangle[0] - boxCenter, triangle[1] - boxCenter, triangle[2] - boxCenter};
    const glm::dvec3 edges[3] = {triangle[1] - triangle[0], triangle[2] - triangle[1], triangle[0] - triangle[2]};
    double separation = -std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 boxNormal(0.0);
        boxNormal[axis] = 1.0;
        separation = std::max(separation, gapOnAxis(boxNormal, v, halfSize));
        for (const glm::dvec3& edge : edges)
            separation = std::max(separation, gapOnAxis(glm::cross(boxNormal, edge), v, halfSize));
    }
    return std::max(separation, gapOnAxis(glm::cross(edges[0], edges[1]), v, halfSize));
}

VoxelRange triangleVoxelRange(const TriangleD& triangle, uint32_t resolution, double margin) {
    const glm::dvec3 low = glm::min(triangle[0], glm::min(triangle[1], triangle[2]));
    const glm::dvec3 high = glm::max(triangle[0], glm::max(triangle[1], triangle[2]));
    VoxelRange range;
    for (int axis = 0; axis < 3; ++axis) {
        // Voxel i spans [i, i+1]: the closed triangle can touch it iff low ≤ i + 1 and high ≥ i.
        const double first = std::max(std::ceil(low[axis] - 1.0 - margin), 0.0);
        const double last = std::min(std::floor(high[axis] + margin), double(resolution) - 1.0);
        // Clamp before converting: a triangle far outside the grid must not overflow an int.
        range.first[axis] = int(std::min(first, double(resolution)));
        range.last[axis] = int(std::max(last, -1.0));
    }
    return range;
}

VoxelReference voxelizeReference(const Scene& scene, const glsl::VoxelGridParams& grid) {
    VoxelReference result;
    const uint32_t n = grid.resolution;
    result.resolution = n;
    const size_t voxels = size_t(n) * n * n;
    result.count.assign(voxels, 0);
    result.emitters.assign(voxels, 0);
    result.albedo.assign(voxels, glm::dvec3(0.0));
    result.opacity.assign(voxels, 0.0);
    result.maskedByTexture.assign(voxels, 0);
    result.normal.assign(voxels, glm::dvec3(0.0));
    result.surfaceOffset.assign(voxels, 0.0);
    std::vector<glm::dvec3> toPlanes(voxels, glm::dvec3(0.0));
    result.emission.assign(voxels, glm::dvec3(0.0));
    result.decisionMargin.assign(voxels, std::numeric_limits<double>::infinity());

    for (size_t t = 0; t < scene.triangleCount(); ++t) {
        if (isDegenerateTriangle(scene, t)) continue;
        const TriangleD triangle = gridTriangle(scene, grid, t);
        const Material& material = scene.materials[scene.triangleMaterials[t]];
        const double coverage = std::clamp(double(voxelCoverage(scene, material)), 0.0, 1.0);
        if (!(coverage > 0.0)) continue;
        const glm::dvec3 normal = glm::normalize(glm::cross(triangle[1] - triangle[0], triangle[2] - triangle[0]));
        const glm::dvec3 albedo = glm::clamp(glm::dvec3(glm::vec3(material.baseColorFactor)), 0.0, 1.0);
        const bool masked = masksVoxelsByTexture(scene, material);
        // A material emits where its emissive texture's mean is not black, with its factor.
        const glm::dvec3 emission =
            emitsLight(scene, material) ? glm::max(glm::dvec3(material.emission), 0.0) : glm::dvec3(0.0);
        // Marked where its set-back copy touches; its own plane says where the surface lies.
        const TriangleD marking = setBackTriangle(triangle);
        // One voxel of slack so voxels just outside the range also get their decision margin.
        const VoxelRange range = triangleVoxelRange(marking, n, 1.0);
        for (int z = range.first.z; z <= range.last.z; ++z)
            for (int y = range.first.y; y <= range.last.y; ++y)
                for (int x = range.first.x; x <= range.last.x; ++x) {
                    const double separation = triangleBoxSeparation(marking, glm::dvec3(x, y, z) + 0.5, 0.5);
                    const size_t i = result.index(uint32_t(x), uint32_t(y), uint32_t(z));
                    result.decisionMargin[i] = std::min(result.decisionMargin[i], std::abs(separation));
                    if (separation > 0.0) continue;
                    if (masked) result.maskedByTexture[i] = 1;
                    ++result.count[i];
                    result.albedo[i] += albedo;
                    result.opacity[i] = std::max(result.opacity[i], coverage);
                    result.normal[i] += normal;
                    const glm::dvec3 centre = glm::dvec3(x, y, z) + 0.5;
                    toPlanes[i] += normal * glm::dot(normal, triangle[0] - centre);
                    if (glm::max(emission.x, glm::max(emission.y, emission.z)) > 0.0) {
                        ++result.emitters[i];
                        result.emission[i] += emission;
                    }
                }
    }
    for (size_t i = 0; i < voxels; ++i)
        if (result.count[i] > 0) {
            const double count = double(result.count[i]);
            result.albedo[i] /= count;
            result.normal[i] /= count;
            const double normalLength = glm::length(result.normal[i]);
            if (normalLength > glsl::SURFACE_NORMAL_MIN)
                result.surfaceOffset[i] = glm::dot(result.normal[i], toPlanes[i] / count) / normalLength;
            if (result.emitters[i] > 0) result.emission[i] /= double(result.emitters[i]);
        }
    return result;
}

}  // namespace vct
