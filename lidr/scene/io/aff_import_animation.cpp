// The AFF importer's transforms (xs static, x named: animated by the `k` of that name) and keyframes (k: Kochanek-
// Bartels tracks), read into the node tree of Scene::animation.
#include "lidr/scene/io/aff_importer_internal.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "lidr/base/error.h"
#include "lidr/scene/io/file_checks.h"
#include "lidr/scene/kochanek_bartels.h"

namespace lidr::aff_import {

int AffReader::addNode(AffTokens& in, const std::string& name, int parent, const glm::mat4& rest) {
    if (nodes_.size() >= maxAffNodes) in.fail("more than " + std::to_string(maxAffNodes) + " transforms in all");
    AnimationNode node;
    node.name = name;
    node.parent = parent;
    node.rest = rest;
    nodes_.push_back(std::move(node));
    nodeWhere_.push_back(in.path() + ":" + std::to_string(in.line()));
    return int(nodes_.size() - 1);
}

void AffReader::transform(AffTokens& in, bool isStatic) {
    int node = currentNode();
    if (isStatic) {
        const glm::vec3 scale = vector3(in, "xs scale");
        const glm::vec3 axis = vector3(in, "xs rotation axis");
        const float degrees = in.number("xs rotation angle");
        const glm::vec3 translation = vector3(in, "xs translation");
        const float axisLength = glm::length(axis);
        if (degrees != 0.0f && !(axisLength > 0.0f))
            in.fail("xs rotates " + str(degrees) + " degrees about a zero axis");
        glm::mat4 m = glm::translate(glm::mat4(1.0f), translation);
        if (degrees != 0.0f) m = glm::rotate(m, glm::radians(degrees), axis / axisLength);
        m = glm::scale(m, scale);
        if (glm::determinant(glm::mat3(m)) == 0.0f) in.fail("xs scale " + str(scale) + " flattens everything in it");
        // The identity (xs 1 1 1 0 0 1 0 0 0 0, as every BART part file opens) adds no node.
        if (m != glm::mat4(1.0f)) node = addNode(in, "", node, m);
    } else {
        node = addNode(in, in.word("the transform's name (x NAME)"), node, glm::mat4(1.0f));
    }
    in.expect("{", isStatic ? "a static transform (xs) opens a block" : "a transform (x NAME) opens a block");
    nodeStack_.push_back(node);
}

void AffReader::keyFrames(AffTokens& in) {
    const std::string name = in.word("the keyframes' name (k NAME)");
    const int line = in.line();
    const std::string where = in.path() + ":" + std::to_string(line);
    KeyFrames keys;
    keys.where = where;
    in.expect("{", "keyframes (k " + clipped(name, 40) + ") open a block");
    while (in.peek() != "}") {
        const std::string kind = in.word("keyframes (transl, rot, scale) or '}'");
        const int kindLine = in.line();
        const long count = in.integer(kind + " key count", 0, long(maxAffKeys));
        if (kind == "transl" || kind == "scale") {
            if ((kind == "transl" ? keys.translation : keys.scale)) in.fail(kind + " keys given twice for '" + name + "'");
            std::vector<KochanekBartelsKey> list;
            for (long i = 0; i < count; ++i) {
                KochanekBartelsKey k;
                k.time = in.number(kind + " key time");
                k.value = vector3(in, kind + " key");
                k.tension = in.number("tension"), k.continuity = in.number("continuity"), k.bias = in.number("bias");
                list.push_back(k);
            }
            if (!keysInTimeOrder(list)) outOfOrder(in, kindLine, name, kind);
            try {
                (kind == "transl" ? keys.translation : keys.scale) = kochanekBartelsTrack(list);
            } catch (const Error& e) {
                in.failAt(kindLine, "keyframes '" + clipped(name, 40) + "', " + kind + ": " + e.what());
            }
        } else if (kind == "rot") {
            if (keys.rotation) in.fail("rot keys given twice for '" + name + "'");
            std::vector<KochanekBartelsRotationKey> list;
            for (long i = 0; i < count; ++i) {
                KochanekBartelsRotationKey k;
                k.time = in.number("rot key time");
                k.axis = vector3(in, "rot key axis");
                k.angleRadians = glm::radians(in.number("rot key angle (degrees)"));
                k.tension = in.number("tension"), k.continuity = in.number("continuity"), k.bias = in.number("bias");
                list.push_back(k);
            }
            if (!keysInTimeOrder(list)) outOfOrder(in, kindLine, name, kind);
            try {
                keys.rotation = kochanekBartelsRotationTrack(list);
            } catch (const Error& e) {
                in.failAt(kindLine, "keyframes '" + clipped(name, 40) + "', rot: " + e.what());
            }
        } else if (kind == "visibility") {
            in.fail("visibility keyframes are not read: lidr draws every object at every time");
        } else {
            in.fail("unknown keyframe kind '" + clipped(kind, 40) + "' (transl, rot or scale)");
        }
    }
    in.expect("}", "the keyframes' block closes");
    const auto [found, added] = keys_.emplace(name, keys);
    if (!added) in.failAt(line, "keyframes '" + clipped(name, 40) + "' given twice (first at " + found->second.where + ")");
}

void AffReader::outOfOrder(AffTokens& in, int line, const std::string& name, const std::string& kind) {
    warnings_.push_back(in.path() + ":" + std::to_string(line) + ": keyframes '" + name + "', " + kind +
                        ": times go back; read as BART reads them (at each time the first segment in key order "
                        "that ends after it)");
}

}  // namespace lidr::aff_import
