#pragma once
// Shared by the GL tests: small controlled scenes, and "render with LIDR and with the brute-force reference,
// then evaluate" in one call.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "lidr/platform/context.h"
#include "lidr/eval/brdf.h"
#include "lidr/eval/frame_evaluation.h"
#include "lidr/render/output_transform.h"
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
// A glass material (light blue, translucent: alpha 0.4) added to the scene; returns its index.
int addGlassMaterial(Scene& scene);
// firstPersonScene() with a glass sphere 2 m in front of the eye and 60 floor lights (the MSAA-with-transparency
// cases of the forward modes).
Scene firstPersonGlassScene();
// A camera at `position` looking at `target` (fovY in degrees).
Camera camera(glm::vec3 position, glm::vec3 target, float nearPlane = 0.1f, float farPlane = 60.0f, float fov = 60.0f);
// `count` random lights over floorScene()'s 24 x 24 m, 0.05..3 m high, radii in [rMin, rMax], colours 0.2..1.
std::vector<PointLight> floorLights(int count, float rMin, float rMax, unsigned seed);

// A 4 x 4 sweep of flat 2 x 2 m tiles on y = 0 in 2.2 m cells centred on the origin: metallic i / 3 along x,
// roughness(j) along z, base colour (0.9, 0.6, 0.3); seen from `eye` towards the origin (55 degrees, near 0.5,
// far 40), testWidth() x testHeight(). No lights, the default ambient: tests add their own (test_brdf.cpp,
// test_environment.cpp).
Scene metallicRoughnessSweep(float (*roughness)(int j), const glm::vec3& eye);
// The sweep's tile under pixel (x, y) of a frame with that depth, away from the tile's edges (where the pixel
// centre's triangle may differ): its material index (i x 4 + j) and the surface point; -1 for none.
int sweepTileAt(const CameraMatrices& camera, const ImageFloat& depth, int x, int y, glm::vec3& point);
// Every sweep pixel (sweepTileAt) of a frame against the CPU model: model(surface, point) is the pixel's linear
// light (the surface: its tile's material, normal up, seen from the camera), `output` makes it 8-bit. The pixels
// compared, those within one step of it, those whose expected `channel` passes brightLevel, the worst step.
struct SweepCheck {
    long compared = 0, withinOne = 0, bright = 0;
    int worst = 0;
};
SweepCheck checkSweep(const Scene& scene, const ImageRGBA8& image, const ImageFloat& depth, const OutputTransform& output,
                      const std::function<glm::dvec3(const BrdfSurface&, const glm::vec3&)>& model, int channel,
                      double brightLevel);
// lidr's default room (255 lights) at testWidth() x testHeight(), at `time` seconds.
Scene testRoom(float time = 0.0f);
// A toon material shader of the program's own (lidr_lights.glsl): per listed light 2 steps where its attenuation
// exceeds 0.5, 1 where it is above 0; red = steps x `step` / 255.
std::string toonMaterialShader(int step);

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
// The same against a reference already rendered (another result's `.reference`) for the same scene, frame and
// size with the same MSAA, transparency, per-sample shading and light table: the brute-force reference is most of
// a deep scene's time (hall-1024 at 384 x 288, 4x MSAA: 7.8 s against LIDR's 0.08 s on llvmpipe).
RenderResult renderAndEvaluate(const Scene& scene, const LidrOptions& options, const ImageRGBA8& reference);

// The references of a table whose rows differ only in what the reference does not take (scheme, budget, width,
// volume test, tiles): each rendered by the first row that names its key (what the reference does take: the
// scene's own parameters) and passed on to the rest. One per case, a function-local static: the rows are the
// case's runs in one process and one context.
class SharedReferences {
public:
    RenderResult renderAndEvaluate(const std::string& key, const Scene& scene, const LidrOptions& options);

private:
    std::map<std::string, ImageRGBA8> images_;
};

// Per-pixel conditions checked without a Catch assertion per pixel and condition (the controlled-overlap table made
// 21 million of them, more time than its frames): expect() records a failure, the first one named; require()
// REQUIREs that none failed.
class PixelChecks {
public:
    explicit PixelChecks(std::string what) : what_(std::move(what)) {}
    bool expect(bool holds, size_t pixel, const char* condition) {
        if (!holds && failures_++ == 0) first_ = what_ + ", pixel " + std::to_string(pixel) + ": " + condition;
        return holds;
    }
    void require() const;

private:
    std::string what_, first_;
    long failures_ = 0;
};

// The render tests' common bound, "exact within the budget": no corrupted slot anywhere; no light that touches a
// surface missing where the pixel was marked by no more lights than the budget; those pixels equal the reference
// within one 8-bit step (the same lights summed in another order). REQUIREs each (Catch2), naming `what`.
void requireExactWithinBudget(const FrameEvaluation& e, const std::string& what = "");

}  // namespace lidr::test
