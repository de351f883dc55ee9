#pragma once
// Shared by the GL tests: small controlled scenes, and "render with LIDR and with the brute-force reference,
// then evaluate" in one call.
#include <vector>

#include "lidr/platform/context.h"
#include "lidr/eval/frame_evaluation.h"
#include "lidr/technique/lidr_renderer.h"
#include "lidr/scene/scene.h"

namespace lidr::test {

// A point light, for scenes built in tests.
PointLight light(glm::vec3 position, float radius, glm::vec3 color = glm::vec3(1.0f), float priority = 0.0f);

// A 24 x 24 m floor (finely tessellated) with a box and a sphere on it, seen from above at an angle; the
// size is testWidth() x testHeight(). No lights: tests add their own.
Scene floorScene();
// floorScene() seen first-person (eye 1.7 m over the floor, looking along it) and from 22 m above.
Scene firstPersonScene();
Scene topDownScene();
// A camera at `position` looking at `target` (fovY in degrees).
Camera camera(glm::vec3 position, glm::vec3 target, float nearPlane = 0.1f, float farPlane = 60.0f, float fov = 60.0f);
// `count` random lights over floorScene()'s 24 x 24 m, 0.05..3 m high, radii in [rMin, rMax], colours 0.2..1.
std::vector<PointLight> floorLights(int count, float rMin, float rMax, unsigned seed);

// lidr's default room (255 lights) at testWidth() x testHeight(), at `time` seconds.
Scene testRoom(float time = 0.0f);

struct RenderResult {
    ImageRGBA8 lidr, reference;
    FrameEvaluation evaluation;
    FrameStats stats;
    std::vector<ImageRGBA8> indexTargets;
};

// Renders `scene` at scene.time with LIDR (`options`) and the reference; `info` may be a modified copy of
// the test context's (to take a fallback path).
RenderResult renderAndEvaluate(const Scene& scene, const LidrOptions& options);
// `output`: the frames' output transform (default: lidr's, PBR Neutral + sRGB).
RenderResult renderAndEvaluate(const Scene& scene, const LidrOptions& options, const GlInfo& info,
                               const OutputTransform& output = OutputTransform{});

// The render tests' common bound, "exact within the budget": no corrupted slot anywhere; no light that touches a
// surface missing where the pixel was marked by no more lights than the budget; those pixels equal the reference
// within one 8-bit step (the same lights summed in another order). REQUIREs each (Catch2), naming `what`.
void requireExactWithinBudget(const FrameEvaluation& e, const std::string& what = "");

}  // namespace lidr::test
