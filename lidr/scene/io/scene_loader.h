#pragma once
// Scenes from files: the one entry point, loadScene(path), picks the reader by the file's extension. Every
// problem in a file is an lidr::Error naming the file (and, for scene files, the field).
#include <string>

#include "lidr/scene/scene.h"
#include "lidr/scene/io/gltf_importer.h"  // appendGltf
#include "lidr/scene/io/obj_importer.h"   // appendObj
#include "lidr/scene/io/scene_file.h"     // loadSceneFile, parseSceneJson

namespace lidr {

// .gltf / .glb: the glTF model with its lights, seen by its first camera in node order that lidr can draw (a
// perspective one), else by the default view that frames its bounds (cameraFramingBounds); Scene::views lists
// every camera of the file. .obj: the model alone, no lights, seen by that default view. .aff / .nff: a BART scene
// (aff_importer.h) with its camera, lights and keyframe animation, posed at its start.
// Other model formats (.ply, .fbx, ...) are errors naming the format; anything else is read as a lidr JSON scene
// file (doc/scene-format.md; usually .json). Extensions are matched without regard to case. The result is
// validated (Scene::validate).
// `objDefaults` (smooth normals) applies to an .obj file, and to a scene file's OBJ models that do not say
// otherwise.
Scene loadScene(const std::string& path, const ObjImportOptions& objDefaults = {});

// Makes scene.views[index] (a glTF file's camera `index`, counted as in its `cameras` array; in a scene file, its
// glTF models' cameras in model order) the scene's camera.
// Throws lidr::Error naming how many cameras the scene has where `index` is out of range, or why that camera
// cannot be drawn (orthographic; placed by no node).
void chooseView(Scene& scene, int index);

}  // namespace lidr
