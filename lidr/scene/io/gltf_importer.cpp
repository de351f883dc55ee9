#include "lidr/scene/io/gltf_importer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

// tinygltf's implementation is compiled here, once, against Debian's own nlohmann json and stb_image (libstb);
// tinygltf only reads here, so stb_image_write is left out.
#include <nlohmann/json.hpp>
#include <stb_image.h>
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_INCLUDE_JSON
#define TINYGLTF_NO_INCLUDE_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>

#include "lidr/base/colour.h"
#include "lidr/base/error.h"
#include "lidr/scene/io/file_checks.h"
#include "lidr/scene/io/gltf_accessors.h"
#include "lidr/scene/io/gltf_animation.h"
#include "lidr/scene/io/gltf_validator.h"
#include "lidr/scene/io/mesh_split.h"

namespace lidr {

namespace {

namespace fs = std::filesystem;

// Node trees deeper than this are refused (a cycle would otherwise recurse without end).
constexpr int maxNodeDepth = 256;

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

glm::vec3 normalizedOr(const glm::vec3& v, const glm::vec3& fallback) {
    const float length = glm::length(v);
    return std::isfinite(length) && length > 1e-20f ? v / length : fallback;
}

std::string trimmed(std::string text) {
    text.erase(text.find_last_not_of(" \n") + 1);
    return text;
}

class GltfReader {
public:
    GltfReader(Scene& scene, const std::string& path, const glm::mat4& transform, int overrideMaterial)
        : scene_(scene), path_(path), transform_(transform), overrideMaterial_(overrideMaterial) {}

    GltfContents read() {
        const std::string problem = fileProblem(path_);
        if (!problem.empty()) fail("glTF file " + problem);
        validateGltfFile(path_, scene_.warnings);  // the specification's rules and lidr's limits, before tinygltf
        if (overrideMaterial_ >= int(scene_.materials.size())) fail("override material out of range");
        load();
        stem_ = fs::path(path_).stem().string();
        for (const tinygltf::Mesh& mesh : model_.meshes)
            for (const tinygltf::Primitive& primitive : mesh.primitives) checkMode(mesh, primitive);
        std::vector<int> roots;
        if (!model_.scenes.empty()) {
            const int sceneIndex = model_.defaultScene >= 0 ? model_.defaultScene : 0;
            if (sceneIndex >= int(model_.scenes.size())) fail("scene " + std::to_string(sceneIndex) + " out of range");
            roots = model_.scenes[size_t(sceneIndex)].nodes;
        } else {  // no scenes: every node that is no other node's child is a root
            std::vector<bool> isChild(model_.nodes.size(), false);
            for (const tinygltf::Node& node : model_.nodes)
                for (int child : node.children)
                    if (child >= 0 && size_t(child) < isChild.size()) isChild[size_t(child)] = true;
            for (size_t i = 0; i < model_.nodes.size(); ++i)
                if (!isChild[i]) roots.push_back(int(i));
        }
        checkInstancedTriangles(roots);
        listCameras();
        const size_t trianglesBefore = scene_.triangleCount();
        const int root = startAnimation();
        for (int r : roots) visit(r, transform_, 0, root);
        if (scene_.triangleCount() == trianglesBefore && contents_.lights == 0) fail("no triangles and no lights");
        finishAnimation();
        return contents_;
    }

private:
    [[noreturn]] void fail(const std::string& problem) const { throw Error(path_ + ": " + problem); }

    void warn(const std::string& warning) { scene_.warnings.push_back(path_ + ": " + warning); }

    void load() {
        tinygltf::TinyGLTF loader;
        loader.SetImageLoader(loadImage, &imageFailures_);
        std::string error, warning;
        const bool binary = lowerCaseExtension(path_) == ".glb";
        const bool ok = binary ? loader.LoadBinaryFromFile(&model_, &error, &warning, path_)
                               : loader.LoadASCIIFromFile(&model_, &error, &warning, path_);
        if (!ok) fail("malformed glTF: " + trimmed(error.empty() ? "tinygltf gave no reason" : error));
        if (!trimmed(warning).empty()) warn(trimmed(warning));
    }

    void checkMode(const tinygltf::Mesh& mesh, const tinygltf::Primitive& primitive) const {
        static const char* const names[] = {"POINTS", "LINES", "LINE_LOOP", "LINE_STRIP"};
        if (primitive.mode >= TINYGLTF_MODE_POINTS && primitive.mode <= TINYGLTF_MODE_LINE_STRIP)
            fail("mesh '" + mesh.name + "': primitive mode " + std::to_string(primitive.mode) + " (" +
                 names[primitive.mode] + ") is not triangles; only TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN can be drawn");
        if (primitive.mode > TINYGLTF_MODE_TRIANGLE_FAN)
            fail("mesh '" + mesh.name + "': unknown primitive mode " + std::to_string(primitive.mode));
    }

    static glm::mat4 localMatrix(const tinygltf::Node& node) {
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
    size_t declaredTriangles(const tinygltf::Primitive& primitive) const {
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
    void checkInstancedTriangles(const std::vector<int>& roots) const {
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

    // ---- animation (gltf_animation.h): the node tree as AnimationNodes, what each node carries -------------------

    // Where the file has animations: its nodes join the scene's animation (after any it has), under a static root
    // holding `transform` where that is not the identity. Returns the root's node, -1: none.
    int startAnimation() {
        animated_ = !model_.animations.empty();
        if (!animated_) return -1;
        SceneAnimation& a = scene_.animation;
        nodeBase_ = a.nodes.size();
        nodeOf_.assign(model_.nodes.size(), -1);
        contents_.viewNodes.assign(contents_.views.size(), -1);
        if (transform_ == glm::mat4(1.0f)) return -1;
        AnimationNode root;
        root.name = stem_ + " (placed by the scene file)";
        root.rest = transform_;
        a.nodes.push_back(root);
        return int(a.nodes.size() - 1);
    }

    int addAnimationNode(int nodeIndex, const tinygltf::Node& node, const std::string& name, int parentNode) {
        AnimationNode n;
        n.name = name;
        n.parent = parentNode;
        n.rest = localMatrix(node);
        if (node.translation.size() == 3) n.translation = glm::vec3(node.translation[0], node.translation[1], node.translation[2]);
        if (node.rotation.size() == 4)
            n.rotation = glm::normalize(
                glm::quat(float(node.rotation[3]), float(node.rotation[0]), float(node.rotation[1]), float(node.rotation[2])));
        if (node.scale.size() == 3) n.scale = glm::vec3(node.scale[0], node.scale[1], node.scale[2]);
        scene_.animation.nodes.push_back(std::move(n));
        nodeOf_[size_t(nodeIndex)] = int(scene_.animation.nodes.size() - 1);
        return nodeOf_[size_t(nodeIndex)];
    }

    // The meshes and lights a node just added ride on it (a light at its origin, shining down its -z, its radius
    // scaled with the node as readLight scales it).
    void carry(int animationNode, size_t meshesBefore, size_t lightsBefore, const glm::mat4& world) {
        SceneAnimation& a = scene_.animation;
        if (scene_.meshes.size() > meshesBefore) {
            a.meshNodes.resize(meshesBefore, -1);
            a.meshNodes.resize(scene_.meshes.size(), animationNode);
        }
        if (scene_.lights.size() > lightsBefore) {
            const glm::mat3 linear(world);
            const float scale = std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
            a.lightBindings.resize(lightsBefore);
            for (size_t i = lightsBefore; i < scene_.lights.size(); ++i) {
                LightBinding b;
                b.node = animationNode;
                b.radius = scene_.lights[i].radius / std::max(scale, 1e-30f);
                a.lightBindings.push_back(b);
            }
        }
    }

    // The channels onto the nodes; the posed transforms of the new nodes (their rest pose, which the geometry was
    // built in); a file whose channels move nothing adds no nodes.
    void finishAnimation() {
        if (!animated_) return;
        SceneAnimation& a = scene_.animation;
        readGltfAnimations(model_, path_, nodeOf_, a, scene_.warnings);
        bool moves = false;
        for (size_t i = nodeBase_; i < a.nodes.size(); ++i) moves = moves || a.nodes[i].animated;
        if (!moves) {
            a.nodes.resize(nodeBase_);
            for (int& n : a.meshNodes) n = n >= int(nodeBase_) ? -1 : n;
            for (LightBinding& b : a.lightBindings) b.node = b.node >= int(nodeBase_) ? -1 : b.node;
            contents_.viewNodes.clear();
            if (a.nodes.empty()) a = SceneAnimation{};
            return;
        }
        a.posedWorld.resize(a.nodes.size());
        for (size_t i = nodeBase_; i < a.nodes.size(); ++i) {
            const AnimationNode& n = a.nodes[i];
            a.posedWorld[i] = n.parent >= 0 ? a.posedWorld[size_t(n.parent)] * n.rest : n.rest;
        }
        for (size_t i = 0; i < directionalNodes_.size(); ++i)
            if (a.movingNodes()[size_t(directionalNodes_[i])])
                warn("a directional light on an animated node (" + a.nodes[size_t(directionalNodes_[i])].name +
                     ") keeps its rest direction: directional lights are not moved");
    }

    void visit(int nodeIndex, const glm::mat4& parent, int depth, int parentNode) {
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

    // ---- geometry ----------------------------------------------------------------------------------------

    // The bytes of element i of an accessor, checked against its buffer view and buffer (gltf_accessors.h).
    using AccessorView = GltfAccessorView;

    AccessorView view(int accessorIndex, const std::string& what, std::initializer_list<int> types,
                      std::initializer_list<int> componentTypes) const {
        return gltfAccessorView(model_, path_, accessorIndex, what, types, componentTypes);
    }

    static float component(const AccessorView& v, size_t element, int c) { return gltfComponent(v, element, c); }
    static uint32_t index(const AccessorView& v, size_t element) { return gltfIndex(v, element); }

    // Before the corner list is allocated: a strip or fan of n corners has n - 2 triangles, a list n / 3.
    void checkTriangleLimit(const std::string& what, size_t corners, int mode) const {
        const size_t triangles =
            scene_.triangleCount() + (mode == TINYGLTF_MODE_TRIANGLES ? corners / 3 : corners < 2 ? 0 : corners - 2);
        if (triangles > maxSceneTriangles)
            fail(what + ": the scene would have at least " + std::to_string(triangles) + " triangles; at most " +
                 std::to_string(maxSceneTriangles) + " are supported");
    }

    void addPrimitive(const tinygltf::Mesh& mesh, int meshIndex, size_t primitiveIndex, const glm::mat4& world) {
        const tinygltf::Primitive& primitive = mesh.primitives[primitiveIndex];
        const std::string what = "mesh " + std::to_string(meshIndex) + (mesh.name.empty() ? "" : " '" + mesh.name + "'") +
                                 " primitive " + std::to_string(primitiveIndex);
        const auto attribute = [&](const char* name) {
            const auto it = primitive.attributes.find(name);
            return it == primitive.attributes.end() ? -1 : it->second;
        };
        if (attribute("POSITION") < 0) fail(what + ": no POSITION attribute");
        const AccessorView positions =
            view(attribute("POSITION"), what + " POSITION", {TINYGLTF_TYPE_VEC3}, {TINYGLTF_COMPONENT_TYPE_FLOAT});
        const bool hasNormals = attribute("NORMAL") >= 0;
        const AccessorView normals = hasNormals ? view(attribute("NORMAL"), what + " NORMAL", {TINYGLTF_TYPE_VEC3},
                                                       {TINYGLTF_COMPONENT_TYPE_FLOAT})
                                                : AccessorView{};
        // A texture coordinate set: float, or normalised unsigned byte / short (the specification's three).
        const auto texCoordView = [&](const char* name) {
            return attribute(name) >= 0 ? view(attribute(name), what + " " + name, {TINYGLTF_TYPE_VEC2},
                                               {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT})
                                        : AccessorView{};
        };
        const bool hasTexCoords = attribute("TEXCOORD_0") >= 0, hasTexCoords1 = attribute("TEXCOORD_1") >= 0;
        const AccessorView texCoords = texCoordView("TEXCOORD_0"), texCoords1 = texCoordView("TEXCOORD_1");
        // glTF: without NORMAL the flat normals are computed and TANGENT is ignored.
        const bool hasTangents = hasNormals && attribute("TANGENT") >= 0;
        const AccessorView tangents = hasTangents ? view(attribute("TANGENT"), what + " TANGENT", {TINYGLTF_TYPE_VEC4},
                                                         {TINYGLTF_COMPONENT_TYPE_FLOAT})
                                                  : AccessorView{};
        // An accessor without a buffer view is all zeros: every triangle would be degenerate and draw nothing.
        if (!positions.data) {
            warn(what + ": POSITION has no buffer view (all zeros); the primitive draws nothing and is left out");
            return;
        }
        if (hasNormals && normals.count != positions.count)
            fail(what + ": " + std::to_string(normals.count) + " normals for " + std::to_string(positions.count) + " positions");
        if (hasTexCoords && texCoords.count != positions.count)
            fail(what + ": " + std::to_string(texCoords.count) + " texture coordinates for " +
                 std::to_string(positions.count) + " positions");

        if (hasTexCoords1 && texCoords1.count != positions.count)
            fail(what + ": " + std::to_string(texCoords1.count) + " TEXCOORD_1 coordinates for " +
                 std::to_string(positions.count) + " positions");
        if (hasTangents && tangents.count != positions.count)
            fail(what + ": " + std::to_string(tangents.count) + " tangents for " + std::to_string(positions.count) + " positions");

        const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
        // The corner list: indices, or 0..count-1, then strips and fans unrolled into triangles.
        std::vector<uint32_t> corners;
        if (primitive.indices >= 0) {
            const AccessorView indices = view(primitive.indices, what + " indices", {TINYGLTF_TYPE_SCALAR},
                                              {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                               TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT});
            if (!indices.data) {
                warn(what + ": indices have no buffer view (all zero); the primitive draws nothing and is left out");
                return;
            }
            checkTriangleLimit(what, indices.count, mode);
            corners.resize(indices.count);
            for (size_t i = 0; i < indices.count; ++i) {
                corners[i] = index(indices, i);
                if (corners[i] >= positions.count)
                    fail(what + ": index " + std::to_string(corners[i]) + " (element " + std::to_string(i) +
                         ") out of range (" + std::to_string(positions.count) + " vertices)");
            }
        } else {
            checkTriangleLimit(what, positions.count, mode);
            corners.resize(positions.count);
            for (size_t i = 0; i < corners.size(); ++i) corners[i] = uint32_t(i);
        }
        std::vector<uint32_t> triangles;
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            if (corners.size() % 3 != 0)
                fail(what + ": " + std::to_string(corners.size()) + " corners is not a whole number of triangles");
            triangles = std::move(corners);
        } else {
            for (size_t i = 2; i < corners.size(); ++i) {
                if (mode == TINYGLTF_MODE_TRIANGLE_FAN)
                    triangles.insert(triangles.end(), {corners[0], corners[i - 1], corners[i]});
                else if (i % 2 == 0)
                    triangles.insert(triangles.end(), {corners[i - 2], corners[i - 1], corners[i]});
                else  // odd strip triangles swap two corners to keep the winding
                    triangles.insert(triangles.end(), {corners[i - 1], corners[i - 2], corners[i]});
            }
        }
        if (scene_.triangleCount() + triangles.size() / 3 > maxSceneTriangles)
            fail("the scene would have " + std::to_string(scene_.triangleCount() + triangles.size() / 3) +
                 " triangles; at most " + std::to_string(maxSceneTriangles) + " are supported");
        if (triangles.empty()) return;

        const glm::mat3 linear(world);
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));
        const bool mirrored = glm::determinant(linear) < 0.0f;  // keep triangles counter-clockwise from outside
        Mesh out;
        out.name = stem_ + "/" + (mesh.name.empty() ? "mesh " + std::to_string(meshIndex) : mesh.name) +
                   (mesh.primitives.size() > 1 ? "/" + std::to_string(primitiveIndex) : "");
        out.material = materialFor(primitive.material);
        const auto position = [&](uint32_t i) {
            const glm::vec3 p(component(positions, i, 0), component(positions, i, 1), component(positions, i, 2));
            if (!isFinite(p)) fail(what + ": position " + std::to_string(i) + " is not finite");
            return glm::vec3(world * glm::vec4(p, 1.0f));
        };
        const auto texCoordOf = [&](const AccessorView& set, uint32_t i) {
            // glTF puts v = 0 at the image's top; lidr (like OBJ) at the bottom.
            const glm::vec2 t(component(set, i, 0), 1.0f - component(set, i, 1));
            if (!std::isfinite(t.x) || !std::isfinite(t.y)) fail(what + ": texture coordinate " + std::to_string(i) + " is not finite");
            return t;
        };
        const auto texCoord = [&](uint32_t i) { return texCoordOf(texCoords, i); };
        const auto tangent = [&](uint32_t i) {
            const glm::vec4 t(component(tangents, i, 0), component(tangents, i, 1), component(tangents, i, 2),
                              component(tangents, i, 3));
            if (!isFinite(glm::vec3(t)) || !std::isfinite(t.w)) fail(what + ": tangent " + std::to_string(i) + " is not finite");
            // A mirroring transform turns the frame's handedness over (the normal follows the inverse transpose).
            const float w = (t.w < 0.0f ? -1.0f : 1.0f) * (mirrored ? -1.0f : 1.0f);
            return glm::vec4(normalizedOr(linear * glm::vec3(t), glm::vec3(1.0f, 0.0f, 0.0f)), w);
        };
        const std::string needsSecond = secondSetUser(primitive.material);
        if (!needsSecond.empty() && !hasTexCoords1)
            warn(what + ": " + needsSecond + " reads TEXCOORD_1, which the primitive does not have; drawn with TEXCOORD_0");
        if (hasNormals) {  // shared vertices, as the file has them
            std::vector<uint32_t> remap(positions.count, ~0u);
            for (size_t c = 0; c < triangles.size(); ++c) {
                const size_t corner = mirrored ? (c - c % 3) + (3 - c % 3) % 3 : c;  // 0, 2, 1 when mirrored
                const uint32_t source = triangles[corner];
                if (remap[source] == ~0u) {
                    remap[source] = uint32_t(out.positions.size());
                    out.positions.push_back(position(source));
                    const glm::vec3 n(component(normals, source, 0), component(normals, source, 1), component(normals, source, 2));
                    if (!isFinite(n)) fail(what + ": normal " + std::to_string(source) + " is not finite");
                    out.normals.push_back(normalizedOr(normalMatrix * n, glm::vec3(0.0f, 1.0f, 0.0f)));
                    if (hasTexCoords) out.texCoords.push_back(texCoord(source));
                    if (hasTexCoords1) out.texCoords1.push_back(texCoordOf(texCoords1, source));
                    if (hasTangents) out.tangents.push_back(tangent(source));
                }
                out.indices.push_back(remap[source]);
            }
        } else {  // flat normals (the glTF specification's rule without NORMAL): three vertices per triangle
            for (size_t t = 0; t < triangles.size(); t += 3) {
                uint32_t source[3] = {triangles[t], triangles[t + 1], triangles[t + 2]};
                if (mirrored) std::swap(source[1], source[2]);
                const glm::vec3 p[3] = {position(source[0]), position(source[1]), position(source[2])};
                const glm::vec3 normal = normalizedOr(glm::cross(p[1] - p[0], p[2] - p[0]), glm::vec3(0.0f, 1.0f, 0.0f));
                for (int k = 0; k < 3; ++k) {
                    out.indices.push_back(uint32_t(out.positions.size()));
                    out.positions.push_back(p[k]);
                    out.normals.push_back(normal);
                    if (hasTexCoords) out.texCoords.push_back(texCoord(source[k]));
                    if (hasTexCoords1) out.texCoords1.push_back(texCoordOf(texCoords1, source[k]));
                }
            }
        }
        for (Mesh& part : splitMeshSpatially(std::move(out))) scene_.meshes.push_back(std::move(part));
    }

    // ---- materials -----------------------------------------------------------------------------------------

    // The decoded image of glTF texture `texture`; fails naming `what` for an index out of range or an image
    // that is missing or not decoded to RGBA8.
    const tinygltf::Image& textureImage(int texture, const std::string& what) {
        if (texture < 0 || size_t(texture) >= model_.textures.size())
            fail(what + " " + std::to_string(texture) + " out of range (" + std::to_string(model_.textures.size()) +
                 " textures)");
        const int source = model_.textures[size_t(texture)].source;
        if (source < 0 || size_t(source) >= model_.images.size())
            fail(what + ": texture " + std::to_string(texture) + " has no image (source " + std::to_string(source) + ")");
        const tinygltf::Image& image = model_.images[size_t(source)];
        if (image.width <= 0 || image.height <= 0 || image.image.size() != size_t(image.width) * size_t(image.height) * 4) {
            const auto failure = imageFailures_.find(source);  // the file and the decoder's reason, where known
            fail(what + ": " + (failure != imageFailures_.end() ? failure->second
                                                                : "image " + std::to_string(source) + " was not loaded"));
        }
        return image;
    }

    // A glTF textureInfo as lidr draws it: the decoded image (shared by every texture of the same image), its
    // name, the coordinate set (texCoord, or KHR_texture_transform's override) and the transform, turned into
    // lidr's texture space (v up: flipped on import, rows flipped on upload) as F T F with F (u, v) = (u, 1 - v).
    MaterialTexture readTexture(int texture, int texCoord, const tinygltf::ExtensionMap& extensions, const std::string& what) {
        warnSampler(texture, what);
        const tinygltf::Image& image = textureImage(texture, what);
        const int source = model_.textures[size_t(texture)].source;
        MaterialTexture out;
        std::shared_ptr<const ImageRGBA8>& decoded = decodedImages_[source];
        if (!decoded) {
            auto pixels = std::make_shared<ImageRGBA8>(image.width, image.height);
            pixels->pixels = image.image;
            decoded = std::move(pixels);
        }
        out.image = decoded;
        out.name = image.uri.rfind("data:", 0) == 0 || image.uri.empty()
                       ? path_ + "#image" + std::to_string(source)
                       : (fs::path(path_).parent_path() / image.uri).lexically_normal().string();
        // The validator held every field to its type and to finite floats.
        glm::dvec2 offset(0.0), scale(1.0);
        double rotation = 0.0;
        const auto transform = extensions.find("KHR_texture_transform");
        if (transform != extensions.end()) {
            const tinygltf::Value& t = transform->second;
            const auto pair = [&](const char* field, glm::dvec2& into) {
                if (t.Has(field))
                    into = glm::dvec2(t.Get(field).Get(0).GetNumberAsDouble(), t.Get(field).Get(1).GetNumberAsDouble());
            };
            pair("offset", offset);
            pair("scale", scale);
            if (t.Has("rotation")) rotation = t.Get("rotation").GetNumberAsDouble();
            if (t.Has("texCoord")) texCoord = t.Get("texCoord").GetNumberAsInt();
        }
        if (texCoord != 0 && texCoord != 1) {
            warn(what + " uses TEXCOORD_" + std::to_string(texCoord) + "; lidr reads TEXCOORD_0 and TEXCOORD_1, drawn with TEXCOORD_0");
            texCoord = 0;
        }
        out.mapping.texCoord = texCoord;
        // The extension's matrix: translation x rotation x scale, rotating the UVs counter-clockwise by `rotation`
        // (its example: offset (0, 1), rotation pi/2, scale 0.5 reads the image's lower left quadrant).
        const double c = std::cos(rotation), s = std::sin(rotation);
        const glm::dmat3 translate(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
        const glm::dmat3 rotate(c, -s, 0, s, c, 0, 0, 0, 1);
        const glm::dmat3 scaling(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
        const glm::dmat3 flip(1, 0, 0, 0, -1, 0, 0, 1, 1);
        out.mapping.transform = glm::mat3(flip * translate * rotate * scaling * flip);
        for (int i = 0; i < 9; ++i)  // each field is a finite float, but their sums can still overflow one
            if (!std::isfinite(glm::value_ptr(out.mapping.transform)[i]))
                fail(what + ": KHR_texture_transform (offset " + str(offset.x) + " " + str(offset.y) + ", rotation " +
                     str(rotation) + ", scale " + str(scale.x) + " " + str(scale.y) + ") is not finite as a float matrix");
        return out;
    }

    // The name of a texture of glTF material `gltfMaterial` that reads the second coordinate set; empty if none.
    std::string secondSetUser(int gltfMaterial) {
        if (overrideMaterial_ >= 0 || gltfMaterial < 0 || size_t(gltfMaterial) >= model_.materials.size()) return {};
        const int scene = materialFor(gltfMaterial);
        const Material& m = scene_.materials[size_t(scene)];
        if (m.diffuseMapping.texCoord == 1) return "the base colour texture";
        if (m.emissiveTexture.mapping.texCoord == 1) return "the emissive texture";
        if (m.metallicRoughnessTexture.mapping.texCoord == 1) return "the metallic-roughness texture";
        if (m.occlusionTexture.mapping.texCoord == 1) return "the occlusion texture";
        if (m.normalTexture.mapping.texCoord == 1) return "the normal texture";
        return {};
    }

    // lidr samples every texture with REPEAT and trilinear filtering: another wrap or filter is a warning.
    void warnSampler(int texture, const std::string& what) {
        const int sampler = model_.textures[size_t(texture)].sampler;
        if (sampler < 0 || size_t(sampler) >= model_.samplers.size()) return;
        const tinygltf::Sampler& s = model_.samplers[size_t(sampler)];
        const int repeat = 10497, nearest = 9728, nearestMipmapNearest = 9984;
        if (s.wrapS != repeat || s.wrapT != repeat)
            warn(what + ": sampler wrap " + std::to_string(s.wrapS) + " / " + std::to_string(s.wrapT) +
                 " is drawn as REPEAT");
        if (s.magFilter == nearest || s.minFilter == nearest || s.minFilter == nearestMipmapNearest)
            warn(what + ": sampler's nearest filtering is drawn trilinear");
    }

    // KHR_materials_emissive_strength: the emissive factor times emissiveStrength (the validator held it to a
    // float >= 0; the factor is at most 1, so the product stays finite). The shared shading adds the emission in
    // every mode (shading.glsl, lidrAmbient), unclamped, in linear light.
    void readEmissiveStrength(const tinygltf::Material& source, Material& material) {
        const auto it = source.extensions.find("KHR_materials_emissive_strength");
        if (it == source.extensions.end()) return;
        const tinygltf::Value& strength = it->second.Get("emissiveStrength");
        if (!strength.IsNumber() && !strength.IsInt()) return;  // the extension's default, 1
        material.emissive *= float(strength.GetNumberAsDouble());
    }

    // KHR_materials_ior and KHR_materials_specular's factors (validated): the dielectric's F0 and F90, drawn by
    // every mode through the material's shader variant. Their two textures are not drawn: lidr's material
    // textures and light tables take texture units 0..15 (WebGL's usual 16), and 16 is the shadow atlas'.
    void readDielectricSpecular(const tinygltf::Material& source, const std::string& name, Material& material) {
        const auto ior = source.extensions.find("KHR_materials_ior");
        if (ior != source.extensions.end() && ior->second.Has("ior"))
            material.dielectric.ior = float(ior->second.Get("ior").GetNumberAsDouble());
        const auto specular = source.extensions.find("KHR_materials_specular");
        if (specular == source.extensions.end()) return;
        const tinygltf::Value& s = specular->second;
        if (s.Has("specularFactor")) material.dielectric.weight = float(s.Get("specularFactor").GetNumberAsDouble());
        if (s.Has("specularColorFactor"))
            for (int c = 0; c < 3; ++c)
                material.dielectric.color[c] = float(s.Get("specularColorFactor").Get(c).GetNumberAsDouble());
        for (const char* texture : {"specularTexture", "specularColorTexture"})
            if (s.Has(texture))
                warn(name + ": KHR_materials_specular " + texture +
                     " is not drawn (no texture unit is left for it); its factors are");
    }

    int materialFor(int gltfMaterial) {
        if (overrideMaterial_ >= 0) return overrideMaterial_;
        if (gltfMaterial < 0) return findOrAddDefaultMaterial(scene_);
        if (size_t(gltfMaterial) >= model_.materials.size())
            fail("material " + std::to_string(gltfMaterial) + " out of range (" + std::to_string(model_.materials.size()) +
                 " materials)");
        const auto known = sceneMaterialOf_.find(gltfMaterial);
        if (known != sceneMaterialOf_.end()) return known->second;
        const tinygltf::Material& source = model_.materials[size_t(gltfMaterial)];
        const std::string name = "material " + std::to_string(gltfMaterial) + (source.name.empty() ? "" : " '" + source.name + "'");
        const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
        Material material;
        material.name = source.name.empty() ? stem_ + "/material " + std::to_string(gltfMaterial) : source.name;
        glm::vec4 base(1.0f);
        for (size_t c = 0; c < 4 && c < pbr.baseColorFactor.size(); ++c) base[int(c)] = float(pbr.baseColorFactor[c]);
        if (!(base.r >= 0 && base.g >= 0 && base.b >= 0 && base.a >= 0 && base.a <= 1 && isFinite(glm::vec3(base))))
            fail(name + ": baseColorFactor must be finite with colour >= 0 and alpha in [0, 1]");
        const float metallic = glm::clamp(float(pbr.metallicFactor), 0.0f, 1.0f);
        const float roughness = glm::clamp(float(pbr.roughnessFactor), 0.0f, 1.0f);
        material.diffuse = glm::vec3(base);
        for (size_t c = 0; c < 3 && c < source.emissiveFactor.size(); ++c) material.emissive[int(c)] = float(source.emissiveFactor[c]);
        if (!(isFinite(material.emissive) && glm::all(glm::greaterThanEqual(material.emissive, glm::vec3(0.0f)))))
            fail(name + ": emissiveFactor must be finite and >= 0, got " + str(material.emissive));
        // lidr's BRDF is glTF's: the factors as they are (specular and shininess stay unused defaults)
        material.metallicRoughness = true;
        material.metallic = metallic;
        material.roughness = roughness;
        if (source.alphaMode == "BLEND") {
            material.opacity = base.a;
        } else if (source.alphaMode == "MASK") {
            material.alphaMode = AlphaMode::Mask;
            if (!(std::isfinite(source.alphaCutoff) && source.alphaCutoff >= 0.0 && source.alphaCutoff <= 1.0))
                fail(name + ": alphaCutoff must be in [0, 1], got " + std::to_string(source.alphaCutoff));
            // The test is factor alpha x texel alpha < cutoff; the shaders test the texel alone against the cutoff
            // divided by the factor's alpha (above 1: everything is cut, as factor alpha 0 cuts everything).
            const float cutoff = float(source.alphaCutoff);
            material.alphaCutoff = base.a > 0.0f ? std::min(cutoff / base.a, 2.0f) : (cutoff > 0.0f ? 2.0f : 0.0f);
        }
        material.doubleSided = source.doubleSided;
        readEmissiveStrength(source, material);
        readDielectricSpecular(source, name, material);
        // Every texture is read per pixel by the material's shader variant (lidr/render/material_variants.h).
        if (source.emissiveTexture.index >= 0)
            material.emissiveTexture = readTexture(source.emissiveTexture.index, source.emissiveTexture.texCoord,
                                                   source.emissiveTexture.extensions, name + ": emissive texture");
        if (pbr.metallicRoughnessTexture.index >= 0)  // glTF: roughness in G, metallic in B, linear data
            material.metallicRoughnessTexture =
                readTexture(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                            pbr.metallicRoughnessTexture.extensions, name + ": metallic-roughness texture");
        if (source.occlusionTexture.index >= 0) {
            material.occlusionTexture = readTexture(source.occlusionTexture.index, source.occlusionTexture.texCoord,
                                                    source.occlusionTexture.extensions, name + ": occlusion texture");
            if (!(std::isfinite(source.occlusionTexture.strength) && source.occlusionTexture.strength >= 0.0 &&
                  source.occlusionTexture.strength <= 1.0))
                fail(name + ": occlusionTexture strength must be in [0, 1], got " +
                     std::to_string(source.occlusionTexture.strength));
            material.occlusionTexture.scale = float(source.occlusionTexture.strength);
        }
        if (source.normalTexture.index >= 0) {
            material.normalTexture = readTexture(source.normalTexture.index, source.normalTexture.texCoord,
                                                 source.normalTexture.extensions, name + ": normal texture");
            if (!std::isfinite(source.normalTexture.scale))
                fail(name + ": normalTexture scale is not finite");
            material.normalTexture.scale = float(source.normalTexture.scale);
        }
        const int texture = pbr.baseColorTexture.index;
        if (texture >= 0) {
            const MaterialTexture read = readTexture(texture, pbr.baseColorTexture.texCoord,
                                                     pbr.baseColorTexture.extensions, name + ": base colour texture");
            material.diffuseImage = read.image;
            material.diffuseTexture = read.name;
            material.diffuseMapping = read.mapping;
        }
        const int index = findOrAddMaterial(scene_, material);
        sceneMaterialOf_[gltfMaterial] = index;
        return index;
    }

    // ---- lights and cameras ----------------------------------------------------------------------------------

    // extras.lidr.shadow of a light or its node (the validator checked it is true or false); false where absent.
    static bool lidrShadowFlag(const tinygltf::Value& extras, bool& flag) {
        if (!extras.IsObject() || !extras.Has("lidr")) return false;
        const tinygltf::Value& lidr = extras.Get("lidr");
        if (!lidr.Has("shadow")) return false;
        flag = lidr.Get("shadow").Get<bool>();
        return true;
    }

    void readLight(const tinygltf::Value& value, const std::string& nodeName, const glm::mat4& world,
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
    bool nodeDirection(const glm::mat4& world, const std::string& name, const std::string& nodeName, glm::vec3& out) {
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
    void readDirectionalLight(const std::string& name, const std::string& nodeName, const glm::vec3& color,
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
    void listCameras() {
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
    void readCamera(const tinygltf::Node& node, const std::string& nodeName, const glm::mat4& world, int animationNode) {
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

    Scene& scene_;
    const std::string& path_;
    const glm::mat4 transform_;
    const int overrideMaterial_;
    tinygltf::Model model_;
    std::string stem_;
    std::map<int, int> sceneMaterialOf_;
    std::map<int, std::shared_ptr<const ImageRGBA8>> decodedImages_;  // by glTF image index
    ImageFailures imageFailures_;
    GltfContents contents_;
    bool animated_ = false;          // the file has animations: its nodes join Scene::animation
    size_t nodeBase_ = 0;            // the first of this file's nodes in Scene::animation
    std::vector<int> nodeOf_;        // per glTF node, its AnimationNode (-1: not in the default scene)
    std::vector<int> directionalNodes_;  // the nodes of the directional lights read
};

}  // namespace

float gltfLightRadiusWithoutRange(float brightestChannel) {
    // Windowed, the light differs from the unwindowed one by C / d^2 x (d / r)^4 <= C / r^2 (at d = r), and
    // beyond r the real light gives less than C / r^2 too: r = sqrt(C / threshold) keeps both under it.
    const float radius = std::sqrt(std::max(brightestChannel, 0.0f) / gltfLightCutThreshold);
    return glm::clamp(radius, gltfLightMinRadius, gltfLightMaxRadius);
}

GltfContents appendGltf(Scene& scene, const std::string& path, const glm::mat4& transform, int overrideMaterial) {
    return GltfReader(scene, path, transform, overrideMaterial).read();
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
