#include "lidr/render/shadow_lookup.h"

#include <algorithm>
#include <cmath>

namespace lidr {

ShadowMapCoord shadowMapCoord(const PointLight& light, int firstTile, const glm::vec3& point) {
    ShadowMapCoord c;
    const glm::vec3 w = point - light.position;
    c.tile = firstTile;
    if (light.isSpot()) {
        const glm::vec3 forward = glm::normalize(light.direction);
        const float cosOuter = std::clamp(std::cos(light.outerConeAngle), 1e-4f, 1.0f);
        c.tanHalfFov = std::sqrt(std::max(1.0f - cosOuter * cosOuter, 0.0f)) / cosOuter;
        glm::vec3 up = std::abs(forward.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
        const glm::vec3 right = glm::normalize(glm::cross(forward, up));
        up = glm::cross(right, forward);
        c.viewDepth = glm::dot(w, forward);
        if (c.viewDepth <= 0.0f) return c;
        c.ndc = glm::vec2(glm::dot(w, right), glm::dot(w, up)) / (c.viewDepth * c.tanHalfFov);
        if (std::abs(c.ndc.x) > 1.0f || std::abs(c.ndc.y) > 1.0f) return c;
    } else {
        const glm::vec3 a = glm::abs(w);
        glm::vec2 st;
        if (a.x >= a.y && a.x >= a.z) {
            c.viewDepth = a.x;
            c.tile += w.x > 0.0f ? 0 : 1;
            st = glm::vec2(w.x > 0.0f ? -w.z : w.z, -w.y);
        } else if (a.y >= a.z) {
            c.viewDepth = a.y;
            c.tile += w.y > 0.0f ? 2 : 3;
            st = glm::vec2(w.x, w.y > 0.0f ? w.z : -w.z);
        } else {
            c.viewDepth = a.z;
            c.tile += w.z > 0.0f ? 4 : 5;
            st = glm::vec2(w.z > 0.0f ? w.x : -w.x, -w.y);
        }
        if (c.viewDepth <= 0.0f) return c;
        c.ndc = st / c.viewDepth;
    }
    const float f = std::abs(light.radius), n = f * 0.01f;
    c.windowDepth = (c.viewDepth - n) * f / ((f - n) * c.viewDepth);
    c.seen = true;
    return c;
}

}  // namespace lidr
