#pragma once
#include <glm/glm.hpp>

#include "lidr/scene/scene.h"

namespace lidr {

// The matrices every pass uses for one frame.
struct CameraMatrices {
    glm::mat4 view{1.0f}, projection{1.0f}, viewProjection{1.0f}, inverseViewProjection{1.0f};
    glm::vec3 eye{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
    float nearPlane = 0.1f, farPlane = 100.0f;
    int width = 1, height = 1;
};

CameraMatrices cameraMatrices(const Camera& camera, int width, int height);

// World position of pixel (x, y) (y = 0 at the top, pixel centres) at window depth `depth` in [0, 1].
glm::vec3 unprojectPixel(const CameraMatrices& m, int x, int y, float depth);

// False only when the sphere lies wholly outside one of the six frustum planes (conservative).
bool sphereMayBeVisible(const CameraMatrices& m, const glm::vec3& center, float radius);

// The default view of a scene that brings no camera (an OBJ or glTF file alone): looking at the centre of the
// box [boundsMin, boundsMax] from the front (+z) and above (direction (0, 0.5, 1)), far enough that the box's
// bounding sphere fits the vertical field of view with 10% to spare; near and far planes enclose the sphere.
Camera cameraFramingBounds(const glm::vec3& boundsMin, const glm::vec3& boundsMax, float fovYDegrees = 60.0f);

}  // namespace lidr
