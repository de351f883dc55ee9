#include "lidr/eval/bench_scenes.h"

#include <cmath>

#include "lidr/scene/default_scene.h"
#include "lidr/base/error.h"

namespace lidr {

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
