// The glTF importer's KHR_lights_punctual lights (point, spot, directional) and cameras.
#include "lidr/scene/io/gltf_importer_internal.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "lidr/base/colour.h"

namespace lidr::gltf_import {

// extras.lidr.shadow of a light or its node (the validator checked it is true or false); false where absent.
bool GltfReader::lidrShadowFlag(const tinygltf::Value& extras, bool& flag) {
    if (!extras.IsObject() || !extras.Has("lidr")) return false;
    const tinygltf::Value& lidr = extras.Get("lidr");
    if (!lidr.Has("shadow")) return false;
    flag = lidr.Get("shadow").Get<bool>();
    return true;
}

void GltfReader::readLight(const tinygltf::Value& value, const std::string& nodeName, const glm::mat4& world,
                           const tinygltf::Value& nodeExtras) {
    if (!value.IsNumber() && !value.IsInt()) fail(nodeName + ": KHR_lights_punctual light is not an index");
    const int lightIndex = value.GetNumberAsInt();
    if (lightIndex < 0 || size_t(lightIndex) >= model_.lights.size())
        fail(nodeName + ": light " + std::to_string(lightIndex) + " out of range (" + std::to_string(model_.lights.size()) +
             " lights)");
    const tinygltf::Light& source = model_.lights[size_t(lightIndex)];
    const std::string name = "light " + std::to_string(lightIndex) + (source.name.empty() ? "" : " '" + source.name + "'");
    if (source.type != "point" && source.type != "spot" && source.type != "directional") {
        warn(name + ": " + source.type + " lights are not supported (lidr draws point, spot and directional lights); left out");
        return;
    }
    // Candela (point, spot) or lux (directional) x colour, over pi: lidr's light colour is what a white
    // Lambert surface shows (it shades with BRDF x pi x colour), glTF's intensity is illuminance, of which
    // that surface reflects 1 / pi as luminance; a pixel is luminance x 2^exposure (doc/colour.md).
    glm::vec3 color(1.0f);
    for (size_t c = 0; c < 3 && c < source.color.size(); ++c) color[int(c)] = float(source.color[c]);
    color *= float(source.intensity / glm::pi<double>());
    if (!(isFinite(color) && color.r >= 0 && color.g >= 0 && color.b >= 0))
        fail(name + ": colour x intensity must be finite and >= 0, got " + str(color));
    if (source.type == "directional") {
        readDirectionalLight(name, nodeName, color, world);
        return;
    }
    PointLight light;
    light.color = color;
    light.falloff = LightFalloff::InverseSquare;
    // The node's flag wins over its light's: one light placed by several nodes can cast from some of them.
    if (!lidrShadowFlag(nodeExtras, light.castsShadow)) lidrShadowFlag(source.extras, light.castsShadow);
    if (source.type == "spot") {
        // The validator held the angles to 0 <= inner < outer <= pi/2.
        if (!nodeDirection(world, name, nodeName, light.direction)) return;
        light.innerConeAngle = float(source.spot.innerConeAngle);
        light.outerConeAngle = float(source.spot.outerConeAngle);
        // inner < outer in double may round to equal floats
        light.innerConeAngle = std::min(light.innerConeAngle, std::nextafter(light.outerConeAngle, 0.0f));
    }
    light.position = glm::vec3(world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    // The node's scale scales the range (its largest axis: the light stays a sphere).
    const glm::mat3 linear(world);
    const float scale = std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
    if (source.range > 0.0) {
        light.radius = float(source.range) * scale;
    } else {
        light.radius = gltfLightRadiusWithoutRange(std::max({light.color.r, light.color.g, light.color.b}));
    }
    if (!(std::isfinite(light.radius) && light.radius > 0.0f && light.radius <= maxLightRadius))
        fail(name + ": radius " + str(light.radius) + " is not in (0, " + str(maxLightRadius) + "]");
    scene_.lights.push_back(light);
    if (!scene_.lightPaths.empty()) scene_.lightPaths.emplace_back();
    ++contents_.lights;
}

// Spot and directional lights shine down their node's -z (KHR_lights_punctual): the unit direction, or
// false with a warning (the light is left out) where the node's transform flattens -z to nothing.
bool GltfReader::nodeDirection(const glm::mat4& world, const std::string& name, const std::string& nodeName, glm::vec3& out) {
    const glm::vec3 direction(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
    if (!isUsableDirection(direction)) {
        warn(name + " on node " + nodeName + ": the node's transform gives no direction (-z maps to " +
             str(direction) + "); left out");
        return false;
    }
    out = glm::normalize(direction);
    return true;
}

// The node's position and scale do not matter. Past maxDirectionalLights (the forward shaders' uniforms)
// the rest are left out with a warning.
void GltfReader::readDirectionalLight(const std::string& name, const std::string& nodeName, const glm::vec3& color,
                                      const glm::mat4& world) {
    DirectionalLight light{glm::vec3(0.0f), color};
    if (!nodeDirection(world, name, nodeName, light.direction)) return;
    if (scene_.directionalLights.size() >= maxDirectionalLights) {
        warn(name + " on node " + nodeName + ": more than " + std::to_string(maxDirectionalLights) +
             " directional lights (the forward shaders' limit); left out");
        return;
    }
    scene_.directionalLights.push_back(light);
}

// Every camera of the file becomes a view, usable or not, so views are numbered as the file's `cameras`.
void GltfReader::listCameras() {
    for (size_t i = 0; i < model_.cameras.size(); ++i) {
        const tinygltf::Camera& source = model_.cameras[i];
        SceneView view;
        view.name = "camera " + std::to_string(i) + (source.name.empty() ? "" : " '" + source.name + "'");
        view.unusable = source.type == "perspective" ? "it is placed by no node of the default scene (nothing to view from)"
                                                     : "it is orthographic; lidr draws perspective cameras only (its light "
                                                       "volumes and tiles assume a perspective projection)";
        if (source.type != "perspective")
            warn(view.name + ": orthographic cameras are not supported (lidr's light volumes and tiles assume a "
                             "perspective projection); it cannot be the view");
        contents_.views.push_back(view);
    }
}

// The node's world transform places the camera (the validator checked its numbers as floats); the first node
// in node order that places a camera gives its view.
void GltfReader::readCamera(const tinygltf::Node& node, const std::string& nodeName, const glm::mat4& world, int animationNode) {
    if (size_t(node.camera) >= model_.cameras.size())
        fail(nodeName + ": camera " + std::to_string(node.camera) + " out of range");
    const tinygltf::Camera& source = model_.cameras[size_t(node.camera)];
    SceneView& view = contents_.views[size_t(node.camera)];
    if (source.type != "perspective" || view.unusable.empty()) return;  // orthographic, or placed before
    Camera& camera = view.camera;
    camera.position = glm::vec3(world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    // A glTF camera looks down its -z with +y up.
    camera.target = camera.position + normalizedOr(glm::vec3(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f)), glm::vec3(0, 0, -1));
    camera.up = normalizedOr(glm::vec3(world * glm::vec4(0.0f, 1.0f, 0.0f, 0.0f)), glm::vec3(0, 1, 0));
    // yfov is kept and the image's aspect is the output's (aspectRatio is not used), as the Khronos viewer does
    camera.fovYDegrees = glm::degrees(float(source.perspective.yfov));
    camera.nearPlane = float(source.perspective.znear);
    camera.farPlane = float(source.perspective.zfar);  // 0: infinite, replaced from the bounds by the caller
    view.unusable.clear();
    if (animated_) contents_.viewNodes[size_t(node.camera)] = animationNode;
    if (contents_.firstView < 0) contents_.firstView = node.camera;  // the first camera met is the default view
}

}  // namespace lidr::gltf_import
