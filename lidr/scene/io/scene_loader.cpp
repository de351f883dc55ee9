#include "lidr/scene/io/scene_loader.h"

#include <algorithm>
#include <filesystem>

#include "lidr/base/error.h"
#include "lidr/scene/camera.h"
#include "lidr/scene/io/aff_importer.h"
#include "lidr/scene/io/file_checks.h"

namespace lidr {

Scene loadScene(const std::string& path, const ObjImportOptions& objDefaults) {
    const std::string extension = lowerCaseExtension(path);
    const std::string format = unsupportedModelFormat(path);
    if (!format.empty())
        throw Error(path + ": format not supported (" + format + "); lidr reads .json scene files, glTF (.gltf, .glb) "
                    "and OBJ (.obj) models, and BART's AFF scenes (.aff, .nff)");
    if (extension == ".aff" || extension == ".nff") {
        Scene scene = loadAff(path);
        try {
            scene.validate();
        } catch (const Error& error) {
            throw Error(path + ": " + error.what());
        }
        return scene;
    }
    if (extension != ".obj" && extension != ".gltf" && extension != ".glb") return loadSceneFile(path, objDefaults);
    Scene scene;
    scene.name = std::filesystem::path(path).stem().string();
    if (extension == ".obj") {
        appendObj(scene, path, glm::mat4(1.0f), -1, objDefaults);
    } else {
        const GltfContents contents = appendGltf(scene, path, glm::mat4(1.0f));
        scene.views = contents.views;
        scene.view = contents.firstView;
        scene.animation.viewNodes = contents.viewNodes;
        finishGltfViews(scene);
    }
    if (scene.view >= 0) {
        scene.camera = scene.views[size_t(scene.view)].camera;
        if (size_t(scene.view) < scene.animation.viewNodes.size())
            scene.animation.cameraNode = scene.animation.viewNodes[size_t(scene.view)];
    } else {
        scene.camera = cameraFramingBounds(scene.boundsMin(), scene.boundsMax(), scene.camera.fovYDegrees);
    }
    if (!scene.animation.empty()) poseScene(scene, scene.time);  // built in the rest pose
    try {
        scene.validate();
    } catch (const Error& error) {
        throw Error(path + ": " + error.what());
    }
    return scene;
}

void chooseView(Scene& scene, int index) {
    const size_t count = scene.views.size();
    if (index < 0 || size_t(index) >= count) {
        const std::string range = count == 0 ? "no cameras (only a glTF model's cameras can be chosen)"
                                  : count == 1 ? "1 camera (0; its glTF models' cameras in their order)"
                                               : std::to_string(count) + " cameras (0 .. " + std::to_string(count - 1) +
                                                     "; its glTF models' cameras in their order)";
        throw Error("camera " + std::to_string(index) + " is out of range: the scene has " + range);
    }
    const SceneView& view = scene.views[size_t(index)];
    if (!view.unusable.empty()) throw Error(view.name + " cannot be the view: " + view.unusable);
    scene.camera = view.camera;
    scene.view = index;
    // A camera on an animated node rides on it (its view holds its rest pose).
    SceneAnimation& a = scene.animation;
    a.cameraNode = size_t(index) < a.viewNodes.size() ? a.viewNodes[size_t(index)] : -1;
    if (a.cameraNode >= 0) {
        const float time = scene.time;
        const std::vector<glm::mat4> posed = a.posedWorld;
        a.posedWorld = a.worldAt(time);  // the camera from its node at the scene's time; the geometry stays posed
        scene.camera = cameraAt(scene, time);
        a.posedWorld = posed;
    }
}

}  // namespace lidr
