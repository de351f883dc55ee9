// Shadows in the modes other than LIDR (issue 30): tiled, clustered and multi-pass forward shade with the same
// lookups as the brute-force reference (shadow_lookup.glsl, the same atlas and light-table tiles), so each equals
// the reference with shadows on, as it does without: spot and point casters among lights that cast none, a
// transparent layer (tiled, clustered), the float and the fixed-point light table. The suite also runs these under the
// GL 2.1 override (suite.gl21). The frame's statistics count the casters and the maps drawn: all of them on the
// first frame, none on the next when nothing moved.
#include <algorithm>
#include <cmath>
#include <memory>

#include <catch2/catch.hpp>

#include "gl_test_context.h"
#include "lidr/eval/image_compare.h"
#include "lidr/eval/light_coverage.h"
#include "lidr/modes/reference_renderer.h"
#include "lidr/modes/render_mode.h"
#include "lidr/scene/primitives.h"
#include "render_helpers.h"

using namespace lidr;
using namespace lidr::test;

namespace {

PointLight spotCaster(glm::vec3 position, glm::vec3 direction, float radius, float outer, glm::vec3 color) {
    PointLight l = light(position, radius, color);
    l.direction = glm::normalize(direction);
    l.outerConeAngle = outer;
    l.innerConeAngle = 0.6f * outer;
    l.castsShadow = true;
    return l;
}

// The floor scene with four pillars: three spot casters and two point casters whose shadows fall across the
// floor, the box, the sphere and the pillars, among 20 small lights that cast none. `glass`: a transparent
// sphere too, lit and shadowed in its own layer.
Scene pillarFloor(bool glass) {
    Scene scene = floorScene();
    for (float x : {-6.0f, 6.0f})
        for (float z : {-5.0f, 5.0f}) addBox(scene, {x - 0.4f, 0.0f, z - 0.4f}, {x + 0.4f, 4.0f, z + 0.4f}, 1, 2);
    if (glass) {
        addSphere(scene, {-3.0f, 2.0f, 4.0f}, 1.2f, addGlassMaterial(scene), 24);
    }
    scene.lights.push_back(spotCaster({-1.0f, 7.0f, 1.0f}, {-0.1f, -1.0f, -0.2f}, 12.0f, 0.7f, {1.0f, 0.9f, 0.7f}));
    scene.lights.push_back(spotCaster({7.0f, 5.0f, 0.0f}, {-1.0f, -0.6f, 0.0f}, 14.0f, 0.6f, {0.6f, 0.7f, 1.0f}));
    scene.lights.push_back(spotCaster({-8.0f, 3.0f, -8.0f}, {1.0f, -0.3f, 1.0f}, 14.0f, 0.5f, {0.9f, 0.5f, 0.4f}));
    PointLight point = light({2.0f, 3.5f, 3.0f}, 9.0f, {0.8f, 0.8f, 0.6f});
    point.castsShadow = true;
    scene.lights.push_back(point);
    point = light({-5.0f, 2.0f, -2.0f}, 7.0f, {0.5f, 0.9f, 0.5f});
    point.castsShadow = true;
    scene.lights.push_back(point);
    for (int i = 0; i < 20; ++i) {  // non-casters on a grid, low over the floor
        const float x = -9.0f + 18.0f * float(i % 5) / 4.0f, z = -9.0f + 18.0f * float(i / 5) / 3.0f;
        scene.lights.push_back(light({x, 0.8f, z}, 2.5f, {0.3f, 0.3f, 0.4f}));
    }
    return scene;
}

constexpr int kCasters = 5, kTiles = 3 + 2 * 6;

ShadingParameters shadowedShading(const Scene& scene, bool filtered) {
    ShadingParameters shading = sceneShading(scene, OutputTransform::linear());  // multi-pass's bound is linear
    shading.shadows.enabled = true;
    shading.shadows.atlas.size = 1024;
    shading.shadows.atlas.tileSize = 128;  // 64 tiles, 15 used
    shading.shadows.filtered = filtered;
    return shading;
}

struct Frame {
    ImageRGBA8 image;
    FrameStats first, second;
};

// Two frames of the same lights: the second must draw no map.
Frame renderTwice(Renderer& renderer, const Scene& scene, const ShadingParameters& shading) {
    Frame f;
    renderer.setTiming(true, true);
    f.first = renderer.render(scene.camera, scene.lights, shading);
    f.second = renderer.render(scene.camera, scene.lights, shading);
    f.image = renderer.targets().readColor();
    return f;
}

// A frame of `mode` ("tiled", "tiled without depth bounds", "clustered", "clustered occupied", "forward-multipass")
// with shadows on (spot and point casters; a transparent layer where the mode draws one), checked against the
// reference rendered the same way.
void checkShadowedMode(const std::string& mode, bool fixedTable, bool filtered) {
    const bool glass = mode != "forward-multipass";  // multi-pass draws no transparent layer (additive passes)
    const Scene scene = pillarFloor(glass);
    const ShadingParameters shading = shadowedShading(scene, filtered);

    ReferenceRenderer reference(testGl(), scene, scene.width, scene.height, int(scene.lights.size()), fixedTable,
                                0, glass);
    const Frame ref = renderTwice(reference, scene, shading);
    ShadingParameters unshadowed = shading;
    unshadowed.shadows.enabled = false;
    reference.render(scene.camera, scene.lights, unshadowed);
    // The shadows are really there: without them the reference is brighter, by far, in many pixels.
    const ImageError shadowEffect = compareImages(reference.targets().readColor(), ref.image);
    INFO("shadows change the reference in " << shadowEffect.differingPixels << " pixels, up to "
                                             << shadowEffect.maxAbsError << " steps");
    REQUIRE(shadowEffect.maxAbsError > 40);
    REQUIRE(shadowEffect.differingPixels > scene.width * scene.height / 20);

    RenderModeOptions o;
    o.mode = mode == "forward-multipass" ? mode : mode.rfind("clustered", 0) == 0 ? "clustered" : "tiled";
    o.tiled.depthBounds = mode == "tiled";
    o.clustered.occupiedClusters = mode == "clustered occupied";
    o.forceFixedLightTable = fixedTable;
    o.transparency = glass;
    std::unique_ptr<Renderer> renderer = createRenderer(o, testGl(), scene, scene.width, scene.height);
    const Frame f = renderTwice(*renderer, scene, shading);

    // The frame's statistics: every caster's maps on the first frame, none on the next (nothing moved).
    for (const FrameStats* s : {&ref.first, &f.first}) {
        CHECK(s->shadowCasters == kCasters);
        CHECK(s->shadowMapsDrawn == kTiles);
    }
    CHECK(f.second.shadowCasters == kCasters);
    CHECK(f.second.shadowMapsDrawn == 0);
    const auto& passes = f.second.passes;
    CHECK(std::any_of(passes.begin(), passes.end(), [](const PassTime& p) { return p.pass == "shadow-maps"; }));

    const auto* multipass = dynamic_cast<const MultipassForwardRenderer*>(renderer.get());
    if (!multipass || std::string(multipass->accumulation()) == "half-float") {
        // The same lights summed in the same order (ascending lists); one step for reassociation.
        // Multi-pass in half float: its float sum encoded once, the same step.
        const ImageError e = compareImages(f.image, ref.image);
        INFO(mode << " against the reference: max " << e.maxAbsError << ", " << e.differingPixels << " pixels");
        REQUIRE(e.maxAbsError <= 1);
        return;
    }
    // Multi-pass in its 8-bit target (no half-float colour buffers) rounds each light's term to 8 bits as it blends: floor(n / 2) + 1 steps where n lights touch
    // the pixel (test_forward_baselines.cpp), shadowed or not.
    const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
    const CoverageTruth touching = computeCoverage(renderer->targets().readDepth(), cam, scene.lights, -2e-3f);
    long violations = 0;
    int worst = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            int e = 0;
            for (int k = 0; k < 3; ++k)
                e = std::max(e, std::abs(int(f.image.at(x, y)[k]) - int(ref.image.at(x, y)[k])));
            worst = std::max(worst, e);
            if (e > touching.count(size_t(y) * scene.width + x) / 2 + 1) ++violations;
        }
    INFO("multi-pass against the reference: max " << worst << ", pixels over their bound " << violations);
    REQUIRE(violations == 0);
}

}  // namespace

TEST_CASE("clustered forward equals the reference with shadows on, nearest and filtered", "[shadows][modes][clustered]") {
    testContext();
    const bool filtered = GENERATE(false, true);
    DYNAMIC_SECTION("clustered" << (filtered ? ", filtered" : "")) { checkShadowedMode("clustered", false, filtered); }
}

TEST_CASE("tiled, clustered and multi-pass forward equal the reference with shadows on: spot and point casters",
          "[shadows][modes][slow][every-gl]") {
    testContext();
    const std::string mode = GENERATE(as<std::string>{}, "tiled", "tiled without depth bounds", "clustered",
                                      "clustered occupied", "forward-multipass");
    const bool fixedTable = GENERATE(false, true);
    const bool filtered = GENERATE(false, true);
    // Representative: tiled filtered with the float table, clustered with occupancy nearest with the fixed-point
    // one, multi-pass nearest with the fixed-point one.
    if (!takeRow((mode == "tiled" && !fixedTable && filtered) || (mode == "clustered occupied" && fixedTable && !filtered) ||
                 (mode == "forward-multipass" && fixedTable && !filtered)))
        return;
    DYNAMIC_SECTION(mode << (fixedTable ? ", fixed-point light table" : "") << (filtered ? ", filtered" : "")
                         << (mode != "forward-multipass" ? ", a transparent layer" : "")) {
        checkShadowedMode(mode, fixedTable, filtered);
    }
}

TEST_CASE("tiled, clustered and multi-pass forward: a moved caster redraws only its maps; shadows off draws none",
          "[shadows][modes]") {
    testContext();
    const std::string mode = GENERATE(as<std::string>{}, "tiled", "clustered", "forward-multipass");
    DYNAMIC_SECTION(mode) {
        Scene scene = pillarFloor(false);
        ShadingParameters shading = shadowedShading(scene, false);
        RenderModeOptions o;
        o.mode = mode;
        std::unique_ptr<Renderer> renderer = createRenderer(o, testGl(), scene, scene.width, scene.height);
        CHECK(renderer->render(scene.camera, scene.lights, shading).shadowMapsDrawn == kTiles);
        scene.lights[3].position.x += 0.5f;  // the first point caster: its six faces
        CHECK(renderer->render(scene.camera, scene.lights, shading).shadowMapsDrawn == 6);
        scene.lights[0].position.y += 0.5f;  // a spot caster: one map
        CHECK(renderer->render(scene.camera, scene.lights, shading).shadowMapsDrawn == 1);
        shading.shadows.enabled = false;
        const FrameStats& off = renderer->render(scene.camera, scene.lights, shading);
        CHECK(off.shadowCasters == 0);
        CHECK(off.shadowMapsDrawn == 0);
    }
}
