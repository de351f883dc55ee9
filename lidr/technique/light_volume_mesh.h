#pragma once
// The light volume: a geodesic sphere scaled so that it CONTAINS the unit sphere. A mesh whose vertices lie
// on the sphere is inscribed: its faces cut inside the true radius and miss lit pixels near the edge.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace lidr {

struct LightVolumeMesh {
    std::vector<glm::vec3> positions;
    std::vector<uint16_t> indices;  // CCW seen from outside
    float insideRadius = 0.0f;      // smallest distance from the centre to a face plane (>= 1)
    float outsideRadius = 0.0f;     // largest vertex distance (for far-plane checks)
};

// subdivisions: 0 = icosahedron (20 faces), 1 = 80, 2 = 320. `margin` is the relative clearance kept
// between the unit sphere and the closest face (protects against rounding in transform and raster).
LightVolumeMesh makeLightVolumeMesh(int subdivisions = 2, float margin = 1e-3f);

}  // namespace lidr
