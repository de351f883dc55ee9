#include "lidr/eval/controlled_scenes.h"

#include <algorithm>
#include <numeric>
#include <random>

#include "lidr/base/error.h"
#include "lidr/scene/primitives.h"

namespace lidr {

Scene makeControlledOverlapScene(const ControlledOverlapOptions& o) {
    if (o.overlap < 1 || o.maxLights < 1 || o.clusters < 1 || o.clusters > 9)
        throw Error("makeControlledOverlapScene: overlap >= 1, maxLights >= 1, clusters 1..9");
    Scene s;
    s.name = "controlled-overlap-" + std::to_string(o.overlap);
    s.materials.push_back(Material{"floor", glm::vec3(0.8f), "", glm::vec3(0.3f), 24.0f, 1.0f});
    addPlane(s, glm::vec3(0.0f), glm::vec2(30.0f), 0, 30);
    s.camera.position = glm::vec3(0.0f, 26.0f, 5.0f);
    s.camera.target = glm::vec3(0.0f, 0.0f, 0.0f);
    s.camera.fovYDegrees = 55.0f;
    s.camera.nearPlane = 0.5f;
    s.camera.farPlane = 80.0f;
    s.width = o.width;
    s.height = o.height;
    s.ambient = glm::vec3(0.05f);
    const int k = std::min(o.overlap, o.maxLights);
    const int clusters = std::max(1, std::min(o.clusters, o.maxLights / k));
    std::mt19937 rng(o.seed);
    std::uniform_real_distribution<float> colour(0.05f, 0.35f);
    for (int c = 0; c < clusters; ++c) {
        const glm::vec3 centre(-8.5f + 8.5f * float(c % 3), 0.4f, -7.5f + 7.5f * float(c / 3));
        const float radius = 1.8f + 0.15f * float(c % 4);
        std::vector<int> priorities(static_cast<size_t>(k), 0);
        std::iota(priorities.begin(), priorities.end(), 0);
        std::shuffle(priorities.begin(), priorities.end(), rng);
        for (int j = 0; j < k; ++j) {
            PointLight l;
            l.position = centre;
            l.radius = radius;
            l.color = glm::vec3(colour(rng), colour(rng), colour(rng));
            l.priority = float(priorities[size_t(j)]);
            s.lights.push_back(l);
        }
    }
    return s;
}

Scene makeOccludedLightScene(int width, int height) {
    Scene s;
    s.name = "occluded-light";
    s.materials.push_back(Material{"floor", glm::vec3(0.8f), "", glm::vec3(0.3f), 24.0f, 1.0f});
    s.materials.push_back(Material{"wall", glm::vec3(0.6f, 0.7f, 0.8f), "", glm::vec3(0.2f), 16.0f, 1.0f});
    addPlane(s, glm::vec3(0.0f), glm::vec2(24.0f), 0, 24);
    addBox(s, glm::vec3(-4.0f, 0.0f, -0.5f), glm::vec3(4.0f, 4.0f, 0.0f), 1, 8);  // the wall faces +z
    s.camera.position = glm::vec3(0.0f, 2.0f, 9.0f);
    s.camera.target = glm::vec3(0.0f, 2.0f, 0.0f);
    s.camera.fovYDegrees = 55.0f;
    s.camera.nearPlane = 0.5f;
    s.camera.farPlane = 60.0f;
    s.width = width;
    s.height = height;
    s.ambient = glm::vec3(0.05f);
    PointLight front, behind;
    front.position = glm::vec3(0.0f, 2.0f, 1.2f);  // touches the wall's front face
    front.radius = 2.0f;
    front.color = glm::vec3(0.9f, 0.6f, 0.3f);
    front.priority = 1.0f;
    behind.position = glm::vec3(0.5f, 2.0f, -3.0f);  // 4.2 m from the front light: spheres apart
    behind.radius = 2.0f;
    behind.color = glm::vec3(0.3f, 0.6f, 0.9f);
    s.lights = {front, behind};
    return s;
}

}  // namespace lidr
