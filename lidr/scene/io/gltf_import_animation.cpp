// The glTF importer's animation (gltf_animation.h reads the channels): the node tree as Scene::animation's
// AnimationNodes, and what each node carries.
#include "lidr/scene/io/gltf_importer_internal.h"

#include <algorithm>

#include <glm/gtc/quaternion.hpp>

#include "lidr/scene/io/gltf_animation.h"

namespace lidr::gltf_import {

// Where the file has animations: its nodes join the scene's animation (after any it has), under a static root
// holding `transform` where that is not the identity. Returns the root's node, -1: none.
int GltfReader::startAnimation() {
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

int GltfReader::addAnimationNode(int nodeIndex, const tinygltf::Node& node, const std::string& name, int parentNode) {
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
void GltfReader::carry(int animationNode, size_t meshesBefore, size_t lightsBefore, const glm::mat4& world) {
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
void GltfReader::finishAnimation() {
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

}  // namespace lidr::gltf_import
