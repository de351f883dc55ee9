#include "lidr/scene/io/scene_loader.h"

#include <algorithm>
#include <filesystem>

#include "lidr/base/error.h"
#include "lidr/scene/camera.h"
#include "lidr/scene/io/file_checks.h"

namespace lidr {

namespace {

// A glTF camera without zfar (infinite) gets a far plane past the farthest corner of the scene's bounds.
float farPlaneEnclosing(const Camera& camera, const glm::vec3& boundsMin, const glm::vec3& boundsMax) {
    float farthest = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? boundsMax.x : boundsMin.x, (corner & 2) ? boundsMax.y : boundsMin.y,
                          (corner & 4) ? boundsMax.z : boundsMin.z);
        farthest = std::max(farthest, glm::length(p - camera.position));
    }
    return std::max(1.5f * farthest, 2.0f * camera.nearPlane);
}

}  // namespace

Scene loadScene(const std::string& path, const ObjImportOptions& objDefaults) {
    const std::string extension = lowerCaseExtension(path);
    const std::string format = unsupportedModelFormat(path);
    if (!format.empty())
        throw Error(path + ": format not supported (" + format + "); lidr reads .json scene files, glTF (.gltf, .glb) "
                    "and OBJ (.obj) models");
    if (extension != ".obj" && extension != ".gltf" && extension != ".glb") return loadSceneFile(path, objDefaults);
    Scene scene;
    scene.name = std::filesystem::path(path).stem().string();
    bool hasCamera = false;
    if (extension == ".obj") {
        appendObj(scene, path, glm::mat4(1.0f), -1, objDefaults);
    } else {
        const GltfContents contents = appendGltf(scene, path, glm::mat4(1.0f));
        hasCamera = contents.hasCamera;
        scene.camera = contents.camera;
    }
    if (!hasCamera) {
        scene.camera = cameraFramingBounds(scene.boundsMin(), scene.boundsMax(), scene.camera.fovYDegrees);
    } else if (!(scene.camera.farPlane > 0.0f)) {
        scene.camera.farPlane = farPlaneEnclosing(scene.camera, scene.boundsMin(), scene.boundsMax());
    }
    try {
        scene.validate();
    } catch (const Error& error) {
        throw Error(path + ": " + error.what());
    }
    return scene;
}

}  // namespace lidr
