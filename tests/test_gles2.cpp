// OpenGL ES 2.0: the GLSL ES 1.00 shaders made from the GLSL 1.20 sources, the context's capabilities, the
// bit-shift scheme at budgets 1, 2, 4 in one RGBA8 target against the CPU model and the brute-force reference,
// and the refusals that name what ES 2.0 lacks. The [gles2] cases are hidden ([.gles2]): suite.gles2 runs them
// with LIDR_CONTEXT=egl-gles2 MESA_GLES_VERSION_OVERRIDE=2.0, and they fail unless the context is ES 2.0.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "config_cases.h"
#include "gl_test_context.h"
#include "lidr/base/error.h"
#include "lidr/base/gl.h"
#include "lidr/eval/controlled_scenes.h"
#include "lidr/gl/frame_timer.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/render_targets.h"
#include "lidr/gl/shader_source.h"
#include "lidr/modes/clustered_renderer.h"
#include "lidr/modes/tiled_renderer.h"
#include "lidr/scene/default_scene.h"
#include "pixel_list_geometry.h"
#include "render_helpers.h"

using namespace lidr;
using namespace lidr::test;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {
// The suite.gles2 cases need a true ES 2.0 context; anything else is a set-up error, reported as a failure.
const GlInfo& requireEs2() {
    const GlInfo& info = testGl();
    INFO("context: " << info.summary());
    REQUIRE(info.gles);
    REQUIRE_THAT(info.version, StartsWith("OpenGL ES 2."));
    REQUIRE(info.glsl == 100);
    return info;
}

bool hasExtension(const char* name) {
    const char* ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
    const std::string all = std::string(" ") + (ext ? ext : "") + " ";
    return all.find(std::string(" ") + name + " ") != std::string::npos;
}

// The text after the first line (#version), with GLSL 1.20's `#line L N` written as GLSL ES 1.00's `#line L+1 N`.
std::string afterVersionLine(const std::string& source) {
    std::istringstream in(source.substr(source.find('\n') + 1));
    std::string out;
    for (std::string line; std::getline(in, line);) {
        int number = 0, string = 0;
        if (line.rfind("#line ", 0) == 0 && std::sscanf(line.c_str(), "#line %d %d", &number, &string) == 2)
            line = "#line " + std::to_string(number + 1) + " " + std::to_string(string);
        out += line + "\n";
    }
    return out;
}
}  // namespace

TEST_CASE("GLSL ES 1.00 from the GLSL 1.20 sources: a new header, the rest byte for byte", "[shader][cpu]") {
    const ShaderIncludes unpack = {{"lidr_unpack.glsl", "unpack_bitshift.glsl"}};
    const std::string desktop = buildShaderSource("lidr_forward.frag", {{"LIDR_SLOTS", "4"}}, unpack);
    REQUIRE_THAT(desktop, StartsWith("#version 120\n"));  // the desktop source is not touched
    const std::string es = glslEs100FromGlsl120(desktop, ShaderStage::Fragment, "lidr_forward.frag");
    // shading.glsl's environment light: the bias lookup's derivatives (dFdx) and the LOD lookup (textureCubeLod, which
    // is EXT_shader_texture_lod's textureCubeLodEXT) enable their extensions where the context has them.
    const std::string header = "#version 100\n"
                               "#ifdef GL_OES_standard_derivatives\n#extension GL_OES_standard_derivatives : enable\n#endif\n"
                               "#ifdef GL_EXT_shader_texture_lod\n#extension GL_EXT_shader_texture_lod : enable\n#endif\n"
                               "#ifdef GL_FRAGMENT_PRECISION_HIGH\n"
                               "precision highp float;\n"
                               "precision highp sampler2D;\n"
                               "precision highp samplerCube;\n"
                               "#else\n"
                               "precision mediump float;\n"
                               "precision mediump sampler2D;\n"
                               "precision mediump samplerCube;\n"
                               "#define LIDR_FRAGMENT_FP16 1\n"
                               "#endif\n";
    std::string body = afterVersionLine(desktop);
    REQUIRE(body.find("textureCubeLod(") != std::string::npos);
    for (size_t p = 0; (p = body.find("textureCubeLod(", p)) != std::string::npos; p += 18)
        body.replace(p, 15, "textureCubeLodEXT(");
    REQUIRE(es == header + body);

    // Vertex shaders: highp is the ES default, nothing to add.
    const std::string vertex = buildShaderSource("geometry.vert");
    REQUIRE(glslEs100FromGlsl120(vertex, ShaderStage::Vertex, "geometry.vert") ==
            "#version 100\n" + afterVersionLine(vertex));

    // gl_FragData[i > 0] asks for EXT_draw_buffers where the context has it (the scheme checks refuse more than
    // one target before a shader is built where it does not); gl_FragData[0] alone does not.
    const std::string sphere = glslEs100FromGlsl120(buildShaderSource("light_volume_sphere.frag", {{"LIDR_DRAW_TARGETS", "1"}}),
                                                    ShaderStage::Fragment, "light_volume_sphere.frag");
    REQUIRE_THAT(sphere, StartsWith("#version 100\n#ifdef GL_EXT_draw_buffers\n#extension GL_EXT_draw_buffers : require\n#endif\n"));
    REQUIRE_THAT(es, !Contains("GL_EXT_draw_buffers"));
    const std::string loop = glslEs100FromGlsl120(buildShaderSource("light_volume.frag", {{"LIDR_DRAW_TARGETS", "2"}}),
                                                  ShaderStage::Fragment, "light_volume.frag");
    REQUIRE_THAT(loop, Contains("#extension GL_EXT_draw_buffers : require"));  // gl_FragData[i] in a loop

    // What ES 2.0 cannot take is named.
    REQUIRE_THROWS_WITH(glslEs100FromGlsl120("#version 150\nvoid main() {}\n", ShaderStage::Fragment, "ms.frag"),
                        Contains("ms.frag") && Contains("GLSL 150") && Contains("GLSL ES 1.00"));
    // gl_FragDepth (the pixel-list test hook) is EXT_frag_depth's.
    const std::string depth = glslEs100FromGlsl120(testShaderSource("pixel_list_volume.frag", {{"LIDR_DRAW_TARGETS", "1"}}),
                                                   ShaderStage::Fragment, "pixel_list_volume.frag");
    REQUIRE_THAT(depth, Contains("#extension GL_EXT_frag_depth : require\n") && Contains("gl_FragDepthEXT = "));
    REQUIRE_THAT(depth, !Contains("gl_FragDepth ="));
}

TEST_CASE("the OpenGL ES 2.0 context: capabilities from its extensions, no desktop-only feature", "[.gles2][context]") {
    const GlInfo& info = requireEs2();
    WARN("ES 2.0 context: " << info.summary());
    CHECK(info.backend == "egl-gles2");
    CHECK(info.framebufferObject == hasExtension("GL_OES_packed_depth_stencil"));
    CHECK(info.textureFloat == hasExtension("GL_OES_texture_float"));
    CHECK(info.halfFloatColorBuffer ==
          (hasExtension("GL_OES_texture_half_float") && hasExtension("GL_EXT_color_buffer_half_float")));
    CHECK(info.depthTexture == hasExtension("GL_OES_depth_texture"));
    CHECK(info.blendMinMax == hasExtension("GL_EXT_blend_minmax"));
    CHECK(info.drawBuffers == hasExtension("GL_EXT_draw_buffers"));
    CHECK(info.readDepthStencil == hasExtension("GL_NV_read_depth_stencil"));
    CHECK_FALSE(info.occlusionQuery);
    CHECK_FALSE(info.timerQuery);
    CHECK_FALSE(info.multisampleFbo);
    CHECK_FALSE(info.multisampleTexture);
    CHECK_FALSE(info.depthClamp);
    CHECK(info.maxVertexUniformVectors >= 128);
    // What suite.gles2 runs on: Mesa's ES 2.0 has all of these (the refusal test below covers their absence).
    REQUIRE(info.framebufferObject);
    REQUIRE(info.readDepthStencil);
    REQUIRE(info.halfFloatColorBuffer);  // multi-pass forward's half-float path runs in suite.gles2
    // A clear of colour, depth and stencil reads back exactly through the ES read paths.
    RenderTargets targets(info, 8, 6);
    targets.bindSingleSample();
    glClearColor(0.0f, 128.0f / 255.0f, 1.0f, 64.0f / 255.0f);
    setClearDepth(0.5f);
    glClearStencil(7);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    checkGl("ES clear");
    const ImageRGBA8 color = targets.readColor();
    const ImageFloat depth = targets.readDepth();
    const std::vector<uint8_t> stencil = targets.readStencil();
    for (int p = 0; p < 8 * 6; ++p) {
        REQUIRE(color.pixels[size_t(p) * 4 + 0] == 0);
        REQUIRE(color.pixels[size_t(p) * 4 + 1] == 128);
        REQUIRE(color.pixels[size_t(p) * 4 + 2] == 255);
        REQUIRE(color.pixels[size_t(p) * 4 + 3] == 64);
        REQUIRE(std::abs(depth.pixels[size_t(p)] - 0.5f) <= 1.0f / 16777215.0f);
        REQUIRE(stencil[size_t(p)] == 7);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_CASE("ES 2.0: bit-shift at budgets 1, 2, 4 in one RGBA8 target keeps exactly the top-priority lights and "
          "matches the reference", "[.gles2][render]") {
    const GlInfo& info = requireEs2();
    const ConfigCase c = GENERATE(from_range(
        withOverlaps(withVolumeTests(packingCases({1, 2, 4}, {8}, {PackingSchemeKind::BitShift}), {VolumeTest::Sphere, VolumeTest::BackFace}),
                     [](const ConfigCase&) { return std::vector<int>{1, 2, 4, 8}; })));
    DYNAMIC_SECTION(c.name) {
        const int budget = c.packing.budget, k = c.overlap;
        ControlledOverlapOptions o;
        o.overlap = k;
        o.maxLights = 255;
        o.width = 192;
        o.height = 144;
        const Scene scene = makeControlledOverlapScene(o);
        LidrOptions options;
        options.packing = c.packing;
        options.volumeTest = c.volumeTest;
        const RenderResult r = renderAndEvaluate(scene, options, info);
        const FrameEvaluation& e = r.evaluation;
        INFO(c.name << ": invalid " << e.lists.invalidSlots << ", within-budget max error "
                    << e.errorWithinBudget.maxAbsError << ", PSNR " << e.errorWithinBudget.psnr);
        REQUIRE(r.indexTargets.size() == 1);  // one RGBA8 target
        REQUIRE(e.lists.invalidSlots == 0);
        REQUIRE(e.errorWithinBudget.maxAbsError <= 1);
        long clusterPixels = 0;
        PixelChecks checks("ES 2.0 controlled overlap");
        for (size_t p = 0; p < e.marked.size(); ++p) {
            const int touching = e.truth.count(p);
            if (touching == 0) continue;
            ++clusterPixels;
            checks.expect(touching == k, p, "k lights touch");
            checks.expect(e.marked[p] == k, p, "GPU stencil count = CPU truth");
            const int kept = std::min(k, budget);
            checks.expect(int(e.lists.decoded[p].size()) == kept, p, "min(k, budget) lights listed");  // exact lists
            for (uint32_t index : e.lists.decoded[p])
                checks.expect(index >= 1 && index <= scene.lights.size() && scene.lights[index - 1].priority >= float(k - kept),
                              p, "a listed light among the kept highest priorities");
            checks.expect(e.lists.droppedPerPixel[p] == k - kept, p, "k - kept dropped");
        }
        checks.require();
        CHECK(clusterPixels > 40);
    }
}

TEST_CASE("ES 2.0: the default room at budget 4 against the brute-force reference", "[.gles2][render]") {
    const GlInfo& info = requireEs2();
    Scene scene = makeDefaultScene();
    scene.width = testWidth();
    scene.height = testHeight();
    LidrOptions options;
    options.packing = {PackingSchemeKind::BitShift, 4, PackingConfig::kAuto};
    const RenderResult r = renderAndEvaluate(scene, options, info);
    const FrameEvaluation& e = r.evaluation;
    requireExactWithinBudget(e, "ES 2.0 room, bit-shift budget 4");
    INFO("whole image PSNR " << e.error.psnr);
    REQUIRE(e.error.psnr >= 35.0);
    long lit = 0;
    for (size_t p = 0; p < e.marked.size(); ++p) lit += e.truth.count(p) > 0;
    REQUIRE(lit > 1000);  // the frame is really lit, not two black images
}

TEST_CASE("ES 2.0 refuses what it lacks before drawing, naming the missing feature", "[.gles2][bad-input]") {
    const GlInfo& es = requireEs2();
    const Scene scene = floorScene();
    const int w = scene.width, h = scene.height;
    auto make = [&](const GlInfo& info, const LidrOptions& options) { LidrRenderer(info, scene, options, w, h); };

    LidrOptions maxStencil;
    maxStencil.packing = {PackingSchemeKind::MaxStencil, 4, 8};
    GlInfo noMinMax = es;
    noMinMax.blendMinMax = false;
    REQUIRE_THROWS_AS(make(noMinMax, maxStencil), UnsupportedError);
    REQUIRE_THROWS_WITH(make(noMinMax, maxStencil), Contains("EXT_blend_minmax"));

    LidrOptions twoTargets;
    twoTargets.packing = {PackingSchemeKind::BitShift, 8, 8};
    GlInfo noDrawBuffers = es;
    noDrawBuffers.drawBuffers = false;
    noDrawBuffers.maxDrawBuffers = noDrawBuffers.maxColorAttachments = 1;
    REQUIRE_THROWS_WITH(make(noDrawBuffers, twoTargets), Contains("EXT_draw_buffers"));
    LidrOptions oneTarget;
    oneTarget.packing = {PackingSchemeKind::BitShift, 4, 8};
    REQUIRE_NOTHROW(make(noDrawBuffers, oneTarget));  // the paper's main case needs none

    GlInfo noDepthTexture = es;
    noDepthTexture.depthTexture = false;
    LidrOptions sphere = oneTarget;
    sphere.volumeTest = VolumeTest::Sphere;
    REQUIRE_THROWS_WITH(make(noDepthTexture, sphere), Contains("OES_depth_texture") && Contains("backface"));
    LidrOptions backface = oneTarget;
    backface.volumeTest = VolumeTest::BackFace;
    REQUIRE_NOTHROW(make(noDepthTexture, backface));  // the documented fallback

    GlInfo noPacked = es;
    noPacked.framebufferObject = false;
    REQUIRE_THROWS_WITH(make(noPacked, oneTarget), Contains("OES_packed_depth_stencil"));

    LidrOptions msaa = oneTarget;
    msaa.msaaSamples = 4;
    msaa.volumeTest = VolumeTest::SphereRay;
    REQUIRE_THROWS_WITH(make(es, msaa), Contains("multisample"));

    REQUIRE_THROWS_WITH(FrameTimer(es, TimingMethod::GpuQueries), Contains("timer"));

    // Tiled depth bounds need a highp gl_FragCoord.z; without them tiled runs.
    TiledOptions tiled;
    REQUIRE_THROWS_WITH(TiledRenderer(es, scene, tiled, w, h), Contains("mediump") && Contains("--no-depth-bounds"));
    tiled.depthBounds = false;
    REQUIRE_NOTHROW(TiledRenderer(es, scene, tiled, w, h));
    // Clustered runs as it is (its slices come from the highp world position, not gl_FragCoord); occupied clusters
    // read depth back, which needs NV_read_depth_stencil; without highp fragments the grid has one slice.
    ClusteredOptions clustered;
    REQUIRE_NOTHROW(ClusteredRenderer(es, scene, clustered, w, h));
    clustered.occupiedClusters = true;
    GlInfo noDepthReadBack = es;
    noDepthReadBack.readDepthStencil = false;
    REQUIRE_THROWS_WITH(ClusteredRenderer(noDepthReadBack, scene, clustered, w, h), Contains("read the pre-Z depth back"));
    GlInfo mediump = es;
    mediump.fragmentHighp = false;
    REQUIRE(ClusteredRenderer(mediump, scene, ClusteredOptions{}, w, h).grid().sliceCount() == 1);

    // An automatic budget cannot be measured without occlusion queries: a fixed one, said in the frame's stats.
    Scene lit = scene;
    lit.lights.push_back(light(glm::vec3(0.0f, 0.5f, 0.0f), 6.0f));
    LidrOptions automatic;
    LidrRenderer renderer(es, lit, automatic, w, h);
    const FrameStats& stats = renderer.render(lit.camera, lit.lightsAt(lit.time), {lit.ambient, lit.backgroundColor});
    REQUIRE(renderer.scheme().config().budget == LidrRenderer::kBudgetWithoutOcclusionQueries);
    REQUIRE_FALSE(stats.autoDecision.autoBudget);
    REQUIRE_THAT(std::string(stats.autoDecision.budgetFallback), Contains("no occlusion queries"));
    REQUIRE(stats.drawnLights > 0);
}
