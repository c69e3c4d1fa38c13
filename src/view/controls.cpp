#include "view/controls.h"

#include <algorithm>
#include <cmath>

namespace vct {

static constexpr float lookRadiansPerPixel = 0.004f;
static constexpr float maxPitch = glm::radians(89.0f);

void CameraControl::reset(const Camera& sceneCamera, const Bounds& sceneBounds) {
    sceneSize_ = std::max(glm::length(sceneBounds.extent()), 1e-3f);
    speed_ = 0.25f * sceneSize_;  // crosses the scene in about four seconds
    orbitCentre_ = sceneBounds.center();
    const glm::vec3 forward = glm::normalize(sceneCamera.forward);
    yaw_ = std::atan2(forward.z, forward.x);
    pitch_ = std::asin(std::clamp(forward.y, -1.0f, 1.0f));
    orbitDistance_ = std::max(glm::distance(sceneCamera.position, orbitCentre_), 1e-3f);
    mode_ = Mode::Fly;
}

void CameraControl::setMode(Mode mode, Camera& camera) {
    mode_ = mode;
    if (mode != Mode::Orbit) return;
    // Look at the centre from where the camera is.
    const glm::vec3 toCentre = orbitCentre_ - camera.position;
    orbitDistance_ = std::max(glm::length(toCentre), 0.05f * sceneSize_);
    const glm::vec3 forward = glm::length(toCentre) > 0.0f ? glm::normalize(toCentre) : camera.forward;
    yaw_ = std::atan2(forward.z, forward.x);
    pitch_ = std::asin(std::clamp(forward.y, -1.0f, 1.0f));
    aimFromAngles(camera);
}

void CameraControl::aimFromAngles(Camera& camera) const {
    camera.forward = glm::vec3(std::cos(pitch_) * std::cos(yaw_), std::sin(pitch_), std::cos(pitch_) * std::sin(yaw_));
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    if (mode_ == Mode::Orbit) camera.position = orbitCentre_ - camera.forward * orbitDistance_;
}

bool CameraControl::update(const CameraInput& input, Camera& camera) {
    bool changed = false;
    if (input.drag != glm::vec2(0.0f)) {
        // Dragging right turns right; dragging down looks down (screen y grows downwards).
        yaw_ += input.drag.x * lookRadiansPerPixel;
        pitch_ = std::clamp(pitch_ - input.drag.y * lookRadiansPerPixel, -maxPitch, maxPitch);
        changed = true;
    }
    if (mode_ == Mode::Orbit) {
        if (input.scroll != 0.0f) {
            orbitDistance_ =
                std::clamp(orbitDistance_ * std::pow(0.9f, input.scroll), 0.02f * sceneSize_, 20.0f * sceneSize_);
            changed = true;
        }
        if (changed) aimFromAngles(camera);
        return changed;
    }
    if (input.scroll != 0.0f)
        speed_ = std::clamp(speed_ * std::pow(1.25f, input.scroll), 1e-3f * sceneSize_, 1e2f * sceneSize_);
    if (changed) aimFromAngles(camera);
    const glm::vec3 forward = glm::normalize(camera.forward);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
    glm::vec3 move(0.0f);
    if (input.forward) move += forward;
    if (input.back) move -= forward;
    if (input.right) move += right;
    if (input.left) move -= right;
    if (input.up) move.y += 1.0f;
    if (input.down) move.y -= 1.0f;
    if (move != glm::vec3(0.0f) && input.seconds > 0.0f) {
        camera.position += glm::normalize(move) * speed_ * (input.fast ? 4.0f : 1.0f) * input.seconds;
        changed = true;
    }
    return changed;
}

glm::vec3 SunControl::travelDirection() const {
    const float azimuth = glm::radians(azimuthDegrees), elevation = glm::radians(elevationDegrees);
    const glm::vec3 towardsSun(std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
                               std::cos(elevation) * std::sin(azimuth));
    return -towardsSun;
}

void SunControl::setFromTravelDirection(glm::vec3 direction) {
    const glm::vec3 towardsSun = -glm::normalize(direction);
    elevationDegrees = glm::degrees(std::asin(std::clamp(towardsSun.y, -1.0f, 1.0f)));
    azimuthDegrees = glm::degrees(std::atan2(towardsSun.z, towardsSun.x));
    normalize();
}

void SunControl::normalize() {
    azimuthDegrees = std::fmod(azimuthDegrees, 360.0f);
    if (azimuthDegrees < 0.0f) azimuthDegrees += 360.0f;
    elevationDegrees = std::clamp(elevationDegrees, -89.0f, 89.0f);
}

}  // namespace vct
