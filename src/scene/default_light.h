// The light a scene without any gets, the same in `vct render`, `vct view`, `vct bench` and the
// path tracer, so that a glTF file without lights (most sample models) is not rendered black.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace vct {

// A sun from above, in front (+Z, where glTF models face) and a little to the left, fixed in world
// space so that every command and every camera sees the scene under the same light.
inline constexpr glm::vec3 kDefaultSunTravel{0.3f, -1.0f, -0.6f};  // normalised where used
inline constexpr float kDefaultSunIlluminance = 3.0f;              // lux, as --light-dir's sun
inline constexpr const char* kDefaultSunName = "default sun";
// A pale blue sky beside it, radiance in scene units: its irradiance on open ground, π·L, is about
// a sixth of the sun's there, as on a clear day, so faces the sun does not reach are not black.
inline constexpr glm::vec3 kDefaultSkyRadiance{0.11f, 0.14f, 0.18f};

// Throws vct::Error unless `radiance` can be a sky's (0 to 1e9 in each of red, green and blue):
// what --environment takes, in vct and in vct_pathtrace alike.
void checkSkyRadiance(glm::vec3 radiance);

// Emissive surfaces light a scene without lights or sky when they send out at least this share of
// the power the default sun would bring onto it. Below it they are decoration, as the glowing
// trims of DamagedHelmet, Lantern or BoomBox are (emissiveFactor 1 through a texture that is black
// nearly everywhere): left unlit, such a model renders black but for its glow.
inline constexpr double kEmittersLightTheSceneShare = 0.1;

// The power (W, in scene units) the default sun brings onto the scene's bounding box: its
// illuminance times the area of the box's shadow across the sun, Σ |travelᵢ| × the faces across axis i.
double defaultSunPowerOnBounds(const Bounds& bounds);

// The power the scene's emissive triangles send out of their front faces: π × the luminance of
// each one's mean radiance (emittedRadianceOverTriangle: its emissive texture and its holes) × its area.
double emittedPower(const Scene& scene);

// True if the scene has a light, a sky (Scene::environment not black), or emissive surfaces that
// send out at least kEmittersLightTheSceneShare of the power the default sun would bring.
bool sceneHasLight(const Scene& scene);

// Adds the default sun and sky to a scene without light, and a warning naming them (direction,
// illuminance, radiance) to scene.warnings, which every command prints. Returns whether it did.
bool addDefaultSunAndSkyIfUnlit(Scene& scene);

}  // namespace vct
