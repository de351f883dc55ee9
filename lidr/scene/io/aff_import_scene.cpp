// The AFF importer's Scene, made once every file is read: keyframes onto their nodes, the camera, the geometry
// posed and merged, materials, lights placed, the far plane.
#include "lidr/scene/io/aff_importer_internal.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>

#include "lidr/base/colour.h"
#include "lidr/base/error.h"
#include "lidr/scene/camera.h"
#include "lidr/scene/io/mesh_split.h"

namespace lidr::aff_import {

namespace fs = std::filesystem;

// Nodes named like a `k` are animated by it (the keys' translation, rotation, scale; each missing one identity).
void AffReader::attachKeyFrames(Scene& scene) {
    std::map<std::string, std::vector<std::string>> unkeyed;  // file -> names
    for (size_t i = 0; i < nodes_.size(); ++i) {
        AnimationNode& node = nodes_[i];
        if (node.name.empty()) continue;
        const auto found = keys_.find(node.name);
        if (found == keys_.end()) {
            auto& names = unkeyed[nodeWhere_[i].substr(0, nodeWhere_[i].rfind(':'))];
            if (std::find(names.begin(), names.end(), node.name) == names.end()) names.push_back(node.name);
            continue;
        }
        found->second.used = true;
        node.animated = true;
        node.translationTrack = found->second.translation;
        node.rotationTrack = found->second.rotation;
        node.scaleTrack = found->second.scale;
    }
    for (const auto& [file, names] : unkeyed) {
        std::string list;
        for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
        scene.warnings.push_back(file + ": transforms without keyframes (k NAME) stay as they are: " + list);
    }
    for (const auto& [name, keys] : keys_)
        if (!keys.used && name != "camera")
            scene.warnings.push_back(keys.where + ": keyframes '" + name +
                                     "' move nothing (no transform x or light la has that name)");
}

// The view: `v`, on a node that `k camera` animates (its translation the eye, its rotation turning the view
// that looks down -z with +y up; the one it lacks stays as `v` gives it).
void AffReader::addCamera(Scene& scene) {
    Camera& camera = scene.camera;
    if (view_.given) {
        camera.position = view_.from;
        camera.target = view_.at;
        camera.up = view_.up;
        camera.fovYDegrees = view_.angle;  // BART: the angle is the vertical field of view where width != height
        camera.nearPlane = view_.hither;
        scene.width = view_.width;
        scene.height = view_.height;
    }
    const auto keys = keys_.find("camera");
    if (keys == keys_.end()) return;
    keys->second.used = true;
    AnimationNode node;
    node.name = "camera";
    node.animated = true;
    node.translation = camera.position;
    const glm::vec3 forward = camera.target - camera.position;
    if (glm::length(forward) > 0.0f && glm::length(glm::cross(forward, camera.up)) > 0.0f)
        node.rotation = glm::quat_cast(glm::inverse(glm::lookAt(glm::vec3(0.0f), forward, camera.up)));
    node.translationTrack = keys->second.translation;
    node.rotationTrack = keys->second.rotation;
    node.scaleTrack = keys->second.scale;
    nodes_.push_back(std::move(node));
    nodeWhere_.push_back(keys->second.where);
    cameraNode_ = int(nodes_.size() - 1);
}

// Geometry baked at the start time into world space, merged per (node, look): one mesh per material and moving
// part; the static parts by material in 64-unit cells, so per-mesh light culling still has pieces to skip.
void AffReader::poseGeometry(Scene& scene) {
    SceneAnimation& a = scene.animation;
    a.nodes = std::move(nodes_);
    a.cameraNode = cameraNode_;
    a.start = rangeGiven_ ? start_ : 0.0f;
    a.end = rangeGiven_ ? end_ : 0.0f;
    a.frames = rangeGiven_ ? frames_ : 0;
    if (!rangeGiven_) keyRange(a);  // without `a`: the keyframes' own range, no frame count
    scene.time = rangeGiven_ ? a.start : 0.0f;
    world_ = a.worldAt(a.start);
    a.posedWorld = world_;
    const std::vector<bool> moving = a.movingNodes();
    std::vector<int> lookMaterial(looks_.size(), -1);
    std::map<std::tuple<int, size_t, int, int, int>, size_t> meshOf;
    std::vector<Mesh> meshes;
    std::vector<int> meshNodes;
    for (Piece& piece : pieces_) {
        const glm::mat4 w = piece.node >= 0 ? world_[size_t(piece.node)] : glm::mat4(1.0f);
        bake(piece.mesh, w);
        const bool moves = piece.node >= 0 && moving[size_t(piece.node)];
        glm::ivec3 cell(0);
        if (!moves) {
            glm::vec3 centroid(0.0f);
            for (const glm::vec3& p : piece.mesh.positions) centroid += p;
            cell = glm::ivec3(glm::clamp(glm::floor(centroid / float(piece.mesh.positions.size()) / 64.0f),
                                         glm::vec3(-1e6f), glm::vec3(1e6f)));
        }
        const auto key = std::make_tuple(moves ? piece.node : -1, piece.look, cell.x, cell.y, cell.z);
        const auto [found, added] = meshOf.emplace(key, meshes.size());
        if (added) {
            if (lookMaterial[piece.look] < 0) lookMaterial[piece.look] = findOrAddMaterial(scene, material(looks_[piece.look], scene));
            Mesh m;
            m.name = piece.mesh.name;
            m.material = lookMaterial[piece.look];
            meshes.push_back(std::move(m));
            meshNodes.push_back(moves ? piece.node : -1);
        }
        append(meshes[found->second], piece.mesh);
    }
    pieces_.clear();
    for (size_t i = 0; i < meshes.size(); ++i)
        for (Mesh& part : splitMeshSpatially(std::move(meshes[i]))) {
            scene.meshes.push_back(std::move(part));
            a.meshNodes.push_back(meshNodes[i]);
        }
    if (std::all_of(a.meshNodes.begin(), a.meshNodes.end(), [](int n) { return n < 0; })) a.meshNodes.clear();
    if (transmissive_ > 0)
        scene.warnings.push_back(root_ + ": " + std::to_string(transmissive_) +
                                 " materials transmit light (fm T > 0): drawn transparent with opacity 1 - T; "
                                 "their refraction (index of refraction) is not drawn");
}

// From the earliest to the latest key of every track (0 .. 0 without any).
void AffReader::keyRange(SceneAnimation& a) {
    bool any = false;
    const auto cover = [&](const std::vector<float>& times) {
        if (times.empty()) return;
        a.start = any ? std::min(a.start, times.front()) : times.front();
        a.end = any ? std::max(a.end, times.back()) : times.back();
        any = true;
    };
    for (const AnimationNode& n : a.nodes) {
        if (n.translationTrack) cover(n.translationTrack->times);
        if (n.rotationTrack) cover(n.rotationTrack->times);
        if (n.scaleTrack) cover(n.scaleTrack->times);
    }
}

void AffReader::bake(Mesh& mesh, const glm::mat4& w) {
    if (w == glm::mat4(1.0f)) return;
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(w)));
    for (glm::vec3& p : mesh.positions) p = glm::vec3(w * glm::vec4(p, 1.0f));
    for (glm::vec3& n : mesh.normals) {
        const glm::vec3 moved = normalMatrix * n;
        const float length = glm::length(moved);
        if (length > 0.0f && std::isfinite(length)) n = moved / length;
    }
    if (glm::determinant(glm::mat3(w)) < 0.0f)
        for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
}

void AffReader::append(Mesh& to, const Mesh& from) {
    const uint32_t base = uint32_t(to.positions.size());
    const bool textured = !from.texCoords.empty();
    if (textured && to.texCoords.size() < to.positions.size()) to.texCoords.resize(to.positions.size(), glm::vec2(0.0f));
    to.positions.insert(to.positions.end(), from.positions.begin(), from.positions.end());
    to.normals.insert(to.normals.end(), from.normals.begin(), from.normals.end());
    if (textured) to.texCoords.insert(to.texCoords.end(), from.texCoords.begin(), from.texCoords.end());
    else if (!to.texCoords.empty()) to.texCoords.resize(to.positions.size(), glm::vec2(0.0f));
    for (uint32_t i : from.indices) to.indices.push_back(base + i);
}

// BART's Phong material as lidr's (doc/scene-format.md, "AFF"): diffuse and specular colours as display values,
// the exponent x 4 as Blinn-Phong's (metallicRoughnessOf turns them into the BRDF's base colour, metallic,
// roughness), the texture modulating the diffuse colour; the ambient colour times `am` becomes the emission
// (textured like the diffuse), BART's ambient term; transmittance T makes it transparent (opacity 1 - T).
Material AffReader::material(const Look& look, const Scene&) {
    const AffMaterial& m = look.material;
    Material out;
    out.name = m.where + (look.texture.empty() ? "" : " " + fs::path(look.texture).filename().string());
    out.diffuse = displayColourToLinear(m.diffuse);
    out.specular = displayColourToLinear(m.specular);
    out.shininess = std::max(1.0f, 4.0f * m.shine);
    out.emissive = displayColourToLinear(m.ambient * ambient_);
    if (m.transmittance > 0.0f) {
        out.opacity = std::max(0.05f, 1.0f - m.transmittance);
        ++transmissive_;
    }
    if (!look.texture.empty()) {
        out.diffuseTexture = look.texture;
        out.diffuseImage = textures_.at(look.texture);
        if (out.emissive != glm::vec3(0.0f)) {
            out.emissiveTexture.name = look.texture;
            out.emissiveTexture.image = out.diffuseImage;
        }
    }
    return out;
}

// `l` lights: lidr's lights fade to nothing at their radius, BART's do not fade: the radius reaches twice as
// far as the farthest corner of the scene's bounds, so the falloff (1 - d^2 / r^2) stays within [0.75, 1] over
// the scene. Lights under a moving transform (or `la`) ride on their node.
void AffReader::placeLights(Scene& scene) {
    const glm::vec3 lo = scene.boundsMin(), hi = scene.boundsMax();
    const std::vector<bool> moving = scene.animation.movingNodes();
    bool carried = false;
    for (const AffLight& l : lights_) {
        PointLight light = l.light;
        light.color = displayColourToLinear(light.color);
        const glm::mat4 w = l.node >= 0 ? world_[size_t(l.node)] : glm::mat4(1.0f);
        const glm::vec3 local = light.position;
        light.position = glm::vec3(w * glm::vec4(local, 1.0f));
        float farthest = 0.0f;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 c(corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z);
            farthest = std::max(farthest, glm::length(c - light.position));
        }
        light.radius = std::max(1.0f, 2.0f * farthest);
        LightBinding binding;
        if (l.node >= 0 && moving[size_t(l.node)]) {
            binding.node = l.node;
            binding.position = local;
            const glm::mat4& wl = world_[size_t(l.node)];
            const float scale = std::max({glm::length(glm::vec3(wl[0])), glm::length(glm::vec3(wl[1])), glm::length(glm::vec3(wl[2]))});
            binding.radius = light.radius / std::max(scale, 1e-6f);
            carried = true;
        }
        scene.lights.push_back(light);
        scene.animation.lightBindings.push_back(binding);
    }
    if (!carried) scene.animation.lightBindings.clear();
    scene.backgroundColor = displayColourToLinear(background_);
    scene.ambient = glm::vec3(0.0f);  // BART's ambient is each material's emission (above)
}

// Far enough for the whole scene from wherever the camera goes (sampled over the animation).
void AffReader::finishCamera(Scene& scene) {
    if (!view_.given && cameraNode_ < 0) {
        scene.camera = cameraFramingBounds(scene.boundsMin(), scene.boundsMax(), scene.camera.fovYDegrees);
        return;
    }
    const glm::vec3 lo = scene.boundsMin(), hi = scene.boundsMax();
    const glm::vec3 center = 0.5f * (lo + hi);
    const float radius = 0.5f * glm::length(hi - lo);
    float farthest = 0.0f;
    const SceneAnimation& a = scene.animation;
    for (int i = 0; i <= 64; ++i) {
        const float t = a.start + (a.end - a.start) * float(i) / 64.0f;
        farthest = std::max(farthest, glm::length(cameraAt(scene, t).position - center));
    }
    scene.camera.farPlane = std::max(scene.camera.nearPlane * 2.0f, 1.01f * (farthest + radius));
    scene.camera = cameraAt(scene, scene.time);
}

}  // namespace lidr::aff_import
