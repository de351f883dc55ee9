#pragma once
// The viewer's fly camera: a position and a view direction (yaw, pitch) over the scene's camera, whose field
// of view and planes it keeps. Until it is moved or turned it returns the scene's camera unchanged, so a
// viewer frame at the start equals lidr-demo --headless's image bit for bit.
#include <glm/glm.hpp>

#include "lidr/scene/scene.h"

namespace lidr::viewer {

class FlyCamera {
public:
    void reset(const Camera& sceneCamera);
    // Moves by `distance` along the camera's right (x), world up (y) and forward (z) axes, scaled by `local`.
    void move(const glm::vec3& local, float distance);
    // Turns by the given angles in radians (yaw to the right, pitch up); pitch stays within +-89 degrees.
    void turn(float yawRadians, float pitchRadians);
    Camera camera() const;
    glm::vec3 position() const { return position_; }
    glm::vec3 forward() const;
    glm::vec3 right() const;
    float yaw() const { return yaw_; }
    float pitch() const { return pitch_; }
    bool moved() const { return moved_; }

private:
    Camera base_;
    glm::vec3 position_{0.0f};
    float yaw_ = 0.0f, pitch_ = 0.0f;
    bool moved_ = false;
};

}  // namespace lidr::viewer
