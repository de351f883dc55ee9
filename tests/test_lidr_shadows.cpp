// Shadows in LIDR itself (issue 30), the paper's two ways: the sphere test discards surface points a light's
// maps shadow (ShadowLookup::VolumePass: the light takes no slot there), or the forward pass looks each listed
// light up by index (ShadowLookup::ForwardPass, and always for transparent layers and front-face lists). Either
// way the image is the reference's with shadows on; the first way's lists hold fewer light-pixel pairs.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <numeric>
#include <sstream>

#include "config_cases.h"
#include "gl_test_context.h"
#include "render_helpers.h"
#include "lidr/eval/frame_evaluation.h"
#include "lidr/eval/image_compare.h"
#include "lidr/modes/auto_mode_renderer.h"
#include "lidr/modes/reference_renderer.h"
#include "lidr/modes/render_mode.h"
#include "lidr/render/shadow_casters.h"
#include "lidr/scene/default_scene.h"
#include "lidr/scene/primitives.h"

using namespace lidr;
using namespace lidr::test;

namespace {

PointLight spot(glm::vec3 position, glm::vec3 target, float radius, float outerDegrees, glm::vec3 color) {
    PointLight l = light(position, radius, color);
    l.direction = glm::normalize(target - position);
    l.outerConeAngle = glm::radians(outerDegrees);
    l.innerConeAngle = 0.6f * l.outerConeAngle;
    return l;
}

// The test floor (box and sphere) with four pillars, lit by two shadow-casting point lights (six maps each),
// three shadow-casting spots and one point light that casts none: 15 maps, in a 1024 atlas of 256 tiles.
// glass: a transparent pane among them (transparent layers look up in the forward pass).
Scene pillarFloor(bool glass = false) {
    Scene s = floorScene();
    for (const glm::vec2 at : {glm::vec2(-5.0f, 3.0f), glm::vec2(2.5f, -4.5f), glm::vec2(6.5f, -1.0f), glm::vec2(-1.0f, 6.0f)})
        addBox(s, glm::vec3(at.x - 0.4f, 0.0f, at.y - 0.4f), glm::vec3(at.x + 0.4f, 3.5f, at.y + 0.4f), 1, 2);
    if (glass) {
        s.materials.push_back(Material{"glass", glm::vec3(0.4f, 0.6f, 0.9f), "", glm::vec3(0.5f), 32.0f, 0.45f});
        addBox(s, glm::vec3(-3.0f, 0.0f, 2.0f), glm::vec3(1.0f, 2.0f, 2.2f), int(s.materials.size()) - 1, 2);
    }
    auto cast = [](PointLight l) {
        l.castsShadow = true;
        return l;
    };
    s.lights = {cast(light({-3.5f, 2.5f, 4.5f}, 10.0f, {1.0f, 0.8f, 0.6f})),
                cast(light({4.0f, 3.0f, -2.0f}, 9.0f, {0.6f, 0.8f, 1.0f})),
                cast(spot({0.0f, 7.0f, 7.0f}, {-1.0f, 0.0f, 0.0f}, 14.0f, 45.0f, {0.9f, 0.9f, 0.7f})),
                cast(spot({8.0f, 5.0f, 3.0f}, {2.0f, 0.0f, -2.0f}, 12.0f, 40.0f, {0.8f, 0.5f, 0.9f})),
                cast(spot({-7.0f, 6.0f, -4.0f}, {-2.0f, 0.0f, 1.0f}, 12.0f, 42.0f, {0.5f, 1.0f, 0.6f})),
                light({1.5f, 1.2f, 7.5f}, 5.0f, {0.7f, 0.7f, 0.7f})};
    return s;
}

ShadingParameters shadowShading(const Scene& scene, ShadowLookup lookup, bool shadows = true) {
    ShadingParameters shading = sceneShading(scene, OutputTransform::linear());
    shading.shadows.enabled = shadows;
    shading.shadows.atlas.size = 1024;
    shading.shadows.atlas.tileSize = 256;
    shading.shadows.lidrLookup = lookup;
    return shading;
}

// lights: the scene's own at its time where empty.
ImageRGBA8 referenceImage(const Scene& scene, const ShadingParameters& shading, const LidrOptions& o,
                          std::vector<PointLight> lights = {}) {
    if (lights.empty()) lights = scene.lightsAt(scene.time);
    ReferenceRenderer reference(testGl(), scene, scene.width, scene.height, int(lights.size()), o.forceFixedLightTable,
                                o.msaaSamples, o.transparency, o.perSampleIndices);
    reference.render(scene.camera, lights, shading);
    return reference.targets().readColor();
}

struct ShadowedFrame {
    ImageRGBA8 image;
    FrameStats stats, second;
    FrameEvaluation evaluation;
    long countedPairs = -1;  // light-pixel pairs the volume test kept (stencil count), -1 without a count
};

ShadowedFrame renderLidr(const Scene& scene, const LidrOptions& o, const ShadingParameters& shading,
                         const ImageRGBA8& reference) {
    const std::vector<PointLight> lights = scene.lightsAt(scene.time);
    LidrRenderer renderer(testGl(), scene, o, scene.width, scene.height);
    ShadowedFrame f;
    f.stats = renderer.render(scene.camera, lights, shading);
    f.second = renderer.render(scene.camera, lights, shading);  // a static scene: the maps are kept
    f.image = renderer.targets().readColor();
    if (!o.perSampleIndices) f.evaluation = evaluateFrame(renderer, scene.camera, lights, f.image, reference);
    const std::vector<uint8_t> counts = renderer.readLightCounts();
    if (!counts.empty()) {
        f.countedPairs = 0;
        for (uint8_t c : counts) f.countedPairs += c;
    }
    return f;
}

const char* lookupName(ShadowLookup l) { return l == ShadowLookup::VolumePass ? "volume pass" : "forward pass"; }

}  // namespace

TEST_CASE("LIDR shadows: the shadows are there (the reference with them differs from the one without)",
          "[shadows][lidr][every-gl]") {
    testContext();
    const Scene scene = pillarFloor();
    const LidrOptions o;
    const ImageRGBA8 shadowed = referenceImage(scene, shadowShading(scene, ShadowLookup::VolumePass), o);
    const ImageRGBA8 unshadowed = referenceImage(scene, shadowShading(scene, ShadowLookup::VolumePass, false), o);
    const ImageError e = compareImages(shadowed, unshadowed, 8);
    INFO("pixels darker by more than 8 steps with shadows: " << e.pixelsOverThreshold << " of " << e.comparedPixels);
    REQUIRE(e.pixelsOverThreshold > e.comparedPixels / 20);
    long brighter = 0;
    for (size_t i = 0; i < shadowed.pixels.size(); ++i)
        if ((i & 3) != 3 && shadowed.pixels[i] > unshadowed.pixels[i]) ++brighter;
    REQUIRE(brighter == 0);  // a shadow only takes light away
}

// Every scheme at budgets 1, 4 and 16 (8-bit) and the automatic configuration, both lookups: where the budget
// holds a pixel's marks the image is the reference's within a step, and with the automatic budget everywhere.
TEST_CASE("LIDR shadows equal the reference: every scheme x budget 1/4/16 and auto, both lookups", "[shadows][lidr][slow][every-gl]") {
    testContext();
    std::vector<ConfigCase> cases = packingCases({1, 4, 16}, {8});
    cases.push_back({"auto", PackingConfig{}});
    const ConfigCase c = GENERATE_COPY(from_range(cases));
    const ShadowLookup lookup = GENERATE(ShadowLookup::VolumePass, ShadowLookup::ForwardPass);
    const bool tiles = GENERATE(true, false);
    // Representative: the automatic configuration with the volume pass's test over tiles, and bit-shift budget 4
    // with the forward pass's lookup over volume meshes.
    if (!takeRow((c.name == "auto" && lookup == ShadowLookup::VolumePass && tiles) ||
                 (c.name == "bitshift budget 4, 8-bit" && lookup == ShadowLookup::ForwardPass && !tiles)))
        return;
    DYNAMIC_SECTION(c.name << ", lookup in the " << lookupName(lookup) << (tiles ? ", tile-culled" : ", volume meshes")) {
        const Scene scene = pillarFloor();
        LidrOptions o;
        o.packing = c.packing;
        o.tileCulledVolumes = tiles;
        const ShadingParameters shading = shadowShading(scene, lookup);
        const ImageRGBA8 reference = referenceImage(scene, shading, o);
        const ShadowedFrame f = renderLidr(scene, o, shading, reference);
        const FrameEvaluation& e = f.evaluation;
        INFO("within budget: max " << e.errorWithinBudget.maxAbsError << " over " << e.errorWithinBudget.comparedPixels
                                   << " pixels; whole image max " << e.error.maxAbsError << "; pixels over budget "
                                   << e.pixelsOverBudget << ", most marks " << e.maxMarked);
        CHECK(f.stats.shadowCasters == 5);
        CHECK(f.stats.shadowMapsDrawn == 15);
        CHECK(f.second.shadowMapsDrawn == 0);
        REQUIRE(e.lists.invalidSlots == 0);
        REQUIRE(e.errorWithinBudget.comparedPixels > e.error.comparedPixels / 4);
        REQUIRE(e.errorWithinBudget.maxAbsError <= 1);
        // The automatic budget holds every pixel where occlusion queries measure it (ES 2.0 falls back to 4).
        if ((c.packing.autoBudget() && testGl().occlusionQuery) ||
            (c.packing.budget >= e.maxMarked && c.packing.scheme != PackingSchemeKind::CpuSorted)) {
            REQUIRE(e.pixelsOverBudget == 0);
            REQUIRE(e.error.maxAbsError <= 1);
        }
    }
}

// The fixed-point light table (contexts without float textures) holds positions to 16 bits: the forward pass
// and the reference look up from those, the volume pass's test from the exact light; the image is still the
// reference's.
TEST_CASE("LIDR shadows with the fixed-point light table equal the reference, both lookups", "[shadows][lidr][slow]") {
    testContext();
    const ShadowLookup lookup = GENERATE(ShadowLookup::VolumePass, ShadowLookup::ForwardPass);
    DYNAMIC_SECTION("lookup in the " << lookupName(lookup)) {
        const Scene scene = pillarFloor();
        LidrOptions o;
        o.packing = {PackingSchemeKind::BitShift, 16, 8};
        o.forceFixedLightTable = true;
        const ShadingParameters shading = shadowShading(scene, lookup);
        const ImageRGBA8 reference = referenceImage(scene, shading, o);
        const ShadowedFrame f = renderLidr(scene, o, shading, reference);
        const FrameEvaluation& e = f.evaluation;
        INFO("whole image max " << e.error.maxAbsError << ", pixels over 1 " << e.error.pixelsOverThreshold);
        REQUIRE(e.lists.invalidSlots == 0);
        REQUIRE(e.pixelsOverBudget == 0);
        REQUIRE(e.error.maxAbsError <= 1);
    }
}

// The paper's first way takes shadowed pixels out of the lists: the same frame indexed both ways, bit-shift
// budget 16 (every pixel's overlap fits): the forward-pass lookup keeps every light that reaches a surface
// (the CPU truth's pairs), the volume pass fewer, by the pairs it found shadowed; both images the reference's.
TEST_CASE("LIDR shadows: the volume pass's test leaves fewer light-pixel pairs in the lists", "[shadows][lidr][slow]") {
    testContext();
    const Scene scene = pillarFloor();
    LidrOptions o;
    o.packing = {PackingSchemeKind::BitShift, 16, 8};
    const ImageRGBA8 reference = referenceImage(scene, shadowShading(scene, ShadowLookup::VolumePass), o);
    const ShadowedFrame volume = renderLidr(scene, o, shadowShading(scene, ShadowLookup::VolumePass), reference);
    const ShadowedFrame forward = renderLidr(scene, o, shadowShading(scene, ShadowLookup::ForwardPass), reference);
    const long truthPairs = long(volume.evaluation.truth.lights.size());
    INFO("light-pixel pairs: truth " << truthPairs << ", forward-pass lookup: slots " << forward.evaluation.lists.slotsUsed
                                     << " counted " << forward.countedPairs << ", volume-pass test: slots "
                                     << volume.evaluation.lists.slotsUsed << " counted " << volume.countedPairs
                                     << "; most per pixel " << forward.evaluation.lists.maxSlotsUsed << " -> "
                                     << volume.evaluation.lists.maxSlotsUsed);
    REQUIRE(forward.evaluation.pixelsOverBudget == 0);
    REQUIRE(forward.evaluation.lists.droppedLightPixels == 0);  // every light reaching a surface is listed
    REQUIRE(forward.evaluation.lists.slotsUsed >= truthPairs);
    REQUIRE(forward.countedPairs == forward.evaluation.lists.slotsUsed);
    REQUIRE(volume.countedPairs == volume.evaluation.lists.slotsUsed);
    // A quarter of the pairs and more lie in a shadow on this floor (measured: see doc/shadows.md).
    REQUIRE(double(volume.evaluation.lists.slotsUsed) < 0.8 * double(forward.evaluation.lists.slotsUsed));
    REQUIRE(volume.evaluation.error.maxAbsError <= 1);
    REQUIRE(forward.evaluation.error.maxAbsError <= 1);
    // Every pair the volume pass kept, the forward-pass lookup kept too (the first way only removes).
    long keptOnlyByVolume = 0;
    for (size_t p = 0; p < volume.evaluation.lists.decoded.size(); ++p) {
        std::vector<uint32_t> a = volume.evaluation.lists.decoded[p], b = forward.evaluation.lists.decoded[p];
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        for (uint32_t l : a) keptOnlyByVolume += !std::binary_search(b.begin(), b.end(), l);
    }
    REQUIRE(keptOnlyByVolume == 0);

    // At a budget below the overlap the shorter lists drop fewer lights: bit-shift budget 4 keeps the first four
    // marks of a pixel, and shadowed lights no longer take those slots.
    o.packing = {PackingSchemeKind::BitShift, 4, 8};
    const ShadowedFrame volume4 = renderLidr(scene, o, shadowShading(scene, ShadowLookup::VolumePass), reference);
    const ShadowedFrame forward4 = renderLidr(scene, o, shadowShading(scene, ShadowLookup::ForwardPass), reference);
    INFO("budget 4: pixels over budget " << forward4.evaluation.pixelsOverBudget << " (forward-pass lookup) -> "
                                         << volume4.evaluation.pixelsOverBudget << " (volume-pass test); pixels off the "
                                         << "reference by more than a step " << forward4.evaluation.error.pixelsOverThreshold
                                         << " -> " << volume4.evaluation.error.pixelsOverThreshold);
    REQUIRE(forward4.evaluation.pixelsOverBudget > 0);
    REQUIRE(volume4.evaluation.pixelsOverBudget < forward4.evaluation.pixelsOverBudget / 2);
    REQUIRE(volume4.evaluation.error.pixelsOverThreshold < forward4.evaluation.error.pixelsOverThreshold);
}

// Where a volume fragment cannot know the surface (the front-face lists of transparent layers and of MSAA edge
// samples; the per-sample path's stencil tests) the forward pass looks up, whatever the lookup asked: the image is
// the reference's. Single-sample MSAA's edge samples take the front-face lists, which differ from the reference
// by their own bound (doc/msaa-transparency.md) with or without shadows: there the pixels it gets right without
// shadows must stay right with them.
TEST_CASE("LIDR shadows with MSAA and transparent layers equal the reference", "[shadows][lidr][msaa][slow]") {
    testContext();
    const GlInfo& info = testGl();
    enum Path { SingleSample, Msaa, PerSample };
    const Path path = GENERATE(SingleSample, Msaa, PerSample);
    const ShadowLookup lookup = GENERATE(ShadowLookup::VolumePass, ShadowLookup::ForwardPass);
    const char* names[] = {"single-sample, sphere", "MSAA x4, sphere-ray", "MSAA x4 per-sample, frontface"};
    DYNAMIC_SECTION(names[path] << ", glass, lookup in the " << lookupName(lookup)) {
        const bool perSampleAvailable = info.multisampleTexture && info.sampleShading &&
                                        info.maxColorTextureSamples >= 4 && info.maxSamples >= 4;
        if ((path == Msaa && info.maxSamples < 4) || (path == PerSample && !perSampleAvailable)) {
            WARN(names[path] << ": not in this context (" << info.version << ")");
            return;
        }
        const Scene scene = pillarFloor(true);
        LidrOptions o;
        o.transparency = true;
        // The automatic budget where occlusion queries measure it; ES 2.0's fallback (4) would not hold the pane's
        // lists: budget 16 there.
        if (!info.occlusionQuery) o.packing = {PackingSchemeKind::BitShift, 16, 8};
        if (path != SingleSample) o.msaaSamples = 4;
        if (path == Msaa) o.volumeTest = VolumeTest::SphereRay;
        if (path == PerSample) {
            o.perSampleIndices = true;
            o.volumeTest = VolumeTest::FrontFace;
        }
        const ShadingParameters shading = shadowShading(scene, lookup);
        const ImageRGBA8 reference = referenceImage(scene, shading, o);
        const ShadowedFrame f = renderLidr(scene, o, shading, reference);
        REQUIRE(f.stats.shadowCasters == 5);
        if (path != Msaa) {
            const ImageError e = compareImages(f.image, reference);
            INFO("against the reference: max " << e.maxAbsError << ", pixels over 1 " << e.pixelsOverThreshold);
            if (path == SingleSample) {
                REQUIRE(f.evaluation.lists.invalidSlots == 0);
                REQUIRE(f.evaluation.pixelsOverBudget == 0);
            }
            REQUIRE(e.maxAbsError <= 1);
            return;
        }
        const ShadingParameters unshadowed = shadowShading(scene, lookup, false);
        const ImageRGBA8 plainReference = referenceImage(scene, unshadowed, o);
        const ImageRGBA8 plain = renderLidr(scene, o, unshadowed, plainReference).image;
        long right = 0, wrongNow = 0, shadowMatters = 0;
        for (size_t p = 0; p < plain.pixels.size() / 4; ++p) {
            bool wasRight = true, isRight = true, differs = false;
            for (size_t c = 0; c < 3; ++c) {
                const size_t i = p * 4 + c;
                wasRight = wasRight && std::abs(int(plain.pixels[i]) - int(plainReference.pixels[i])) <= 1;
                isRight = isRight && std::abs(int(f.image.pixels[i]) - int(reference.pixels[i])) <= 1;
                differs = differs || std::abs(int(reference.pixels[i]) - int(plainReference.pixels[i])) > 8;
            }
            right += wasRight;
            wrongNow += wasRight && !isRight;
            shadowMatters += wasRight && differs;
        }
        INFO("pixels equal to the reference without shadows " << right << " of " << plain.pixels.size() / 4
                                                              << ", of them wrong with shadows " << wrongNow
                                                              << ", shadowed by more than 8 steps " << shadowMatters);
        REQUIRE(double(right) > 0.98 * double(plain.pixels.size() / 4));
        REQUIRE(shadowMatters > long(plain.pixels.size() / 4) / 20);
        REQUIRE(wrongNow == 0);
    }
}

// Not a check, a measurement (hidden; doc/shadows.md): the room (makeDefaultScene, 255 lights, 1024 x 768) with its
// N brightest lights casting (chooseShadowCasters, lidr-demo --shadows N; point lights: six maps each, 128 x 128), indexed both ways with bit-shift budget 16 (8-bit): the
// light-pixel pairs the volume test kept (the stencil count; the first frame draws the maps, the second none), the most lights on one pixel, and the image against
// the reference. LIDR_SHADOW_MEASURE="N lookup" (lookup: volume | forward) runs one frame pair of that alone, with
// CPU pass timing, for scripts/callgrind_passes.sh-style instruction counts per pass under valgrind.
TEST_CASE("LIDR shadows: list sizes on the room, both lookups (measurement)", "[.][shadows-measure]") {
    testContext();
    DefaultSceneOptions so;
    std::vector<int> only;
    std::string onlyLookup;
    if (const char* m = std::getenv("LIDR_SHADOW_MEASURE")) {
        std::istringstream in(m);
        int n = 0;
        in >> n >> onlyLookup;
        only = {n};
        so.width = 512, so.height = 384;  // under valgrind: a quarter of the pixels
    }
    const Scene scene = makeDefaultScene(so);
    for (int casters : only.empty() ? std::vector<int>{0, 8, 32, 128} : only) {
        const Scene& s = scene;
        std::vector<PointLight> lights = s.lightsAt(s.time);
        chooseShadowCasters(lights, cameraMatrices(s.camera, s.width, s.height), casters);  // as lidr-demo --shadows K
        for (ShadowLookup lookup : {ShadowLookup::ForwardPass, ShadowLookup::VolumePass}) {
            if (!onlyLookup.empty() && onlyLookup != (lookup == ShadowLookup::VolumePass ? "volume" : "forward")) continue;
            ShadingParameters shading = shadowShading(s, lookup, casters > 0);
            shading.shadows.atlas.size = 4096;  // 1024 maps of 128 x 128: 128 point lights take 768
            shading.shadows.atlas.tileSize = 128;
            LidrOptions o;
            o.packing = {PackingSchemeKind::BitShift, 16, 8};
            o.timing = !onlyLookup.empty();
            o.timingMethod = TimingMethod::CpuFinish;
            LidrRenderer renderer(testGl(), s, o, s.width, s.height);
            const int firstMaps = renderer.render(s.camera, lights, shading).shadowMapsDrawn;
            const FrameStats stats = renderer.render(s.camera, lights, shading);
            long pairs = 0;
            int most = 0;
            for (uint8_t c : renderer.readLightCounts()) pairs += c, most = std::max(most, int(c));
            std::cout << "room, " << casters << " casters, lookup in the " << lookupName(lookup) << ": light-pixel pairs "
                      << pairs << " (" << double(pairs) / (double(s.width) * s.height) << " per pixel), most on a pixel "
                      << most << ", maps drawn " << firstMaps << " then " << stats.shadowMapsDrawn;
            if (onlyLookup.empty()) {
                const ImageRGBA8 image = renderer.targets().readColor();
                const ImageError e = compareImages(image, referenceImage(s, shading, o, lights));
                std::cout << ", against the reference: max " << e.maxAbsError << " steps";
            }
            std::cout << "\n";
        }
    }
}

// The automatic mode hands the frame's shading (shadows included) to whichever candidate draws it: every trial
// frame, LIDR's among them, is the reference's.
TEST_CASE("LIDR shadows through the automatic mode: every trial frame equals the reference", "[shadows][lidr][modes][auto][slow]") {
    testContext();
    const Scene scene = pillarFloor();
    RenderModeOptions o;
    o.mode = "auto";
    const std::unique_ptr<Renderer> renderer = createRenderer(o, testGl(), scene, scene.width, scene.height);
    const auto& automatic = dynamic_cast<const AutoModeRenderer&>(*renderer);
    const ShadingParameters shading = shadowShading(scene, ShadowLookup::VolumePass);
    const ImageRGBA8 reference = referenceImage(scene, shading, LidrOptions{});
    const std::vector<PointLight> lights = scene.lightsAt(scene.time);
    bool lidrDrew = false;
    for (int frame = 0; frame < 3 * AutoModeOptions{}.trialFrames; ++frame) {
        const FrameStats& stats = renderer->render(scene.camera, lights, shading);
        const ImageError e = compareImages(renderer->targets().readColor(), reference);
        INFO("frame " << frame << " drawn by " << automatic.lastMode() << ": max " << e.maxAbsError << ", casters "
                      << stats.shadowCasters);
        REQUIRE(stats.shadowCasters == 5);
        // Multi-pass: 1 step in half float; in its 8-bit target (contexts without half-float colour buffers) it
        // rounds each light's term as it blends: floor(n / 2) + 1 steps with n lights at a pixel
        // (test_forward_baselines.cpp), n at most the scene's 6 here.
        REQUIRE(e.maxAbsError <= (automatic.lastMode() == "forward-multipass" ? int(lights.size()) / 2 + 1 : 1));
        lidrDrew = lidrDrew || automatic.lastMode() == "lidr";
    }
    REQUIRE(lidrDrew);
}
