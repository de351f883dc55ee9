#include "lidr/eval/bench_scenes.h"

#include <algorithm>
#include <cmath>

#include "lidr/scene/default_scene.h"
#include "lidr/base/error.h"
#include "lidr/scene/primitives.h"

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

long sceneTriangleCount(const Scene& scene) {
    long n = 0;
    for (const Mesh& m : scene.meshes) n += long(m.triangleCount());
    return n;
}

Scene makeHeavyScene(long totalTriangles, int width, int height, uint32_t seed) {
    if (totalTriangles < 1 || totalTriangles > 20000000)
        throw Error("heavy scene: triangle count must be in [1, 20000000], got " + std::to_string(totalTriangles));
    DefaultSceneOptions room;
    room.seed = seed;
    room.width = width;
    room.height = height;
    Scene scene = makeDefaultScene(room);
    scene.name = "heavy-" + std::to_string(totalTriangles);
    // A sphere of S segments has S * S triangles (S around, S / 2 rings, two triangles a quad).
    const long extra = totalTriangles - sceneTriangleCount(scene);
    const double perMesh = double(std::max(0L, extra)) / heavyMeshCount;
    int segments = 2 * int(std::lround(std::sqrt(perMesh) / 2.0));
    segments = std::max(8, segments);
    // 8 x 8 x 3 lattice over the floor (x, z in [-16, 17.5]), layers at 0.9, 2.3 and 3.7 m, the middle one
    // shifted in x and the top one in z; radius 0.45 m keeps neighbours apart. Materials cycle through the room's opaque ones (no glass: forward-multipass
    // draws no transparent meshes).
    const int materials[] = {3, 4, 5, 6, 7};
    int i = 0;
    for (int layer = 0; layer < 3; ++layer)
        for (int zi = 0; zi < 8; ++zi)
            for (int xi = 0; xi < 8; ++xi, ++i) {
                const glm::vec3 center(-16.0f + 4.5f * float(xi) + (layer == 1 ? 2.0f : 0.0f), 0.9f + 1.4f * float(layer),
                                       -16.0f + 4.5f * float(zi) + (layer == 2 ? 2.0f : 0.0f));
                addSphere(scene, center, 0.45f, materials[i % 5], segments);
                scene.meshes.back().name = "heavy-sphere";
            }
    scene.validate();
    return scene;
}

}  // namespace lidr
