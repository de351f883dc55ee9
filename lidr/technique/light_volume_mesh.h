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

// A spot light's volume for the stencil tests and the front-face lists: a closed, convex cone from the apex,
// capped by a spherical cap (so wide cones, up to 180 degrees in all, stay bounded), that ENCLOSES the spot's
// range-capped cone. One mesh serves every cone: a vertex is (cos a, sin a, f), a the angle around the axis and f
// the polar angle as a fraction of the rim's (f < 0: the apex); spotVolumeVertex (and light_volume.vert) place it.
// kSpotVolumeSegments around the axis, kSpotVolumeRings rings of the cap from the pole to the rim.
constexpr int kSpotVolumeSegments = 16, kSpotVolumeRings = 4;
LightVolumeMesh makeSpotVolumeMesh();

// How a spot light of this outer cone angle (radians, (0, pi/2]) is drawn with that mesh: the rim's polar angle
// (the side faces, planes through the apex, touch the cone widened to spotBoundingConeAngle, which covers the
// fixed-point light table's 16-bit cosines) and the cap's radius relative to the range (its nearest face plane at
// 1 + margin).
struct SpotVolumeShape {
    float rimAngle = 0.0f;
    float capScale = 1.0f;
};
SpotVolumeShape spotVolumeShape(float outerConeAngle, float margin = 1e-3f);
// A mesh vertex of makeSpotVolumeMesh for a unit range along +z (the shader's mapping, on the CPU).
glm::vec3 spotVolumeVertex(const glm::vec3& meshVertex, const SpotVolumeShape& shape);

}  // namespace lidr
