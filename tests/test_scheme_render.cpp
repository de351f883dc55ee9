// Every packing scheme x budget x width renders whole frames correctly: controlled-overlap scenes (every lit
// pixel covered by exactly k lights) and the default room, against the brute-force reference, the CPU truth
// of which lights touch each pixel and the GPU stencil count of marks. Plus the back-face trap of CPU sorting.
#include <algorithm>
#include <map>

#include <catch2/catch.hpp>

#include "config_cases.h"
#include "gl_test_context.h"
#include "lidr/base/gl.h"
#include "lidr/technique/cpu_sorted_scheme.h"
#include "lidr/scene/default_scene.h"
#include "lidr/eval/controlled_scenes.h"
#include "render_helpers.h"

using namespace lidr;
using namespace lidr::test;

namespace {
// Exact where every marking light was kept, no corrupted slot anywhere, every truly dropped light counted.
void requireCorrectFrame(const RenderResult& r, const std::string& what) {
    const FrameEvaluation& e = r.evaluation;
    requireExactWithinBudget(e, what);
    long uncounted = 0;
    for (size_t p = 0; p < e.withinBudget.size(); ++p)
        if (e.lists.droppedPerPixel[p] > e.droppedMarks[p]) ++uncounted;
    INFO(what << ": pixels with uncounted drops " << uncounted);
    REQUIRE(uncounted == 0);
}

int controlledSize(bool width) { return isSoftpipe() ? (width ? 96 : 72) : (width ? 192 : 144); }

// Both volume tests x every scheme x width x budget x overlap k = 1, 2, 4, 8, 16; softpipe (an interpreter) only
// at k = the budget and twice it, and k = 16 at budget 1.
std::vector<ConfigCase> controlledOverlapCases() {
    const bool thin = isSoftpipe();
    return withOverlaps(withVolumeTests(packingCases(), {VolumeTest::Sphere, VolumeTest::BackFace}),
                        [thin](const ConfigCase& c) {
                            const int b = c.packing.budget;
                            if (!thin) return std::vector<int>{1, 2, 4, 8, 16};
                            if (b == 1) return std::vector<int>{1, 2, 16};
                            return b == 16 ? std::vector<int>{16} : std::vector<int>{b, 2 * b};
                        });
}
}  // namespace

TEST_CASE("controlled overlap k = 1, 2, 4, 8, 16: every scheme x budget x width keeps the top-priority lights, "
          "counts the rest exactly, corrupts nothing", "[render][schemes][every-gl]") {
    const ConfigCase c = GENERATE(from_range(controlledOverlapCases()));
    // Representative: each scheme at budget 4 with 8 lights on a pixel (kept, dropped and counted), 8-bit.
    if (!takeRow(c.packing.budget == 4 && c.packing.indexBits == 8 && c.overlap == 8)) return;
    DYNAMIC_SECTION(c.name) {
        const int bits = c.packing.indexBits, budget = c.packing.budget;
        ControlledOverlapOptions o;
        o.overlap = c.overlap;
        o.maxLights = int((1u << bits) - 1u);
        o.width = controlledSize(true);
        o.height = controlledSize(false);
        const Scene scene = makeControlledOverlapScene(o);
        const int kk = int(scene.lights.size()) / std::max(1, int(scene.lights.size()) / std::min(c.overlap, o.maxLights));
        LidrOptions options;
        options.packing = c.packing;
        options.volumeTest = c.volumeTest;
        static SharedReferences references;  // the scene is k and the width's light count
        const RenderResult r = references.renderAndEvaluate(std::to_string(c.overlap) + " " + std::to_string(bits), scene, options);
        const std::string what = c.name + " (k " + std::to_string(kk) + " lights)";
        requireCorrectFrame(r, what);
        const FrameEvaluation& e = r.evaluation;
        long clusterPixels = 0;
        PixelChecks checks(what);
        for (size_t p = 0; p < e.marked.size(); ++p) {
            checks.expect(e.marked[p] == 0 || e.marked[p] == kk, p, "marked by exactly k lights, or none");
            const int touching = e.truth.count(p);
            if (touching == 0) continue;
            ++clusterPixels;
            checks.expect(touching == kk, p, "k lights touch");
            checks.expect(e.marked[p] == kk, p, "GPU count of marks = CPU truth");
            // Kept: the min(k, budget) highest priorities of the cluster; the GPU counts the rest.
            const int kept = std::min(kk, budget);
            checks.expect(int(e.lists.decoded[p].size()) == kept, p, "min(k, budget) lights listed");
            for (uint32_t index : e.lists.decoded[p])
                checks.expect(index >= 1 && index <= scene.lights.size() &&
                                  scene.lights[index - 1].priority >= float(kk - kept),
                              p, "a listed light among the cluster's top priorities");
            checks.expect(e.lists.droppedPerPixel[p] == kk - kept, p, "k - kept dropped");
            checks.expect(e.droppedMarks[p] == kk - kept, p, "k - kept counted as dropped");
        }
        checks.require();
        CHECK(clusterPixels > 40);  // one cluster covers about 50 pixels at softpipe's 96 x 72
    }
}

TEST_CASE("controlled overlap under the exact tests (stencil and sphere): every scheme x width at budgets 2, 8, 16",
          "[render][schemes][exact][every-gl]") {
    // softpipe interprets every fragment: budgets 2 and 16 there.
    const std::vector<int> budgets = isSoftpipe() ? std::vector<int>{2, 16} : std::vector<int>{2, 8, 16};
    const ConfigCase c = GENERATE_COPY(
        from_range(withVolumeTests(packingCases(budgets), {VolumeTest::ExactStencil, VolumeTest::Sphere})));
    // Representative: budget 16, 8-bit; max-stencil under the stencil test, bit-shift under the sphere test.
    if (!takeRow(c.packing.budget == 16 && c.packing.indexBits == 8 &&
                 c.packing.scheme == (c.volumeTest == VolumeTest::Sphere ? PackingSchemeKind::BitShift
                                                                         : PackingSchemeKind::MaxStencil)))
        return;
    DYNAMIC_SECTION(c.name) {
        const int bits = c.packing.indexBits;
        ControlledOverlapOptions o;
        o.overlap = 8;
        o.maxLights = int((1u << bits) - 1u);
        o.width = controlledSize(true);
        o.height = controlledSize(false);
        const Scene scene = makeControlledOverlapScene(o);
        LidrOptions options;
        options.packing = c.packing;
        options.volumeTest = c.volumeTest;
        const RenderResult r = renderAndEvaluate(scene, options);
        requireCorrectFrame(r, c.name);
        long pixels = 0;
        for (size_t p = 0; p < r.evaluation.marked.size(); ++p)
            if (r.evaluation.truth.count(p) > 0) {
                ++pixels;
                REQUIRE(r.evaluation.marked[p] == r.evaluation.truth.count(p));
                REQUIRE(r.evaluation.lists.droppedPerPixel[p] == r.evaluation.droppedMarks[p]);
            }
        CHECK(pixels > 40);
    }
}

TEST_CASE("the default room with each scheme at budget 4, 8-bit indices", "[render][schemes][default-room]") {
    const Scene scene = testRoom();
    const ConfigCase c = GENERATE(from_range(withVolumeTests(
        packingCases({4}, {8}), {VolumeTest::BackFace, VolumeTest::ExactStencil, VolumeTest::Sphere})));
    DYNAMIC_SECTION(c.name) {
        LidrOptions options;
        options.packing = c.packing;
        options.volumeTest = c.volumeTest;
        // CPU sorting drops whole lights from the transparent layers' front-face lists too, where the
        // evaluation's within-budget mask (a conservative CPU count of front-face marks) cannot see it:
        // its opaque frame is checked here, transparency in the transparency tests.
        options.transparency = c.packing.scheme != PackingSchemeKind::CpuSorted;
        const RenderResult r = renderAndEvaluate(scene, options);
        requireCorrectFrame(r, c.name);
        CHECK(r.evaluation.lists.slotsUsed > 0);
    }
}

TEST_CASE("the default room: every scheme x budget x width", "[render][schemes][default-room][slow]") {
    Scene scene = testRoom(2.0f);
    const ConfigCase c = GENERATE(from_range(packingCases()));
    DYNAMIC_SECTION(c.name) {
        Scene s = scene;
        if (c.packing.indexBits == 4) {  // 15 lights: the 15 of highest priority, where they are at this time
            s.lights = scene.lightsAt(scene.time);
            s.lightPaths.clear();
            std::stable_sort(s.lights.begin(), s.lights.end(),
                             [](const PointLight& a, const PointLight& b) { return a.priority > b.priority; });
            s.lights.resize(15);
        }
        LidrOptions options;
        options.packing = c.packing;
        options.transparency = c.packing.scheme != PackingSchemeKind::CpuSorted;  // see the test above
        static SharedReferences references;  // the reference takes the lights (15 at 4-bit indices) and transparency
        const RenderResult r = references.renderAndEvaluate(
            std::string(c.packing.indexBits == 4 ? "15 lights" : "every light") + (options.transparency ? ", glass" : ""), s, options);
        requireCorrectFrame(r, c.name);
        if (c.packing.budget == 16 && c.packing.scheme != PackingSchemeKind::CpuSorted) CHECK(r.evaluation.pixelsOverBudget == 0);
    }
}

TEST_CASE("CPU sorting under the back-face test: lights with disjoint spheres can mark one pixel, so they must "
          "not share a group", "[render][cpu-sorted][every-gl]") {
    const Scene scene = makeOccludedLightScene(controlledSize(true), controlledSize(false));
    const std::vector<PointLight> lights = scene.lightsAt(scene.time);
    REQUIRE(glm::length(lights[0].position - lights[1].position) > 2.05f * (lights[0].radius + lights[1].radius) / 2.0f);

    // What the back-face test does: light 2, behind the wall, marks the wall where light 1 lights it.
    LidrOptions backface;
    backface.packing = {PackingSchemeKind::BitShift, 4, 8};
    backface.volumeTest = VolumeTest::BackFace;
    const RenderResult rb = renderAndEvaluate(scene, backface);
    long doubleMarkedOneTouching = 0;
    for (size_t p = 0; p < rb.evaluation.marked.size(); ++p)
        if (rb.evaluation.marked[p] == 2 && rb.evaluation.truth.count(p) == 1) ++doubleMarkedOneTouching;
    CHECK(doubleMarkedOneTouching > 50);
}

TEST_CASE("CPU sorting, one group: under back-face the disjoint pair conflicts (light 2 dropped and counted); under "
          "the exact tests it does not (both in group 0, nothing dropped)", "[render][cpu-sorted][every-gl]") {
    const Scene scene = makeOccludedLightScene(controlledSize(true), controlledSize(false));
    const VolumeTest test = GENERATE(VolumeTest::BackFace, VolumeTest::ExactStencil, VolumeTest::Sphere);
    DYNAMIC_SECTION(volumeTestName(test)) {
        LidrOptions sorted;
        sorted.packing = {PackingSchemeKind::CpuSorted, 1, 8};
        sorted.volumeTest = test;
        const RenderResult r = renderAndEvaluate(scene, sorted);
        requireCorrectFrame(r, std::string("cpu-sorted budget 1, ") + volumeTestName(test));
        long light1 = 0, light2 = 0, countedDrops = 0;
        for (size_t p = 0; p < r.evaluation.lists.decoded.size(); ++p) {
            for (uint32_t i : r.evaluation.lists.decoded[p]) (i == 1 ? light1 : light2)++;
            countedDrops += r.evaluation.droppedMarks[p];
        }
        CHECK(light1 > 100);
        if (test == VolumeTest::BackFace) {
            CHECK(light2 == 0);
            CHECK(countedDrops > 100);
        } else {
            CHECK(r.evaluation.lists.droppedLightPixels == 0);
            CHECK(countedDrops == 0);
            CHECK(r.evaluation.error.maxAbsError <= 1);
        }
    }
}

TEST_CASE("CPU sorting groups per frame, deterministically, in priority order", "[cpu-sorted]") {
    const Scene scene = testRoom();
    const std::vector<PointLight> lights = scene.lightsAt(1.0f);
    const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
    std::vector<VolumeLight> volumes;
    for (uint32_t index : LidrRenderer::drawOrder(lights)) {
        const PointLight& l = lights[index - 1];
        if (sphereMayBeVisible(cam, l.position, l.radius)) volumes.push_back({index, glm::vec4(l.position, l.radius)});
    }
    const VolumeTest test = GENERATE(VolumeTest::BackFace, VolumeTest::ExactStencil);
    DYNAMIC_SECTION(volumeTestName(test)) {
        gl::Renderbuffer ds = gl::Renderbuffer::create(GL_DEPTH24_STENCIL8, 4, 4);
        IndexTargets targets(1, 4, 4, ds);
        LightVolumePass pass(testGl(), test);
        pass.begin(targets, cam);  // camera and test for the grouping
        const CpuSortedScheme s({PackingSchemeKind::CpuSorted, 4, 8}, testGl());
        const std::vector<int> groups = s.assignGroups(volumes, &pass);
        REQUIRE(groups == s.assignGroups(volumes, &pass));
        int dropped = 0;
        for (size_t i = 0; i < volumes.size(); ++i) {
            for (size_t j = 0; j < i; ++j)  // no conflict inside a group
                if (groups[i] >= 0 && groups[i] == groups[j]) REQUIRE_FALSE(CpuSortedScheme::mayShareAPixel(volumes[i], volumes[j], pass));
            if (groups[i] >= 0) continue;
            ++dropped;
            // Dropped only because every group already holds a conflicting, higher-priority light.
            for (int g = 0; g < 4; ++g) {
                bool conflict = false;
                for (size_t j = 0; j < i; ++j) conflict = conflict || (groups[j] == g && CpuSortedScheme::mayShareAPixel(volumes[i], volumes[j], pass));
                REQUIRE(conflict);
            }
        }
        pass.end();
        INFO(dropped << " of " << volumes.size() << " dropped");
        CHECK(dropped > 0);  // the room overlaps more than 4 deep in screen space
    }
}
