// The glTF importer's entry point, the file read by tinygltf, and the node tree; the rest of the reader by
// concern in gltf_import_*.cpp (gltf_importer_internal.h lists them).
#include "lidr/scene/io/gltf_importer.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

// tinygltf's implementation is compiled here, once, against Debian's own nlohmann json and stb_image (libstb);
// tinygltf only reads here, so stb_image_write is left out (gltf_importer_internal.h includes tiny_gltf.h with
// the TINYGLTF_NO_INCLUDE_* defines).
#include <nlohmann/json.hpp>
#include <stb_image.h>
#define TINYGLTF_IMPLEMENTATION
#include "lidr/scene/io/gltf_importer_internal.h"

#include "lidr/base/error.h"
#include "lidr/scene/io/file_checks.h"
#include "lidr/scene/io/gltf_validator.h"

namespace lidr {

namespace gltf_import {

namespace {

namespace fs = std::filesystem;

// Images are decoded by lidr, not by tinygltf's loader: the size is checked before decoding, and every image
// becomes RGBA8 (16-bit PNGs included).
bool decodeImage(tinygltf::Image* image, const int index, std::string* err, const unsigned char* bytes, int size) {
    int width = 0, height = 0, channels = 0;
    const std::string name = "image " + std::to_string(index) + (image->uri.empty() ? "" : " '" + image->uri + "'");
    if (!stbi_info_from_memory(bytes, size, &width, &height, &channels)) {
        const char* reason = stbi_failure_reason();
        if (err) *err += name + " cannot be read (" + (reason ? reason : "unknown format") + ")";
        return false;
    }
    if (width > maxTextureSide || height > maxTextureSide) {
        if (err)
            *err += name + " is " + std::to_string(width) + "x" + std::to_string(height) +
                    ", over the texture limit of " + std::to_string(maxTextureSide) + " per side";
        return false;
    }
    std::unique_ptr<stbi_uc, void (*)(void*)> data(stbi_load_from_memory(bytes, size, &width, &height, &channels, 4),
                                                   stbi_image_free);
    if (!data) {
        const char* reason = stbi_failure_reason();
        if (err) *err += name + " cannot be decoded (" + (reason ? reason : "unknown format") + ")";
        return false;
    }
    image->width = width;
    image->height = height;
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image.assign(data.get(), data.get() + size_t(width) * size_t(height) * 4);
    return true;
}

// Why each image that failed was not decoded, by image index (tinygltf turns a failure into a warning only).
using ImageFailures = std::map<int, std::string>;

bool loadImage(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
               const unsigned char* bytes, int size, void* failures) {
    std::string reason;
    const bool ok = decodeImage(image, index, &reason, bytes, size);
    if (!ok) {
        (*static_cast<ImageFailures*>(failures))[index] = reason;
        if (err) *err += reason;
    }
    return ok;
}

std::string trimmed(std::string text) {
    text.erase(text.find_last_not_of(" \n") + 1);
    return text;
}

}  // namespace

GltfContents GltfReader::read() {
    const std::string problem = fileProblem(path_);
    if (!problem.empty()) fail("glTF file " + problem);
    validateGltfFile(path_, scene_.warnings);  // the specification's rules and lidr's limits, before tinygltf
    if (overrideMaterial_ >= int(scene_.materials.size())) fail("override material out of range");
    load();
    stem_ = fs::path(path_).stem().string();
    for (const tinygltf::Mesh& mesh : model_.meshes)
        for (const tinygltf::Primitive& primitive : mesh.primitives) checkMode(mesh, primitive);
    const std::vector<int> roots = rootNodes();
    checkInstancedTriangles(roots);
    listCameras();
    const size_t trianglesBefore = scene_.triangleCount();
    const int root = startAnimation();
    for (int r : roots) visit(r, transform_, 0, root);
    if (scene_.triangleCount() == trianglesBefore && contents_.lights == 0) fail("no triangles and no lights");
    finishAnimation();
    return contents_;
}

// The default scene's root nodes; without scenes, every node that is no other node's child.
std::vector<int> GltfReader::rootNodes() const {
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
        const int sceneIndex = model_.defaultScene >= 0 ? model_.defaultScene : 0;
        if (sceneIndex >= int(model_.scenes.size())) fail("scene " + std::to_string(sceneIndex) + " out of range");
        return model_.scenes[size_t(sceneIndex)].nodes;
    }
    std::vector<bool> isChild(model_.nodes.size(), false);
    for (const tinygltf::Node& node : model_.nodes)
        for (int child : node.children)
            if (child >= 0 && size_t(child) < isChild.size()) isChild[size_t(child)] = true;
    for (size_t i = 0; i < model_.nodes.size(); ++i)
        if (!isChild[i]) roots.push_back(int(i));
    return roots;
}

void GltfReader::load() {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(loadImage, &imageFailures_);
    std::string error, warning;
    const bool binary = lowerCaseExtension(path_) == ".glb";
    const bool ok = binary ? loader.LoadBinaryFromFile(&model_, &error, &warning, path_)
                           : loader.LoadASCIIFromFile(&model_, &error, &warning, path_);
    if (!ok) fail("malformed glTF: " + trimmed(error.empty() ? "tinygltf gave no reason" : error));
    if (!trimmed(warning).empty()) warn(trimmed(warning));
}

void GltfReader::checkMode(const tinygltf::Mesh& mesh, const tinygltf::Primitive& primitive) const {
    static const char* const names[] = {"POINTS", "LINES", "LINE_LOOP", "LINE_STRIP"};
    if (primitive.mode >= TINYGLTF_MODE_POINTS && primitive.mode <= TINYGLTF_MODE_LINE_STRIP)
        fail("mesh '" + mesh.name + "': primitive mode " + std::to_string(primitive.mode) + " (" +
             names[primitive.mode] + ") is not triangles; only TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN can be drawn");
    if (primitive.mode > TINYGLTF_MODE_TRIANGLE_FAN)
        fail("mesh '" + mesh.name + "': unknown primitive mode " + std::to_string(primitive.mode));
}

glm::mat4 GltfReader::localMatrix(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        glm::mat4 m;
        for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = float(node.matrix[size_t(i)]);  // column-major
        return m;
    }
    glm::mat4 m(1.0f);
    if (node.translation.size() == 3)
        m = glm::translate(m, glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4)  // glTF stores x, y, z, w; glm's constructor takes w first
        m *= glm::mat4_cast(glm::normalize(
            glm::quat(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]), float(node.rotation[2]))));
    if (node.scale.size() == 3) m = glm::scale(m, glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

// Triangles one primitive declares (its index or position count by mode), from the accessors alone.
size_t GltfReader::declaredTriangles(const tinygltf::Primitive& primitive) const {
    const auto position = primitive.attributes.find("POSITION");
    const int accessor = primitive.indices >= 0 ? primitive.indices
                         : position != primitive.attributes.end() ? position->second : -1;
    if (accessor < 0 || size_t(accessor) >= model_.accessors.size()) return 0;
    const size_t corners = model_.accessors[size_t(accessor)].count;
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    return mode == TINYGLTF_MODE_TRIANGLES ? corners / 3 : corners < 2 ? 0 : corners - 2;
}

// Before anything is expanded: a small file can instance one mesh from many nodes, so the scene's triangle
// total is summed over the node tree from the accessors' counts and checked against the limit first.
void GltfReader::checkInstancedTriangles(const std::vector<int>& roots) const {
    std::vector<size_t> meshTriangles(model_.meshes.size(), 0);
    for (size_t m = 0; m < model_.meshes.size(); ++m)
        for (const tinygltf::Primitive& primitive : model_.meshes[m].primitives)
            meshTriangles[m] += declaredTriangles(primitive);
    size_t total = scene_.triangleCount();
    std::vector<std::pair<int, int>> stack;  // node, depth; explicit so a deep tree cannot overflow the stack
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, 0);
    while (!stack.empty()) {
        const auto [nodeIndex, depth] = stack.back();
        stack.pop_back();
        if (nodeIndex < 0 || size_t(nodeIndex) >= model_.nodes.size() || depth > maxNodeDepth) continue;  // visit() names it
        const tinygltf::Node& node = model_.nodes[size_t(nodeIndex)];
        if (node.mesh >= 0 && size_t(node.mesh) < meshTriangles.size()) {
            total += meshTriangles[size_t(node.mesh)];
            if (total > maxSceneTriangles)
                fail("the scene would have at least " + std::to_string(total) + " triangles; at most " +
                     std::to_string(maxSceneTriangles) + " are supported (counted over the nodes' meshes before loading)");
        }
        for (int child : node.children) stack.emplace_back(child, depth + 1);
    }
}

void GltfReader::visit(int nodeIndex, const glm::mat4& parent, int depth, int parentNode) {
    if (nodeIndex < 0 || size_t(nodeIndex) >= model_.nodes.size())
        fail("node " + std::to_string(nodeIndex) + " out of range (" + std::to_string(model_.nodes.size()) + " nodes)");
    if (depth > maxNodeDepth)
        fail("node hierarchy deeper than " + std::to_string(maxNodeDepth) + " levels (a node is its own ancestor?)");
    const tinygltf::Node& node = model_.nodes[size_t(nodeIndex)];
    const std::string name = "node " + std::to_string(nodeIndex) + (node.name.empty() ? "" : " '" + node.name + "'");
    const glm::mat4 world = parent * localMatrix(node);
    for (int i = 0; i < 16; ++i)
        if (!std::isfinite(glm::value_ptr(world)[i])) fail(name + ": transform is not finite");
    const int animationNode = animated_ ? addAnimationNode(nodeIndex, node, name, parentNode) : -1;
    const size_t meshesBefore = scene_.meshes.size(), lightsBefore = scene_.lights.size();
    const size_t directionalBefore = scene_.directionalLights.size();
    if (node.mesh >= 0) {
        if (size_t(node.mesh) >= model_.meshes.size())
            fail(name + ": mesh " + std::to_string(node.mesh) + " out of range");
        const tinygltf::Mesh& mesh = model_.meshes[size_t(node.mesh)];
        for (size_t p = 0; p < mesh.primitives.size(); ++p) addPrimitive(mesh, node.mesh, p, world);
    }
    if (node.camera >= 0) readCamera(node, name, world, animationNode);
    const auto light = node.extensions.find("KHR_lights_punctual");
    if (light != node.extensions.end() && light->second.Has("light"))
        readLight(light->second.Get("light"), name, world, node.extras);
    if (animated_) {
        carry(animationNode, meshesBefore, lightsBefore, world);
        if (scene_.directionalLights.size() > directionalBefore) directionalNodes_.push_back(animationNode);
    }
    for (int child : node.children) visit(child, world, depth + 1, animationNode);
}

}  // namespace gltf_import


float gltfLightRadiusWithoutRange(float brightestChannel) {
    // Windowed, the light differs from the unwindowed one by C / d^2 x (d / r)^4 <= C / r^2 (at d = r), and
    // beyond r the real light gives less than C / r^2 too: r = sqrt(C / threshold) keeps both under it.
    const float radius = std::sqrt(std::max(brightestChannel, 0.0f) / gltfLightCutThreshold);
    return glm::clamp(radius, gltfLightMinRadius, gltfLightMaxRadius);
}

GltfContents appendGltf(Scene& scene, const std::string& path, const glm::mat4& transform, int overrideMaterial) {
    return gltf_import::GltfReader(scene, path, transform, overrideMaterial).read();
}

void finishGltfViews(Scene& scene) {
    const glm::vec3 boundsMin = scene.boundsMin(), boundsMax = scene.boundsMax();
    for (SceneView& view : scene.views) {
        Camera& camera = view.camera;
        if (!view.unusable.empty() || camera.farPlane > 0.0f) continue;
        float farthest = 0.0f;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p((corner & 1) ? boundsMax.x : boundsMin.x, (corner & 2) ? boundsMax.y : boundsMin.y,
                              (corner & 4) ? boundsMax.z : boundsMin.z);
            farthest = std::max(farthest, glm::length(p - camera.position));
        }
        camera.farPlane = std::max(1.5f * farthest, 2.0f * camera.nearPlane);
    }
}

}  // namespace lidr
