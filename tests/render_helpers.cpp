#include "render_helpers.h"

#include <algorithm>
#include <cmath>
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

Scene metallicRoughnessSweep(float (*roughness)(int j), const glm::vec3& eye) {
    Scene scene;
    scene.name = "metallic-roughness-sweep";
    for (int mi = 0; mi < 4; ++mi)
        for (int ri = 0; ri < 4; ++ri) {
            Material m;
            m.name = "m" + std::to_string(mi) + "r" + std::to_string(ri);
            m.metallicRoughness = true;
            m.diffuse = glm::vec3(0.9f, 0.6f, 0.3f);
            m.metallic = float(mi) / 3.0f;
            m.roughness = roughness(ri);
            scene.materials.push_back(m);
            addPlane(scene, glm::vec3(-3.3f + 2.2f * float(mi), 0.0f, -3.3f + 2.2f * float(ri)), glm::vec2(2.0f),
                     int(scene.materials.size() - 1), 4);
        }
    scene.camera.position = eye;
    scene.camera.target = glm::vec3(0.0f);
    scene.camera.fovYDegrees = 55.0f;
    scene.camera.nearPlane = 0.5f;
    scene.camera.farPlane = 40.0f;
    scene.width = testWidth();
    scene.height = testHeight();
    return scene;
}

int sweepTileAt(const CameraMatrices& camera, const ImageFloat& depth, int x, int y, glm::vec3& point) {
    const float d = depth.at(x, y);
    if (d >= 1.0f) return -1;
    point = unprojectPixel(camera, x, y, d);
    const float u = (point.x + 4.4f) / 2.2f, v = (point.z + 4.4f) / 2.2f;
    const int mi = int(std::floor(u)), ri = int(std::floor(v));
    if (mi < 0 || mi > 3 || ri < 0 || ri > 3) return -1;
    const float fu = u - float(mi), fv = v - float(ri);
    if (fu < 0.08f || fu > 0.83f || fv < 0.08f || fv > 0.83f) return -1;  // a tile is 2.0 of its 2.2 m cell
    return mi * 4 + ri;
}

SweepCheck checkSweep(const Scene& scene, const ImageRGBA8& image, const ImageFloat& depth, const OutputTransform& output,
                      const std::function<glm::dvec3(const BrdfSurface&, const glm::vec3&)>& model, int channel,
                      double brightLevel) {
    const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
    SweepCheck c;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            glm::vec3 p;
            const int tile = sweepTileAt(cam, depth, x, y, p);
            if (tile < 0) continue;
            const BrdfSurface s =
                brdfSurface(scene.materials[size_t(tile)], glm::dvec3(p), glm::dvec3(0, 1, 0), glm::dvec3(cam.eye));
            const glm::dvec3 expected = 255.0 * applyOutputTransform(model(s, p), output);
            const uint8_t* got = image.at(x, y);
            int e = 0;
            for (int k = 0; k < 3; ++k) e = std::max(e, int(std::lround(std::abs(double(got[k]) - expected[k]))));
            ++c.compared;
            if (e <= 1) ++c.withinOne;
            if (expected[channel] > brightLevel) ++c.bright;
            c.worst = std::max(c.worst, e);
        }
    return c;
}

std::string toonMaterialShader(int step) {
    return R"(#version 120
#include "shading.glsl"
#include "lidr_lights.glsl"
void main() {
    LidrSurface s = lidrSurface();
    float band = 0.0;
    LidrLight light;
    lidrBeginLights();
    for (int i = 0; i < LIDR_MAX_LIGHTS; ++i) {
        if (!lidrNextLight(light)) break;
        vec3 d = light.position - s.position;
        float a = clamp(1.0 - dot(d, d) / (light.radius * light.radius), 0.0, 1.0);
        band += a > 0.5 ? 2.0 : (a > 0.0 ? 1.0 : 0.0);  // two toon steps
    }
    gl_FragColor = vec4(band * )" + std::to_string(step) + R"(.0 / 255.0, 0.0, 0.0, 1.0);
}
)";
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

int addGlassMaterial(Scene& scene) {
    scene.materials.push_back(Material{"glass", glm::vec3(0.6f, 0.8f, 0.9f), "", glm::vec3(0.9f), 64.0f, 0.4f});
    return int(scene.materials.size()) - 1;
}

Scene firstPersonGlassScene() {
    Scene scene = firstPersonScene();
    addSphere(scene, {0.2f, 1.3f, 2.0f}, 1.0f, addGlassMaterial(scene), 24);
    scene.lights = floorLights(60, 0.5f, 3.0f, 8);
    return scene;
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

namespace {
RenderResult renderAndEvaluateWith(const Scene& scene, const LidrOptions& options, const GlInfo& info,
                                   const OutputTransform& output, const ImageRGBA8* reference) {
    testContext();
    const std::vector<PointLight> lights = scene.lightsAt(scene.time);
    const ShadingParameters shading = sceneShading(scene, output);
    RenderResult r;
    LidrRenderer renderer(info, scene, options, scene.width, scene.height);
    r.stats = renderer.render(scene.camera, lights, shading);
    r.lidr = renderer.targets().readColor();
    if (!options.perSampleIndices) r.indexTargets = renderer.readIndexTargets();  // multisample: not readable
    if (reference) {
        REQUIRE(reference->width == r.lidr.width);
        REQUIRE(reference->height == r.lidr.height);
        r.reference = *reference;
    } else {
        ReferenceRenderer brute(info, scene, scene.width, scene.height, static_cast<int>(std::max<size_t>(lights.size(), 1)),
                                options.forceFixedLightTable, options.msaaSamples, options.transparency,
                                options.perSampleIndices);
        brute.render(scene.camera, lights, shading);
        r.reference = brute.targets().readColor();
    }
    r.evaluation = evaluateFrame(renderer, scene.camera, lights, r.lidr, r.reference);
    return r;
}
}  // namespace

RenderResult renderAndEvaluate(const Scene& scene, const LidrOptions& options, const GlInfo& info,
                               const OutputTransform& output) {
    return renderAndEvaluateWith(scene, options, info, output, nullptr);
}

RenderResult renderAndEvaluate(const Scene& scene, const LidrOptions& options, const ImageRGBA8& reference) {
    return renderAndEvaluateWith(scene, options, testGl(), OutputTransform{}, &reference);
}

RenderResult SharedReferences::renderAndEvaluate(const std::string& key, const Scene& scene, const LidrOptions& options) {
    const auto known = images_.find(key);
    if (known != images_.end()) return lidr::test::renderAndEvaluate(scene, options, known->second);
    RenderResult r = lidr::test::renderAndEvaluate(scene, options);
    images_.emplace(key, r.reference);
    return r;
}

void PixelChecks::require() const {
    INFO(failures_ << " failed pixel conditions; the first: " << first_);
    REQUIRE(failures_ == 0);
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
