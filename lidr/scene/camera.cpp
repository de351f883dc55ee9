#include "lidr/scene/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace lidr {

CameraMatrices cameraMatrices(const Camera& c, int width, int height) {
    CameraMatrices m;
    m.width = width;
    m.height = height;
    m.eye = c.position;
    m.forward = glm::normalize(c.target - c.position);
    m.nearPlane = c.nearPlane;
    m.farPlane = c.farPlane;
    m.view = glm::lookAt(c.position, c.target, c.up);
    m.projection = glm::perspective(glm::radians(c.fovYDegrees), float(width) / float(height), c.nearPlane, c.farPlane);
    m.viewProjection = m.projection * m.view;
    m.inverseViewProjection = glm::inverse(m.viewProjection);
    return m;
}

glm::vec3 unprojectPixel(const CameraMatrices& m, int x, int y, float depth) {
    const glm::vec4 ndc((x + 0.5f) / m.width * 2.0f - 1.0f, 1.0f - (y + 0.5f) / m.height * 2.0f, depth * 2.0f - 1.0f,
                        1.0f);
    const glm::dvec4 world = glm::dmat4(m.inverseViewProjection) * glm::dvec4(ndc);
    return glm::vec3(world / world.w);
}

bool sphereMayBeVisible(const CameraMatrices& m, const glm::vec3& center, float radius) {
    const glm::mat4 t = glm::transpose(m.viewProjection);  // rows of the view-projection matrix
    const glm::vec4 planes[6] = {t[3] + t[0], t[3] - t[0], t[3] + t[1], t[3] - t[1], t[3] + t[2], t[3] - t[2]};
    for (const glm::vec4& p : planes) {
        const float len = glm::length(glm::vec3(p));
        if ((glm::dot(glm::vec3(p), center) + p.w) / len < -radius) return false;
    }
    return true;
}

Camera cameraFramingBounds(const glm::vec3& boundsMin, const glm::vec3& boundsMax, float fovYDegrees) {
    const glm::vec3 center = 0.5f * (boundsMin + boundsMax);
    // A flat or point-like scene still gets a view of positive size.
    const float radius = std::max(0.5f * glm::length(boundsMax - boundsMin), 1e-3f);
    const float distance = 1.1f * radius / std::sin(glm::radians(0.5f * fovYDegrees));
    Camera camera;
    camera.fovYDegrees = fovYDegrees;
    camera.target = center;
    camera.position = center + distance * glm::normalize(glm::vec3(0.0f, 0.5f, 1.0f));
    camera.nearPlane = std::max(0.5f * (distance - radius), 1e-3f * distance);
    camera.farPlane = distance + 2.0f * radius;
    return camera;
}

}  // namespace lidr
