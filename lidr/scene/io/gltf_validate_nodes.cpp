// The glTF validator's checks of what nodes place and how they link: cameras, lights (KHR_lights_punctual and
// lidr's extras), meshes and their primitives, skins, nodes (a forest: one parent each, no cycle), scenes (roots
// only) and animations (gltf_validator_internal.h).
#include <cmath>
#include <set>

#include "lidr/scene/io/file_checks.h"
#include "lidr/scene/io/gltf_validator_internal.h"
#include "lidr/scene/scene.h"

namespace lidr::gltf_validation {

void Validator::checkCameras() {
    // Every number is a finite float (number()); the rules hold for the floats lidr keeps, so a znear of 1e-50
    // (0 as a float) or a zfar that rounds to znear is refused here rather than as a bad camera later.
    forEach("cameras", [&](const Json& camera, const std::string& at, size_t) {
        const std::string type = member(camera, at, "type", Kind::String, true)->get<std::string>();
        if (type == "perspective") {
            const Json* p = member(camera, at, "perspective", Kind::Object, true);
            const std::string where = at + "/perspective";
            member(*p, where, "yfov", Kind::Number, true);
            member(*p, where, "znear", Kind::Number, true);
            const float yfov = float(number(*p, where, "yfov", 0));
            if (!(yfov > 0 && yfov < 3.14159265358979f))
                fail(where + "/yfov", "must be in (0, pi) radians, got " + str(yfov));
            const float znear = float(number(*p, where, "znear", 0));
            if (!(znear > 0)) fail(where + "/znear", "must be > 0, got " + str(number(*p, where, "znear", 0)));
            if (p->contains("zfar") && !(float(number(*p, where, "zfar", 0)) > znear))
                fail(where + "/zfar", "must be > znear (" + str(znear) + ")");
            if (p->contains("aspectRatio") && !(float(number(*p, where, "aspectRatio", 1)) > 0))
                fail(where + "/aspectRatio", "must be > 0");
        } else if (type == "orthographic") {
            const Json* o = member(camera, at, "orthographic", Kind::Object, true);
            const std::string where = at + "/orthographic";
            for (const char* key : {"xmag", "ymag", "znear", "zfar"}) member(*o, where, key, Kind::Number, true);
            if (float(number(*o, where, "xmag", 0)) == 0 || float(number(*o, where, "ymag", 0)) == 0)
                fail(where, "xmag and ymag must not be 0");
            const float znear = float(number(*o, where, "znear", 0));
            if (!(znear >= 0)) fail(where + "/znear", "must be >= 0");
            if (!(float(number(*o, where, "zfar", 0)) > znear)) fail(where + "/zfar", "must be > znear");
        } else {
            fail(at + "/type", "'" + clipped(type) + "' is not perspective or orthographic");
        }
    });
}

void Validator::checkLights() {
    const Json* extensions = member(root_, "", "extensions", Kind::Object);
    if (!extensions) return;
    const Json* punctual = member(*extensions, "/extensions", "KHR_lights_punctual", Kind::Object);
    if (!punctual) return;
    const std::string at = "/extensions/KHR_lights_punctual";
    const Json* lights = member(*punctual, at, "lights", Kind::Array, true);
    if (lights->size() > maxSceneLights)
        fail(at + "/lights", std::to_string(lights->size()) + " lights; lidr draws at most " +
                                 std::to_string(maxSceneLights) + " (16-bit light indices)");
    lightCount_ = lights->size();
    forEachIn(*punctual, at, "lights", [&](const Json& light, const std::string& where, size_t) {
        const std::string type = member(light, where, "type", Kind::String, true)->get<std::string>();
        if (type != "point" && type != "spot" && type != "directional")
            fail(where + "/type", "'" + clipped(type) + "' is not point, spot or directional");
        inRange(numbers(light, where, "color", 3), where + "/color", 0, 1);
        const double intensity = number(light, where, "intensity", 1);
        if (!(intensity >= 0 && std::isfinite(intensity))) fail(where + "/intensity", "must be >= 0, got " + str(intensity));
        if (light.contains("range")) {
            const double range = number(light, where, "range", 0);
            if (!(float(range) > 0)) fail(where + "/range", "must be > 0, got " + str(range));
            if (range > double(maxLightRadius))
                fail(where + "/range", "must be at most " + str(double(maxLightRadius)) + " (lidr's largest light radius), got " +
                                           str(range));
        }
        if (type == "spot") {
            const Json* spot = member(light, where, "spot", Kind::Object, true);
            const double inner = number(*spot, where + "/spot", "innerConeAngle", 0);
            const double outer = number(*spot, where + "/spot", "outerConeAngle", 3.14159265358979 / 4);
            if (!(inner >= 0 && inner < outer && outer <= 3.14159265358979 / 2))
                fail(where + "/spot", "cone angles must satisfy 0 <= inner < outer <= pi/2");
        }
        checkLidrExtras(light, where);
    });
}

// lidr's own settings on a light or on the node that places it (doc/scene-format.md, "glTF"): extras.lidr,
// an object whose only key is "shadow" (true or false). Other extras belong to other applications: any type.
// Returns extras.lidr, or null where there is none.
const Json* Validator::checkLidrExtras(const Json& owner, const std::string& at) const {
    const auto extras = owner.find("extras");
    if (extras == owner.end() || !extras->is_object()) return nullptr;
    const Json* lidr = member(*extras, at + "/extras", "lidr", Kind::Object);
    if (!lidr) return nullptr;
    for (const auto& item : lidr->items())
        if (item.key() != "shadow")
            fail(at + "/extras/lidr/" + pointerSegment(item.key()),
                 "unknown lidr setting (lidr reads \"shadow\": true or false, whether the light casts shadows)");
    member(*lidr, at + "/extras/lidr", "shadow", Kind::Boolean);
    return lidr;
}

void Validator::checkMeshes() {
    forEach("meshes", [&](const Json& mesh, const std::string& at, size_t) {
        const Json* primitives = member(mesh, at, "primitives", Kind::Array, true);
        if (primitives->empty()) fail(at + "/primitives", "must have at least one primitive");
        bool morphed = false;
        forEachIn(mesh, at, "primitives", [&](const Json& primitive, const std::string& where, size_t) {
            const Json* attributes = member(primitive, where, "attributes", Kind::Object, true);
            int64_t vertexCount = -1;
            for (const auto& attribute : attributes->items()) {
                const std::string key = where + "/attributes/" + pointerSegment(attribute.key());
                const int64_t accessor = indexAt(attribute.value(), key, accessors_.size(), "accessors");
                const AccessorInfo& info = accessors_[size_t(accessor)];
                // The specification's alignment of vertex attributes, stricter than the component size.
                if (info.bufferView >= 0 && (info.byteOffset % 4 != 0 || views_[size_t(info.bufferView)].byteOffset % 4 != 0))
                    fail(key, "accessor " + std::to_string(accessor) + " starts at byte " +
                                  std::to_string(views_[size_t(info.bufferView)].byteOffset) + " + " +
                                  std::to_string(info.byteOffset) + "; vertex attributes must be 4-byte aligned");
                const int64_t elements = int64_t(info.count);
                if (vertexCount >= 0 && elements != vertexCount)
                    fail(key, "accessor " + std::to_string(accessor) + " has " + std::to_string(elements) +
                                  " elements; the primitive's other attributes have " + std::to_string(vertexCount));
                vertexCount = elements;
            }
            const int64_t indices = index(primitive, where, "indices", "accessors");
            if (indices >= 0) {
                const AccessorInfo& info = accessors_[size_t(indices)];
                if (info.type != "SCALAR" ||
                    (info.componentType != 5121 && info.componentType != 5123 && info.componentType != 5125))
                    fail(where + "/indices", "accessor " + std::to_string(indices) +
                                                 " must be SCALAR of unsigned byte, short or int");
                if (info.bufferView >= 0 && views_[size_t(info.bufferView)].byteStride)
                    fail(where + "/indices", "accessor " + std::to_string(indices) + "'s bufferView " +
                                                 std::to_string(info.bufferView) + " has a byteStride; indices must be tightly packed");
            }
            index(primitive, where, "material", "materials");
            if (primitive.contains("mode")) {
                const int64_t mode = integer(primitive, where, "mode", 4);
                if (mode < 0 || mode > 6) fail(where + "/mode", "must be 0..6, got " + std::to_string(mode));
            }
            forEachIn(primitive, where, "targets", [&](const Json& target, const std::string& t, size_t) {
                morphed = true;
                for (const auto& attribute : target.items())
                    indexAt(attribute.value(), t + "/" + pointerSegment(attribute.key()), accessors_.size(), "accessors");
            });
        });
        if (morphed) warn(at.substr(1) + ": morph targets are not applied (the base shape is drawn)");
    });
}

void Validator::checkSkins() {
    forEach("skins", [&](const Json& skin, const std::string& at, size_t s) {
        index(skin, at, "inverseBindMatrices", "accessors");
        index(skin, at, "skeleton", "nodes");
        const Json* joints = member(skin, at, "joints", Kind::Array, true);
        for (size_t j = 0; j < joints->size(); ++j)
            indexAt((*joints)[j], at + "/joints/" + std::to_string(j), count("nodes"), "nodes");
        const Json* name = member(skin, at, "name", Kind::String);
        warn("skin " + std::to_string(s) + (name ? " '" + name->get<std::string>() + "'" : std::string()) + " (" +
             std::to_string(joints->size()) + " joints) is not applied: its meshes are drawn in their bind pose, moved "
             "only by their own node");
    });
}

void Validator::checkNodes() {
    const size_t nodes = count("nodes");
    std::vector<int64_t> parent(nodes, -1);
    forEach("nodes", [&](const Json& node, const std::string& at, size_t i) {
        index(node, at, "camera", "cameras");
        index(node, at, "mesh", "meshes");
        if (index(node, at, "skin", "skins") >= 0 && !node.contains("mesh"))
            fail(at + "/skin", "a node with a skin must have a mesh");
        const std::vector<double> matrix = numbers(node, at, "matrix", 16);
        const std::vector<double> rotation = numbers(node, at, "rotation", 4);
        const std::vector<double> scale = numbers(node, at, "scale", 3);
        const std::vector<double> translation = numbers(node, at, "translation", 3);
        for (const auto* values : {&matrix, &rotation, &scale, &translation})
            for (double v : *values)
                if (!std::isfinite(v)) fail(at, "transform is not finite");
        if (!matrix.empty()) {
            if (!rotation.empty() || !scale.empty() || !translation.empty())
                fail(at + "/matrix", "a node has matrix or translation/rotation/scale, not both");
            // Column-major: the last row is elements 3, 7, 11, 15.
            if (matrix[3] != 0 || matrix[7] != 0 || matrix[11] != 0 || matrix[15] != 1)
                fail(at + "/matrix", "the last row must be 0 0 0 1 (an affine transform), got " + str(matrix[3]) + " " +
                                         str(matrix[7]) + " " + str(matrix[11]) + " " + str(matrix[15]));
        }
        if (!rotation.empty()) {
            const double length = std::sqrt(rotation[0] * rotation[0] + rotation[1] * rotation[1] +
                                             rotation[2] * rotation[2] + rotation[3] * rotation[3]);
            if (std::abs(length - 1.0) > 0.005)
                fail(at + "/rotation", "must be a unit quaternion, its length is " + str(length));
        }
        if (const Json* children = member(node, at, "children", Kind::Array)) {
            for (size_t c = 0; c < children->size(); ++c) {
                const std::string where = at + "/children/" + std::to_string(c);
                const int64_t child = indexAt((*children)[c], where, nodes, "nodes");
                if (size_t(child) == i) fail(where, "node " + std::to_string(i) + " is its own child");
                if (parent[size_t(child)] == int64_t(i)) fail(where, "node " + std::to_string(child) + " is listed twice");
                if (parent[size_t(child)] >= 0)
                    fail(where, "node " + std::to_string(child) + " already has parent node " +
                                    std::to_string(parent[size_t(child)]) + " (a node has at most one parent)");
                parent[size_t(child)] = int64_t(i);
            }
        }
        bool placesLight = false;
        if (const Json* extensions = member(node, at, "extensions", Kind::Object))
            if (const Json* punctual = member(*extensions, at + "/extensions", "KHR_lights_punctual", Kind::Object)) {
                indexAt(*member(*punctual, at + "/extensions/KHR_lights_punctual", "light", Kind::Integer, true),
                        at + "/extensions/KHR_lights_punctual/light", lightCount_, "lights");
                placesLight = true;
            }
        if (checkLidrExtras(node, at) && !placesLight)
            fail(at + "/extras/lidr", "only for a node with a KHR_lights_punctual light (it says whether that "
                                      "light casts shadows)");
    });
    // One parent each, so a cycle is a walk up the parents that comes back to a node on the same walk.
    std::vector<char> state(nodes, 0);  // 0 unseen, 1 on the current walk, 2 done
    for (size_t start = 0; start < nodes; ++start) {
        std::vector<size_t> walk;
        int64_t at = int64_t(start);
        while (at >= 0 && state[size_t(at)] == 0) {
            state[size_t(at)] = 1;
            walk.push_back(size_t(at));
            at = parent[size_t(at)];
        }
        if (at >= 0 && state[size_t(at)] == 1)
            fail("/nodes/" + std::to_string(at), "node " + std::to_string(at) + " is its own ancestor (a cycle)");
        for (size_t n : walk) state[n] = 2;
    }
    parent_ = std::move(parent);
}

void Validator::checkScenes() {
    forEach("scenes", [&](const Json& scene, const std::string& at, size_t) {
        const Json* nodes = member(scene, at, "nodes", Kind::Array);
        if (!nodes) return;
        std::set<int64_t> seen;
        for (size_t n = 0; n < nodes->size(); ++n) {
            const std::string where = at + "/nodes/" + std::to_string(n);
            const int64_t node = indexAt((*nodes)[n], where, parent_.size(), "nodes");
            if (!seen.insert(node).second) fail(where, "node " + std::to_string(node) + " is listed twice");
            if (parent_[size_t(node)] >= 0)
                fail(where, "node " + std::to_string(node) + " is a child of node " +
                                std::to_string(parent_[size_t(node)]) + "; a scene's nodes must be roots");
        }
    });
}

void Validator::checkAnimations() {
    forEach("animations", [&](const Json& animation, const std::string& at, size_t) {
        const Json* samplers = member(animation, at, "samplers", Kind::Array, true);
        forEachIn(animation, at, "samplers", [&](const Json& sampler, const std::string& where, size_t) {
            const int64_t input = index(sampler, where, "input", "accessors", true);
            const AccessorInfo& info = accessors_[size_t(input)];
            if (info.type != "SCALAR" || info.componentType != 5126)
                fail(where + "/input", "accessor " + std::to_string(input) + " must be SCALAR of float (the key times)");
            index(sampler, where, "output", "accessors", true);
            if (const Json* interpolation = member(sampler, where, "interpolation", Kind::String)) {
                const std::string name = interpolation->get<std::string>();
                if (name != "LINEAR" && name != "STEP" && name != "CUBICSPLINE")
                    fail(where + "/interpolation", "must be LINEAR, STEP or CUBICSPLINE, got '" + name + "'");
            }
        });
        forEachIn(animation, at, "channels", [&](const Json& channel, const std::string& where, size_t) {
            indexAt(*member(channel, where, "sampler", Kind::Integer, true), where + "/sampler", samplers->size(), "samplers");
            const Json& target = *member(channel, where, "target", Kind::Object, true);
            index(target, where + "/target", "node", "nodes");
            const std::string path = member(target, where + "/target", "path", Kind::String, true)->get<std::string>();
            if (path != "translation" && path != "rotation" && path != "scale" && path != "weights" && path != "pointer")
                fail(where + "/target/path", "must be translation, rotation, scale or weights, got '" + path + "'");
        }, true);
    });
}

}  // namespace lidr::gltf_validation
