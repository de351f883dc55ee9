#pragma once
// lidr's own JSON scene files (format: doc/scene-format.md). Every problem is an lidr::Error naming the file and
// the field.
#include <string>

#include "lidr/scene/scene.h"
#include "lidr/scene/io/obj_importer.h"

namespace lidr {

// Loads a JSON scene file. Relative model and texture paths resolve against the file's folder. The result is
// validated (Scene::validate).
// `objDefaults` applies to every OBJ model whose entry does not say otherwise (its "smooth_normals").
Scene loadSceneFile(const std::string& path, const ObjImportOptions& objDefaults = {});
Scene parseSceneJson(const std::string& jsonText, const std::string& baseDir, const std::string& nameForErrors,
                     const ObjImportOptions& objDefaults = {});

}  // namespace lidr
