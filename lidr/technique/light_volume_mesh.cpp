#include "lidr/technique/light_volume_mesh.h"

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

}  // namespace lidr
