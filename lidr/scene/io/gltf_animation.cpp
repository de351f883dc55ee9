#include "lidr/scene/io/gltf_animation.h"

#include <cmath>
#include <set>

#include <nlohmann/json.hpp>
#define TINYGLTF_NO_INCLUDE_JSON
#define TINYGLTF_NO_INCLUDE_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>

#include "lidr/base/error.h"
#include "lidr/scene/io/gltf_accessors.h"

namespace lidr {

namespace {

class AnimationReader {
public:
    AnimationReader(const tinygltf::Model& model, const std::string& path, const std::vector<int>& nodeOf,
                    SceneAnimation& animation, std::vector<std::string>& warnings)
        : model_(model), path_(path), nodeOf_(nodeOf), animation_(animation), warnings_(warnings) {}

    void read() {
        for (size_t a = 0; a < model_.animations.size(); ++a) {
            const tinygltf::Animation& source = model_.animations[a];
            name_ = "animation " + std::to_string(a) + (source.name.empty() ? "" : " '" + source.name + "'");
            float start = 0.0f, end = 0.0f;
            int played = 0, weights = 0;
            for (size_t c = 0; c < source.channels.size(); ++c) {
                channel_ = name_ + " channel " + std::to_string(c);
                const tinygltf::AnimationChannel& channel = source.channels[c];
                if (channel.target_path == "weights") {
                    ++weights;
                    continue;
                }
                if (!readChannel(source, channel, start, end, played == 0)) continue;
                ++played;
            }
            if (weights > 0)
                warn(name_ + ": " + std::to_string(weights) + " morph target weight channel" + (weights == 1 ? "" : "s") +
                     " not played (the base shape is drawn)");
            if (played == 0) continue;
            char range[64];
            std::snprintf(range, sizeof range, "%g .. %g s", double(start), double(end));
            if (animation_.clips.empty()) {  // the scene's first clip sets the range
                animation_.start = start, animation_.end = end;
            } else {
                animation_.start = std::min(animation_.start, start), animation_.end = std::max(animation_.end, end);
            }
            animation_.clips.push_back("glTF " + name_ + " (" + std::to_string(played) + " channels, " + range + ")");
        }
    }

private:
    [[noreturn]] void fail(const std::string& problem) const { throw Error(path_ + ": " + channel_ + ": " + problem); }
    void warn(const std::string& warning) { warnings_.push_back(path_ + ": " + warning); }

    bool readChannel(const tinygltf::Animation& source, const tinygltf::AnimationChannel& channel, float& start,
                     float& end, bool firstPlayed) {
        const std::string& property = channel.target_path;
        if (property != "translation" && property != "rotation" && property != "scale") {
            warn(channel_ + ": target path '" + property + "' is not played (lidr plays translation, rotation and scale)");
            return false;
        }
        if (channel.target_node < 0 || size_t(channel.target_node) >= model_.nodes.size())
            fail("target node " + std::to_string(channel.target_node) + " out of range");
        const int nodeIndex = nodeOf_.at(size_t(channel.target_node));
        if (nodeIndex < 0) {
            warn(channel_ + ": node " + std::to_string(channel.target_node) +
                 " is not in the default scene; its " + property + " is not played");
            return false;
        }
        if (model_.nodes[size_t(channel.target_node)].matrix.size() == 16)
            fail("node " + std::to_string(channel.target_node) + " has a matrix; an animated node must give translation, "
                 "rotation and scale (glTF 2.0, 3.5.2)");
        if (!played_.insert({nodeIndex, property}).second) {
            warn(channel_ + ": node " + std::to_string(channel.target_node) + "'s " + property +
                 " is moved by an earlier channel already; this one is not played");
            return false;
        }
        if (channel.sampler < 0 || size_t(channel.sampler) >= source.samplers.size())
            fail("sampler " + std::to_string(channel.sampler) + " out of range");
        const tinygltf::AnimationSampler& sampler = source.samplers[size_t(channel.sampler)];
        const Interpolation interpolation = interpolationOf(sampler.interpolation);
        const std::vector<float> times = readTimes(sampler.input);
        AnimationNode& node = animation_.nodes[size_t(nodeIndex)];
        node.animated = true;
        if (property == "rotation") {
            RotationTrack track;
            track.interpolation = interpolation;
            track.times = times;
            track.values = readRotations(sampler.output, expectedValues(interpolation, times.size()), interpolation);
            node.rotationTrack = std::move(track);
        } else {
            Vec3Track track;
            track.interpolation = interpolation;
            track.times = times;
            track.values = readVectors(sampler.output, expectedValues(interpolation, times.size()));
            (property == "translation" ? node.translationTrack : node.scaleTrack) = std::move(track);
        }
        start = firstPlayed ? times.front() : std::min(start, times.front());
        end = firstPlayed ? times.back() : std::max(end, times.back());
        return true;
    }

    Interpolation interpolationOf(const std::string& name) const {
        if (name.empty() || name == "LINEAR") return Interpolation::Linear;
        if (name == "STEP") return Interpolation::Step;
        if (name == "CUBICSPLINE") return Interpolation::CubicSpline;
        fail("interpolation '" + name + "' is not LINEAR, STEP or CUBICSPLINE");
    }

    static size_t expectedValues(Interpolation interpolation, size_t keys) {
        return interpolation == Interpolation::CubicSpline ? 3 * keys : keys;
    }

    std::vector<float> readTimes(int accessor) const {
        const GltfAccessorView v = gltfAccessorView(model_, path_, accessor, channel_ + " input", {TINYGLTF_TYPE_SCALAR},
                                                    {TINYGLTF_COMPONENT_TYPE_FLOAT});
        if (v.count == 0) fail("input accessor " + std::to_string(accessor) + " has no keys");
        std::vector<float> times(v.count);
        for (size_t i = 0; i < v.count; ++i) {
            times[i] = gltfComponent(v, i, 0);
            if (!std::isfinite(times[i])) fail("key " + std::to_string(i) + "'s time is not finite");
            if (i > 0 && !(times[i] > times[i - 1]))
                fail("key " + std::to_string(i) + "'s time " + std::to_string(times[i]) +
                     " does not follow the previous key's " + std::to_string(times[i - 1]) +
                     " (times must increase strictly)");
        }
        return times;
    }

    void checkCount(const GltfAccessorView& v, int accessor, size_t expected) const {
        if (v.count != expected)
            fail("output accessor " + std::to_string(accessor) + " has " + std::to_string(v.count) + " elements; " +
                 std::to_string(expected) + " are needed for the input's keys");
    }

    std::vector<glm::vec3> readVectors(int accessor, size_t expected) const {
        const GltfAccessorView v = gltfAccessorView(model_, path_, accessor, channel_ + " output", {TINYGLTF_TYPE_VEC3},
                                                    {TINYGLTF_COMPONENT_TYPE_FLOAT});
        checkCount(v, accessor, expected);
        std::vector<glm::vec3> values(v.count);
        for (size_t i = 0; i < v.count; ++i) {
            values[i] = {gltfComponent(v, i, 0), gltfComponent(v, i, 1), gltfComponent(v, i, 2)};
            if (!std::isfinite(values[i].x) || !std::isfinite(values[i].y) || !std::isfinite(values[i].z))
                fail("output value " + std::to_string(i) + " is not finite");
        }
        return values;
    }

    // Quaternions x, y, z, w: floats, or normalized integers. Key values are normalised (CUBICSPLINE's tangents are
    // left as they are: they are derivatives, not rotations).
    std::vector<glm::quat> readRotations(int accessor, size_t expected, Interpolation interpolation) const {
        const GltfAccessorView v = gltfAccessorView(
            model_, path_, accessor, channel_ + " output", {TINYGLTF_TYPE_VEC4},
            {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
             TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT});
        if (v.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !v.normalized)
            fail("output accessor " + std::to_string(accessor) + ": integer rotations must be normalized");
        checkCount(v, accessor, expected);
        std::vector<glm::quat> values(v.count);
        for (size_t i = 0; i < v.count; ++i) {
            glm::quat q(gltfComponent(v, i, 3), gltfComponent(v, i, 0), gltfComponent(v, i, 1), gltfComponent(v, i, 2));
            if (!std::isfinite(q.w) || !std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z))
                fail("output value " + std::to_string(i) + " is not finite");
            const bool isValue = interpolation != Interpolation::CubicSpline || i % 3 == 1;
            if (isValue) {
                const float length = glm::length(q);
                if (!(length > 1e-6f)) fail("output rotation " + std::to_string(i) + " is zero (not a rotation)");
                q /= length;
            }
            values[i] = q;
        }
        return values;
    }

    const tinygltf::Model& model_;
    const std::string& path_;
    const std::vector<int>& nodeOf_;
    SceneAnimation& animation_;
    std::vector<std::string>& warnings_;
    std::string name_, channel_;
    std::set<std::pair<int, std::string>> played_;
};

}  // namespace

void readGltfAnimations(const tinygltf::Model& model, const std::string& path, const std::vector<int>& nodeOf,
                        SceneAnimation& animation, std::vector<std::string>& warnings) {
    AnimationReader(model, path, nodeOf, animation, warnings).read();
}

}  // namespace lidr
