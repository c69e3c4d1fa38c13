// Validation of a parsed glTF model, before any of it is converted.
//
// tinygltf 2.7.0 parses what the JSON says and checks little of it: accessors may run past their
// buffers, indices past the vertex count, references may name objects that do not exist, node
// hierarchies may hold cycles. Everything the loader later reads is checked here, so the
// conversion in gltf_loader.cpp can index without checking. Messages read
// "<file>: <json path>: <problem>", e.g.
// "scene.gltf: meshes[0].primitives[1].indices: index 97 is past the vertex count 24".
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "scene/scene_limits.h"

namespace vct {

// The extensions the loader understands; a file that requires any other is refused.
const std::vector<std::string>& supportedGltfExtensions();

// Throws vct::Error naming `file`, the JSON path and the problem for the first problem found:
// first the structure (references, ranges, formats), then whether the geometry fits `limits`
// (from the accessors' counts), and only then the values (finite numbers, indices in range).
void validateGltf(const tinygltf::Model& model, const std::string& file, const SceneBufferLimits& limits = {});

// The default scene's root nodes: `scene`, else scene 0, else every node without a parent.
std::vector<int> gltfRootNodes(const tinygltf::Model& model);

}  // namespace vct
