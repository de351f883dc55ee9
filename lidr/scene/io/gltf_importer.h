#pragma once
// glTF 2.0 models (.gltf with external or embedded buffers, .glb) through tinygltf. Every problem is an lidr::Error
// naming the file; what is read but cannot be drawn as asked (spot and directional lights, MASK alpha, ...) is a
// warning on the Scene. What is read and how: doc/scene-format.md, "glTF".
#include <string>

#include <glm/glm.hpp>

#include "lidr/scene/scene.h"

namespace lidr {

struct GltfContents {
    bool hasCamera = false;  // the file has a perspective camera: `camera` is the first one (in node order)
    Camera camera;
    size_t lights = 0;       // point lights appended
};

// Appends the glTF file's triangles (node transforms, then `transform`, baked into world space), its materials
// and its KHR_lights_punctual point lights to `scene`. `overrideMaterial` >= 0 replaces the file's materials
// with that scene material.
GltfContents appendGltf(Scene& scene, const std::string& path, const glm::mat4& transform, int overrideMaterial = -1);

// The radius lidr gives a glTF point light without a range: where inverse-square falloff of its brightest
// channel (colour x intensity) falls below 1/256 of full brightness, sqrt(256 x brightest), clamped to
// [0.01, 1000] m.
float gltfLightRadiusWithoutRange(float brightestChannel);

}  // namespace lidr
