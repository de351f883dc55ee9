#pragma once
// Lights for any model: `count` seeded point lights scattered over the scene's surfaces (area-weighted), so
// every model becomes a many-light scene in one call (lidr-demo/lidr-bench `--lights N`, lidr-viewer's slider, the
// web page's `lights=N`, a scene file's "scatter_lights"). Deterministic for the same scene, count and seed.
#include <cstdint>
#include <vector>

#include "lidr/scene/scene.h"

namespace lidr {

struct LightScatterOptions {
    int count = 0;           // lights to add, 1 .. maxSceneLights - the scene's lights
    uint32_t seed = 1;
    // Light radius in scene units; <= 0: automatic (defaultScatterRadius).
    float radius = 0.0f;
    float intensity = 1.0f;  // colour scale
    // The share of the lights that are spot lights, [0, 1]: each aims back at the surface it sits over, its
    // outer cone kScatterSpotOuterDegrees; every (1 / spotShare)-th light, so the points stay where they were.
    float spotShare = 0.0f;
};

// The cone of a scattered spot light: a lamp over its surface, lighting a disc of about its radius.
constexpr float kScatterSpotOuterDegrees = 60.0f, kScatterSpotInnerDegrees = 40.0f;

// The automatic radius: lights of this radius over the scene's surfaces cover each surface point about
// kScatterMeanOverlap times on average (N pi r^2 = overlap x area, counting one side of every triangle), so
// the lists of an ordinary view fit the automatic budget; clamped to [1e-4, 0.25] x the bounds' diagonal.
constexpr float kScatterMeanOverlap = 1.5f;
float defaultScatterRadius(const Scene& scene, int count);

// The lights, not yet in the scene: each sits at a random point of a random triangle (chosen by area), lifted
// off the surface along the face normal by a quarter of its radius, with a bright seeded colour. Throws
// lidr::Error for a count out of range, a negative or non-finite radius, or a scene without triangles.
std::vector<PointLight> scatterLights(const Scene& scene, const LightScatterOptions& options);
// Appends scatterLights(scene, options) to scene.lights (static: paths, if the scene has them, stay put).
void addScatteredLights(Scene& scene, const LightScatterOptions& options);

// The default rig of a scene that has no lights (a glTF without KHR_lights_punctual, an OBJ), so that any
// model looks lit (doc/colour.md, "Lights for any model"): one white key light at the camera's eye with a
// radius of three times the geometry's bounds diagonal (so the falloff 1 - d^2/r^2 keeps at least 8/9 of it
// over the whole model), and the ambient raised to at least 0.1 (uniform light from every direction, lit
// from behind included; not where the scene has an environment light, which lights it from every direction
// already). Nothing changes where the scene has lights (point or directional). Returns whether it added the rig.
bool addDefaultLightRig(Scene& scene);

}  // namespace lidr
