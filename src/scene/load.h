// Loading a scene: a glTF file (.gltf/.glb) or a built-in scene by name.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "scene/scene_limits.h"

namespace vct {

struct LoadOptions {
    // Buffer and image URIs must resolve inside this folder; empty = the scene file's own folder.
    std::string allowedRoot;
    // Turn every warning (missing or corrupt image, ignored extension...) into an error.
    bool strict = false;
    // Files (the scene, its buffers and images) larger than this are refused.
    uint64_t maxFileBytes = uint64_t(1) << 30;
    // The vertex and index buffers the scene may need (the device's, when the caller has one):
    // a file naming more is refused from its counts, before any array is built.
    SceneBufferLimits bufferLimits;
};

// Loads a glTF 2.0 file. Throws vct::Error naming the file, the JSON path and the problem.
Scene loadGltf(const std::string& path, const LoadOptions& options = {});

// Names of the built-in scenes ("cornell", ...), for --help and the viewer's picker.
std::vector<std::string> builtinSceneNames();

// A built-in scene by name, or a glTF file by path.
Scene loadScene(const std::string& nameOrPath, const LoadOptions& options = {});

}  // namespace vct
