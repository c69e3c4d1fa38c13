// Vertex tangents for meshes whose file gives none, so that a normal texture turns smoothly across
// the triangles (glTF 2.0 §3.7.2.1 asks for MikkTSpace's where a file leaves TANGENT out). Without
// them the renderer takes each pixel's frame from its own triangle's texture coordinates, which
// turns at every edge: a low-polygon sphere's normal-mapped light shows its facets.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace vct {

// Gives the vertices of the triangles indices[firstIndex..] a tangent along increasing u of
// TEXCOORD_0 (Vertex::u, v) with its handedness, as Vertex::tangent defines them, MikkTSpace's way
// where the coordinates are not skewed: each triangle's ∂position/∂u, made perpendicular to the
// vertex normal and weighted by the triangle's angle at the vertex, summed over the triangles that
// share the vertex. A vertex that triangles of both handednesses share (the seam where a symmetric
// model's mirrored halves meet) is split in two, the copy appended to `vertices` and the triangles
// of the second handedness pointed at it, so that neither side's tangents cancel. Vertices whose
// triangles' coordinates are degenerate keep a zero tangent (the frame is then taken per pixel).
void generateTangents(std::vector<Vertex>& vertices, std::vector<uint32_t>& indices, size_t firstIndex);

}  // namespace vct
