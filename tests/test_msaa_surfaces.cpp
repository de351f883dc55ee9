// LIDR's default under MSAA (issue 43): the sphere-span lists hold every light of every sample's surface on the
// deep scenes, at 2x and 4x, against the reference with the same MSAA; and they stay short (interior pixels take
// the sphere lists). Runs on llvmpipe and under the GL 2.1 override (the same path: no multisample texture is
// read; doc/msaa-transparency.md, "Edge pixels").
#include <algorithm>
#include <numeric>

#include <catch2/catch.hpp>

#include "gl_test_context.h"
#include "lidr/base/gl.h"
#include "lidr/base/error.h"
#include "lidr/eval/bench_scenes.h"
#include "lidr/modes/reference_renderer.h"
#include "lidr/modes/tiled_renderer.h"
#include "render_helpers.h"

using namespace lidr;
using namespace lidr::test;

namespace {
bool contextHasMsaa(int samples) {
    const GlInfo& info = testGl();
    if (info.multisampleFbo && info.maxSamples >= samples && info.halfFloatColorBuffer) return true;
    WARN("skipped: this context has no " << samples << "x MSAA with half-float colour buffers (" << info.summary() << ")");
    return false;
}

// Small sizes: CI runs every case under two contexts.
Scene deepScene(const std::string& name) {
    if (name == "room") return testRoom();
    return makeOccludedScene(name == "hall-255" ? OccludedSceneKind::Hall : OccludedSceneKind::City, 255, 192, 144);
}

long sum(const std::vector<int>& v) { return std::accumulate(v.begin(), v.end(), 0L); }
}  // namespace

TEST_CASE("MSAA by default: every sample's surface finds its lights on the deep scenes", "[msaa][every-gl]") {
    const std::string name = GENERATE("hall-255", "city-255", "room");
    const int samples = GENERATE(2, 4);
    if (!contextHasMsaa(samples)) return;
    DYNAMIC_SECTION(name << ", " << samples << "x MSAA") {
        const Scene scene = deepScene(name);
        LidrOptions o;  // the default, as a user turning MSAA on gets it
        o.msaaSamples = samples;
        const RenderResult r = renderAndEvaluate(scene, o);
        const FrameEvaluation& e = r.evaluation;
        const long pixels = long(scene.width) * scene.height;
        INFO("edge pixels " << e.edgePixels << " of " << pixels << ", dropped (samples' surfaces) "
                            << e.spanLists.droppedLightPixels << ", dropped (centres) " << e.lists.droppedLightPixels
                            << ", over budget " << e.pixelsOverBudget << ", budget " << r.stats.autoDecision.budget
                            << ", PSNR " << e.error.psnr << ", max error " << e.error.maxAbsError << ", pixels over 1 "
                            << e.error.pixelsOverThreshold);
        // sphere-span ran (it alone reads spans) and found edges, a minority of the pixels.
        REQUIRE(e.edgePixels > 0);
        REQUIRE(e.edgePixels * 4 < pixels);
        REQUIRE(e.lists.invalidSlots == 0);
        REQUIRE(e.spanLists.droppedLightPixels == 0);
        REQUIRE(e.lists.droppedLightPixels == 0);
        REQUIRE(e.pixelsOverBudget == 0);
        REQUIRE(e.error.psnr >= 50.0);
        REQUIRE(glGetError() == GL_NO_ERROR);
    }
}

TEST_CASE("MSAA: sphere-span lists are far shorter than whole-ray lists on the hall", "[msaa][every-gl]") {
    if (!contextHasMsaa(4)) return;
    const Scene scene = deepScene("hall-255");
    LidrOptions o;
    o.msaaSamples = 4;
    o.transparency = false;
    const RenderResult span = renderAndEvaluate(scene, o);
    o.volumeTest = VolumeTest::SphereRay;
    const RenderResult ray = renderAndEvaluate(scene, o);
    o.msaaSamples = 0;
    o.volumeTest = VolumeTest::Sphere;
    const RenderResult single = renderAndEvaluate(scene, o);
    const long spanMarks = sum(span.evaluation.marked), rayMarks = sum(ray.evaluation.marked),
               singleMarks = sum(single.evaluation.marked);
    INFO("marks per frame: sphere-span " << spanMarks << ", sphere-ray " << rayMarks << ", single-sample sphere "
                                         << singleMarks << "; most on a pixel " << span.evaluation.maxMarked << " / "
                                         << ray.evaluation.maxMarked);
    // Interior pixels take the sphere lists: a few per cent over the single-sample frame, a fraction of the rays'.
    REQUIRE(spanMarks * 10 <= singleMarks * 12);
    REQUIRE(spanMarks * 3 <= rayMarks);
    REQUIRE(span.evaluation.maxMarked < ray.evaluation.maxMarked);
}

TEST_CASE("sphere-span is refused where it cannot run", "[msaa][bad-input][every-gl]") {
    const Scene scene = deepScene("city-255");
    LidrOptions o;
    o.volumeTest = VolumeTest::SphereSpan;
    REQUIRE_THROWS_WITH(LidrRenderer(testGl(), scene, o, scene.width, scene.height), Catch::Contains("needs MSAA"));
    if (!testGl().multisampleFbo || testGl().maxSamples < 2) return;
    o.msaaSamples = 2;
    GlInfo noFloat = testGl();
    noFloat.halfFloatColorBuffer = false;
    REQUIRE_THROWS_AS(LidrRenderer(noFloat, scene, o, scene.width, scene.height), UnsupportedError);
    REQUIRE_THROWS_WITH(LidrRenderer(noFloat, scene, o, scene.width, scene.height), Catch::Contains("sphere-ray"));
    o.volumeTest = VolumeTest::Sphere;  // the library's default under MSAA becomes sphere-span
    if (testGl().halfFloatColorBuffer) {
        const LidrRenderer renderer(testGl(), scene, o, scene.width, scene.height);
        REQUIRE(renderer.options().volumeTest == VolumeTest::SphereSpan);
    }
    REQUIRE(glGetError() == GL_NO_ERROR);
}

TEST_CASE("tiled forward under MSAA bounds its tiles by every sample's surface", "[msaa][tiled][every-gl]") {
    if (!contextHasMsaa(4) || !testGl().textureFloat) return;
    const Scene scene = deepScene("hall-255");
    const std::vector<PointLight> lights = scene.lightsAt(scene.time);
    const ShadingParameters shading = sceneShading(scene, OutputTransform{});
    auto entries = [&](int samples, bool bounds, ImageRGBA8* image) {
        TiledOptions t;
        t.msaaSamples = samples;
        t.depthBounds = bounds;
        TiledRenderer r(testGl(), scene, t, scene.width, scene.height);
        r.render(scene.camera, lights, shading);
        if (image) *image = r.targets().readColor();
        REQUIRE(r.frameInfo().depthBoundsUsed == bounds);
        return r.frameInfo().grid.opaqueEntries;
    };
    ImageRGBA8 image;
    const long msaa = entries(4, true, &image), single = entries(0, true, nullptr), flat = entries(4, false, nullptr);
    ReferenceRenderer reference(testGl(), scene, scene.width, scene.height, int(lights.size()), false, 4, true);
    reference.render(scene.camera, lights, shading);
    const ImageError e = compareImages(image, reference.targets().readColor());
    INFO("tile list entries: MSAA 4x " << msaa << ", single-sample " << single << ", MSAA without depth bounds " << flat
                                       << "; against the reference: max " << e.maxAbsError << ", PSNR " << e.psnr);
    REQUIRE(e.maxAbsError <= 1);
    // Edge samples widen a few tiles' ranges: near the single-sample lists, below the 2D lists of before (by far at 1024x768: doc/tiled.md).
    REQUIRE(msaa * 10 <= single * 15);
    REQUIRE(msaa < flat);
}
