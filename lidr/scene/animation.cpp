#include "lidr/scene/animation.h"

#include <algorithm>
#include <cmath>

#include "lidr/base/error.h"
#include "lidr/scene/kochanek_bartels.h"
#include "lidr/scene/scene.h"

namespace lidr {

namespace {

// Where t falls: i with times[i] <= t < times[i + 1] and the fraction u, or false before the first time (i = 0) or
// from the last on (i = the last).
bool locate(const std::vector<float>& times, float t, size_t& i, float& u) {
    if (!(t > times.front())) {  // NaN holds the first key too
        i = 0;
        return false;
    }
    if (t >= times.back()) {
        i = times.size() - 1;
        return false;
    }
    i = size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
    u = (t - times[i]) / (times[i + 1] - times[i]);  // times[i] <= t < times[i + 1]: a segment of positive length
    return true;
}

// glTF's cubic Hermite (specification, appendix C): v0 + out-tangent b0, v1 + in-tangent a1, over a segment of `td`.
template <typename T>
T hermite(const T& v0, const T& b0, const T& a1, const T& v1, float td, float s) {
    const float s2 = s * s, s3 = s2 * s;
    return v0 * (2.0f * s3 - 3.0f * s2 + 1.0f) + b0 * (td * (s3 - 2.0f * s2 + s)) + v1 * (-2.0f * s3 + 3.0f * s2) +
           a1 * (td * (s3 - s2));
}

// A key's value: CubicSpline keeps three per key (in-tangent, value, out-tangent).
template <typename T>
const T& keyValue(const std::vector<T>& values, Interpolation interpolation, size_t key) {
    return interpolation == Interpolation::CubicSpline ? values[3 * key + 1] : values[key];
}

// A scale axis never quite reaches 0: the transform stays invertible (a glTF node scaled to 0 to hide it is drawn a
// ten-thousandth of its size), so the geometry posed there can be moved back.
glm::vec3 invertibleScale(glm::vec3 s) {
    for (int c = 0; c < 3; ++c)
        if (std::abs(s[c]) < 1e-4f) s[c] = s[c] < 0.0f ? -1e-4f : 1e-4f;
    return s;
}

[[noreturn]] void fail(const std::string& what) { throw Error("animation: " + what); }

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite(const glm::quat& q) { return std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w); }

template <typename Track>
void validateTrack(const Track& track, const std::string& item) {
    if (track.times.empty()) fail(item + " has no keys");
    for (size_t i = 0; i < track.times.size(); ++i) {
        if (!std::isfinite(track.times[i])) fail(item + ": key " + std::to_string(i) + " time is not finite");
        if (i > 0 && !(track.times[i] > track.times[i - 1]))
            fail(item + ": key " + std::to_string(i) + " time " + std::to_string(track.times[i]) +
                 " does not follow the previous key's " + std::to_string(track.times[i - 1]));
    }
    const bool kb = track.interpolation == Interpolation::KochanekBartels;
    const size_t per = track.interpolation == Interpolation::CubicSpline ? 3 : 1;
    const size_t values = kb ? 2 : per * track.times.size();
    if (track.values.size() != values)
        fail(item + ": " + std::to_string(track.values.size()) + " values for " + std::to_string(track.times.size()) +
             " keys (" + interpolationName(track.interpolation) + ")");
    for (const auto& v : track.values)
        if (!finite(v)) fail(item + ": a value is not finite");
    const size_t pieces = kb ? track.times.size() - 1 : 0;
    if (kb && pieces == 0) fail(item + ": a Kochanek-Bartels track needs a piece");
    if (track.segments.size() != 4 * pieces || track.spans.start.size() != pieces || track.spans.length.size() != pieces)
        fail(item + ": " + std::to_string(track.segments.size()) + " segment coefficients and " +
             std::to_string(track.spans.start.size()) + " spans for " + std::to_string(pieces) + " pieces");
    for (const auto& v : track.segments)
        if (!finite(v)) fail(item + ": a segment coefficient is not finite");
    for (size_t i = 0; i < pieces; ++i)
        if (!std::isfinite(track.spans.start[i]) || !std::isfinite(track.spans.length[i]) || track.spans.length[i] == 0.0f)
            fail(item + ": piece " + std::to_string(i) + "'s span is not finite or empty");
}

}  // namespace

const char* interpolationName(Interpolation interpolation) {
    switch (interpolation) {
    case Interpolation::Step: return "STEP";
    case Interpolation::Linear: return "LINEAR";
    case Interpolation::CubicSpline: return "CUBICSPLINE";
    case Interpolation::KochanekBartels: return "Kochanek-Bartels";
    }
    return "?";
}

glm::vec3 Vec3Track::at(float t) const {
    size_t i = 0;
    float u = 0.0f;
    const bool kb = interpolation == Interpolation::KochanekBartels;
    if (!locate(times, t, i, u)) return kb ? (i == 0 ? values.front() : values.back()) : keyValue(values, interpolation, i);
    switch (interpolation) {
    case Interpolation::Step: return values[i];
    case Interpolation::Linear: return glm::mix(values[i], values[i + 1], u);
    case Interpolation::CubicSpline:
        return hermite(values[3 * i + 1], values[3 * i + 2], values[3 * i + 3], values[3 * i + 4], times[i + 1] - times[i], u);
    case Interpolation::KochanekBartels: {
        const glm::vec3* c = &segments[4 * i];
        const float v = (t - spans.start[i]) / spans.length[i];
        return c[0] + v * (c[1] + v * (c[2] + v * c[3]));
    }
    }
    return values[i];
}

glm::quat RotationTrack::at(float t) const {
    size_t i = 0;
    float u = 0.0f;
    const bool kb = interpolation == Interpolation::KochanekBartels;
    if (!locate(times, t, i, u))
        return glm::normalize(kb ? (i == 0 ? values.front() : values.back()) : keyValue(values, interpolation, i));
    switch (interpolation) {
    case Interpolation::Step: return glm::normalize(values[i]);
    case Interpolation::Linear: {
        const glm::quat& a = values[i];
        const glm::quat b = glm::dot(a, values[i + 1]) < 0.0f ? -values[i + 1] : values[i + 1];  // the shorter arc
        return glm::normalize(quatSlerp(a, b, u));
    }
    case Interpolation::CubicSpline:
        return glm::normalize(
            hermite(values[3 * i + 1], values[3 * i + 2], values[3 * i + 3], values[3 * i + 4], times[i + 1] - times[i], u));
    case Interpolation::KochanekBartels: {
        const glm::quat* s = &segments[4 * i];
        return glm::normalize(quatSquad(s[0], s[1], s[2], s[3], (t - spans.start[i]) / spans.length[i]));
    }
    }
    return values[i];
}

glm::mat4 AnimationNode::localAt(float t) const {
    if (!animated) return rest;
    const glm::vec3 T = translationTrack ? translationTrack->at(t) : translation;
    const glm::quat R = rotationTrack ? rotationTrack->at(t) : rotation;
    const glm::vec3 S = invertibleScale(scaleTrack ? scaleTrack->at(t) : scale);
    glm::mat4 m = glm::mat4_cast(glm::normalize(R));
    m[0] *= S.x;
    m[1] *= S.y;
    m[2] *= S.z;
    m[3] = glm::vec4(T, 1.0f);
    return m;
}

bool SceneAnimation::moves() const {
    return std::any_of(nodes.begin(), nodes.end(), [](const AnimationNode& n) { return n.animated; });
}

std::vector<bool> SceneAnimation::movingNodes() const {
    std::vector<bool> moving(nodes.size(), false);
    for (size_t i = 0; i < nodes.size(); ++i)
        moving[i] = nodes[i].animated || (nodes[i].parent >= 0 && moving[size_t(nodes[i].parent)]);
    return moving;
}

std::vector<glm::mat4> SceneAnimation::worldAt(float t) const {
    std::vector<glm::mat4> world(nodes.size());
    for (size_t i = 0; i < nodes.size(); ++i) {
        const glm::mat4 local = nodes[i].localAt(t);
        world[i] = nodes[i].parent >= 0 ? world[size_t(nodes[i].parent)] * local : local;
    }
    return world;
}

float SceneAnimation::frameTime(int frame) const {
    if (frames <= 1) return start;
    return start + float(double(frame) * (double(end) - double(start)) / double(frames - 1));
}

void validateAnimation(const SceneAnimation& a, size_t meshes, size_t lights, size_t views) {
    if (!std::isfinite(a.start) || !std::isfinite(a.end) || a.end < a.start)
        fail("time range " + std::to_string(a.start) + " .. " + std::to_string(a.end) + " must be finite, start <= end");
    if (a.frames < 0) fail("frame count " + std::to_string(a.frames) + " must be >= 0");
    for (size_t i = 0; i < a.nodes.size(); ++i) {
        const AnimationNode& n = a.nodes[i];
        const std::string item = "node " + std::to_string(i) + (n.name.empty() ? "" : " '" + n.name + "'");
        if (n.parent < -1 || n.parent >= int(i)) fail(item + ": parent " + std::to_string(n.parent) + " is not an earlier node");
        for (int c = 0; c < 4; ++c)
            if (!finite(glm::vec3(n.rest[c])) || !std::isfinite(n.rest[c][3])) fail(item + ": rest transform is not finite");
        if (!finite(n.translation) || !finite(n.rotation) || !finite(n.scale)) fail(item + ": rest TRS is not finite");
        if (n.translationTrack) validateTrack(*n.translationTrack, item + " translation");
        if (n.rotationTrack) validateTrack(*n.rotationTrack, item + " rotation");
        if (n.scaleTrack) validateTrack(*n.scaleTrack, item + " scale");
        if (!n.animated && (n.translationTrack || n.rotationTrack || n.scaleTrack)) fail(item + ": tracks on a static node");
    }
    const auto checkNode = [&](int node, const std::string& item) {
        if (node < -1 || node >= int(a.nodes.size()))
            fail(item + ": node " + std::to_string(node) + " out of range (" + std::to_string(a.nodes.size()) + " nodes)");
    };
    if (a.meshNodes.size() > meshes)
        fail(std::to_string(a.meshNodes.size()) + " mesh bindings for " + std::to_string(meshes) + " meshes");
    for (size_t i = 0; i < a.meshNodes.size(); ++i) checkNode(a.meshNodes[i], "mesh " + std::to_string(i));
    if (a.lightBindings.size() > lights)
        fail(std::to_string(a.lightBindings.size()) + " light bindings for " + std::to_string(lights) + " lights");
    for (size_t i = 0; i < a.lightBindings.size(); ++i) {
        const LightBinding& b = a.lightBindings[i];
        checkNode(b.node, "light " + std::to_string(i));
        if (!finite(b.position) || !finite(b.direction) || !(std::isfinite(b.radius) && b.radius > 0.0f))
            fail("light " + std::to_string(i) + ": its place on the node is not finite (or its radius not > 0)");
    }
    if (a.viewNodes.size() > views)
        fail(std::to_string(a.viewNodes.size()) + " view bindings for " + std::to_string(views) + " views");
    for (size_t i = 0; i < a.viewNodes.size(); ++i) checkNode(a.viewNodes[i], "view " + std::to_string(i));
    checkNode(a.cameraNode, "camera");
    if (!a.nodes.empty() && a.posedWorld.size() != a.nodes.size())
        fail(std::to_string(a.posedWorld.size()) + " posed transforms for " + std::to_string(a.nodes.size()) + " nodes");
}

std::vector<glm::mat4> meshTransformsAt(const Scene& scene, float t) {
    const SceneAnimation& a = scene.animation;
    std::vector<glm::mat4> result(scene.meshes.size(), glm::mat4(1.0f));
    if (a.empty()) return result;
    const std::vector<glm::mat4> world = a.worldAt(t);
    const std::vector<bool> moving = a.movingNodes();
    std::vector<glm::mat4> delta(a.nodes.size(), glm::mat4(1.0f));
    std::vector<bool> done(a.nodes.size(), false);
    for (size_t m = 0; m < a.meshNodes.size() && m < result.size(); ++m) {
        const int n = a.meshNodes[m];
        if (n < 0 || !moving[size_t(n)]) continue;
        if (!done[size_t(n)]) {
            delta[size_t(n)] = world[size_t(n)] * glm::inverse(a.posedWorld[size_t(n)]);
            done[size_t(n)] = true;
        }
        result[m] = delta[size_t(n)];
    }
    return result;
}

std::vector<size_t> movingMeshes(const Scene& scene) {
    const SceneAnimation& a = scene.animation;
    std::vector<size_t> result;
    const std::vector<bool> moving = a.movingNodes();
    for (size_t m = 0; m < a.meshNodes.size() && m < scene.meshes.size(); ++m)
        if (a.meshNodes[m] >= 0 && moving[size_t(a.meshNodes[m])]) result.push_back(m);
    return result;
}

namespace {
Camera cameraOnNode(const Camera& base, const glm::mat4& world) {
    Camera c = base;
    const glm::vec3 eye(world[3]);
    glm::vec3 forward = glm::vec3(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
    glm::vec3 up = glm::vec3(world * glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
    const float forwardLength = glm::length(forward), upLength = glm::length(up);
    if (!(forwardLength > 0.0f) || !(upLength > 0.0f) || !std::isfinite(forwardLength) || !std::isfinite(upLength)) return base;
    forward /= forwardLength;
    up /= upLength;
    const float distance = glm::length(base.target - base.position);
    c.position = eye;
    c.target = eye + forward * (distance > 0.0f && std::isfinite(distance) ? distance : 1.0f);
    c.up = up;
    return c;
}
}  // namespace

Camera cameraAt(const Scene& scene, float t) {
    const SceneAnimation& a = scene.animation;
    if (a.cameraNode < 0 || size_t(a.cameraNode) >= a.nodes.size()) return scene.camera;
    return cameraOnNode(scene.camera, a.worldAt(t)[size_t(a.cameraNode)]);
}

void poseScene(Scene& scene, float t) {
    SceneAnimation& a = scene.animation;
    if (a.empty()) {
        scene.time = t;
        return;
    }
    const std::vector<glm::mat4> world = a.worldAt(t);
    const std::vector<glm::mat4> moves = meshTransformsAt(scene, t);
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const glm::mat4& move = moves[m];
        if (move == glm::mat4(1.0f)) continue;
        Mesh& mesh = scene.meshes[m];
        const glm::mat3 linear(move);
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));
        const bool mirrored = glm::determinant(linear) < 0.0f;
        for (glm::vec3& p : mesh.positions) p = glm::vec3(move * glm::vec4(p, 1.0f));
        for (glm::vec3& n : mesh.normals) {
            const glm::vec3 moved = normalMatrix * n;
            const float length = glm::length(moved);
            if (length > 0.0f && std::isfinite(length)) n = moved / length;
        }
        for (glm::vec4& tangent : mesh.tangents) {
            const glm::vec3 moved = linear * glm::vec3(tangent);
            const float length = glm::length(moved);
            if (length > 0.0f && std::isfinite(length)) tangent = glm::vec4(moved / length, mirrored ? -tangent.w : tangent.w);
        }
        if (mirrored)  // keep the triangles counter-clockwise seen from outside
            for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
    }
    if (a.cameraNode >= 0 && size_t(a.cameraNode) < world.size())
        scene.camera = cameraOnNode(scene.camera, world[size_t(a.cameraNode)]);
    a.posedWorld = world;
    scene.time = t;
}

}  // namespace lidr
