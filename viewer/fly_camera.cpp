#include "fly_camera.h"

#include <algorithm>
#include <cmath>

namespace lidr::viewer {

void FlyCamera::reset(const Camera& c) {
    base_ = c;
    position_ = c.position;
    glm::vec3 f = c.target - c.position;
    const float len = glm::length(f);
    f = len > 0.0f ? f / len : glm::vec3(0.0f, 0.0f, -1.0f);
    pitch_ = std::asin(std::clamp(f.y, -1.0f, 1.0f));
    yaw_ = std::atan2(f.x, -f.z);
    moved_ = false;
}

glm::vec3 FlyCamera::forward() const {
    return {std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_), -std::cos(pitch_) * std::cos(yaw_)};
}

glm::vec3 FlyCamera::right() const { return {std::cos(yaw_), 0.0f, std::sin(yaw_)}; }

void FlyCamera::move(const glm::vec3& local, float distance) {
    if (local == glm::vec3(0.0f) || distance == 0.0f) return;
    const glm::vec3 d = local.x * right() + local.y * glm::vec3(0.0f, 1.0f, 0.0f) + local.z * forward();
    position_ += glm::normalize(d) * distance;
    moved_ = true;
}

void FlyCamera::turn(float yawRadians, float pitchRadians) {
    if (yawRadians == 0.0f && pitchRadians == 0.0f) return;
    const float limit = glm::radians(89.0f);
    yaw_ = std::remainder(yaw_ + yawRadians, 2.0f * float(M_PI));
    pitch_ = std::clamp(pitch_ + pitchRadians, -limit, limit);
    moved_ = true;
}

Camera FlyCamera::camera() const {
    if (!moved_) return base_;
    Camera c = base_;
    c.position = position_;
    c.target = position_ + forward();
    c.up = glm::vec3(0.0f, 1.0f, 0.0f);
    return c;
}

}  // namespace lidr::viewer
