// lidr-viewer's files: a scene file dropped on the window (or named by the script's drop action) replaces the
// scene, F5 reads the current file again, and the panel's file section shows the file, its warnings and its
// lights, with a slider that scatters more lights over it (lidr::scatterLights). A file that cannot be read or
// rendered leaves the current scene as it was, with the reason in the status line.
#include "lidr/base/gl.h"  // GLEW before anything that includes GL/gl.h (GLFW does)

#include "viewer.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "lidr/render/material_variants.h"
#include "lidr/scene/light_scatter.h"
#include "viewer_internal.h"

namespace lidr::viewer {

void dropCallback(GLFWwindow* w, int count, const char** paths) {
    if (auto* v = static_cast<Viewer*>(glfwGetWindowUserPointer(w)))
        v->onDrop(std::vector<std::string>(paths, paths + count));
}

void Viewer::onDrop(const std::vector<std::string>& paths) {
    if (paths.empty()) return;
    // Several files at once (a .gltf with its .bin and images, say): the scene is the first glTF or scene file;
    // the others are read by it, if it names them.
    auto isScene = [](const std::string& p) {
        std::string ext = std::filesystem::path(p).extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        return ext == ".gltf" || ext == ".glb" || ext == ".obj" || ext == ".json" || ext == ".aff";
    };
    const auto it = std::find_if(paths.begin(), paths.end(), isScene);
    pendingOpen_ = it != paths.end() ? *it : paths.front();
    std::cout << "lidr-viewer: dropped " << paths.size() << " file(s), opening " << *pendingOpen_ << std::endl;
}

void Viewer::openPendingFile() {
    if (!pendingOpen_) return;
    const std::string path = *pendingOpen_;
    pendingOpen_.reset();
    openScene(path, "open " + path, false);
}

void Viewer::scatterOver(int count) {
    Scene next = fileScene_;
    if (count > 0) {
        LightScatterOptions o;
        o.count = count;
        addScatteredLights(next, o);
    }
    scene_ = std::move(next);
    scatteredLights_ = count;
}

void Viewer::addTextureUnitWarnings() {
    for (const std::string& w : textureUnitWarnings(fileScene_, context_->info().maxTextureUnits))
        fileScene_.warnings.push_back(w);
}

bool Viewer::openScene(const std::string& path, const std::string& what, bool keepCamera) {
    demo::SceneChoice choice = sceneChoice_;
    if (path != choice.sceneFile) choice.camera.reset();  // --camera N was the first file's; a reload keeps it
    choice.sceneFile = path;
    Scene loaded;
    try {
        loaded = choice.load();
    } catch (const std::exception& e) {
        status_ = what + " refused: " + e.what();
        lastRefused_ = true;
        std::cerr << "lidr-viewer: " << status_ << std::endl;
        return false;
    }
    // Everything a failed renderer build must put back.
    Scene oldFile = std::move(fileScene_), oldScene = std::move(scene_);
    const std::string oldPath = scenePath_;
    const int oldScattered = scatteredLights_, oldCount = lightCount_;
    const FlyCamera oldCamera = camera_;
    const float oldTime = animTime_, oldSpeed = moveSpeed_;
    const bool oldFollow = followSceneCamera_;
    const ShadingParameters oldShading = shading_;

    fileScene_ = std::move(loaded);
    addTextureUnitWarnings();
    scenePath_ = path;
    // The slider's scattered lights stay, within what the new scene can hold (none over a scene without triangles).
    const int room = int(maxSceneLights) - int(fileScene_.lights.size());
    try {
        scatterOver(std::min(oldScattered, room));
    } catch (const Error&) {
        scatterOver(0);
    }
    lightCount_ = int(scene_.lights.size());
    shading_ = sceneShading(scene_);
    if (!keepCamera) {
        camera_.reset(scene_.camera);
        followSceneCamera_ = scene_.animation.cameraNode >= 0;
        animTime_ = scene_.time;
        moveSpeed_ = std::max(0.5f, 0.15f * glm::length(scene_.boundsMax() - scene_.boundsMin()));
    }
    if (apply(rc_, what)) {
        sceneChoice_ = choice;
        for (const std::string& w : fileScene_.warnings) std::cout << "lidr-viewer: warning: " << w << std::endl;
        return true;
    }
    const std::string refused = status_;
    fileScene_ = std::move(oldFile);
    scene_ = std::move(oldScene);
    scenePath_ = oldPath;
    scatteredLights_ = oldScattered;
    lightCount_ = oldCount;
    camera_ = oldCamera;
    animTime_ = oldTime;
    followSceneCamera_ = oldFollow;
    moveSpeed_ = oldSpeed;
    shading_ = oldShading;
    apply(rc_, "the previous scene");  // was rendering a frame ago
    status_ = refused + " (kept " + (scenePath_.empty() ? std::string("the built-in room") : scenePath_) + ")";
    lastRefused_ = true;
    return false;
}

void Viewer::reloadScene() {
    if (scenePath_.empty()) {
        status_ = "reload: the built-in room has no file (drop one on the window)";
        lastRefused_ = true;
        return;
    }
    openScene(scenePath_, "reload " + scenePath_, true);
}

void Viewer::uiFile() {
    ImGui::TextWrapped("%s", scenePath_.empty() ? "built-in room: drop a .glb, .gltf, .obj, .aff or scene .json here"
                                                : scenePath_.c_str());
    if (ImGui::Button("reload (F5)")) reloadScene();
    ImGui::SameLine();
    ImGui::Text("%s, %zu meshes", scene_.name.c_str(), scene_.meshes.size());
    ImGui::Text("%d lights: %d from the file, %d scattered", int(scene_.lights.size()), int(fileScene_.lights.size()),
                scatteredLights_);
    // Each count is a new scene and renderer: applied when the slider is let go, not at every step of a drag.
    if (!scatterDragged_) scatterDraft_ = scatteredLights_;  // follows the script, reloads and refusals
    const int room = int(maxSceneLights) - int(fileScene_.lights.size());
    ImGui::SliderInt("scatter lights", &scatterDraft_, 0, std::min(room, 16384), "%d", ImGuiSliderFlags_Logarithmic);
    scatterDragged_ = ImGui::IsItemActive();
    const bool released = ImGui::IsItemDeactivatedAfterEdit();
    if (released && scatterDraft_ != scatteredLights_) {
        try {
            changeSetting("scatter", std::to_string(scatterDraft_));
        } catch (const Error& e) {
            status_ = e.what();
            lastRefused_ = true;
        }
    }
    if (!fileScene_.warnings.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.35f, 1.0f));
        const size_t shown = std::min<size_t>(fileScene_.warnings.size(), 6);
        ImGui::Text("%zu warning(s):", fileScene_.warnings.size());
        for (size_t i = 0; i < shown; ++i) ImGui::TextWrapped("%s", fileScene_.warnings[i].c_str());
        if (shown < fileScene_.warnings.size())
            ImGui::Text("... %zu more (printed on the terminal)", fileScene_.warnings.size() - shown);
        ImGui::PopStyleColor();
    }
}

}  // namespace lidr::viewer
