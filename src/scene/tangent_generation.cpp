#include "scene/tangent_generation.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace vct {

namespace {

// What one triangle says about its corners' tangents.
struct TriangleFrame {
    glm::dvec3 alongU{0.0};  // ∂position/∂u
    int side = 0;            // 0: the bitangent cross(normal, tangent) points up the image; 1: down
    bool valid = false;      // false where its coordinates are degenerate
};

TriangleFrame triangleFrame(const Vertex& a, const Vertex& b, const Vertex& c) {
    const glm::dvec3 step1 = glm::dvec3(b.position) - glm::dvec3(a.position);
    const glm::dvec3 step2 = glm::dvec3(c.position) - glm::dvec3(a.position);
    const glm::dvec2 change1(double(b.u) - a.u, double(b.v) - a.v);
    const glm::dvec2 change2(double(c.u) - a.u, double(c.v) - a.v);
    // The 2 × 2 system of normal_map.h's axesFromSteps, in double.
    const double determinant = change1.x * change2.y - change2.x * change1.y;
    TriangleFrame frame;
    if (!(std::abs(determinant) > 0.0)) return frame;
    frame.alongU = (change2.y * step1 - change1.y * step2) / determinant;
    const glm::dvec3 alongV = (change1.x * step2 - change2.x * step1) / determinant;
    // The triangle's side: its vertex normals' (which the shading uses), or its winding's where those cancel.
    glm::dvec3 normal = glm::dvec3(a.normal) + glm::dvec3(b.normal) + glm::dvec3(c.normal);
    if (!(glm::length(normal) > 0.0)) normal = glm::cross(step1, step2);
    // Up the image is decreasing v, −∂position/∂v (normal_map.h).
    frame.side = glm::dot(glm::cross(normal, frame.alongU), -alongV) >= 0.0 ? 0 : 1;
    frame.valid = std::isfinite(glm::dot(frame.alongU, frame.alongU)) && glm::length(frame.alongU) > 0.0;
    return frame;
}

// The angle of the triangle at `corner`, between the edges to the two others.
double cornerAngle(const glm::vec3& corner, const glm::vec3& next, const glm::vec3& previous) {
    const glm::dvec3 toNext = glm::dvec3(next) - glm::dvec3(corner);
    const glm::dvec3 toPrevious = glm::dvec3(previous) - glm::dvec3(corner);
    const double lengths = glm::length(toNext) * glm::length(toPrevious);
    if (!(lengths > 0.0)) return 0.0;
    return std::acos(std::clamp(glm::dot(toNext, toPrevious) / lengths, -1.0, 1.0));
}

// `direction` made perpendicular to the unit `normal` and normalized; zero where it is along it.
glm::dvec3 perpendicularUnit(const glm::dvec3& direction, const glm::dvec3& normal) {
    const glm::dvec3 perpendicular = direction - normal * glm::dot(normal, direction);
    const double length = glm::length(perpendicular);
    return length > 1e-12 * glm::length(direction) ? perpendicular / length : glm::dvec3(0.0);
}

}  // namespace

void generateTangents(std::vector<Vertex>& vertices, std::vector<uint32_t>& indices, size_t firstIndex) {
    const size_t end = firstIndex + (indices.size() - firstIndex) / 3 * 3;
    if (end <= firstIndex) return;
    const uint32_t lowest =
        *std::min_element(indices.begin() + ptrdiff_t(firstIndex), indices.begin() + ptrdiff_t(end));
    const uint32_t highest =
        *std::max_element(indices.begin() + ptrdiff_t(firstIndex), indices.begin() + ptrdiff_t(end));
    const size_t span = size_t(highest - lowest) + 1;

    // Per vertex and side: the weighted sum of its triangles' tangents, and whether any triangle had it.
    std::vector<glm::dvec3> sums(2 * span, glm::dvec3(0.0));
    std::vector<uint8_t> used(2 * span, 0);
    std::vector<TriangleFrame> frames((end - firstIndex) / 3);
    for (size_t t = 0; t < frames.size(); ++t) {
        const uint32_t* corner = &indices[firstIndex + 3 * t];
        TriangleFrame& frame = frames[t] = triangleFrame(vertices[corner[0]], vertices[corner[1]], vertices[corner[2]]);
        if (!frame.valid) continue;
        for (int k = 0; k < 3; ++k) {
            const Vertex& vertex = vertices[corner[k]];
            const double angle = cornerAngle(vertex.position, vertices[corner[(k + 1) % 3]].position,
                                             vertices[corner[(k + 2) % 3]].position);
            const size_t slot = 2 * (corner[k] - lowest) + size_t(frame.side);
            sums[slot] += angle * perpendicularUnit(frame.alongU, glm::dvec3(vertex.normal));
            used[slot] = 1;
        }
    }

    // A vertex both sides use keeps the first; the second gets a copy of it.
    std::vector<uint32_t> secondSide(span, UINT32_MAX);
    for (size_t i = 0; i < span; ++i) {
        if (used[2 * i] && used[2 * i + 1]) {
            secondSide[i] = uint32_t(vertices.size());
            vertices.push_back(vertices[lowest + i]);
        }
    }
    for (size_t t = 0; t < frames.size(); ++t) {
        if (!frames[t].valid || frames[t].side == 0) continue;
        for (int k = 0; k < 3; ++k) {
            uint32_t& corner = indices[firstIndex + 3 * t + size_t(k)];
            const uint32_t copy = secondSide[corner - lowest];
            if (copy != UINT32_MAX) corner = copy;
        }
    }
    for (size_t i = 0; i < span; ++i) {
        for (int side = 0; side < 2; ++side) {
            if (!used[2 * i + size_t(side)]) continue;
            const uint32_t index = side == 1 && secondSide[i] != UINT32_MAX ? secondSide[i] : uint32_t(lowest + i);
            Vertex& vertex = vertices[index];
            const glm::dvec3 tangent = perpendicularUnit(sums[2 * i + size_t(side)], glm::dvec3(vertex.normal));
            vertex.tangent =
                tangent == glm::dvec3(0.0) ? glm::vec4(0.0f) : glm::vec4(glm::vec3(tangent), side == 0 ? 1.0f : -1.0f);
        }
    }
}

}  // namespace vct
