#pragma once
// Which side of a mesh can never be seen from outside it. A closed mesh (every edge, positions matched exactly,
// is shared by exactly two triangles that run along it in opposite directions) with a non-zero volume shows an eye
// outside it only the side its triangles wind towards the outside; the other side is always behind it. GpuScene
// culls that side of such meshes when the eye and the near plane are outside their bounds (back faces are half
// of a closed mesh's triangles; at a silhouette they tie with the front faces at coarse depth precision).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace lidr {

enum class OuterWinding {
    Open,              // not closed, not consistently wound, or no volume: both sides may be seen
    CounterClockwise,  // seen from outside, the triangles wind counter-clockwise (GL's front faces)
    Clockwise,         // seen from outside, they wind clockwise (the mesh is wound inside out)
};

// positions: the mesh's vertices; indices: triangles. Triangles with two corners at one position have no area
// and are left out. About linear in the triangle count (0.1-0.2 s for a million triangles on the 2-core VM).
OuterWinding closedMeshOuterWinding(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices);

}  // namespace lidr
