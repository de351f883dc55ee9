#include "lidr/technique/light_volume_mesh.h"

#include "lidr/scene/sphere_bounds.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace lidr {

LightVolumeMesh makeLightVolumeMesh(int subdivisions, float margin) {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<glm::vec3> v = {{-1, t, 0}, {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (auto& p : v) p = glm::normalize(p);
    std::vector<uint16_t> f = {0, 11, 5, 0, 5,  1,  0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                               4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                               6, 8,  3, 8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<uint16_t, uint16_t>, uint16_t> midpoints;
        auto mid = [&](uint16_t a, uint16_t b) {
            auto key = std::minmax(a, b);
            auto it = midpoints.find(key);
            if (it != midpoints.end()) return it->second;
            v.push_back(glm::normalize(v[a] + v[b]));
            const auto i = static_cast<uint16_t>(v.size() - 1);
            midpoints.emplace(key, i);
            return i;
        };
        std::vector<uint16_t> next;
        for (size_t i = 0; i < f.size(); i += 3) {
            const uint16_t a = f[i], b = f[i + 1], c = f[i + 2];
            const uint16_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        f = std::move(next);
    }
    // Scale so the nearest face plane sits at 1 + margin from the centre: then the mesh contains the sphere.
    float nearestFace = 1.0f;
    for (size_t i = 0; i < f.size(); i += 3) {
        const glm::vec3 n = glm::normalize(glm::cross(v[f[i + 1]] - v[f[i]], v[f[i + 2]] - v[f[i]]));
        nearestFace = std::min(nearestFace, std::abs(glm::dot(n, v[f[i]])));
    }
    const float scale = (1.0f + margin) / nearestFace;
    LightVolumeMesh m;
    for (auto& p : v) m.positions.push_back(p * scale);
    m.indices = std::move(f);
    m.insideRadius = 1.0f + margin;
    m.outsideRadius = scale;
    return m;
}

LightVolumeMesh makeSpotVolumeMesh() {
    constexpr int n = kSpotVolumeSegments, rings = kSpotVolumeRings;
    constexpr float kPi = 3.14159265358979f;
    LightVolumeMesh m;
    m.positions.push_back({0.0f, 0.0f, -1.0f});  // 0: the apex
    m.positions.push_back({0.0f, 0.0f, 0.0f});   // 1: the cap's pole, on the axis
    const auto ringVertex = [](int ring, int i) { return uint16_t(2 + (ring - 1) * n + (i % n)); };
    for (int ring = 1; ring <= rings; ++ring)
        for (int i = 0; i < n; ++i) {
            const float a = 2.0f * kPi * float(i) / float(n);
            m.positions.push_back({std::cos(a), std::sin(a), float(ring) / float(rings)});
        }
    // Counter-clockwise seen from outside (the axis is +z, the angle a grows counter-clockwise seen from +z).
    for (int i = 0; i < n; ++i) {
        m.indices.insert(m.indices.end(), {1, ringVertex(1, i), ringVertex(1, i + 1)});  // the cap's pole fan
        for (int ring = 1; ring < rings; ++ring) {
            const uint16_t a = ringVertex(ring, i), b = ringVertex(ring + 1, i), c = ringVertex(ring + 1, i + 1),
                           d = ringVertex(ring, i + 1);
            m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
        }
        m.indices.insert(m.indices.end(), {0, ringVertex(rings, i + 1), ringVertex(rings, i)});  // the side
    }
    m.insideRadius = 0.0f;  // the apex is a vertex: no sphere around it fits inside
    m.outsideRadius = 1.0f; // per cone: spotVolumeShape().capScale
    return m;
}

glm::vec3 spotVolumeVertex(const glm::vec3& v, const SpotVolumeShape& shape) {
    if (v.z < 0.0f) return glm::vec3(0.0f);
    const float polar = v.z * shape.rimAngle;
    return shape.capScale * glm::vec3(std::sin(polar) * v.x, std::sin(polar) * v.y, std::cos(polar));
}

SpotVolumeShape spotVolumeShape(float outerConeAngle, float margin) {
    constexpr float kHalfPi = 1.57079632679f;
    constexpr double kPi = 3.14159265358979;
    SpotVolumeShape shape;
    const double widest = spotBoundingConeAngle(outerConeAngle);  // the widest cone the shading may light
    // A side face's plane touches the cone at the middle of its rim edge, cos(pi / n) of the rim's radius off the
    // axis: tan(rim) x cos(pi / n) = tan(widest). A right angle stays one (the side is then the apex's plane).
    const double rim = widest >= double(kHalfPi) - 1e-7 ? double(kHalfPi)
                                                         : std::atan(std::tan(widest) / std::cos(kPi / kSpotVolumeSegments));
    shape.rimAngle = float(std::min(rim, double(kHalfPi)));
    // The cap's faces at unit radius: every face of a ring is the same up to a turn, so one quad (two triangles)
    // per ring and the pole's triangle give the nearest face plane; the cap is scaled to put it at 1 + margin.
    shape.capScale = 1.0f;
    double nearest = 1.0;
    const auto at = [&](int ring, int i) {
        const double a = 2.0 * kPi * i / kSpotVolumeSegments, polar = double(shape.rimAngle) * ring / kSpotVolumeRings;
        return glm::dvec3(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), std::cos(polar));
    };
    const auto planeDistance = [](const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& r) {
        const glm::dvec3 normal = glm::cross(q - p, r - p);
        const double length = glm::length(normal);
        return length > 0.0 ? std::abs(glm::dot(normal, p)) / length : 1.0;  // a degenerate face: no plane
    };
    nearest = std::min(nearest, planeDistance(at(0, 0), at(1, 0), at(1, 1)));
    for (int ring = 1; ring < kSpotVolumeRings; ++ring) {
        nearest = std::min(nearest, planeDistance(at(ring, 0), at(ring + 1, 0), at(ring + 1, 1)));
        nearest = std::min(nearest, planeDistance(at(ring, 0), at(ring + 1, 1), at(ring, 1)));
    }
    shape.capScale = float((1.0 + double(margin)) / nearest);
    return shape;
}

}  // namespace lidr
