// Light types beyond point lights. Directional lights (the sun) are not indexed: every mode adds them in its
// forward pass through shading.glsl's lidrDirectionalLights, so every mode still equals the brute-force reference
// with them present; they are checked, read from scene files and (test_gltf_import.cpp) from glTF. Spot lights
// are indexed like point lights (the sphere test by their cone, the other volumes by their bounding sphere) and carry their cone in the light table, float
// and fixed point: every mode equals the reference with point, spot and directional lights, stress cones
// included, and with both falloffs in one scene (lidr's and glTF's inverse square). The BRDF model test (test_brdf.cpp) checks both types' pixels against the CPU model in every mode.
#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include <catch2/catch.hpp>

#include "config_cases.h"
#include "gl_test_context.h"
#include "lidr/base/error.h"
#include "lidr/eval/bench_scenes.h"
#include "lidr/eval/brdf.h"
#include "lidr/eval/image_compare.h"
#include "lidr/eval/light_coverage.h"
#include "lidr/modes/reference_renderer.h"
#include "lidr/modes/render_mode.h"
#include "lidr/render/light_table.h"
#include "lidr/scene/io/gltf_importer.h"
#include "lidr/scene/io/scene_file.h"
#include "lidr/scene/sphere_bounds.h"
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

PointLight spot(glm::vec3 position, glm::vec3 direction, float radius, float inner, float outer,
               glm::vec3 color = glm::vec3(1.0f)) {
    PointLight l = light(position, radius, color);
    l.direction = direction;
    l.innerConeAngle = inner;
    l.outerConeAngle = outer;
    return l;
}

// The sunlit floor with spot lights too: lamps aimed down and sideways at random, and the stress cones: nearly
// 0 and exactly 90 degrees, one holding the camera, one edge-on to the floor, ranges 1e-4 and (float table) 1e4.
Scene spotlitFloor(int pointLights, int spots, bool fixedTable) {
    Scene scene = sunlitFloor(pointLights);
    std::mt19937 rng(2029);
    std::uniform_real_distribution<float> xz(-10.0f, 10.0f), y(1.0f, 4.0f), r(2.0f, 5.0f), c(0.3f, 1.2f),
        tilt(-0.7f, 0.7f), angle(0.1f, 1.2f), innerShare(0.0f, 0.9f);
    for (int i = 0; i < spots; ++i) {
        const float outer = angle(rng);
        scene.lights.push_back(spot({xz(rng), y(rng), xz(rng)}, {tilt(rng), -1.0f, tilt(rng)}, r(rng),
                                    outer * innerShare(rng), outer, {c(rng), c(rng), c(rng)}));
    }
    const glm::vec3 eye = scene.camera.position;
    scene.lights.push_back(spot({-3.0f, 3.0f, 3.0f}, {0.0f, -1.0f, 0.0f}, 6.0f, 0.0f, 1e-3f, {50.0f, 50.0f, 50.0f}));
    scene.lights.push_back(spot({3.0f, 0.5f, -3.0f}, {0.0f, -1.0f, 0.2f}, 5.0f, 1.2f, 1.5707963f, {0.8f, 0.3f, 0.3f}));
    scene.lights.push_back(spot(eye + glm::vec3(0.0f, 1.0f, 1.0f), -eye, 40.0f, 0.2f, 0.4f, {0.3f, 0.3f, 0.3f}));
    scene.lights.push_back(spot({0.0f, 0.0f, 5.0f}, {1.0f, 0.0f, 0.0f}, 6.0f, 0.3f, 0.6f, {1.0f, 0.9f, 0.2f}));
    scene.lights.push_back(spot({1.0f, 1e-5f, 1.0f}, {0.0f, -1.0f, 0.0f}, 1e-4f, 0.1f, 0.5f));
    // Not with the fixed-point table: its 16-bit radii are fractions of the largest, so beside a 1e4 m light the
    // 2 m ones reach 0.15 m farther in the shader, and LIDR's lists then differ from the reference's sums by up
    // to 167 steps with point lights alike (a limit of that table, not of the cone: measured with every cone
    // angle set to 0).
    if (!fixedTable)
        scene.lights.push_back(spot({0.0f, 500.0f, 0.0f}, {0.1f, -1.0f, 0.0f}, 1e4f, 0.01f, 0.02f, {0.5f, 0.5f, 0.5f}));
    return scene;
}

Scene lampStreet() {
    Scene scene = loadSceneFile(sourcePath("media/scenes/lamp-street.json"));
    scene.width = testWidth();
    scene.height = testHeight();
    return scene;
}

ImageRGBA8 referenceImage(const Scene& scene, const ShadingParameters& shading, bool fixedTable = false) {
    const std::vector<PointLight> lights = scene.lightsAt(scene.time);
    ReferenceRenderer reference(testGl(), scene, scene.width, scene.height, std::max<int>(1, int(lights.size())),
                                fixedTable, 0, true);
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

TEST_CASE("scene files: spot lights (\"type\": \"spot\", cone angles in degrees), with their errors", "[lights][cpu][bad-input]") {
    const Scene scene = parseSceneJson(R"({"lights": [
        {"position": [0, 4, 0], "radius": 6, "type": "spot", "direction": [0, -1, 0], "inner_cone_angle": 20,
         "outer_cone_angle": 30},
        {"position": [1, 4, 0], "radius": 6, "type": "spot", "direction": [1, -1, 0]},
        {"position": [2, 4, 0], "radius": 6, "type": "point"}]})", ".", "spots.json");
    REQUIRE(scene.lights.size() == 3);
    CHECK(scene.lights[0].isSpot());
    CHECK(scene.lights[0].innerConeAngle == Approx(glm::radians(20.0f)));
    CHECK(scene.lights[0].outerConeAngle == Approx(glm::radians(30.0f)));
    CHECK(scene.lights[0].direction == glm::vec3(0.0f, -1.0f, 0.0f));
    CHECK(scene.lights[1].innerConeAngle == 0.0f);  // KHR_lights_punctual's defaults
    CHECK(scene.lights[1].outerConeAngle == Approx(glm::radians(45.0f)));
    CHECK_FALSE(scene.lights[2].isSpot());
    const auto error = [](const std::string& light) {
        try {
            parseSceneJson(R"({"lights": [)" + light + "]}", ".", "bad.json");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    const std::string at = R"({"position": [0, 1, 0], "radius": 2, )";
    CHECK_THAT(error(at + R"("type": "spot"})"), Contains("bad.json") && Contains("lights[0].direction") &&
                                                   Contains("missing"));
    CHECK_THAT(error(at + R"("type": "spot", "direction": [0, 0, 0]})"), Contains("lights[0].direction"));
    CHECK_THAT(error(at + R"("type": "spot", "direction": [0, -1, 0], "outer_cone_angle": 95})"),
               Contains("lights[0].outer_cone_angle") && Contains("(0, 90]"));
    CHECK_THAT(error(at + R"("type": "spot", "direction": [0, -1, 0], "inner_cone_angle": 45})"),
               Contains("lights[0].inner_cone_angle") && Contains("[0, outer_cone_angle 45)"));
    CHECK_THAT(error(at + R"("direction": [0, -1, 0]})"), Contains("lights[0].direction") && Contains("only for spot"));
    CHECK_THAT(error(at + R"("type": "area"})"), Contains("lights[0].type") && Contains("unknown light type 'area'"));
}

TEST_CASE("media/scenes/lamp-street.json: 16 spot lamps, 3 point lights and a sun", "[lights][cpu]") {
    const Scene scene = loadSceneFile(sourcePath("media/scenes/lamp-street.json"));
    REQUIRE(scene.lights.size() == 19);
    CHECK(std::count_if(scene.lights.begin(), scene.lights.end(), [](const PointLight& l) { return l.isSpot(); }) == 16);
    CHECK(scene.directionalLights.size() == 1);
    CHECK(scene.warnings.empty());
}

TEST_CASE("every mode equals the reference with directional lights present, and with spot lights", "[lights][every-gl]") {
    testContext();
    struct Case {
        const char* name;
        int pointLights;
    };
    const Case c = GENERATE(Case{"40 point lights + 2 directional", 40}, Case{"2 directional lights alone", 0},
                            Case{"30 point + 24 spot + 6 stress spot lights + 2 directional", 30},
                            Case{"30 point + 24 spot + 6 stress spot lights + 2 directional, every other one inverse-square", 30});
    std::vector<std::string> modes = {"lidr", "tiled", "clustered", "forward-multipass", "forward-brute"};
    if (testGl().gles) modes.erase(modes.begin() + 1);  // tiled's default depth bounds are refused on ES 2.0
    const std::string mode = GENERATE_COPY(from_range(modes));
    const bool spots = std::string(c.name).find("spot") != std::string::npos;
    const bool fixedTable = GENERATE(false, true);  // the RGBA8 fixed-point light table
    // Representative: points, spots and suns together in LIDR and multi-pass (float table), tiled (fixed-point).
    if (!takeRow(c.pointLights == 30 && std::string(c.name).find("inverse-square") == std::string::npos &&
                 fixedTable == (mode == "tiled") && mode != "forward-brute"))
        return;
    DYNAMIC_SECTION(c.name << ", " << mode << (fixedTable ? ", fixed-point light table" : "")) {
        Scene scene = spots ? spotlitFloor(c.pointLights, 24, fixedTable) : sunlitFloor(c.pointLights);
        if (std::string(c.name).find("inverse-square") != std::string::npos)
            for (size_t i = 0; i < scene.lights.size(); i += 2) {
                // glTF's falloff, as bright as lidr's at a third of the range (1/d^2 there is 9 / r^2)
                scene.lights[i].falloff = LightFalloff::InverseSquare;
                scene.lights[i].color *= scene.lights[i].radius * scene.lights[i].radius / 9.0f;
            }
        // Linear output: multi-pass's bound is in linear 8-bit steps (test_forward_baselines.cpp).
        const ShadingParameters shading = sceneShading(scene, OutputTransform::linear());
        const ImageRGBA8 reference = referenceImage(scene, shading, fixedTable);
        // The suns are really there: the reference without them is darker, by far, where they shine.
        ShadingParameters unlit = shading;
        unlit.directionalLights.clear();
        const ImageError sunEffect = compareImages(referenceImage(scene, unlit, fixedTable), reference);
        INFO("the suns change the reference by up to " << sunEffect.maxAbsError << " steps");
        REQUIRE(sunEffect.maxAbsError > 60);

        if (mode == "lidr") {
            LidrOptions options;  // the automatic configuration: the budget holds every pixel's overlap
            options.forceFixedLightTable = fixedTable;
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
        o.forceFixedLightTable = fixedTable;
        std::unique_ptr<Renderer> renderer = createRenderer(o, testGl(), scene, scene.width, scene.height);
        const std::vector<PointLight> lights = scene.lightsAt(scene.time);
        renderer->render(scene.camera, lights, shading);
        const ImageRGBA8 image = renderer->targets().readColor();
        const auto* multipass = dynamic_cast<const MultipassForwardRenderer*>(renderer.get());
        if (!multipass || std::string(multipass->accumulation()) == "half-float") {
            // The same lights summed in the same order (tiled, clustered: ascending lists); one step for reassociation.
            // Multi-pass in half float: its float sum encoded once, the same step.
            const ImageError e = compareImages(image, reference);
            INFO(mode << " against the reference: max " << e.maxAbsError << ", PSNR " << e.psnr);
            REQUIRE(e.maxAbsError <= 1);
            return;
        }
        // Multi-pass in its 8-bit target (no half-float colour buffers) rounds its first pass (ambient +
        // directional lights) and each light's term to 8 bits as it blends: with n point lights at a pixel, floor(n / 2) + 1 steps (test_forward_baselines.cpp).
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

TEST_CASE("spot lights: the cone term and the checks of the cone", "[lights][cpu][bad-input]") {
    PointLight l;
    CHECK(spotCone(l) == glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));  // a point light: the term is 1
    l.direction = {0.0f, -2.0f, 0.0f};
    l.innerConeAngle = 0.5f;
    l.outerConeAngle = 1.0f;
    const glm::vec4 cone = spotCone(l);
    const float scale = 1.0f / (std::cos(0.5f) - std::cos(1.0f));
    CHECK(cone.y == Approx(-scale));
    CHECK(cone.w == Approx(-std::cos(1.0f) * scale));
    // Along the axis: 1; at the outer angle: 0; between: the squared ramp, as the shader computes it.
    const auto term = [&](float angle) {
        const glm::vec3 toLight(-std::sin(angle), std::cos(angle), 0.0f);  // from the surface up to the light
        const float t = std::clamp(cone.w - glm::dot(toLight, glm::vec3(cone)), 0.0f, 1.0f);
        return t * t;
    };
    CHECK(term(0.0f) == 1.0f);
    CHECK(term(0.5f) == Approx(1.0f).margin(1e-5));
    CHECK(term(1.0f) == Approx(0.0f).margin(1e-5));
    CHECK(term(1.2f) == 0.0f);
    const float mid = (std::cos(0.75f) - std::cos(1.0f)) * scale;
    CHECK(term(0.75f) == Approx(mid * mid).epsilon(1e-4));
    const auto problem = [](PointLight light) {
        Scene s;
        s.lights = {light};
        try {
            s.validate();
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("(accepted)");
    };
    CHECK(problem(l) == "(accepted)");
    PointLight bad = l;
    bad.outerConeAngle = 1.6f;
    CHECK_THAT(problem(bad), Contains("light 0: outer cone angle 1.6 must be in [0, pi/2]"));
    bad = l;
    bad.innerConeAngle = 1.0f;
    CHECK_THAT(problem(bad), Contains("inner cone angle 1 must be in [0, outer cone angle 1)"));
    bad = l;
    bad.direction = glm::vec3(0.0f);
    CHECK_THAT(problem(bad), Contains("spot direction") && Contains("length 0"));
    bad = l;
    bad.outerConeAngle = NAN;
    CHECK_THAT(problem(bad), Contains("outer cone angle"));
}

TEST_CASE("spot lights: the CPU truth holds a spot where its cone reaches the surface, and only there", "[lights][every-gl]") {
    testContext();
    const Scene scene = lampStreet();
    const std::vector<PointLight> lights = scene.lightsAt(scene.time);
    ReferenceRenderer reference(testGl(), scene, scene.width, scene.height, int(lights.size()), false, 0, false);
    reference.render(scene.camera, lights, sceneShading(scene));
    const ImageFloat depth = reference.targets().readDepth();
    const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
    const float band = 2e-3f;
    const CoverageTruth cones = computeCoverage(depth, cam, lights, band);
    std::vector<PointLight> spheres = lights;  // the same lights as points: their bounding spheres
    for (PointLight& l : spheres) l.outerConeAngle = 0.0f;
    const CoverageTruth bounds = computeCoverage(depth, cam, spheres, band);
    long conePairs = 0, spherePairs = 0, spotSpherePairs = 0, missing = 0, outside = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            const size_t p = size_t(y) * scene.width + x;
            if (!cones.surface[p]) continue;
            const glm::dvec3 surface(unprojectPixel(cam, x, y, depth.at(x, y)));
            const auto has = [](const CoverageTruth& t, size_t pixel, uint32_t light) {
                return std::binary_search(t.lights.begin() + t.offsets[pixel], t.lights.begin() + t.offsets[pixel + 1], light);
            };
            for (size_t i = 0; i < lights.size(); ++i) {
                const PointLight& l = lights[i];
                const bool inCone = has(cones, p, uint32_t(i + 1)), inSphere = has(bounds, p, uint32_t(i + 1));
                conePairs += inCone;
                spherePairs += inSphere;
                if (!l.isSpot()) continue;
                spotSpherePairs += inSphere;
                // What the light gives there apart from the BRDF: range attenuation x cone term.
                const glm::dvec3 toLight = glm::dvec3(l.position) - surface;
                const double d2 = glm::dot(toLight, toLight), r = double(l.radius);
                const double reach = std::max(0.0, 1.0 - d2 / (r * r)) * spotTerm(l, toLight / std::sqrt(d2));
                if (reach > 0.02 && !inCone) ++missing;     // well inside cone and range: must be listed
                if (inCone && reach <= 0.0) ++outside;      // listed where the spot gives nothing
            }
        }
    INFO("lamp-street at " << scene.width << "x" << scene.height << ": light-pixel pairs, cones exact " << conePairs
                           << ", spots as their spheres " << spherePairs << " (the 16 spots' spheres: " << spotSpherePairs
                           << "); missing " << missing << ", listed outside " << outside);
    REQUIRE(missing == 0);
    REQUIRE(outside == 0);
    REQUIRE(conePairs < spherePairs);
    // The cones of lamps aimed down light a fraction of their spheres' surfaces (the measured figure is in
    // doc/architecture.md, "Light types").
    CHECK(double(spherePairs - conePairs) > 0.3 * double(spotSpherePairs));
}

TEST_CASE("inverse-square lights: KHR_lights_punctual's falloff and window, scene files' \"falloff\", fixed-point colours",
          "[lights][cpu][bad-input]") {
    PointLight l = light({0.0f, 0.0f, 0.0f}, 4.0f, {2.0f, 1.0f, 0.5f});
    l.falloff = LightFalloff::InverseSquare;
    // The specification's recommended window: saturate(1 - (d / r)^4) / d^2; 1 cm floor; exactly 0 from r on.
    for (const double d : {0.5, 1.0, 2.0, 3.0, 3.9, 3.999})
        CHECK(distanceAttenuation(l, d) == Approx((1.0 - std::pow(d / 4.0, 4.0)) / (d * d)).epsilon(1e-12));
    CHECK(distanceAttenuation(l, 0.0) == Approx(1e4));
    CHECK(distanceAttenuation(l, 4.0) == 0.0);
    CHECK(distanceAttenuation(l, 7.0) == 0.0);
    l.falloff = LightFalloff::Smooth;
    CHECK(distanceAttenuation(l, 2.0) == Approx(0.75));
    CHECK(distanceAttenuation(l, 4.0) == 0.0);

    // gltfLightRadiusWithoutRange's cut: the windowed light differs from the infinite one by less than the
    // threshold at every distance (checked densely), and the infinite one gives less than it beyond the cut.
    for (const float brightest : {0.01f, 1.0f, 40.0f}) {
        PointLight cut = l;
        cut.falloff = LightFalloff::InverseSquare;
        cut.radius = gltfLightRadiusWithoutRange(brightest);
        double worst = 0.0;
        for (int k = 1; k <= 4000; ++k) {
            const double d = cut.radius * 1.5 * k / 4000.0;
            const double infinite = brightest / std::max(d * d, 1e-4);
            worst = std::max(worst, infinite - brightest * distanceAttenuation(cut, d));
        }
        INFO("brightest channel " << brightest << ", radius " << cut.radius << ", worst difference " << worst);
        CHECK(worst <= gltfLightCutThreshold * 1.0001);
        CHECK(worst >= gltfLightCutThreshold * 0.99);  // the cut is where it stops being visible, not far beyond
    }

    // Scene files: "falloff" is smooth (the default) or inverse_square; anything else names the field.
    const Scene scene = parseSceneJson(R"({"lights": [
        {"position": [0, 4, 0], "radius": 6, "falloff": "inverse_square"},
        {"position": [1, 4, 0], "radius": 6, "falloff": "smooth"}, {"position": [2, 4, 0], "radius": 6}]})", ".", "f.json");
    REQUIRE(scene.lights.size() == 3);
    CHECK(scene.lights[0].falloff == LightFalloff::InverseSquare);
    CHECK(scene.lights[1].falloff == LightFalloff::Smooth);
    CHECK(scene.lights[2].falloff == LightFalloff::Smooth);
    try {
        parseSceneJson(R"({"lights": [{"position": [0, 4, 0], "radius": 6, "falloff": "linear"}]})", ".", "bad.json");
        FAIL("no error");
    } catch (const Error& e) {
        CHECK_THAT(e.what(), Contains("bad.json") && Contains("lights[0].falloff") && Contains("linear"));
    }

    // The fixed-point table's colour for them: each channel within brightest / 255 of the real one, over 80
    // octaves of intensity (one shared scale would leave a 1 cd light beside a 1e5 cd one nothing but 0).
    for (const float brightest : {1e-6f, 0.3183f, 1.0f, 3.0f, 1000.0f, 1e5f, 3e7f})
        for (const glm::vec3 hue : {glm::vec3(1.0f), glm::vec3(1.0f, 0.37f, 0.02f), glm::vec3(0.0f, 0.5f, 1.0f)})
            for (const bool spotLight : {false, true}) {
                const glm::vec3 color = hue * brightest;
                const FixedColor fixed = fixedInverseSquareColor(color, spotLight);
                INFO("colour " << color.r << " " << color.g << " " << color.b << ", decoded " << fixed.decoded.r << " "
                               << fixed.decoded.g << " " << fixed.decoded.b);
                for (int c = 0; c < 3; ++c) CHECK(std::abs(fixed.decoded[c] - color[c]) <= brightest / 255.0f * 1.0001f);
                // alpha 1..254 (0 and 255 are lidr-falloff spot and point lights), the spot flag in code >= 127
                CHECK(fixed.bytes[3] >= 1);
                CHECK(fixed.bytes[3] <= 254);
                CHECK((fixed.bytes[3] - 1 >= 127) == spotLight);
            }
}

// The exact volume test (sphere, batched with the point lights) keeps a spot light's fragment only where the
// surface point lies inside its cone and range, so its slot is taken only there. For every scheme x width x
// budget, on the lamp street and on the spot-lit floor (stress cones included), with tile-culled volumes and with
// the icosahedron meshes: no light missing where the budget holds the pixel's marks (the CPU truth with its band
// inside), no light listed or counted where its cone and range do not reach the surface (the truth with the band
// outside), and so, where the budget holds the overlap, the GPU count equals the truth.
TEST_CASE("the sphere test indexes a spot light by its cone: lists equal the CPU truth, every scheme x width x budget",
          "[lights][render][schemes][cones][every-gl]") {
    testContext();
    const bool floor = GENERATE(false, true);
    const bool tiles = GENERATE(true, false);
    const ConfigCase c = GENERATE(from_range(packingCases(kBudgets, {8, 16})));
    if (!takeRow(!floor && tiles && c.packing.scheme == PackingSchemeKind::BitShift && c.packing.budget == 4 &&
                 c.packing.indexBits == 8))
        return;  // representative: the lamp street, bit-shift budget 4, 8-bit, tile-culled volumes
    DYNAMIC_SECTION((floor ? "spot-lit floor" : "lamp street") << ", " << c.name
                    << (tiles ? ", tile-culled volumes" : ", volume meshes")) {
        const Scene scene = floor ? spotlitFloor(10, 24, false) : lampStreet();
        LidrOptions options;
        options.packing = c.packing;
        options.volumeTest = VolumeTest::Sphere;
        options.tileCulledVolumes = tiles;
        // The reference and the truths below depend on the scene alone, not on the row's scheme, budget, width or
        // tiles: computed once a scene for the rows that share it.
        static SharedReferences references;
        const RenderResult r = references.renderAndEvaluate(floor ? "floor" : "street", scene, options);
        const FrameEvaluation& e = r.evaluation;
        requireExactWithinBudget(e, c.name);

        static std::map<bool, std::pair<CoverageTruth, CoverageTruth>> truths;  // (touching, the spheres') a scene
        if (!truths.count(floor)) {
            const std::vector<PointLight> lights = scene.lightsAt(scene.time);
            ReferenceRenderer reference(testGl(), scene, scene.width, scene.height, int(lights.size()), false, 0, false);
            reference.render(scene.camera, lights, sceneShading(scene));
            const ImageFloat depth = reference.targets().readDepth();
            const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
            std::vector<PointLight> spheres = lights;  // the same lights as points: what bounding spheres would mark
            for (PointLight& l : spheres) l.outerConeAngle = 0.0f;
            truths.emplace(floor, std::make_pair(computeCoverage(depth, cam, lights, -2e-3f),  // the band outside
                                                 computeCoverage(depth, cam, spheres, 2e-3f)));
        }
        const CoverageTruth& touching = truths.at(floor).first;
        const CoverageTruth& sphereTruth = truths.at(floor).second;
        long listedOutside = 0, countedOutside = 0, countNotTruth = 0, marks = 0, spherePairs = 0;
        const int budget = c.packing.budget;
        for (size_t p = 0; p < e.marked.size(); ++p) {
            if (!e.truth.surface[p]) continue;
            const auto first = touching.lights.begin() + touching.offsets[p], last = touching.lights.begin() + touching.offsets[p + 1];
            for (uint32_t index : e.lists.decoded[p]) listedOutside += !std::binary_search(first, last, index);
            countedOutside += e.marked[p] > touching.count(p);
            if (e.marked[p] <= budget) countNotTruth += e.marked[p] < e.truth.count(p) || e.marked[p] > touching.count(p);
            marks += e.marked[p];
            spherePairs += sphereTruth.count(p);
        }
        INFO(c.name << ": lights listed outside their cone or range " << listedOutside << ", pixels counting more "
                    << "lights than touch them " << countedOutside << ", within budget with a count other than the "
                    << "truth's " << countNotTruth << "; marks " << marks << ", the truth's pairs "
                    << e.truth.lights.size() << ", the bounding spheres' " << spherePairs);
        REQUIRE(listedOutside == 0);
        REQUIRE(countedOutside == 0);
        REQUIRE(countNotTruth == 0);
        REQUIRE(marks >= long(e.truth.lights.size()));
        // The spheres around the cones would have marked far more (lamps aimed down: about 60 % more pairs).
        REQUIRE(double(marks) < 0.8 * double(spherePairs));
        // CPU sorting drops whole lights where its groups (by screen footprint) conflict, counted (checked above).
        if (budget >= e.maxMarked && c.packing.scheme != PackingSchemeKind::CpuSorted) REQUIRE(e.pixelsOverBudget == 0);
    }
}

// The stencil tests (backface, exact) and the front-face test draw a spot light's cone mesh (a cone with a
// spherical cap that encloses the range-capped cone; test_lidr_core.cpp checks it on the CPU): no light of the
// truth is lost where the budget holds the marks, the image equals the reference there, and the marks are far
// fewer than the spots' spheres would make; `exact` marks nothing outside the cone mesh's reach (the spheres
// grown by the cap's 5 %), and the front-face lists are checked against the CPU's conservative count.
TEST_CASE("the stencil and front-face tests draw a spot light's cone mesh: no light lost, far fewer marks than spheres",
          "[lights][render][cones][every-gl]") {
    testContext();
    const bool floor = GENERATE(false, true);
    const VolumeTest test = GENERATE(VolumeTest::BackFace, VolumeTest::ExactStencil, VolumeTest::FrontFace);
    if (!takeRow(floor)) return;  // representative: each test on the spot-lit floor
    DYNAMIC_SECTION((floor ? "spot-lit floor" : "lamp street") << ", " << volumeTestName(test)) {
        const Scene scene = floor ? spotlitFloor(10, 24, false) : lampStreet();
        LidrOptions options;
        options.packing = {PackingSchemeKind::BitShift, 16, 8};
        options.volumeTest = test;
        const RenderResult r = renderAndEvaluate(scene, options);
        const FrameEvaluation& e = r.evaluation;
        requireExactWithinBudget(e, volumeTestName(test));

        const std::vector<PointLight> lights = scene.lightsAt(scene.time);
        ReferenceRenderer reference(testGl(), scene, scene.width, scene.height, int(lights.size()), false, 0, false);
        reference.render(scene.camera, lights, sceneShading(scene));
        const ImageFloat depth = reference.targets().readDepth();
        const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
        std::vector<PointLight> spheres = lights;
        for (PointLight& l : spheres) l.outerConeAngle = 0.0f;
        const CoverageTruth sphereTruth = computeCoverage(depth, cam, spheres, 2e-3f);
        const CoverageTruth grownSpheres = computeCoverage(depth, cam, spheres, -0.05f);
        long marks = 0, spherePairs = 0, beyondMesh = 0, belowTruth = 0;
        for (size_t p = 0; p < e.marked.size(); ++p) {
            if (!e.truth.surface[p]) continue;
            marks += e.marked[p];
            spherePairs += sphereTruth.count(p);
            belowTruth += e.marked[p] < e.truth.count(p);
            if (test == VolumeTest::ExactStencil) beyondMesh += e.marked[p] > grownSpheres.count(p);
        }
        INFO(volumeTestName(test) << ": marks " << marks << ", the truth's pairs " << e.truth.lights.size()
                                  << ", the bounding spheres' " << spherePairs << "; pixels marked by fewer lights "
                                  << "than touch them " << belowTruth << ", beyond the meshes' reach " << beyondMesh
                                  << ", over budget " << e.pixelsOverBudget);
        REQUIRE(belowTruth == 0);
        REQUIRE(beyondMesh == 0);
        REQUIRE(e.pixelsOverBudget == 0);
        // backface also marks surfaces in front of a volume; exact and front-face far fewer than the spheres.
        if (test == VolumeTest::ExactStencil) REQUIRE(double(marks) < 0.6 * double(spherePairs));
        if (test == VolumeTest::BackFace) REQUIRE(double(marks) < double(spherePairs) + 0.5 * double(e.truth.lights.size()));
    }
}

TEST_CASE("spot lights: the cone's box holds every point of the range-capped cone and is tighter than the sphere's",
          "[lights][cpu][cones]") {
    std::mt19937 rng(29);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), u01(0.0f, 1.0f), angle(1e-4f, 1.5707963f);
    double boxVolume = 0.0, sphereBoxVolume = 0.0;
    for (int trial = 0; trial < 400; ++trial) {
        PointLight l;
        l.position = {u(rng) * 10.0f, u(rng) * 10.0f, u(rng) * 10.0f};
        l.radius = 0.1f + 5.0f * u01(rng);
        l.direction = {u(rng), u(rng), u(rng)};
        if (trial % 7 == 0) l.direction = {0.0f, trial % 2 ? -1.0f : 1.0f, 0.0f};  // along an axis: the cap's extreme
        if (glm::length(l.direction) < 1e-3f) l.direction = {0.0f, -1.0f, 0.0f};
        l.outerConeAngle = trial % 5 == 0 ? 1.5707963f : angle(rng);
        glm::vec3 lo, hi;
        spotLightBox(l, l.radius, lo, hi);
        const glm::vec3 axis = glm::normalize(l.direction);
        for (int k = 0; k < 400; ++k) {
            // A point of the cone: on its rim or cap (the box's extremes lie there), or inside.
            const glm::vec3 d = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(1e-6f));
            const float off = (k % 2 ? 1.0f : u01(rng)) * l.outerConeAngle;
            const glm::vec3 side = glm::normalize(d - axis * glm::dot(d, axis) + glm::vec3(1e-7f));
            const glm::vec3 dir = std::cos(off) * axis + std::sin(off) * side;
            const glm::vec3 p = l.position + dir * (l.radius * (k % 3 ? 1.0f : u01(rng)));
            INFO("trial " << trial << ", outer " << l.outerConeAngle << ", point " << k);
            REQUIRE(glm::all(glm::lessThanEqual(lo, p + 1e-5f)));
            REQUIRE(glm::all(glm::lessThanEqual(p - 1e-5f, hi)));
        }
        const glm::vec3 size = hi - lo;
        boxVolume += double(size.x) * size.y * size.z;
        sphereBoxVolume += 8.0 * double(l.radius) * l.radius * l.radius;
    }
    INFO("boxes " << boxVolume << ", the spheres' boxes " << sphereBoxVolume);
    CHECK(boxVolume < 0.6 * sphereBoxVolume);
}

TEST_CASE("multi-pass forward culls meshes by the spot cone's box: fewer mesh draws than the spheres, the same image",
          "[lights][forward][cones][every-gl]") {
    testContext();
    const Scene scene = lampStreet();
    const std::vector<PointLight> lights = scene.lightsAt(scene.time);
    std::vector<PointLight> points = lights;
    for (PointLight& l : points) l.outerConeAngle = 0.0f;
    RenderModeOptions o;
    o.mode = "forward-multipass";
    const ShadingParameters shading = sceneShading(scene, OutputTransform::linear());
    std::unique_ptr<Renderer> cones = createRenderer(o, testGl(), scene, scene.width, scene.height);
    const FrameStats withCones = cones->render(scene.camera, lights, shading);
    std::unique_ptr<Renderer> spheres = createRenderer(o, testGl(), scene, scene.width, scene.height);
    const FrameStats withSpheres = spheres->render(scene.camera, points, shading);
    INFO("mesh draws: cones " << withCones.volumeDrawCalls << ", the same lights as spheres " << withSpheres.volumeDrawCalls);
    REQUIRE(withCones.volumeDrawCalls < withSpheres.volumeDrawCalls);
    // Culling only skips meshes the cone cannot light: the image equals the reference (as in the every-mode test).
    const ImageRGBA8 image = cones->targets().readColor(), reference = referenceImage(scene, shading);
    const ImageError e = compareImages(image, reference);
    INFO("multi-pass against the reference: max " << e.maxAbsError);
    REQUIRE(e.maxAbsError <= 3);
}

TEST_CASE("the automatic budget counts spot lights by their cones", "[lights][auto][cones]") {
    testContext();
    if (!testGl().occlusionQuery) return;  // the automatic budget is measured with occlusion queries
    // The lamp street at 512 x 384: at most 4 lights touch a pixel (the cones); the spots' spheres overlap 6.
    Scene scene = lampStreet();
    scene.width = 512;
    scene.height = 384;
    std::vector<PointLight> points = scene.lightsAt(scene.time);
    for (PointLight& l : points) l.outerConeAngle = 0.0f;
    Scene asPoints = scene;
    asPoints.lights = points;
    asPoints.lightPaths.clear();  // the lights at scene.time, static
    const RenderResult cones = renderAndEvaluate(scene, LidrOptions{});
    const RenderResult spheres = renderAndEvaluate(asPoints, LidrOptions{});
    INFO("budget: cones " << cones.stats.autoDecision.budget << " (truth's overlap " << cones.evaluation.maxTruthOverlap
                          << ", marked " << cones.evaluation.maxMarked << "), the same lights as points "
                          << spheres.stats.autoDecision.budget << " (marked " << spheres.evaluation.maxMarked << ")");
    requireExactWithinBudget(cones.evaluation, "cones");
    REQUIRE(cones.evaluation.maxMarked == cones.evaluation.maxTruthOverlap);
    REQUIRE(cones.stats.autoDecision.budget == 4);
    REQUIRE(spheres.stats.autoDecision.budget == 8);
    REQUIRE(cones.evaluation.pixelsOverBudget == 0);
}

TEST_CASE("bench scenes spots-N and spots-N-points: the same lights, spots aimed down or points; bad names refused",
          "[lights][cpu][bench][bad-input]") {
    Scene spots, points;
    REQUIRE(makeSpotSceneByName("spots-64", spots));
    REQUIRE(makeSpotSceneByName("spots-64-points", points));
    REQUIRE(spots.lights.size() == 64);
    REQUIRE(points.lights.size() == 64);
    int spotCount = 0;
    for (size_t i = 0; i < spots.lights.size(); ++i) {
        REQUIRE(spots.lights[i].position == points.lights[i].position);
        REQUIRE(spots.lights[i].radius == points.lights[i].radius);
        REQUIRE_FALSE(points.lights[i].isSpot());
        spotCount += spots.lights[i].isSpot();
        if (spots.lights[i].isSpot()) REQUIRE(spots.lights[i].direction == glm::vec3(0.0f, -1.0f, 0.0f));
    }
    REQUIRE(spotCount == 61);  // the 3 large movers stay point lights
    Scene other;
    REQUIRE_FALSE(makeSpotSceneByName("hall-255", other));
    for (const char* bad : {"spots-", "spots-3", "spots-x", "spots-70000", "spots-64-spheres"}) {
        INFO(bad);
        REQUIRE_THROWS_WITH(makeSpotSceneByName(bad, other), Contains("use spots-N or spots-N-points"));
    }
}
