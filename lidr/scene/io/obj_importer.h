#pragma once
// Wavefront OBJ models with their MTL materials. Every problem is an lidr::Error naming the file.
#include <string>

#include <glm/glm.hpp>

#include "lidr/scene/scene.h"

namespace lidr {

struct ObjImportOptions {
    // Faces without `vn` normals get smooth normals (averaged over the faces sharing a position, weighted by
    // corner angle) whatever their smoothing group, as if every face were in `s 1`.
    bool smoothNormals = false;
};

// Appends the OBJ file's triangles (with its .mtl materials) to `scene`, transformed by `transform`: one mesh
// per group or object (`g`, `o`) and material, meshes above maxTrianglesPerImportedMesh split spatially.
// `overrideMaterial` >= 0 replaces the file's materials with that scene material. What the file asks for but
// cannot be drawn as asked (a missing .mtl, an unknown `usemtl`, `d 0`, an unsupported `illum`) is a warning on
// the scene (Scene::warnings), not an error.
void appendObj(Scene& scene, const std::string& objPath, const glm::mat4& transform, int overrideMaterial = -1,
               const ObjImportOptions& options = {});

}  // namespace lidr
