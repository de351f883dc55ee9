#pragma once
// Large meshes split into spatially compact parts, so per-mesh culling (multi-pass forward's light culling,
// the transparent-volume scissor) has pieces to skip. Importers call it on every mesh they make.
#include <cstddef>
#include <vector>

#include "lidr/scene/scene.h"

namespace lidr {

// Meshes above this many triangles are split (doc/scene-format.md, "Large meshes").
constexpr size_t maxTrianglesPerImportedMesh = 16384;

// `mesh` itself when it has at most maxTriangles triangles; else parts of at most maxTriangles triangles each,
// split recursively at the median triangle centroid along the longest axis of the centroids' bounds. Parts are
// named "<name>#<k>" (k from 0), keep the material, and hold only the vertices their triangles use. Every
// triangle lands in exactly one part, with its corners in the same order.
std::vector<Mesh> splitMeshSpatially(Mesh mesh, size_t maxTriangles = maxTrianglesPerImportedMesh);

}  // namespace lidr
