#pragma once
// Scenes from files: the one entry point, loadScene(path), picks the reader by the file's extension. Every
// problem in a file is an lidr::Error naming the file (and, for scene files, the field).
#include <string>

#include "lidr/scene/scene.h"
#include "lidr/scene/io/obj_importer.h"  // appendObj
#include "lidr/scene/io/scene_file.h"    // loadSceneFile, parseSceneJson

namespace lidr {

// .json: a lidr scene file (doc/scene-format.md); .obj: the model alone, no lights, seen by the default view
// that frames its bounds (cameraFramingBounds). The extension is matched without regard to case; any other is
// an error naming the supported ones. The result is validated (Scene::validate).
Scene loadScene(const std::string& path);

}  // namespace lidr
