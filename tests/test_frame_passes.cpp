// Each mode's frame is the list of passes it declares (Renderer::passes(), lidr/render/frame_pass.h): with timing on,
// the passes a frame times carry the list's names, first met in the list's order (LIDR's re-pack times some again),
// every pass the list runs every frame is timed, and each pass says what it reads and writes. A name that drifted
// from its pass, a pass left out of the list or listed out of order fails here.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "gl_test_context.h"
#include "lidr/modes/render_mode.h"
#include "lidr/modes/reference_renderer.h"
#include "render_helpers.h"

using namespace lidr;
using namespace lidr::test;

namespace {

struct PassCase {
    const char* name;
    bool representative;
    const char* mode;
    void (*configure)(RenderModeOptions&, ShadingParameters&);
    bool needsMsaa = false;
};

void none(RenderModeOptions&, ShadingParameters&) {}
void msaa(RenderModeOptions& o, ShadingParameters&) {
    o.msaaSamples = 4;
    o.lidr.volumeTest = VolumeTest::SphereRay;
}
void shadows(RenderModeOptions&, ShadingParameters& s) { s.shadows.enabled = true; }
void fixedBudget(RenderModeOptions& o, ShadingParameters&) {
    o.lidr.packing = {PackingSchemeKind::MaxStencil, 4, 8};
    o.lidr.volumeTest = VolumeTest::ExactStencil;
}
void noDepthBounds(RenderModeOptions& o, ShadingParameters&) { o.tiled.depthBounds = false; }
void occupancy(RenderModeOptions& o, ShadingParameters&) { o.clustered.occupiedClusters = true; }
void eightBitToneMapped(RenderModeOptions& o, ShadingParameters& s) {
    o.multipass.halfFloatAccumulation = false;
    s.output.toneMap = ToneMap::AcesFitted;
}

const PassCase kCases[] = {
    {"lidr", true, "lidr", none},
    {"lidr MSAA", false, "lidr", msaa, true},
    {"lidr shadows", true, "lidr", shadows},
    {"lidr max-stencil exact", false, "lidr", fixedBudget},
    {"tiled", true, "tiled", none},
    {"tiled no depth bounds", false, "tiled", noDepthBounds},
    {"tiled MSAA", false, "tiled", msaa, true},
    {"clustered", true, "clustered", none},
    {"clustered occupancy", false, "clustered", occupancy},
    {"forward-multipass", true, "forward-multipass", none},
    {"forward-multipass 8-bit", false, "forward-multipass", eightBitToneMapped},
    {"forward-multipass MSAA", false, "forward-multipass", msaa, true},
    {"forward-brute MSAA", false, "forward-brute", msaa, true},
    {"forward-brute shadows", true, "forward-brute", shadows},
};

void requireFrameTimesItsPasses(const std::vector<FramePass>& declared, const FrameStats& frame) {
    std::map<std::string, size_t> position;
    for (size_t i = 0; i < declared.size(); ++i) {
        const FramePass& p = declared[i];
        INFO("pass " << p.name);
        CHECK(std::string(p.name).size() > 0);
        CHECK(std::string(p.reads).size() > 0);
        CHECK(std::string(p.writes).size() > 0);
        CHECK(position.emplace(p.name, i).second);  // each name once in the list
    }
    REQUIRE_FALSE(frame.passes.empty());
    std::set<std::string> timed;
    size_t last = 0;
    for (const PassTime& t : frame.passes) {
        INFO("timed pass " << t.pass);
        REQUIRE(position.count(t.pass) == 1);  // a timed pass the list names
        if (!timed.insert(t.pass).second) continue;  // timed again (a re-pack)
        CHECK(position[t.pass] >= last);             // first met in the list's order
        last = position[t.pass];
    }
    for (const FramePass& p : declared) {
        INFO("declared pass " << p.name << " (when: '" << p.when << "')");
        if (!*p.when) CHECK(timed.count(p.name) == 1);  // every frame: timed in this one
    }
}

}  // namespace

TEST_CASE("each mode's frame times the passes it declares, first met in their order", "[frame-passes][modes][every-gl]") {
    testContext();
    const PassCase& c = kCases[GENERATE(range(size_t(0), sizeof(kCases) / sizeof(kCases[0])))];
    if (!takeRow(c.representative)) return;
    DYNAMIC_SECTION(c.name) {
        if (c.needsMsaa && (!testGl().multisampleFbo || testGl().maxSamples < 4)) {
            WARN("no 4x multisample FBOs in this context: " << c.name << " not tested");
            return;
        }
        Scene scene = testRoom(2.0f);
        std::vector<PointLight> lights = scene.lightsAt(2.0f);
        for (size_t i = 0; i < lights.size(); i += 128) lights[i].castsShadow = true;
        RenderModeOptions options;
        options.mode = c.mode;
        ShadingParameters shading = sceneShading(scene);
        c.configure(options, shading);
        std::unique_ptr<Renderer> r;
        if (std::string(c.mode) == "forward-brute")
            r = std::make_unique<ReferenceRenderer>(testGl(), scene, scene.width, scene.height, int(lights.size()),
                                                    false, options.msaaSamples);
        else
            r = createRenderer(options, testGl(), scene, scene.width, scene.height);
        r->setTiming(true, true);
        r->render(scene.camera, lights, shading);
        const FrameStats& frame = r->render(scene.camera, lights, shading);
        requireFrameTimesItsPasses(r->passes(), frame);
        if (c.needsMsaa) {  // resolved: last, or (multi-pass's half-float sum without multisample textures) before its encode
            const std::vector<FramePass> p = r->passes();
            CHECK(std::any_of(p.begin(), p.end(), [](const FramePass& f) { return f.name == std::string("msaa-resolve"); }));
        }
    }
}

TEST_CASE("a frame's passes as text: one a line, in order, with what each reads and writes", "[frame-passes][cpu]") {
    const std::string text = describePasses({pass::kShadowMaps, pass::kLightTable, {"forward", "scene, depth", "colour"}});
    CHECK(text.find("1  shadow-maps") != std::string::npos);
    CHECK(text.find("2  light-table") != std::string::npos);
    CHECK(text.find("3  forward      scene, depth -> colour") != std::string::npos);
    CHECK(text.find("\n                   when: draws the maps that changed") != std::string::npos);
    CHECK(std::count(text.begin(), text.end(), '\n') == 4);  // the shadow maps' condition on a line of its own
}
