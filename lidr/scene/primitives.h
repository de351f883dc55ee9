#pragma once
// Procedural meshes appended to a Scene in world space: the default room and the test scenes are built
// from these, and scene files can ask for them ("primitives" in doc/scene-format.md).
#include <glm/glm.hpp>

#include "lidr/scene/scene.h"

namespace lidr {

// Axis-aligned box; each face split into subdivisions x subdivisions quads; outward normals.
void addBox(Scene& scene, const glm::vec3& min, const glm::vec3& max, int material, int subdivisions = 1);
// Horizontal plane (normal +y) centred at `center`, size.x by size.y, subdivisions per side.
void addPlane(Scene& scene, const glm::vec3& center, const glm::vec2& size, int material, int subdivisions = 1);
// UV sphere.
void addSphere(Scene& scene, const glm::vec3& center, float radius, int material, int segments = 16);
// Vertical cylinder standing on `base`, with caps.
void addCylinder(Scene& scene, const glm::vec3& base, float radius, float height, int material, int segments = 16);
// Torus lying in the xz plane.
void addTorus(Scene& scene, const glm::vec3& center, float majorRadius, float minorRadius, int material,
              int majorSegments = 24, int minorSegments = 12);

}  // namespace lidr
