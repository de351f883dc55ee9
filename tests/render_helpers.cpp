#include "render_helpers.h"

#include <random>

#include <catch2/catch.hpp>

#include "gl_test_context.h"
#include "lidr/scene/default_scene.h"
#include "lidr/scene/primitives.h"
#include "lidr/modes/reference_renderer.h"

namespace lidr::test {

PointLight light(glm::vec3 position, float radius, glm::vec3 color, float priority) {
    PointLight l;
    l.position = position;
    l.radius = radius;
    l.color = color;
    l.priority = priority;
    return l;
}

Scene testRoom(float time) {
    DefaultSceneOptions o;
    o.width = testWidth();
    o.height = testHeight();
    o.time = time;
    return makeDefaultScene(o);
}

Scene floorScene() {
    Scene s;
    s.name = "test-floor";
    s.materials.push_back(Material{"floor", glm::vec3(0.8f), "", glm::vec3(0.3f), 24.0f, 1.0f});
    s.materials.push_back(Material{"box", glm::vec3(0.7f, 0.5f, 0.3f), "", glm::vec3(0.2f), 16.0f, 1.0f});
    addPlane(s, glm::vec3(0.0f), glm::vec2(24.0f), 0, 24);
    addBox(s, glm::vec3(-2.0f, 0.0f, -2.0f), glm::vec3(1.0f, 2.5f, 1.0f), 1, 4);
    addSphere(s, glm::vec3(4.0f, 1.5f, 2.0f), 1.5f, 1, 24);
    s.camera.position = glm::vec3(0.0f, 14.0f, 16.0f);
    s.camera.target = glm::vec3(0.0f, 0.0f, 0.0f);
    s.camera.fovYDegrees = 55.0f;
    s.camera.nearPlane = 0.5f;
    s.camera.farPlane = 80.0f;
    s.width = testWidth();
    s.height = testHeight();
    s.ambient = glm::vec3(0.05f);
    return s;
}

Camera camera(glm::vec3 position, glm::vec3 target, float nearPlane, float farPlane, float fov) {
    Camera c;
    c.position = position;
    c.target = target;
    c.nearPlane = nearPlane;
    c.farPlane = farPlane;
    c.fovYDegrees = fov;
    return c;
}

Scene firstPersonScene() {
    Scene s = floorScene();
    s.camera = camera({0.0f, 1.7f, 11.0f}, {0.0f, 1.2f, 0.0f}, 0.1f, 60.0f);
    return s;
}

Scene topDownScene() {
    Scene s = floorScene();
    s.camera = camera({0.0f, 22.0f, 1.0f}, {0.0f, 0.0f, 0.0f}, 1.0f, 60.0f);
    return s;
}

std::vector<PointLight> floorLights(int count, float rMin, float rMax, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> xz(-11.0f, 11.0f), y(0.05f, 3.0f), r(rMin, rMax), c(0.2f, 1.0f);
    std::vector<PointLight> lights;
    for (int i = 0; i < count; ++i) lights.push_back(light({xz(rng), y(rng), xz(rng)}, r(rng), {c(rng), c(rng), c(rng)}));
    return lights;
}

RenderResult renderAndEvaluate(const Scene& scene, const LidrOptions& options) {
    return renderAndEvaluate(scene, options, testGl());
}

RenderResult renderAndEvaluate(const Scene& scene, const LidrOptions& options, const GlInfo& info,
                               const OutputTransform& output) {
    testContext();
    const std::vector<PointLight> lights = scene.lightsAt(scene.time);
    const ShadingParameters shading = sceneShading(scene, output);
    RenderResult r;
    LidrRenderer renderer(info, scene, options, scene.width, scene.height);
    r.stats = renderer.render(scene.camera, lights, shading);
    r.lidr = renderer.targets().readColor();
    if (!options.perSampleIndices) r.indexTargets = renderer.readIndexTargets();  // multisample: not readable
    ReferenceRenderer reference(info, scene, scene.width, scene.height, static_cast<int>(std::max<size_t>(lights.size(), 1)),
                                options.forceFixedLightTable, options.msaaSamples, options.transparency,
                                options.perSampleIndices);
    reference.render(scene.camera, lights, shading);
    r.reference = reference.targets().readColor();
    r.evaluation = evaluateFrame(renderer, scene.camera, lights, r.lidr, r.reference);
    return r;
}

void requireExactWithinBudget(const FrameEvaluation& e, const std::string& what) {
    long droppedWithinBudget = 0;
    for (size_t p = 0; p < e.withinBudget.size(); ++p)
        if (e.withinBudget[p]) droppedWithinBudget += e.lists.droppedPerPixel[p];
    INFO(what << (what.empty() ? "" : ": ") << "within-budget max error " << e.errorWithinBudget.maxAbsError << ", PSNR "
              << e.errorWithinBudget.psnr << ", invalid " << e.lists.invalidSlots << ", dropped within budget "
              << droppedWithinBudget << ", over budget " << e.pixelsOverBudget);
    REQUIRE(e.lists.invalidSlots == 0);
    REQUIRE(droppedWithinBudget == 0);
    REQUIRE(e.errorWithinBudget.maxAbsError <= 1);
}

}  // namespace lidr::test
