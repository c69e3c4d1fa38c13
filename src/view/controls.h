// What the mouse and keyboard do to the camera and the sun, free of any window code so it reads
// (and can be tested) on its own.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace vct {

// The keys and drags of one frame that move the camera.
struct CameraInput {
    bool forward = false, back = false, left = false, right = false, down = false, up = false;
    bool fast = false;     // Shift
    glm::vec2 drag{0.0f};  // pixels the cursor moved with the look (fly) or orbit button held
    float scroll = 0.0f;   // wheel notches, positive away from the user
    float seconds = 0.0f;  // frame time the movement is scaled by
};

class CameraControl {
public:
    enum class Mode { Fly, Orbit };

    // Starts from `sceneCamera`; speeds and the orbit centre come from the scene's size.
    void reset(const Camera& sceneCamera, const Bounds& sceneBounds);
    void setMode(Mode mode, Camera& camera);
    Mode mode() const { return mode_; }
    float speed() const { return speed_; }
    // Moves `camera`; returns whether it changed.
    bool update(const CameraInput& input, Camera& camera);

private:
    void aimFromAngles(Camera& camera) const;
    Mode mode_ = Mode::Fly;
    float yaw_ = 0.0f, pitch_ = 0.0f;  // radians; forward = (cos p cos y, sin p, cos p sin y)
    float speed_ = 1.0f;               // metres per second in fly mode
    glm::vec3 orbitCentre_{0.0f};
    float orbitDistance_ = 1.0f;
    float sceneSize_ = 1.0f;
};

// The sun as azimuth and elevation (degrees) of the direction it shines from.
struct SunControl {
    float azimuthDegrees = 0.0f;
    float elevationDegrees = 45.0f;
    float intensity = 3.0f;
    bool animate = false;
    float animateDegreesPerSecond = 20.0f;

    // The direction the light travels (the scene's Light::direction).
    glm::vec3 travelDirection() const;
    void setFromTravelDirection(glm::vec3 direction);
    // Keeps the elevation in (−90°, 90°) and the azimuth in [0°, 360°).
    void normalize();
};

}  // namespace vct
