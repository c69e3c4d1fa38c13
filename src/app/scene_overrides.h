// The options that change the scene as loaded (camera, sun, sky): what they hold, and one row per
// option, from which the command line's help, the README's table and their reading all come.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/arguments.h"

namespace vct {

// --camera-pos/--camera-target/--fov, --light-dir/--light-intensity and --environment with
// --environment-rotation, read and checked before the scene loads.
struct SceneOverrides {
    std::optional<glm::vec3> cameraPosition, cameraTarget;
    std::optional<float> yfovDegrees;
    std::optional<glm::vec3> lightDirection;  // not the zero vector
    std::optional<float> lightIntensity;
    std::optional<glm::vec3> environment;  // finite, not negative
    std::string environmentImage;          // --environment FILE.hdr: the sky's image (the file exists)
    float environmentRotation = 0.0f;      // --environment-rotation, radians (Scene::environmentRotation)
};

struct SceneOverrideRow {
    const char* option;  // without its dashes
    const char* shape;   // what it takes, as the help shows it
    std::string help;
    // Reads the option, where given, into `overrides` (the rows are read in the table's order), or
    // throws a vct::Error naming the option and what is wrong with its value.
    void (*read)(const Arguments& arguments, SceneOverrides& overrides);
};
const std::vector<SceneOverrideRow>& sceneOverrideTable();

// Every row read from `arguments`.
SceneOverrides sceneOverridesFromArguments(const Arguments& arguments);
// The README's table of the rows (a CPU test holds the README to it).
std::string sceneOverridesMarkdown();

}  // namespace vct
