#pragma once
// Scene files (JSON) and OBJ models. Every problem in a file is an lidr::Error naming the file and field.
#include <string>

#include "lidr/scene/scene.h"

namespace lidr {

// Loads a JSON scene file (format: doc/scene-format.md). Relative model and texture paths resolve against
// the file's folder. The result is validated (Scene::validate).
Scene loadSceneFile(const std::string& path);
Scene parseSceneJson(const std::string& jsonText, const std::string& baseDir, const std::string& nameForErrors);

// Appends the OBJ file's triangles (with its .mtl materials) to `scene`, transformed by `transform`.
// `overrideMaterial` >= 0 replaces the file's materials with that scene material.
void appendObj(Scene& scene, const std::string& objPath, const glm::mat4& transform, int overrideMaterial = -1);

}  // namespace lidr
