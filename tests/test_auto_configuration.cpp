// LIDR's automatic configuration (doc/auto.md): the decision rules on the CPU, then whole frames on the GPU —
// the measured budget equals the controlled overlap, compact numbering gives the narrowest width, a frame
// that needs more than it was packed with is re-packed at once, and nothing is dropped.
#include <algorithm>
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "gl_test_context.h"
#include "lidr/base/error.h"
#include "lidr/eval/bench_scenes.h"
#include "lidr/eval/controlled_scenes.h"
#include "lidr/scene/default_scene.h"
#include "lidr/modes/auto_mode_renderer.h"
#include "lidr/modes/reference_renderer.h"
#include "lidr/scene/primitives.h"
#include "lidr/eval/image_compare.h"
#include "lidr/technique/auto_configuration.h"
#include "lidr/technique/overlap_probe.h"
#include "render_helpers.h"

using namespace lidr;
using namespace lidr::test;

TEST_CASE("auto: the narrowest index width for the visible lights", "[auto][cpu]") {
    struct Case {
        int lights, bits;
    };
    for (const Case c : {Case{0, 4}, {1, 4}, {15, 4}, {16, 8}, {255, 8}, {256, 16}, {65535, 16}}) {
        INFO(c.lights << " lights");
        REQUIRE(AutoConfiguration::indexBitsFor(c.lights) == c.bits);
    }
    REQUIRE_THROWS_WITH(AutoConfiguration::indexBitsFor(65536), Catch::Contains("65,535"));
}

TEST_CASE("auto: widths widen at once and narrow only after the hold", "[auto][cpu]") {
    AutoConfiguration a(16, 3);
    REQUIRE(a.chooseIndexBits(200) == 8);   // the first frame is taken as it is
    REQUIRE(a.chooseIndexBits(300) == 16);  // wider: at once
    REQUIRE(a.chooseIndexBits(10) == 16);   // narrower: held
    REQUIRE(a.chooseIndexBits(100) == 16);
    REQUIRE(a.chooseIndexBits(10) == 8);    // third frame in a row that fits less: the widest of them, 8
    REQUIRE(a.chooseIndexBits(10) == 8);
    REQUIRE(a.chooseIndexBits(300) == 16);
    // A count that flips across a width boundary every frame never narrows.
    for (int i = 0; i < 20; ++i) REQUIRE(a.chooseIndexBits(i % 2 ? 10 : 300) == 16);
}

TEST_CASE("auto: the budget follows the measured need, re-packs on overflow, never oscillates", "[auto][cpu]") {
    AutoConfiguration a(16, 4);
    REQUIRE(a.budget() == AutoConfiguration::kInitialBudget);
    // First measurement: taken as it is, down or up; down needs no re-pack, up does.
    REQUIRE(a.observeNeed(1) == 0);
    REQUIRE(a.budget() == 1);
    REQUIRE(a.observeNeed(8) == 8);  // overflow: re-pack this frame with 8
    REQUIRE(a.budget() == 8);
    REQUIRE(a.observeNeed(8) == 0);
    for (int i = 0; i < 3; ++i) {
        REQUIRE(a.observeNeed(i == 1 ? 4 : 2) == 0);
        REQUIRE(a.budget() == 8);  // held
    }
    REQUIRE(a.observeNeed(2) == 0);
    REQUIRE(a.budget() == 4);  // after 4 frames that needed at most 4
    // Over the largest budget (need 0): packed with the largest, which still drops: reported, not repeated.
    REQUIRE(a.observeNeed(0) == 16);
    REQUIRE(a.observeNeed(0) == 0);
    REQUIRE(a.budget() == 16);
    // Needs alternating every frame: the budget stays at the larger one.
    for (int i = 0; i < 20; ++i) {
        REQUIRE(a.observeNeed(i % 2 ? 2 : 16) == 0);
        REQUIRE(a.budget() == 16);
    }
    // A context that cannot bind budget 16's targets caps the budget.
    AutoConfiguration capped(4, 0);
    REQUIRE(capped.observeNeed(0) == 0);  // initial 4 is already the largest: nothing to re-pack into
    REQUIRE(capped.observeNeed(8) == 0);
    REQUIRE(capped.budget() == 4);
    REQUIRE_THROWS_WITH(AutoConfiguration(3, 0), Catch::Contains("1, 2, 4, 8, 16 or 32"));
    // The widest budget follows the frame's index width: 32 at 4 and 8 bits, 16 at 16 bits.
    AutoConfiguration wide(32, 2);
    REQUIRE(wide.observeNeed(0) == 32);  // over every threshold: the largest
    REQUIRE(wide.budget() == 32);
    wide.setMaxBudget(16);  // a frame at 16-bit indices: budget 32 would need 16 targets
    REQUIRE(wide.budget() == 16);
    REQUIRE(wide.observeNeed(32) == 0);  // 32 needed, 16 the most: packed with 16, reported over budget
    REQUIRE(wide.budget() == 16);
    wide.setMaxBudget(32);
    REQUIRE(wide.observeNeed(32) == 32);  // back at 8 bits: re-packed with 32 the same frame
    REQUIRE_THROWS_WITH(wide.setMaxBudget(64), Catch::Contains("1, 2, 4, 8, 16 or 32"));
}

TEST_CASE("auto: narrowing is asked every few frames; each answer stands for the frames since the last",
          "[auto][cpu]") {
    AutoConfiguration a(16, 8, 4);
    REQUIRE(a.asksNarrowing());  // the first frame asks everything
    REQUIRE(a.observeNeed(8, true) == 8);  // first measurement above the initial 4: re-packed
    // Frames 1-3 ask only "over 8"; the need they report is the budget ("fits, less unknown").
    for (int f = 1; f <= 3; ++f) {
        REQUIRE_FALSE(a.asksNarrowing());
        REQUIRE(a.observeNeed(8, false) == 0);
        REQUIRE(a.budget() == 8);
    }
    REQUIRE(a.asksNarrowing());          // frame 4
    REQUIRE(a.observeNeed(2, true) == 0);  // fits 4 (the probe's "over half"): stands for frames 1-4
    REQUIRE(a.budget() == 8);
    for (int f = 5; f <= 7; ++f) {
        REQUIRE_FALSE(a.asksNarrowing());
        REQUIRE(a.observeNeed(8, false) == 0);  // unknown below: neither counts nor restarts
        REQUIRE(a.budget() == 8);
    }
    REQUIRE(a.asksNarrowing());
    REQUIRE(a.observeNeed(4, true) == 0);  // frames 5-8: eight frames that fit 4
    REQUIRE(a.budget() == 4);
    // An overflow between two answers is re-packed in its own frame and restarts the count.
    REQUIRE_FALSE(a.asksNarrowing());
    REQUIRE(a.observeNeed(8, false) == 8);
    REQUIRE(a.budget() == 8);
    for (int f = 0; f < 2; ++f) {
        REQUIRE_FALSE(a.asksNarrowing());
        REQUIRE(a.observeNeed(8, false) == 0);
    }
    REQUIRE(a.asksNarrowing());  // every fourth frame: the cadence goes on
    REQUIRE(a.observeNeed(4, true) == 0);
    REQUIRE(a.budget() == 8);  // three frames fit 4 since the overflow, not eight
    REQUIRE_THROWS_WITH(AutoConfiguration(16, 8, 0), Catch::Contains("narrowing interval"));
}

TEST_CASE("auto: the smallest budget no pixel exceeds, from the probe's counts", "[auto][cpu]") {
    using A = std::array<long, OverlapProbe::kThresholds>;
    REQUIRE(OverlapProbe::smallestBudget(A{0, 0, 0, 0, 0, 0}) == 1);
    REQUIRE(OverlapProbe::smallestBudget(A{5, 0, 0, 0, 0, 0}) == 2);
    REQUIRE(OverlapProbe::smallestBudget(A{50, 9, 3, 0, 0, 0}) == 8);
    REQUIRE(OverlapProbe::smallestBudget(A{50, 9, 3, 2, 0, 0}) == 16);
    REQUIRE(OverlapProbe::smallestBudget(A{50, 9, 3, 2, 1, 0}) == 32);
    REQUIRE(OverlapProbe::smallestBudget(A{50, 9, 3, 2, 1, 1}) == 0);
    // Steady frames measure two thresholds (-1: not measured).
    REQUIRE(OverlapProbe::aroundBudget(8) == 0b001100u);
    REQUIRE(OverlapProbe::aroundBudget(1) == 0b000001u);
    REQUIRE(OverlapProbe::aroundBudget(32) == 0b110000u);
    REQUIRE(OverlapProbe::aboveBudget(4) == 0b111000u);
    REQUIRE(OverlapProbe::aboveBudget(16) == 0b100000u);
    REQUIRE(OverlapProbe::smallestBudget(A{-1, -1, 0, 0, -1, -1}) == 4);   // at most half the budget needed
    REQUIRE(OverlapProbe::smallestBudget(A{-1, -1, 7, 0, -1, -1}) == 8);   // the budget was right
    REQUIRE(OverlapProbe::smallestBudget(A{-1, -1, 7, 3, -1, -1}) == -1);  // over: ask the thresholds above
    REQUIRE(OverlapProbe::smallestBudget(A{-1, -1, -1, 9, 2, 1}) == 0);
    // An overflow's second question (the thresholds above the budget) completes the first.
    A asked{-1, -1, 7, 3, -1, -1};
    OverlapProbe::merge(asked, A{-1, -1, -1, -1, 0, 0});
    REQUIRE(asked == A{-1, -1, 7, 3, 0, 0});
    REQUIRE(OverlapProbe::smallestBudget(asked) == 16);
    OverlapProbe::merge(asked, A{-1, -1, -1, 1, 0, -1});  // a later measurement of a threshold replaces it
    REQUIRE(asked == A{-1, -1, 7, 1, 0, 0});
}

namespace {
int controlledSize(bool width) { return isSoftpipe() ? (width ? 96 : 72) : (width ? 192 : 144); }

Scene controlledScene(int k) {
    ControlledOverlapOptions o;
    o.overlap = k;
    o.width = controlledSize(true);
    o.height = controlledSize(false);
    return makeControlledOverlapScene(o);
}

void requireNothingDropped(const RenderResult& r, const std::string& what) {
    const FrameEvaluation& e = r.evaluation;
    INFO(what << ": dropped light-pixels " << e.lists.droppedLightPixels << ", invalid " << e.lists.invalidSlots
              << ", max error " << e.error.maxAbsError << ", PSNR " << e.error.psnr);
    REQUIRE(e.lists.invalidSlots == 0);
    REQUIRE(e.lists.droppedLightPixels == 0);
    REQUIRE(e.error.maxAbsError <= 1);
}
}  // namespace

TEST_CASE("auto: on controlled overlap k the measured budget is k, nothing is dropped", "[render][auto]") {
    const VolumeTest test = GENERATE(VolumeTest::Sphere, VolumeTest::BackFace);
    for (int k : {1, 2, 4, 8, 16}) {
        const Scene scene = controlledScene(k);
        LidrOptions options;  // the default: automatic
        options.volumeTest = test;
        const RenderResult r = renderAndEvaluate(scene, options);
        const std::string what = std::string(volumeTestName(test)) + " k " + std::to_string(k);
        requireNothingDropped(r, what);
        const AutoDecision& d = r.stats.autoDecision;
        INFO(what << ": budget " << d.budget << ", measured " << d.measuredBudget << ", repacks " << d.repacks);
        REQUIRE(d.autoBudget);
        REQUIRE(d.autoIndexBits);
        // The first frame is packed with budget 4: more overlap than that is re-packed once, the same frame;
        // less is packed with 4 (nothing dropped) and the next frame takes the measured k.
        REQUIRE(d.budget == std::max(k, AutoConfiguration::kInitialBudget));
        REQUIRE(d.measuredBudget == k);
        REQUIRE(d.overflowPixels == 0);
        REQUIRE(d.repacks == (k > AutoConfiguration::kInitialBudget ? 1 : 0));
        REQUIRE(d.visibleLights == r.stats.drawnLights);
        REQUIRE(d.indexBits == AutoConfiguration::indexBitsFor(d.visibleLights));
        // The lists hold every touching light: as many as the overlap on every lit pixel.
        for (size_t p = 0; p < r.evaluation.truth.surface.size(); ++p)
            if (r.evaluation.truth.count(p) > 0) REQUIRE(int(r.evaluation.lists.decoded[p].size()) == k);
    }
}

TEST_CASE("auto: over 16 lights on a pixel the budget widens to 32; over 32 it keeps the highest priorities and "
          "reports the rest", "[render][auto][every-gl]") {
    // Coincident lights with distinct priorities: every lit pixel of the floor is touched by all of them.
    const int lights = GENERATE(20, 40);
    Scene scene = floorScene();
    scene.lights.clear();
    for (int i = 0; i < lights; ++i)
        scene.lights.push_back(light(glm::vec3(0.0f, 0.5f, 0.0f), 3.0f, glm::vec3(0.01f * float(i + 1)), float(i)));
    const RenderResult r = renderAndEvaluate(scene, LidrOptions{});
    const AutoDecision& d = r.stats.autoDecision;
    INFO(lights << " lights: budget " << d.budget << ", measured " << d.measuredBudget << ", over " << d.overflowPixels);
    REQUIRE(d.budget == 32);  // 8-bit indices: four rank windows, 8 targets
    REQUIRE(d.indexBits == 8);
    const FrameEvaluation& e = r.evaluation;
    long touched = 0, marked = 0;
    for (size_t p = 0; p < e.truth.surface.size(); ++p) {
        if (e.marked[p] > 32) ++marked;
        if (e.truth.count(p) != lights) continue;
        ++touched;
        REQUIRE(int(e.lists.decoded[p].size()) == std::min(lights, 32));
        // Over the budget the highest priorities are kept (drawn first): priorities lights - 32 and up.
        for (uint32_t index : e.lists.decoded[p]) REQUIRE(scene.lights[index - 1].priority >= float(std::max(0, lights - 32)));
    }
    REQUIRE(touched > 0);
    if (lights <= 32) {
        REQUIRE(d.measuredBudget == 32);
        REQUIRE(d.overflowPixels == 0);
        REQUIRE(e.lists.droppedLightPixels == 0);
        return;
    }
    REQUIRE(d.measuredBudget == 0);
    // The probe counts exactly the pixels whose stencil count is over 32: those the CPU truth has, and the few
    // the sphere test's hair of extra radius (kSphereRadiusScale) adds at the rim.
    REQUIRE(marked == d.overflowPixels);
    REQUIRE(touched <= marked);
    REQUIRE(marked <= touched + touched / 50);
}

TEST_CASE("auto: lights off screen get no index; the visible ones are numbered compactly at the narrowest width",
          "[render][auto]") {
    Scene scene = floorScene();
    scene.lights.clear();
    // 300 lights: 12 on the floor in view, the rest far outside the view (and off every mesh).
    for (int i = 0; i < 300; ++i) {
        const bool visible = i % 25 == 0;
        const glm::vec3 p = visible ? glm::vec3(-9.0f + 1.5f * float(i / 25), 0.5f, float((i / 25) % 3) * 3.0f - 3.0f)
                                    : glm::vec3(500.0f + float(i), 0.5f, 500.0f);
        scene.lights.push_back(light(p, 2.5f, glm::vec3(0.3f + 0.002f * float(i), 0.5f, 0.4f)));
    }
    const RenderResult r = renderAndEvaluate(scene, LidrOptions{});
    const AutoDecision& d = r.stats.autoDecision;
    REQUIRE(d.visibleLights == 12);
    REQUIRE(d.indexBits == 4);  // 12 fit 4-bit indices though the scene has 300 lights
    requireNothingDropped(r, "compact numbering");
    // Decoded (scene) indices are only ever the visible lights.
    for (const auto& list : r.evaluation.lists.decoded)
        for (uint32_t index : list) REQUIRE((index - 1) % 25 == 0);
    // A fixed 16-bit width indexes by scene numbers and gives the same image.
    LidrOptions fixed;
    fixed.packing = {PackingSchemeKind::BitShift, 4, 16};
    const RenderResult f = renderAndEvaluate(scene, fixed);
    REQUIRE(f.stats.autoDecision.autoIndexBits == false);
    REQUIRE(f.lidr.pixels == r.lidr.pixels);
}

TEST_CASE("auto: frames follow the scene without dropping a light, and narrow only after the hold",
          "[render][auto]") {
    testContext();
    const Scene eight = controlledScene(8), two = controlledScene(2);
    LidrOptions options;
    options.autoHoldFrames = 3;
    options.autoNarrowingInterval = 1;  // every frame asks (the default asks every 4th: the next test)
    LidrRenderer renderer(testGl(), eight, options, eight.width, eight.height);
    ReferenceRenderer reference(testGl(), eight, eight.width, eight.height, 255);
    const ShadingParameters shading{eight.ambient, eight.backgroundColor};
    // 8 overlapping, then 2 for seven frames, then 8 again. Steady frames measure only "over the budget" and
    // "over half of it", so the budget narrows one halving per hold: 8 for three frames, 4 for three, then 2;
    // the return to 8 is re-packed in its own frame.
    const int sequence[] = {8, 2, 2, 2, 2, 2, 2, 2, 8, 8};
    const int expectBudget[] = {8, 8, 8, 8, 4, 4, 4, 2, 8, 8};
    const int expectRepacks[] = {1, 0, 0, 0, 0, 0, 0, 0, 1, 0};
    for (int f = 0; f < 10; ++f) {
        const Scene& s = sequence[f] == 8 ? eight : two;
        const std::vector<PointLight> lights = s.lightsAt(s.time);
        const FrameStats stats = renderer.render(s.camera, lights, shading);
        const ImageRGBA8 image = renderer.targets().readColor();
        reference.render(s.camera, lights, shading);
        const FrameEvaluation e = evaluateFrame(renderer, s.camera, lights, image, reference.targets().readColor());
        INFO("frame " << f << ": overlap " << sequence[f] << ", budget " << stats.autoDecision.budget << ", repacks "
                      << stats.autoDecision.repacks << ", dropped " << e.lists.droppedLightPixels);
        REQUIRE(stats.autoDecision.budget == expectBudget[f]);
        REQUIRE(stats.autoDecision.repacks == expectRepacks[f]);
        REQUIRE(e.lists.droppedLightPixels == 0);
        REQUIRE(e.lists.invalidSlots == 0);
    }
}

TEST_CASE("auto: contradicting requests are refused before drawing", "[lidr][auto][every-gl]") {
    testContext();
    const Scene scene = controlledScene(2);
    LidrOptions o;
    o.packing = {PackingSchemeKind::Auto, 4, PackingConfig::kAuto};
    REQUIRE_THROWS_WITH(LidrRenderer(testGl(), scene, o, scene.width, scene.height),
                        Catch::Contains("auto scheme chooses the budget and the index width itself"));
    o.packing = {PackingSchemeKind::MaxStencil, PackingConfig::kAuto, 8};
    REQUIRE_THROWS_WITH(LidrRenderer(testGl(), scene, o, scene.width, scene.height),
                        Catch::Contains("max-stencil needs a fixed budget"));
    // A fixed width too narrow for the scene's lights.
    o.packing = {PackingSchemeKind::BitShift, PackingConfig::kAuto, 4};
    REQUIRE_THROWS_WITH(LidrRenderer(testGl(), controlledScene(16), o, scene.width, scene.height),
                        Catch::Contains("choose a wider index, or an automatic one"));
    REQUIRE_THROWS_WITH(createPackingScheme(PackingConfig{}, testGl()), Catch::Contains("is automatic"));
}

TEST_CASE("auto mode: a candidate whose frames drop lights is not chosen while another draws the scene exactly",
          "[render][auto][auto-mode]") {
    testContext();
    const GlInfo& info = testGl();
    // 40 coincident lights: every lit pixel needs more than LIDR's largest budget (32), so LIDR's frames report
    // pixels over budget (FrameStats::autoDecision.overflowPixels); tiled and clustered drop nothing. LIDR may be
    // the fastest, yet auto keeps an exact candidate.
    Scene scene = floorScene();
    scene.lights.clear();
    for (int i = 0; i < 40; ++i)
        scene.lights.push_back(light(glm::vec3(0.0f, 0.5f, 0.0f), 3.0f, glm::vec3(0.01f * float(i + 1)), float(i)));
    RenderModeOptions o;
    o.mode = "auto";
    AutoModeOptions ao;
    ao.trialFrames = 2;
    AutoModeRenderer renderer(info, scene, o, scene.width, scene.height, ao);
    const ShadingParameters shading{scene.ambient, scene.backgroundColor};
    const std::vector<PointLight> lights = scene.lightsAt(scene.time);
    long lidrOverBudget = 0;
    for (int f = 0; f < 2 * int(renderer.candidates().size()) + 1; ++f) {
        const FrameStats& stats = renderer.render(scene.camera, lights, shading);
        if (renderer.lastMode() == "lidr") lidrOverBudget = std::max(lidrOverBudget, stats.autoDecision.overflowPixels);
    }
    INFO(renderer.reason());
    REQUIRE_FALSE(renderer.measuring());
    REQUIRE(lidrOverBudget > 0);
    REQUIRE(renderer.lastMode() != "lidr");
    REQUIRE(renderer.reason().find("fastest exact") != std::string::npos);
    REQUIRE(renderer.reason().find("pixels over its light budget") != std::string::npos);
}

TEST_CASE("auto mode: measures each candidate, keeps the fastest, measures again when the lights change",
          "[render][auto][auto-mode][every-gl]") {
    testContext();
    Scene scene = floorScene();
    scene.lights.clear();
    for (int i = 0; i < 24; ++i)
        scene.lights.push_back(light(glm::vec3(-9.0f + 0.8f * float(i), 0.5f, float(i % 4) * 2.0f - 3.0f), 2.5f,
                                     glm::vec3(0.4f, 0.3f + 0.02f * float(i), 0.5f)));
    RenderModeOptions o;
    o.mode = "auto";
    o.transparency = false;
    AutoModeOptions ao;
    ao.trialFrames = 2;
    AutoModeRenderer renderer(testGl(), scene, o, scene.width, scene.height, ao);
    REQUIRE(renderer.candidates() == std::vector<std::string>{"lidr", "tiled", "clustered", "forward-multipass"});
    ReferenceRenderer reference(testGl(), scene, scene.width, scene.height, 255, false, 0, false);
    // linear output: the bound counts linear 8-bit steps (multi-pass in its 8-bit target, where the context has no
    // half-float colour buffers, rounds each pass; doc/colour.md)
    const ShadingParameters shading{scene.ambient, scene.backgroundColor, OutputTransform::linear()};
    std::vector<PointLight> lights = scene.lightsAt(scene.time);
    reference.render(scene.camera, lights, shading);
    const ImageRGBA8 truth = reference.targets().readColor();
    std::vector<std::string> drawnWith;
    for (int f = 0; f < 10; ++f) {
        renderer.render(scene.camera, lights, shading);
        drawnWith.push_back(renderer.lastMode());
        // Trial frames are ordinary frames: every one is the right image.
        const ImageError e = compareImages(renderer.targets().readColor(), truth);
        INFO("frame " << f << " drawn with " << renderer.lastMode() << ": max error " << e.maxAbsError);
        REQUIRE(e.maxAbsError <= 2);
    }
    // Two trial frames per candidate, the candidates taking turns, then the choice.
    REQUIRE(std::vector<std::string>(drawnWith.begin(), drawnWith.begin() + 8) ==
            std::vector<std::string>{"lidr", "tiled", "clustered", "forward-multipass", "lidr", "tiled", "clustered",
                                     "forward-multipass"});
    REQUIRE_FALSE(renderer.measuring());
    REQUIRE(drawnWith[8] == drawnWith[9]);
    REQUIRE(renderer.reason().find(drawnWith[8] + " fastest") == 0);
    for (const char* m : {"lidr ", "tiled ", "clustered ", "forward-multipass "})
        REQUIRE(renderer.reason().find(m) != std::string::npos);
    // Half the lights leave: measured again.
    lights.resize(12);
    renderer.render(scene.camera, lights, shading);
    REQUIRE(renderer.measuring());
    REQUIRE(renderer.lastMode() == "lidr");
}

TEST_CASE("auto mode: multi-pass, which draws no transparent layers, is no candidate where they are drawn",
          "[lidr][auto][auto-mode][every-gl]") {
    testContext();
    Scene scene = floorScene();
    scene.lights = {light(glm::vec3(0.0f, 0.5f, 0.0f), 3.0f)};
    Material glass;
    glass.opacity = 0.5f;
    scene.materials.push_back(glass);
    addBox(scene, glm::vec3(-1.0f, 0.0f, -1.0f), glm::vec3(1.0f), int(scene.materials.size() - 1));
    RenderModeOptions o;
    o.mode = "auto";
    REQUIRE(AutoModeRenderer(testGl(), scene, o, 64, 48).candidates() ==
            std::vector<std::string>{"lidr", "tiled", "clustered"});
    o.transparency = false;
    REQUIRE(AutoModeRenderer(testGl(), scene, o, 64, 48).candidates().size() == 4);
}

TEST_CASE("auto: a camera flying through the room, lights moving: no frame drops a light, no choice flips back "
          "the next frame", "[render][auto]") {
    testContext();
    const Scene scene = testRoom();
    LidrRenderer renderer(testGl(), scene, LidrOptions{}, scene.width, scene.height);
    ReferenceRenderer reference(testGl(), scene, scene.width, scene.height, 255);
    const ShadingParameters shading{scene.ambient, scene.backgroundColor};
    const int frames = isSoftpipe() ? 8 : 20;
    std::vector<int> budgets, widths;
    for (int f = 0; f < frames; ++f) {
        const float s = float(f) / float(frames - 1);
        Camera camera = scene.camera;  // from the doorway's view down into the room and round to the side
        camera.position = glm::mix(glm::vec3(0.0f, 4.5f, 17.0f), glm::vec3(-4.0f, 1.6f, -2.0f), s);
        camera.target = camera.position + glm::vec3(std::sin(2.5f * s), -0.25f * (1.0f - s), -std::cos(2.5f * s));
        const std::vector<PointLight> lights = scene.lightsAt(1.0f + 0.4f * float(f));
        const FrameStats stats = renderer.render(camera, lights, shading);
        const ImageRGBA8 image = renderer.targets().readColor();
        reference.render(camera, lights, shading);
        const FrameEvaluation e = evaluateFrame(renderer, camera, lights, image, reference.targets().readColor());
        INFO("frame " << f << ": " << stats.autoDecision.visibleLights << " lights in view, budget "
                      << stats.autoDecision.budget << ", " << stats.autoDecision.indexBits << "-bit, max overlap "
                      << e.maxTruthOverlap << ", dropped " << e.lists.droppedLightPixels);
        REQUIRE(e.lists.droppedLightPixels == 0);
        REQUIRE(e.lists.invalidSlots == 0);
        REQUIRE(e.error.maxAbsError <= 1);
        budgets.push_back(stats.autoDecision.budget);
        widths.push_back(stats.autoDecision.indexBits);
    }
    // A change is kept at least one more frame: never A, B, A in three frames.
    for (size_t f = 2; f < budgets.size(); ++f) {
        REQUIRE_FALSE((budgets[f] == budgets[f - 2] && budgets[f] != budgets[f - 1]));
        REQUIRE_FALSE((widths[f] == widths[f - 2] && widths[f] != widths[f - 1]));
    }
}
