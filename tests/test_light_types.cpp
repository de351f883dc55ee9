// Light types beyond point lights. Directional lights (the sun) are not indexed: every mode adds them in its
// forward pass through shading.glsl's lidrDirectionalLights, so every mode still equals the brute-force reference
// with them present; they are checked, read from scene files and (test_gltf_import.cpp) from glTF. The BRDF
// model test (test_brdf.cpp) checks their pixels against the CPU model in every mode.
#include <algorithm>
#include <random>

#include <catch2/catch.hpp>

#include "gl_test_context.h"
#include "lidr/base/error.h"
#include "lidr/eval/image_compare.h"
#include "lidr/eval/light_coverage.h"
#include "lidr/modes/reference_renderer.h"
#include "lidr/modes/render_mode.h"
#include "lidr/scene/io/scene_file.h"
#include "render_helpers.h"

using namespace lidr;
using namespace lidr::test;
using Catch::Matchers::Contains;

namespace {

// A low warm sun from the side and a cool sky light from above: together they light every face of the floor
// scene's box and sphere that the camera sees.
std::vector<DirectionalLight> twoSuns() {
    return {{{-0.5f, -0.35f, -0.6f}, {0.9f, 0.7f, 0.45f}}, {{0.2f, -1.0f, 0.1f}, {0.15f, 0.2f, 0.3f}}};
}

Scene sunlitFloor(int pointLights) {
    Scene scene = floorScene();
    std::mt19937 rng(29);
    std::uniform_real_distribution<float> xz(-11.0f, 11.0f), y(0.05f, 3.0f), r(0.5f, 4.0f), c(0.1f, 0.8f);
    for (int i = 0; i < pointLights; ++i)
        scene.lights.push_back(light({xz(rng), y(rng), xz(rng)}, r(rng), {c(rng), c(rng), c(rng)}));
    scene.directionalLights = twoSuns();
    return scene;
}

ImageRGBA8 referenceImage(const Scene& scene, const ShadingParameters& shading) {
    const std::vector<PointLight> lights = scene.lightsAt(scene.time);
    ReferenceRenderer reference(testGl(), scene, scene.width, scene.height, std::max<int>(1, int(lights.size())),
                                false, 0, true);
    reference.render(scene.camera, lights, shading);
    return reference.targets().readColor();
}

}  // namespace

TEST_CASE("directional lights: at most 4, a direction that normalises, a colour >= 0; checked before any work",
          "[lights][cpu][bad-input]") {
    Scene scene;  // no GL: a [cpu] test
    scene.directionalLights = twoSuns();
    REQUIRE_NOTHROW(scene.validate());
    const auto problem = [&](std::vector<DirectionalLight> lights) {
        Scene s = scene;
        s.directionalLights = std::move(lights);
        try {
            s.validate();
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    CHECK_THAT(problem(std::vector<DirectionalLight>(5)), Contains("5 directional lights; at most 4"));
    CHECK_THAT(problem({{{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}}}), Contains("directional light 0: direction") &&
                                                                  Contains("has length 0"));
    CHECK_THAT(problem({{}, {{0.0f, 1e30f, 0.0f}, {1.0f, 1.0f, 1.0f}}}), Contains("directional light 1: direction"));
    CHECK_THAT(problem({{{0.0f, -1.0f, 0.0f}, {1.0f, -0.5f, 1.0f}}}), Contains("color must be finite and >= 0"));
    CHECK_THAT(problem({{{0.0f, NAN, 0.0f}, {1.0f, 1.0f, 1.0f}}}), Contains("direction must be finite"));
    // Every render() checks ShadingParameters the same way, before it draws.
    ShadingParameters shading = sceneShading(scene);
    CHECK(shading.directionalLights.size() == 2);
    shading.directionalLights.resize(5);
    CHECK_THROWS_WITH(checkShadingParameters(shading), Contains("at most 4"));
}

TEST_CASE("scene files: directional_lights, with their errors named by field", "[lights][cpu][bad-input]") {
    const Scene scene = parseSceneJson(R"({"directional_lights": [
        {"direction": [0, -2, 0], "color": [1, 0.5, 0.25]}, {"direction": [1, -1, 0]}]})", ".", "suns.json");
    REQUIRE(scene.directionalLights.size() == 2);
    CHECK(scene.directionalLights[0].direction == glm::vec3(0.0f, -2.0f, 0.0f));
    CHECK(scene.directionalLights[0].color == glm::vec3(1.0f, 0.5f, 0.25f));  // linear, like point lights' colours
    CHECK(scene.directionalLights[1].color == glm::vec3(1.0f));
    CHECK(scene.lights.empty());  // not indexed: point lights' indices are unchanged
    const auto error = [](const std::string& text) {
        try {
            parseSceneJson(text, ".", "bad.json");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    CHECK_THAT(error(R"({"directional_lights": [{"color": 1}]})"),
               Contains("bad.json") && Contains("directional_lights[0].direction") && Contains("missing"));
    CHECK_THAT(error(R"({"directional_lights": [{"direction": [0, 0, 0]}]})"),
               Contains("directional_lights[0].direction") && Contains("length 0"));
    CHECK_THAT(error(R"({"directional_lights": [{"direction": [0, -1, 0], "radius": 2}]})"),
               Contains("directional_lights[0].radius") && Contains("unknown key"));
    CHECK_THAT(error(R"({"directional_lights": [{"direction": [0, -1, 0], "color": [1, -1, 1]}]})"),
               Contains("directional_lights[0].color"));
    std::string five = R"({"directional_lights": [)";
    for (int i = 0; i < 5; ++i) five += std::string(i ? ", " : "") + R"({"direction": [0, -1, 0]})";
    CHECK_THAT(error(five + "]}"), Contains("directional_lights") && Contains("5 directional lights; at most 4"));
}

TEST_CASE("every mode equals the reference with directional lights present", "[lights]") {
    testContext();
    struct Case {
        const char* name;
        int pointLights;
    };
    const Case c = GENERATE(Case{"40 point lights + 2 directional", 40}, Case{"2 directional lights alone", 0});
    std::vector<std::string> modes = {"lidr", "tiled", "forward-multipass", "forward-brute"};
    if (testGl().gles) modes.erase(modes.begin() + 1);  // tiled's default depth bounds are refused on ES 2.0
    const std::string mode = GENERATE_COPY(from_range(modes));
    DYNAMIC_SECTION(c.name << ", " << mode) {
        const Scene scene = sunlitFloor(c.pointLights);
        // Linear output: multi-pass's bound is in linear 8-bit steps (test_forward_baselines.cpp).
        const ShadingParameters shading = sceneShading(scene, OutputTransform::linear());
        const ImageRGBA8 reference = referenceImage(scene, shading);
        // The suns are really there: the reference without them is darker, by far, where they shine.
        ShadingParameters unlit = shading;
        unlit.directionalLights.clear();
        const ImageError sunEffect = compareImages(referenceImage(scene, unlit), reference);
        INFO("the suns change the reference by up to " << sunEffect.maxAbsError << " steps");
        REQUIRE(sunEffect.maxAbsError > 60);

        if (mode == "lidr") {
            LidrOptions options;  // the automatic configuration: the budget holds every pixel's overlap
            RenderResult r = renderAndEvaluate(scene, options, testGl(), OutputTransform::linear());
            requireExactWithinBudget(r.evaluation, mode);  // the pixels the budget holds, against the reference
            // With occlusion queries the budget holds every pixel; ES 2.0's fixed budget (no queries) does not.
            if (!testGl().occlusionQuery) return;
            REQUIRE(r.evaluation.pixelsOverBudget == 0);
            const ImageError e = compareImages(r.lidr, reference);
            INFO("lidr against the reference: max " << e.maxAbsError);
            REQUIRE(e.maxAbsError <= 1);
            return;
        }
        RenderModeOptions o;
        o.mode = mode;
        std::unique_ptr<Renderer> renderer = createRenderer(o, testGl(), scene, scene.width, scene.height);
        const std::vector<PointLight> lights = scene.lightsAt(scene.time);
        renderer->render(scene.camera, lights, shading);
        const ImageRGBA8 image = renderer->targets().readColor();
        if (mode != "forward-multipass") {
            // The same lights summed in the same order (tiled: ascending tile lists); one step for reassociation.
            const ImageError e = compareImages(image, reference);
            INFO(mode << " against the reference: max " << e.maxAbsError << ", PSNR " << e.psnr);
            REQUIRE(e.maxAbsError <= 1);
            return;
        }
        // Multi-pass rounds its first pass (ambient + directional lights) and each light's term to 8 bits as it
        // blends: with n point lights at a pixel, floor(n / 2) + 1 steps (test_forward_baselines.cpp).
        const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
        const CoverageTruth touching = computeCoverage(renderer->targets().readDepth(), cam, lights, -2e-3f);
        long violations = 0;
        int worst = 0;
        for (int y = 0; y < scene.height; ++y)
            for (int x = 0; x < scene.width; ++x) {
                int e = 0;
                for (int k = 0; k < 3; ++k) e = std::max(e, std::abs(int(image.at(x, y)[k]) - int(reference.at(x, y)[k])));
                worst = std::max(worst, e);
                if (e > touching.count(size_t(y) * scene.width + x) / 2 + 1) ++violations;
            }
        INFO("multi-pass against the reference: max " << worst << ", pixels over their bound " << violations);
        REQUIRE(violations == 0);
    }
}
