#include "lidr/bench_scenes.h"

#include <cmath>

#include "lidr/default_scene.h"
#include "lidr/error.h"
#include "lidr/primitives.h"

namespace lidr {

Scene makeControlledOverlapScene(int k, int width, int height) {
    constexpr int maxK = 65535 / kControlledOverlapGroups;
    if (k < 1 || k > maxK)
        throw Error("controlled-overlap scene: k must be in [1, " + std::to_string(maxK) + "], got " + std::to_string(k));
    Scene scene;
    scene.name = "overlap-" + std::to_string(k);
    Material floor;
    floor.name = "floor";
    floor.diffuse = glm::vec3(0.75f);
    floor.specular = glm::vec3(0.2f);
    scene.materials.push_back(floor);
    addPlane(scene, glm::vec3(0.0f), glm::vec2(14.0f), 0, 16);

    // Sphere radius 1.8 centred 0.5 above the floor: a lit disk of radius ~1.73. Centres 4 apart leave
    // 0.4 between spheres, more than any volume mesh's outside radius adds.
    const float spacing = 4.0f, radius = 1.8f, height0 = 0.5f;
    const glm::vec3 palette[] = {{1.0f, 0.35f, 0.3f}, {0.3f, 1.0f, 0.4f}, {0.35f, 0.45f, 1.0f}, {1.0f, 0.9f, 0.3f},
                                 {0.9f, 0.35f, 1.0f}, {0.3f, 0.95f, 1.0f}, {1.0f, 0.6f, 0.2f}, {0.6f, 1.0f, 0.7f}};
    for (int gz = -1; gz <= 1; ++gz)
        for (int gx = -1; gx <= 1; ++gx)
            for (int i = 0; i < k; ++i) {
                PointLight light;
                light.position = glm::vec3(spacing * float(gx), height0, spacing * float(gz));
                light.radius = radius;
                light.color = palette[(i + 3 * (gx + 1) + (gz + 1)) % 8] * (1.6f / float(k));
                scene.lights.push_back(light);
            }
    scene.camera.position = {0.0f, 10.0f, 0.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.up = {0.0f, 0.0f, -1.0f};
    scene.camera.fovYDegrees = 70.0f;
    scene.camera.nearPlane = 0.5f;
    scene.camera.farPlane = 30.0f;
    scene.width = width;
    scene.height = height;
    scene.ambient = glm::vec3(0.03f);
    scene.validate();
    return scene;
}

const char* manyLightViewName(ManyLightView view) { return view == ManyLightView::TopDown ? "top" : "fp"; }

Scene makeManyLightScene(int lightCount, ManyLightView view, int width, int height, uint32_t seed) {
    if (lightCount < 4 || lightCount > 65535)
        throw Error("many-light scene: light count must be in [4, 65535], got " + std::to_string(lightCount));
    DefaultSceneOptions room;
    room.seed = seed;
    room.lightCount = 3;  // the large movers only; the particles follow, smaller
    room.width = width;
    room.height = height;
    Scene scene = makeDefaultScene(room);
    scene.name = "many-" + std::to_string(lightCount) + "-" + manyLightViewName(view);
    const float shrink = std::sqrt(255.0f / float(lightCount));
    LightGeneratorOptions particles;
    particles.seed = seed;
    particles.count = lightCount - 3;
    particles.boundsMin = {-19.5f, 0.2f, -19.5f};  // the default room's particle box
    particles.boundsMax = {19.5f, 3.5f, 19.5f};
    particles.radiusMin = 0.8f * shrink;
    particles.radiusMax = 2.2f * shrink;
    particles.intensity = 1.0f;
    particles.speed = 1.5f;
    generateLights(scene, particles);
    if (view == ManyLightView::TopDown) {
        // Just under the ceiling (y = 10), looking straight down over the middle of the floor.
        scene.camera.position = {0.0f, 9.5f, 0.0f};
        scene.camera.target = {0.0f, 0.0f, 0.0f};
        scene.camera.up = {0.0f, 0.0f, -1.0f};
        scene.camera.fovYDegrees = 100.0f;
    } else {
        // Eye height at one end of the nave, looking down its length.
        scene.camera.position = {0.0f, 1.7f, 18.0f};
        scene.camera.target = {0.0f, 1.4f, 0.0f};
        scene.camera.fovYDegrees = 70.0f;
    }
    scene.validate();
    return scene;
}

}  // namespace lidr
