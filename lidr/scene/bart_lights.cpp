#include "lidr/scene/bart_lights.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "lidr/base/error.h"
#include "lidr/scene/random.h"

namespace lidr {

namespace {

// A light colour: a random hue, mixed a third of the way to white (so every light lights every surface colour),
// scaled so its brightest channel is `intensity`.
glm::vec3 lightColour(SplitMix64& random, float intensity) {
    const float h = random.uniform();
    glm::vec3 hue;
    for (int i = 0; i < 3; ++i) {
        const float x = std::fmod(float(5 - 2 * i) + h * 6.0f, 6.0f);
        hue[i] = 1.0f - std::max(0.0f, std::min({x, 4.0f - x, 1.0f}));
    }
    return glm::mix(hue, glm::vec3(1.0f), 1.0f / 3.0f) * intensity;
}

// A walker's path: its node's world origin at `samples` times over the animation.
std::vector<glm::vec3> walkerPath(const SceneAnimation& a, int node, int samples) {
    std::vector<glm::vec3> path;
    for (int i = 0; i <= samples; ++i) {
        const float t = a.start + (a.end - a.start) * float(i) / float(samples);
        path.emplace_back(a.worldAt(t)[size_t(node)][3]);
    }
    return path;
}

// ManyStatic: `o.count` static lights spread evenly along the walkers' paths (their total length, a light every
// length / count), each a seeded sideways offset across the path (horizontal) and 2 .. 6 over it.
std::string placeLightsAlongPaths(Scene& scene, const std::vector<int>& walkers, const BartLightOptions& o, float range,
                                  float intensity, SplitMix64& random) {
    if (o.count < 1 || size_t(o.count) > maxSceneLights)
        throw Error("BART lights: count must be 1.." + std::to_string(maxSceneLights) + ", got " + std::to_string(o.count));
    const SceneAnimation& a = scene.animation;
    std::vector<std::vector<glm::vec3>> paths;
    double total = 0.0;
    for (int w : walkers) {
        paths.push_back(walkerPath(a, w, 2000));
        for (size_t i = 1; i < paths.back().size(); ++i) total += double(glm::length(paths.back()[i] - paths.back()[i - 1]));
    }
    if (!(total > 0.0)) throw Error("BART lights: the walkers do not move (their paths have no length)");
    const double spacing = total / double(o.count);
    double next = 0.5 * spacing, walked = 0.0;
    for (const std::vector<glm::vec3>& path : paths)
        for (size_t i = 1; i < path.size() && int(scene.lights.size()) < o.count; ++i) {
            const glm::vec3 step = path[i] - path[i - 1];
            const double length = double(glm::length(step));
            while (next <= walked + length && int(scene.lights.size()) < o.count) {
                const glm::vec3 at = path[i - 1] + step * float((next - walked) / length);
                glm::vec3 across(-step.z, 0.0f, step.x);
                across = glm::length(across) > 0.0f ? glm::normalize(across) : glm::vec3(1.0f, 0.0f, 0.0f);
                PointLight light;
                light.position = at + across * random.uniform(-o.sideways, o.sideways) +
                                 glm::vec3(0.0f, random.uniform(2.0f, 6.0f), 0.0f);
                light.radius = range;
                light.color = lightColour(random, intensity);
                scene.lights.push_back(light);
                next += spacing;
            }
            walked += length;
        }
    std::ostringstream said;
    said << scene.lights.size() << " static lights along the paths of " << walkers.size() << " walkers ("
         << total << " units, one every " << spacing << "), up to " << o.sideways << " sideways, range " << range;
    return said.str();
}

// FewDynamic: each walker carries one light over its head: the top of what it carries, plus a fifth of its height.
std::string placeLightsOverWalkers(Scene& scene, const std::vector<int>& walkers, float range, float intensity,
                                   SplitMix64& random) {
    SceneAnimation& a = scene.animation;
    for (int w : walkers) {
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
        for (size_t m = 0; m < a.meshNodes.size(); ++m) {
            bool below = false;
            for (int k = a.meshNodes[m]; k >= 0 && !below; k = a.nodes[size_t(k)].parent) below = k == w;
            if (!below) continue;
            for (const glm::vec3& p : scene.meshes[m].positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
        }
        const glm::mat4 world = a.posedWorld[size_t(w)];
        const glm::vec3 over(0.5f * (lo.x + hi.x), hi.y + 0.2f * (hi.y - lo.y), 0.5f * (lo.z + hi.z));
        LightBinding binding;
        binding.node = w;
        binding.position = glm::vec3(glm::inverse(world) * glm::vec4(over, 1.0f));
        binding.radius = range / std::max({glm::length(glm::vec3(world[0])), glm::length(glm::vec3(world[1])),
                                          glm::length(glm::vec3(world[2])), 1e-6f});
        PointLight light;
        light.position = over;
        light.radius = range;
        light.color = lightColour(random, intensity);
        scene.lights.push_back(light);
        a.lightBindings.push_back(binding);
    }
    std::ostringstream said;
    said << scene.lights.size() << " lights, one riding over each walker, range " << range;
    return said.str();
}

}  // namespace

std::vector<int> bartWalkers(const Scene& scene) {
    const SceneAnimation& a = scene.animation;
    std::vector<bool> carries(a.nodes.size(), false);  // some mesh rides on it or below it
    for (int n : a.meshNodes)
        for (int k = n; k >= 0; k = a.nodes[size_t(k)].parent) carries[size_t(k)] = true;
    std::vector<int> walkers;
    for (size_t i = 0; i < a.nodes.size(); ++i) {
        if (!a.nodes[i].animated || !carries[i] || int(i) == a.cameraNode) continue;
        bool underAnimated = false;
        for (int k = a.nodes[i].parent; k >= 0; k = a.nodes[size_t(k)].parent) underAnimated = underAnimated || a.nodes[size_t(k)].animated;
        if (!underAnimated) walkers.push_back(int(i));
    }
    return walkers;
}

std::string addBartLights(Scene& scene, const BartLightOptions& o) {
    const std::vector<int> walkers = bartWalkers(scene);
    if (walkers.empty())
        throw Error("the BART light set-ups follow the scene's walkers (keyframed transforms carrying meshes); "
                    "this scene has none");
    const bool many = o.setup == BartLightSetup::ManyStatic;
    const float range = o.range > 0.0f ? o.range : many ? kBartManyRange : kBartFewRange;
    const float intensity = o.intensity > 0.0f ? o.intensity : many ? kBartManyIntensity : kBartFewIntensity;
    if (!std::isfinite(range) || !std::isfinite(intensity) || !std::isfinite(o.sideways) || o.sideways < 0.0f)
        throw Error("BART lights: range, intensity and sideways offset must be finite (sideways >= 0)");
    const float ambientScale = o.ambientScale >= 0.0f ? o.ambientScale : kBartAmbientScale;
    if (!std::isfinite(ambientScale)) throw Error("BART lights: the ambient scale must be finite");
    for (Material& m : scene.materials) m.emissive *= ambientScale;
    SplitMix64 random(o.seed);
    scene.lights.clear();
    scene.lightPaths.clear();
    scene.animation.lightBindings.clear();
    std::ostringstream said;
    said << (many ? placeLightsAlongPaths(scene, walkers, o, range, intensity, random)
                  : placeLightsOverWalkers(scene, walkers, range, intensity, random));
    said << ", intensity " << intensity << ", the file's ambient x " << ambientScale << ", seed " << o.seed;
    return said.str();
}

}  // namespace lidr
