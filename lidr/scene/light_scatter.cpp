#include "lidr/scene/light_scatter.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/constants.hpp>

#include "lidr/base/error.h"
#include "lidr/scene/random.h"

namespace lidr {

namespace {


double triangleArea(const Mesh& m, size_t t) {
    const glm::dvec3 a(m.positions[m.indices[3 * t]]), b(m.positions[m.indices[3 * t + 1]]),
        c(m.positions[m.indices[3 * t + 2]]);
    return 0.5 * glm::length(glm::cross(b - a, c - a));
}

double surfaceArea(const Scene& scene) {
    double area = 0.0;
    for (const Mesh& m : scene.meshes)
        for (size_t t = 0; t < m.triangleCount(); ++t) area += triangleArea(m, t);
    return area;
}

glm::vec3 hueColor(double h) {  // fully saturated hue in [0, 1), max component 1
    const double k[3] = {5.0, 3.0, 1.0};
    glm::vec3 c;
    for (int i = 0; i < 3; ++i) {
        const double x = std::fmod(k[i] + h * 6.0, 6.0);
        c[i] = float(1.0 - std::max(0.0, std::min({x, 4.0 - x, 1.0})));
    }
    return c;
}

}  // namespace

float defaultScatterRadius(const Scene& scene, int count) {
    if (count <= 0 || scene.meshes.empty()) return 1.0f;
    const float diagonal = glm::length(scene.boundsMax() - scene.boundsMin());
    const double area = surfaceArea(scene);
    double r = std::sqrt(double(kScatterMeanOverlap) * area / (double(count) * glm::pi<double>()));
    if (!std::isfinite(r) || r <= 0.0) r = 0.05 * diagonal;
    return float(std::clamp(r, 1e-4 * diagonal, 0.25 * diagonal));
}

std::vector<PointLight> scatterLights(const Scene& scene, const LightScatterOptions& o) {
    const size_t room = maxSceneLights - std::min(scene.lights.size(), maxSceneLights);
    if (o.count < 1 || size_t(o.count) > room)
        throw Error("scattered lights: the count must be 1.." + std::to_string(room) + " (the scene has " +
                    std::to_string(scene.lights.size()) + " lights, at most " + std::to_string(maxSceneLights) +
                    "), not " + std::to_string(o.count));
    if (!std::isfinite(o.radius) || o.radius < 0.0f || o.radius > maxLightRadius)
        throw Error("scattered lights: the radius must be finite and >= 0 (0: automatic)");
    if (!std::isfinite(o.intensity) || o.intensity < 0.0f)
        throw Error("scattered lights: the intensity must be finite and >= 0");
    if (!(o.spotShare >= 0.0f && o.spotShare <= 1.0f))
        throw Error("scattered lights: the spot share must be in [0, 1], got " + std::to_string(o.spotShare));
    // Cumulative area over every triangle of every mesh.
    std::vector<std::pair<size_t, size_t>> triangles;  // (mesh, triangle)
    std::vector<double> cumulative;
    double total = 0.0;
    for (size_t mi = 0; mi < scene.meshes.size(); ++mi) {
        const Mesh& m = scene.meshes[mi];
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            const double a = triangleArea(m, t);
            if (!(a > 0.0)) continue;
            total += a;
            triangles.emplace_back(mi, t);
            cumulative.push_back(total);
        }
    }
    if (triangles.empty()) throw Error("scattered lights: the scene has no triangle with an area to put them on");
    const float radius = o.radius > 0.0f ? o.radius : defaultScatterRadius(scene, o.count);

    SplitMix64 random((uint64_t(o.seed) << 32) ^ 0x5C47u);
    std::vector<PointLight> lights;
    lights.reserve(size_t(o.count));
    for (int i = 0; i < o.count; ++i) {
        const double pick = random.uniformDouble() * total;
        const size_t k = size_t(std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin());
        const auto [mi, t] = triangles[std::min(k, triangles.size() - 1)];
        const Mesh& m = scene.meshes[mi];
        const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                        c = m.positions[m.indices[3 * t + 2]];
        double u = random.uniformDouble(), v = random.uniformDouble();
        if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
        const glm::vec3 onSurface = a + float(u) * (b - a) + float(v) * (c - a);
        const glm::vec3 normal = glm::normalize(glm::cross(b - a, c - a));
        PointLight light;
        light.position = onSurface + normal * (0.25f * radius);
        light.radius = radius;
        light.color = hueColor(random.uniformDouble()) * o.intensity;
        // Light i is a spot when the share's running count steps past an integer: evenly spread, and the random
        // stream (hence every position and colour) the same as without spots.
        if (std::floor(double(i + 1) * o.spotShare) > std::floor(double(i) * o.spotShare)) {
            light.direction = -normal;
            light.outerConeAngle = glm::radians(kScatterSpotOuterDegrees);
            light.innerConeAngle = glm::radians(kScatterSpotInnerDegrees);
        }
        lights.push_back(light);
    }
    return lights;
}

void addScatteredLights(Scene& scene, const LightScatterOptions& options) {
    std::vector<PointLight> lights = scatterLights(scene, options);
    const bool paths = !scene.lightPaths.empty();
    for (const PointLight& l : lights) {
        scene.lights.push_back(l);
        if (paths) {
            LightPath p;
            p.kind = LightPath::Kind::Static;
            scene.lightPaths.push_back(p);
        }
    }
}

bool addDefaultLightRig(Scene& scene) {
    if (!scene.lights.empty() || !scene.directionalLights.empty() || scene.meshes.empty()) return false;
    const float diagonal = glm::length(scene.boundsMax() - scene.boundsMin());
    PointLight key;
    key.position = scene.camera.position;
    key.radius = std::max(3.0f * diagonal, 1e-3f);
    key.color = glm::vec3(1.0f);
    key.priority = 1.0f;
    scene.lights.push_back(key);
    if (!scene.lightPaths.empty()) scene.lightPaths.push_back(LightPath{});
    if (!scene.environment) scene.ambient = glm::max(scene.ambient, glm::vec3(0.1f));  // else the environment is it
    return true;
}

}  // namespace lidr
