#pragma once
// The built-in default scene: needs no files. A procedural room of about 40,000 triangles with pillars and
// objects, lit by 255 point lights: 3 large slow movers and 252 small particle lights, as in Trebilco's
// original LIDR demo. Deterministic for a given seed and time.
#include <cstdint>

#include "lidr/scene/scene.h"

namespace lidr {

struct DefaultSceneOptions {
    uint32_t seed = 1;
    int lightCount = 255;       // 3 large movers + (lightCount - 3) particles
    float time = 0.0f;
    int width = 1024, height = 768;
};

Scene makeDefaultScene(const DefaultSceneOptions& options = {});

// Seeded light generator shared by the default scene and scene files ("generate" block).
struct LightGeneratorOptions {
    uint32_t seed = 1;
    int count = 0;
    glm::vec3 boundsMin{-1.0f}, boundsMax{1.0f};
    float radiusMin = 0.5f, radiusMax = 1.0f;
    float intensity = 1.0f;
    float speed = 0.0f;  // > 0: the lights bounce around the bounds at this speed
};
// Appends the lights (and paths, when speed > 0, or when the scene already has paths) to the scene.
void generateLights(Scene& scene, const LightGeneratorOptions& options);

}  // namespace lidr
