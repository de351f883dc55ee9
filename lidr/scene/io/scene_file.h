#pragma once
// lidr's own JSON scene files (format: doc/scene-format.md). Every problem is an lidr::Error naming the file and
// the field.
#include <string>

#include "lidr/scene/scene.h"

namespace lidr {

// Loads a JSON scene file. Relative model and texture paths resolve against the file's folder. The result is
// validated (Scene::validate).
Scene loadSceneFile(const std::string& path);
Scene parseSceneJson(const std::string& jsonText, const std::string& baseDir, const std::string& nameForErrors);

}  // namespace lidr
