// The light-volume pass's plan (lidr/technique/volume_draw_plan.h) on the CPU, no GL context: for named cases,
// each draw step's role, lights and the RenderState fields that decide what it marks, counts and writes.
// The GL tests ([lidr], [render], [unpack], [gles2]) check that executing these plans renders exact indices.
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include "lidr/base/gl.h"
#include "lidr/base/error.h"
#include "lidr/technique/packing_scheme.h"
#include "lidr/technique/volume_draw_plan.h"

using namespace lidr;

namespace {

std::string glName(GLenum e) {
    switch (e) {
    case GL_NEVER: return "NEVER";
    case GL_LESS: return "LESS";
    case GL_EQUAL: return "EQUAL";
    case GL_LEQUAL: return "LEQUAL";
    case GL_GREATER: return "GREATER";
    case GL_GEQUAL: return "GEQUAL";
    case GL_ALWAYS: return "ALWAYS";
    case GL_FRONT: return "FRONT";
    case GL_BACK: return "BACK";
    case GL_KEEP: return "KEEP";
    case GL_INCR: return "INCR";
    case GL_REPLACE: return "REPLACE";
    }
    return std::to_string(e);
}

std::string hex(GLuint v) {
    char s[8];
    std::snprintf(s, sizeof s, "%02X", v);
    return s;
}

// One step as a table row: role, lights, depth test, culled face, stencil test and ops, stencil write mask,
// colour mask, blend, and whether the volume is pulled onto the far plane.
std::string row(const VolumeDrawPlan& plan, const VolumeStep& step) {
    const RenderState& s = plan.stateOf(step);
    std::string r = std::string(volumeStepRoleName(step.role)) + " L" + std::to_string(step.firstLight);
    if (step.lightCount != 1) r += "+" + std::to_string(step.lightCount);
    r += " depth " + (s.depthTest ? glName(s.depthFunc) : std::string("off"));
    r += " cull " + (s.cull ? glName(s.cullFace) : std::string("none"));
    r += " stencil " + (s.stencilTest ? glName(s.stencil.func) : std::string("off")) + " ref " + hex(GLuint(s.stencil.ref)) +
         " mask " + hex(s.stencil.readMask) + " ops " + glName(s.stencil.stencilFail) + "/" + glName(s.stencil.depthFail) +
         "/" + glName(s.stencil.depthPass) + " wmask " + hex(s.stencil.writeMask);
    r += " colour ";
    for (int c = 0; c < 4; ++c) r += s.colorMask[c] ? "RGBA"[c] : '-';
    r += s.blend ? " blend" : "";
    r += step.clampToFar ? " far" : "";
    return r;
}

std::vector<std::string> rows(const VolumeDrawPlan& plan) {
    std::vector<std::string> out;
    for (const VolumeStep& s : plan.steps) out.push_back(row(plan, s));
    return out;
}

// The draws of a real scheme's plan (one pixel that every light marks: CPU groups need no pass).
std::vector<VolumeDraw> schemeDraws(PackingSchemeKind scheme, int budget, int bits, int lights = 2) {
    PackingConfig config;
    config.scheme = scheme;
    config.budget = budget;
    config.indexBits = bits;
    std::vector<VolumeLight> ls;
    for (int i = 0; i < lights; ++i) ls.push_back({uint32_t(i + 1), glm::vec4(0.0f, 0.0f, -10.0f, 1.0f)});
    std::vector<VolumeDraw> draws;
    for (const SchemeDraw& sd : createPackingScheme(config, GlInfo{})->plan(ls, nullptr)) draws.push_back(sd.draw);
    return draws;
}

VolumePlanContext context(VolumeTest test, bool depthClamp = true) {
    VolumePlanContext c;
    c.test = test;
    c.depthClamp = depthClamp;
    return c;
}

}  // namespace

TEST_CASE("volume plan: the steps and states of each volume test, as a table", "[volume-plan][cpu]") {
    const std::vector<VolumeLightFacts> two(2);
    VolumeLightFacts far;
    far.reachesFarPlane = true;
    VolumeLightFacts near;
    near.reachesNearPlane = true;
    VolumeDraw plain;  // no rank window: every marking light writes, one draw counts it
    VolumeDraw windowed;
    windowed.rankFirst = 4;
    windowed.rankCount = 4;
    VolumeDraw colourless = windowed;
    colourless.colorMask = glm::bvec4(false);
    const VolumeDraw bitshift4 = schemeDraws(PackingSchemeKind::BitShift, 4, 8).at(0);
    REQUIRE(bitshift4.rankCount == 4);
    const VolumeDraw cpuSorted = schemeDraws(PackingSchemeKind::CpuSorted, 4, 8).at(0);
    REQUIRE(cpuSorted.rankCount == 0);

    struct Case {
        const char* name;
        VolumeDraw draw;
        VolumePlanContext context;
        std::vector<VolumeLightFacts> lights;
        int countBits;
        std::vector<std::string> steps;
    };
    const std::vector<Case> cases = {
        {"back-face, bit-shift budget 4 (8-bit): a 4-slot rank window, so a colour draw then a count draw per light",
         bitshift4, context(VolumeTest::BackFace), two, 8,
         {"write L0 depth GEQUAL cull FRONT stencil EQUAL ref 00 mask FC ops KEEP/KEEP/KEEP wmask 00 colour RGBA blend",
          "count L0 depth GEQUAL cull FRONT stencil ALWAYS ref 00 mask FC ops KEEP/KEEP/INCR wmask FF colour ----",
          "write L1 depth GEQUAL cull FRONT stencil EQUAL ref 00 mask FC ops KEEP/KEEP/KEEP wmask 00 colour RGBA blend",
          "count L1 depth GEQUAL cull FRONT stencil ALWAYS ref 00 mask FC ops KEEP/KEEP/INCR wmask FF colour ----"}},
        {"back-face, CPU sorting's group draw (no window): one draw per light writes and counts",
         cpuSorted, context(VolumeTest::BackFace), two, 8,
         {"write L0 depth GEQUAL cull FRONT stencil ALWAYS ref 00 mask FF ops KEEP/KEEP/INCR wmask FF colour R---",
          "write L1 depth GEQUAL cull FRONT stencil ALWAYS ref 00 mask FF ops KEEP/KEEP/INCR wmask FF colour R---"}},
        {"back-face, a windowed draw that writes no colour: the count draw alone",
         colourless, context(VolumeTest::BackFace), two, 8,
         {"count L0 depth GEQUAL cull FRONT stencil ALWAYS ref 04 mask FC ops KEEP/KEEP/INCR wmask FF colour ----",
          "count L1 depth GEQUAL cull FRONT stencil ALWAYS ref 04 mask FC ops KEEP/KEEP/INCR wmask FF colour ----"}},
        {"back-face, no depth clamp: the light reaching the far plane skips the depth test and is pulled onto it",
         plain, context(VolumeTest::BackFace, false), {VolumeLightFacts{}, far}, 8,
         {"write L0 depth GEQUAL cull FRONT stencil ALWAYS ref 00 mask FF ops KEEP/KEEP/INCR wmask FF colour RGBA",
          "write L1 depth ALWAYS cull FRONT stencil ALWAYS ref 00 mask FF ops KEEP/KEEP/INCR wmask FF colour RGBA far"}},
        {"back-face with depth clamp: the same light keeps its depth test (clamped, not clipped)",
         plain, context(VolumeTest::BackFace, true), {far}, 8,
         {"write L0 depth GEQUAL cull FRONT stencil ALWAYS ref 00 mask FF ops KEEP/KEEP/INCR wmask FF colour RGBA"}},
        {"exact stencil: mark (front faces set bit 7), write where unmarked, count in bits 0-6, unmark; per light",
         plain, context(VolumeTest::ExactStencil), two, 7,
         {"mark L0 depth GREATER cull BACK stencil ALWAYS ref 80 mask FF ops KEEP/KEEP/REPLACE wmask 80 colour ----",
          "write L0 depth GEQUAL cull FRONT stencil GREATER ref 80 mask FF ops KEEP/KEEP/KEEP wmask 00 colour RGBA",
          "count L0 depth GEQUAL cull FRONT stencil GREATER ref 7F mask FF ops KEEP/KEEP/INCR wmask 7F colour ----",
          "unmark L0 depth GREATER cull BACK stencil ALWAYS ref 00 mask FF ops KEEP/KEEP/REPLACE wmask 80 colour ----",
          "mark L1 depth GREATER cull BACK stencil ALWAYS ref 80 mask FF ops KEEP/KEEP/REPLACE wmask 80 colour ----",
          "write L1 depth GEQUAL cull FRONT stencil GREATER ref 80 mask FF ops KEEP/KEEP/KEEP wmask 00 colour RGBA",
          "count L1 depth GEQUAL cull FRONT stencil GREATER ref 7F mask FF ops KEEP/KEEP/INCR wmask 7F colour ----",
          "unmark L1 depth GREATER cull BACK stencil ALWAYS ref 00 mask FF ops KEEP/KEEP/REPLACE wmask 80 colour ----"}},
        {"exact stencil, window 4-7, no depth clamp, a far light: its write and count draws skip the depth test",
         windowed, context(VolumeTest::ExactStencil, false), {far}, 7,
         {"mark L0 depth GREATER cull BACK stencil ALWAYS ref 80 mask FF ops KEEP/KEEP/REPLACE wmask 80 colour ---- far",
          "write L0 depth ALWAYS cull FRONT stencil EQUAL ref 04 mask FC ops KEEP/KEEP/KEEP wmask 00 colour RGBA far",
          "count L0 depth ALWAYS cull FRONT stencil GREATER ref 7F mask FF ops KEEP/KEEP/INCR wmask 7F colour ---- far",
          "unmark L0 depth GREATER cull BACK stencil ALWAYS ref 00 mask FF ops KEEP/KEEP/REPLACE wmask 80 colour ---- far"}},
        {"front-face: front faces LEQUAL; a volume reaching in front of the near plane by its back faces, no depth test",
         windowed, context(VolumeTest::FrontFace), {VolumeLightFacts{}, near}, 8,
         {"write L0 depth LEQUAL cull BACK stencil EQUAL ref 04 mask FC ops KEEP/KEEP/KEEP wmask 00 colour RGBA",
          "count L0 depth LEQUAL cull BACK stencil ALWAYS ref 04 mask FC ops KEEP/KEEP/INCR wmask FF colour ----",
          "write L1 depth ALWAYS cull FRONT stencil EQUAL ref 04 mask FC ops KEEP/KEEP/KEEP wmask 00 colour RGBA",
          "count L1 depth ALWAYS cull FRONT stencil ALWAYS ref 04 mask FC ops KEEP/KEEP/INCR wmask FF colour ----"}},
        {"sphere, batches of 3, no depth clamp: every outcome counts; a batch with a far light drops the pre-test",
         windowed, [] { VolumePlanContext c = context(VolumeTest::Sphere, false); c.batchSize = 3; return c; }(),
         {VolumeLightFacts{}, VolumeLightFacts{}, VolumeLightFacts{}, VolumeLightFacts{}, far}, 8,
         {"write L0+3 depth GEQUAL cull FRONT stencil EQUAL ref 04 mask FC ops INCR/INCR/INCR wmask FF colour RGBA",
          "write L3+2 depth off cull FRONT stencil EQUAL ref 04 mask FC ops INCR/INCR/INCR wmask FF colour RGBA far"}},
        {"sphere with depth clamp: a far light keeps the pre-test",
         plain, [] { VolumePlanContext c = context(VolumeTest::Sphere, true); c.batchSize = 256; return c; }(),
         {VolumeLightFacts{}, far}, 8,
         {"write L0+2 depth GEQUAL cull FRONT stencil ALWAYS ref 00 mask FF ops INCR/INCR/INCR wmask FF colour RGBA"}},
        {"sphere-ray: no depth pre-test (the whole eye ray in front of the surface counts)",
         plain, [] { VolumePlanContext c = context(VolumeTest::SphereRay); c.batchSize = 256; return c; }(), two, 8,
         {"write L0+2 depth off cull FRONT stencil ALWAYS ref 00 mask FF ops INCR/INCR/INCR wmask FF colour RGBA"}},
    };
    for (const Case& k : cases) {
        INFO(k.name);
        const VolumeDrawPlan plan = planVolumeDraw(k.draw, k.context, k.lights);
        CHECK(rows(plan) == k.steps);
        CHECK(plan.countBits == k.countBits);
        CHECK(plan.program == (isShaderVolumeTest(k.context.test) ? VolumeProgram::Batch : VolumeProgram::PerLight));
        for (const VolumeStep& s : plan.steps) {
            const RenderState& st = plan.stateOf(s);
            // What every step shares: the scheme's blend state where it writes colour, the context's depth clamp,
            // no depth writes, no scissor (none was asked for).
            if (s.role == VolumeStepRole::Write && k.draw.blend) {
                CHECK(st.blendEquation == k.draw.blendEquation);
                CHECK(st.blendSrcRgb == k.draw.blendSrc);
                CHECK(st.blendDstRgb == k.draw.blendDst);
                CHECK(st.blendColor == k.draw.blendColor);
            }
            CHECK(st.depthClamp == k.context.depthClamp);
            CHECK_FALSE(st.depthWrite);
            CHECK_FALSE(st.scissor);
        }
    }
}

TEST_CASE("volume plan: states are shared, lights are loaded once, meshes follow the light", "[volume-plan][cpu]") {
    std::vector<VolumeLightFacts> lights(3);
    lights[1].detail = 1;
    lights[2].detail = 2;
    const VolumeDrawPlan exact = planVolumeDraw(VolumeDraw{}, context(VolumeTest::ExactStencil), lights);
    REQUIRE(exact.steps.size() == 12);
    CHECK(exact.states.size() == 4);  // mark, write, count, unmark: the same four for every light
    for (size_t i = 0; i < exact.steps.size(); ++i) {
        const VolumeStep& s = exact.steps[i];
        CHECK(s.firstLight == int(i / 4));
        CHECK(s.lightCount == 1);
        CHECK(s.loadLights == (i % 4 == 0));  // uniforms set before the light's first draw only
        CHECK(s.detail == lights[i / 4].detail);
        CHECK(s.state == exact.steps[i % 4].state);
    }
    // A far light adds the two no-depth states.
    lights[1].reachesFarPlane = true;
    const VolumeDrawPlan farPlan = planVolumeDraw(VolumeDraw{}, context(VolumeTest::ExactStencil, false), lights);
    CHECK(farPlan.states.size() == 6);
    CHECK(farPlan.stateOf(farPlan.steps[5]).depthFunc == GL_ALWAYS);
    CHECK(farPlan.stateOf(farPlan.steps[9]).depthFunc == GL_GEQUAL);
    CHECK(planVolumeDraw(VolumeDraw{}, context(VolumeTest::BackFace), {}).steps.empty());
}

TEST_CASE("volume plan: a rank window with the count restarted, on desktop GL and OpenGL ES", "[volume-plan][cpu]") {
    // Bit-shift at budget 16 with 8-bit indices: two windows of 8 slots, two targets each, drawn last to first:
    // ranks 8-15 from the pass's cleared count, then ranks 0-7 with the count restarted, so the count left in
    // the stencil is every pixel's whole count.
    const std::vector<VolumeDraw> draws = schemeDraws(PackingSchemeKind::BitShift, 16, 8);
    REQUIRE(draws.size() == 2);
    const VolumeDraw& second = draws[0];
    CHECK(second.rankFirst == 8);
    CHECK(draws[1].rankFirst == 0);
    const std::vector<VolumeLightFacts> one(1);
    const VolumeDrawPlan desktop = planVolumeDraw(second, context(VolumeTest::BackFace), one);
    CHECK_FALSE(desktop.restartCount);
    CHECK(planVolumeDraw(draws[1], context(VolumeTest::BackFace), one).restartCount);
    CHECK(desktop.framebufferFrom == -1);
    CHECK(desktop.drawBuffers == std::vector<GLenum>{GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3});
    CHECK(desktop.programTargets == 2);
    CHECK(rows(desktop) == std::vector<std::string>{
        "write L0 depth GEQUAL cull FRONT stencil EQUAL ref 08 mask F8 ops KEEP/KEEP/KEEP wmask 00 colour RGBA blend",
        "count L0 depth GEQUAL cull FRONT stencil ALWAYS ref 08 mask F8 ops KEEP/KEEP/INCR wmask FF colour ----"});
    const RenderState& write = desktop.stateOf(desktop.steps[0]);
    CHECK(write.stencil.func == GL_EQUAL);
    CHECK(write.stencil.ref == 8);
    CHECK(write.stencil.readMask == 0xF8u);
    CHECK(write.blendSrcRgb == GL_ONE);
    CHECK(write.blendDstRgb == GL_CONSTANT_COLOR);
    CHECK(write.blendColor == glm::vec4(0.5f));  // one bit per slot: shift by one

    // OpenGL ES maps gl_FragData[i] to COLOR_ATTACHMENTi: the framebuffer whose attachment 0 is target 2.
    VolumePlanContext es = context(VolumeTest::BackFace, false);
    es.gles = true;
    const VolumeDrawPlan gles = planVolumeDraw(second, es, one);
    CHECK(gles.framebufferFrom == 2);
    CHECK(gles.drawBuffers == std::vector<GLenum>{GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1});
    CHECK(rows(gles) == rows(desktop));
    es.drawBuffers = false;  // ES 2.0 without EXT_draw_buffers: one target, draw buffers never set
    const VolumeDrawPlan single = planVolumeDraw(schemeDraws(PackingSchemeKind::BitShift, 4, 8)[0], es, one);
    CHECK(single.framebufferFrom == 0);
    CHECK(single.drawBuffers.empty());
}

TEST_CASE("volume plan: the scissor reaches every state; bad rank windows are refused", "[volume-plan][cpu]") {
    VolumePlanContext c = context(VolumeTest::ExactStencil);
    c.scissor = glm::ivec4(3, 4, 50, 60);
    const VolumeDrawPlan plan = planVolumeDraw(VolumeDraw{}, c, std::vector<VolumeLightFacts>(1));
    REQUIRE(plan.states.size() == 4);
    for (const RenderState& s : plan.states) {
        CHECK(s.scissor);
        CHECK(s.scissorBox == glm::ivec4(3, 4, 50, 60));
    }
    for (auto [first, count] : std::vector<std::pair<int, int>>{{0, 3}, {2, 4}, {-4, 4}, {64, 64}, {48, 32}, {0, -1}}) {
        VolumeDraw d;
        d.name = "bad";
        d.rankFirst = first;
        d.rankCount = count;
        INFO("rank window " << first << " + " << count);
        CHECK_THROWS_AS(planVolumeDraw(d, context(VolumeTest::BackFace), {}), Error);
    }
    VolumeDraw ok;
    ok.rankFirst = 32;
    ok.rankCount = 32;
    CHECK_NOTHROW(planVolumeDraw(ok, context(VolumeTest::BackFace), {}));
}
