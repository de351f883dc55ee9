#pragma once
// Tangents for normal textures where a file has none (glTF without TANGENT, OBJ): per triangle from the
// derivatives of its texture coordinates, accumulated per vertex and made orthogonal to the vertex normal.
// Not MikkTSpace (no Debian package has it): where a file's normal texture was baked against MikkTSpace tangents,
// vertices shared by triangles whose UV directions differ (seams, strongly distorted UVs) can get a slightly
// different frame (doc/scene-format.md, "Materials").
#include <vector>

#include <glm/glm.hpp>

#include "lidr/scene/scene.h"

namespace lidr {

// One tangent per position of `mesh` (xyz unit, along +u of texture coordinate set `texCoordSet` (0 or 1, set 1
// falling back to 0 where the mesh has none); w = +1 or -1, the side of cross(normal, tangent) that +v is on).
// Vertices whose triangles have no usable UV derivative (no texture coordinates, degenerate UVs) get any unit
// vector perpendicular to the normal, w = +1.
std::vector<glm::vec4> generateTangents(const Mesh& mesh, int texCoordSet);

}  // namespace lidr
