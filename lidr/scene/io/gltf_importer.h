#pragma once
// glTF 2.0 models (.gltf with external or embedded buffers, .glb) through tinygltf. Every problem is an lidr::Error
// naming the file; what is read but cannot be drawn as asked (spot and directional lights, MASK alpha, ...) is a
// warning on the Scene. What is read and how: doc/scene-format.md, "glTF".
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "lidr/scene/scene.h"

namespace lidr {

struct GltfContents {
    // Every camera of the file, by its index in `cameras` (SceneView), placed by the node's world transform
    // (`transform` included); farPlane 0 where the file gives no zfar (infinite): finishGltfViews sets it.
    std::vector<SceneView> views;
    int firstView = -1;      // the first usable camera met in node order (the default view); -1: none
    size_t lights = 0;       // point lights appended
    // Per view, the node of Scene::animation that places it (-1: none); empty where the file moves nothing.
    std::vector<int> viewNodes;
};

// Appends the glTF file's triangles (node transforms, then `transform`, baked into world space), its materials
// and its KHR_lights_punctual point lights to `scene`. A file with animations adds its nodes to Scene::animation
// (gltf_animation.h), posed at rest: the caller poses the scene at its time (poseScene) once everything is loaded. `overrideMaterial` >= 0 replaces the file's materials
// with that scene material.
GltfContents appendGltf(Scene& scene, const std::string& path, const glm::mat4& transform, int overrideMaterial = -1);

// Once the whole scene is loaded: every usable view without a zfar gets a far plane past the farthest corner of
// the scene's bounds.
void finishGltfViews(Scene& scene);

// A glTF light without `range` has infinite range; lidr's lights need a finite volume. It gets the range r
// where it stops being visible: with the specification's window over r it differs from the infinite light by
// less than gltfLightCutThreshold everywhere (at most C / r^2 for C its brightest channel, lidr's colour =
// colour x intensity / pi), the linear value of half an 8-bit step of the sRGB-encoded image at exposure 0 on a
// white Lambert surface facing the light: 0.5 / 255 / 12.92, the sRGB curve's steepest slope (at black; the
// pbr-neutral and none tone maps have slope <= 1). r = sqrt(C / threshold) clamped to [0.01, 1000] m (past
// about 480 cd the cut at 1000 m is visible). doc/colour.md, "glTF lights".
constexpr float gltfLightCutThreshold = 0.5f / 255.0f / 12.92f;
constexpr float gltfLightMinRadius = 0.01f, gltfLightMaxRadius = 1000.0f;
float gltfLightRadiusWithoutRange(float brightestChannel);

}  // namespace lidr
