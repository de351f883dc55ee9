#pragma once
// Wavefront OBJ models with their MTL materials. Every problem is an lidr::Error naming the file.
#include <string>

#include <glm/glm.hpp>

#include "lidr/scene/scene.h"

namespace lidr {

// Appends the OBJ file's triangles (with its .mtl materials) to `scene`, transformed by `transform`.
// `overrideMaterial` >= 0 replaces the file's materials with that scene material.
void appendObj(Scene& scene, const std::string& objPath, const glm::mat4& transform, int overrideMaterial = -1);

}  // namespace lidr
