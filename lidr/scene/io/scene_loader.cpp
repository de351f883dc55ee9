#include "lidr/scene/io/scene_loader.h"

#include <filesystem>

#include "lidr/base/error.h"
#include "lidr/scene/camera.h"
#include "lidr/scene/io/file_checks.h"

namespace lidr {

Scene loadScene(const std::string& path) {
    const std::string extension = lowerCaseExtension(path);
    if (extension == ".json") return loadSceneFile(path);
    if (extension == ".obj") {
        Scene scene;
        scene.name = std::filesystem::path(path).stem().string();
        appendObj(scene, path, glm::mat4(1.0f));
        scene.camera = cameraFramingBounds(scene.boundsMin(), scene.boundsMax(), scene.camera.fovYDegrees);
        try {
            scene.validate();
        } catch (const Error& error) {
            throw Error(path + ": " + error.what());
        }
        return scene;
    }
    throw Error(path + ": unknown scene file type '" + extension + "' (supported: .json scene files, .obj models)");
}

}  // namespace lidr
