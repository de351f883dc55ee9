// The state cache (lidr/gl/gl_state.h): it skips what GL already holds, applies what differs, re-applies
// everything after invalidation, and what GL then holds (glGet*) is the RenderState; the pass description's
// clear opens the masks it needs; a frame's counters land in FrameStats and the caller's state stays unknown.
#include <catch2/catch.hpp>

#include "gl_test_context.h"
#include "lidr/base/gl.h"
#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/scene/default_scene.h"
#include "lidr/technique/lidr_renderer.h"

using namespace lidr;
using namespace lidr::test;

namespace {

// A state far from GL's defaults in every field the cache sets.
RenderState unusualState() {
    RenderState s;
    s.depthTest = true;
    s.depthFunc = GL_GEQUAL;
    s.depthWrite = true;
    s.cull = true;
    s.cullFace = GL_FRONT;
    s.stencilTest = true;
    s.stencil.func = GL_EQUAL;
    s.stencil.ref = 5;
    s.stencil.readMask = 0xF0;
    s.stencil.stencilFail = GL_INCR;
    s.stencil.depthFail = GL_DECR;
    s.stencil.depthPass = GL_REPLACE;
    s.stencil.writeMask = 0x7F;
    s.blend = true;
    s.blendEquation = GL_MAX;
    s.blendSrcRgb = GL_CONSTANT_COLOR;
    s.blendDstRgb = GL_ONE;
    s.blendSrcAlpha = GL_ZERO;
    s.blendDstAlpha = GL_ONE_MINUS_SRC_ALPHA;
    s.blendColor = glm::vec4(0.25f, 0.5f, 0.75f, 1.0f);
    s.colorMask = glm::bvec4(true, false, true, false);
    s.scissor = true;
    s.scissorBox = glm::ivec4(1, 2, 3, 4);
    return s;
}

// GL reports the stencil reference clamped to the bound framebuffer's stencil bits: every glGet here runs
// with a depth-stencil target bound.
struct StencilTarget {
    gl::Texture color = gl::Texture::create2D(GL_RGBA8, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE);
    gl::Renderbuffer depthStencil = gl::Renderbuffer::create(GL_DEPTH24_STENCIL8, 8, 8);
    gl::Framebuffer fbo = gl::Framebuffer::create();
    StencilTarget() {
        fbo.attachTexture(GL_COLOR_ATTACHMENT0, color);
        fbo.attachRenderbuffer(GL_DEPTH_STENCIL_ATTACHMENT, depthStencil);
        fbo.checkComplete("state cache test target");
        StateCache::current().bindFramebuffer(fbo.id());
    }
    ~StencilTarget() { StateCache::current().bindFramebuffer(0); }
};

GLint integer(GLenum e) {
    GLint v = 0;
    glGetIntegerv(e, &v);
    return v;
}

// Every field of `s` as GL reports it.
void requireGlHolds(const RenderState& s) {
    CHECK(bool(glIsEnabled(GL_DEPTH_TEST)) == s.depthTest);
    CHECK(GLenum(integer(GL_DEPTH_FUNC)) == s.depthFunc);
    GLboolean depthMask = GL_FALSE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
    CHECK(bool(depthMask) == s.depthWrite);
    CHECK(bool(glIsEnabled(GL_CULL_FACE)) == s.cull);
    CHECK(GLenum(integer(GL_CULL_FACE_MODE)) == s.cullFace);
    CHECK(bool(glIsEnabled(GL_STENCIL_TEST)) == s.stencilTest);
    CHECK(GLenum(integer(GL_STENCIL_FUNC)) == s.stencil.func);
    CHECK(integer(GL_STENCIL_REF) == s.stencil.ref);
    CHECK(GLuint(integer(GL_STENCIL_VALUE_MASK)) == s.stencil.readMask);
    CHECK(GLenum(integer(GL_STENCIL_FAIL)) == s.stencil.stencilFail);
    CHECK(GLenum(integer(GL_STENCIL_PASS_DEPTH_FAIL)) == s.stencil.depthFail);
    CHECK(GLenum(integer(GL_STENCIL_PASS_DEPTH_PASS)) == s.stencil.depthPass);
    CHECK(GLuint(integer(GL_STENCIL_WRITEMASK)) == s.stencil.writeMask);
    CHECK(bool(glIsEnabled(GL_BLEND)) == s.blend);
    CHECK(GLenum(integer(GL_BLEND_EQUATION_RGB)) == s.blendEquation);
    CHECK(GLenum(integer(GL_BLEND_EQUATION_ALPHA)) == s.blendEquation);
    CHECK(GLenum(integer(GL_BLEND_SRC_RGB)) == s.blendSrcRgb);
    CHECK(GLenum(integer(GL_BLEND_DST_RGB)) == s.blendDstRgb);
    CHECK(GLenum(integer(GL_BLEND_SRC_ALPHA)) == s.blendSrcAlpha);
    CHECK(GLenum(integer(GL_BLEND_DST_ALPHA)) == s.blendDstAlpha);
    GLfloat blendColor[4] = {};
    glGetFloatv(GL_BLEND_COLOR, blendColor);
    CHECK(glm::vec4(blendColor[0], blendColor[1], blendColor[2], blendColor[3]) == s.blendColor);
    GLboolean mask[4] = {};
    glGetBooleanv(GL_COLOR_WRITEMASK, mask);
    CHECK(glm::bvec4(mask[0], mask[1], mask[2], mask[3]) == s.colorMask);
    CHECK(bool(glIsEnabled(GL_SCISSOR_TEST)) == s.scissor);
    if (s.scissor) {
        GLint box[4] = {};
        glGetIntegerv(GL_SCISSOR_BOX, box);
        CHECK(glm::ivec4(box[0], box[1], box[2], box[3]) == s.scissorBox);
    }
    checkGl("state cache test: glGet");
}

// The unusual state applied through a cache that knows nothing: every field is set. Returns the counters from
// before that apply (the tests measure what follows against them).
GlCallCounters applyUnusualToUnknownCache(StateCache& cache) {
    cache.invalidate();
    const GlCallCounters start = cache.counters();
    cache.apply(unusualState());
    return start;
}

}  // namespace

TEST_CASE("the state cache skips a repeated state and applies only a changed field", "[state][every-gl]") {
    testContext();
    const StencilTarget target;
    StateCache& cache = StateCache::current();
    const RenderState s = unusualState();
    const GlCallCounters start = applyUnusualToUnknownCache(cache);
    const GlCallCounters first = cache.counters() - start;
    CHECK(first.stateCallsSkipped == 0);  // nothing known: every field set
    CHECK(first.stateCalls >= 16);  // 17 where the context has depth clamp
    requireGlHolds(s);

    cache.apply(s);
    const GlCallCounters repeated = cache.counters() - start - first;
    CHECK(repeated.stateCalls == 0);
    CHECK(repeated.stateCallsSkipped == first.stateCalls);

    RenderState changed = s;
    changed.depthFunc = GL_LEQUAL;
    const GlCallCounters before = cache.counters();
    cache.apply(changed);
    const GlCallCounters one = cache.counters() - before;
    CHECK(one.stateCalls == 1);
    CHECK(one.stateCallsSkipped == first.stateCalls - 1);
    requireGlHolds(changed);

    // The scissor box counts only while the test is on; a new box is one call.
    changed.scissorBox = glm::ivec4(0, 0, 2, 2);
    const GlCallCounters beforeBox = cache.counters();
    cache.apply(changed);
    CHECK((cache.counters() - beforeBox).stateCalls == 1);
    requireGlHolds(changed);
    cache.apply(RenderState{});
    requireGlHolds(RenderState{});
}

TEST_CASE("invalidating the state cache re-applies every field, and GL then holds the RenderState", "[state][every-gl]") {
    testContext();
    const StencilTarget target;
    StateCache& cache = StateCache::current();
    const RenderState s = unusualState();
    const GlCallCounters start = applyUnusualToUnknownCache(cache);
    const long fullCost = (cache.counters() - start).stateCalls;
    // Behind the cache's back, as a caller's drawing between two frames would.
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glStencilMask(0xFF);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_SCISSOR_TEST);
    cache.apply(s);  // still valid: skipped, so GL does not hold s now
    CHECK_FALSE(glIsEnabled(GL_DEPTH_TEST));
    cache.invalidate();
    CHECK_FALSE(cache.valid());
    const GlCallCounters before = cache.counters();
    cache.apply(s);
    const GlCallCounters again = cache.counters() - before;
    CHECK(again.stateCallsSkipped == 0);
    CHECK(again.stateCalls == fullCost);
    requireGlHolds(s);
    applyRenderState(RenderState{});  // the uncached form: every field, whatever the cache knew
    requireGlHolds(RenderState{});
}

TEST_CASE("a pass description binds, sets the viewport and draw buffers, and its clear opens the masks it needs",
          "[state][every-gl]") {
    testContext();
    const int w = 6, h = 4;
    gl::Texture color0 = gl::Texture::create2D(GL_RGBA8, w, h, GL_RGBA, GL_UNSIGNED_BYTE);
    gl::Framebuffer fbo = gl::Framebuffer::create();
    fbo.attachTexture(GL_COLOR_ATTACHMENT0, color0);
    fbo.checkComplete("state cache test FBO");
    StateCache& cache = StateCache::current();
    cache.invalidate();
    RenderState closed;
    closed.colorMask = glm::bvec4(false);  // a pass that left colour writes off
    closed.scissor = true;
    closed.scissorBox = glm::ivec4(0, 0, 1, 1);
    cache.apply(closed);

    PassDescription pass{fbo.id(), glm::ivec4(0, 0, w, h), {GL_COLOR_ATTACHMENT0}, {}};
    pass.clear.color = true;
    pass.clear.colorValue = glm::vec4(0.0f, 1.0f, 0.0f, 1.0f);
    const GlCallCounters before = cache.counters();
    cache.beginPass(pass);
    const GlCallCounters used = cache.counters() - before;
    CHECK(used.framebufferBinds == 1);
    CHECK(used.clears == 1);
    GLint viewport[4] = {};
    glGetIntegerv(GL_VIEWPORT, viewport);
    CHECK(glm::ivec4(viewport[0], viewport[1], viewport[2], viewport[3]) == pass.viewport);
    CHECK(integer(GL_DRAW_BUFFER0) == GL_COLOR_ATTACHMENT0);
    // The whole target is green: the mask was opened and the scissor turned off for the clear.
    const ImageRGBA8 image = readPixelsRGBA8(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const uint8_t* p = &image.pixels[(size_t(y) * w + x) * 4];
            INFO("pixel " << x << ", " << y);
            CHECK((p[0] == 0 && p[1] == 255 && p[2] == 0 && p[3] == 255));
        }
    // The same pass again: the viewport, draw buffers and clear colour are known, only the bind and clear happen.
    const GlCallCounters beforeAgain = cache.counters();
    cache.beginPass(pass);
    const GlCallCounters again = cache.counters() - beforeAgain;
    CHECK(again.stateCalls == 0);
    CHECK(again.stateCallsSkipped >= 3);  // viewport, draw buffers, clear colour, the open masks
    // The next state closes the mask again.
    cache.apply(closed);
    requireGlHolds(closed);
    cache.apply(RenderState{});
    cache.bindFramebuffer(0);
    checkGl("state cache pass test");
}

TEST_CASE("a frame's GL calls are counted in FrameStats, the same each frame, and leave the cache knowing nothing",
          "[state][lidr][every-gl]") {
    testContext();
    Scene scene = makeDefaultScene();
    scene.width = testWidth();
    scene.height = testHeight();
    const auto lights = scene.lightsAt(2.0f);
    const VolumeTest test = GENERATE(VolumeTest::Sphere, VolumeTest::ExactStencil);
    DYNAMIC_SECTION(volumeTestName(test)) {
        LidrOptions options;
        options.volumeTest = test;
        options.packing = {PackingSchemeKind::BitShift, 4, 8};
        LidrRenderer renderer(testGl(), scene, options, scene.width, scene.height);
        const GlCallCounters first = renderer.render(scene.camera, lights, {scene.ambient, scene.backgroundColor}).glCalls;
        CHECK_FALSE(StateCache::current().valid());  // SavedGlState gave the caller's state back
        const FrameStats second = renderer.render(scene.camera, lights, {scene.ambient, scene.backgroundColor});
        const GlCallCounters& c = second.glCalls;
        CHECK(c.stateCalls == first.stateCalls);
        CHECK(c.stateCallsSkipped == first.stateCallsSkipped);
        CHECK(c.drawCalls == first.drawCalls);
        CHECK(c.framebufferBinds == first.framebufferBinds);
        // The volume draws and at least one scene draw in each of the pre-pass and the forward pass.
        CHECK(c.drawCalls >= second.volumeDrawCalls + 2);
        CHECK(c.clears >= 2);  // the pre-pass's depth and stencil, the index targets, the forward pass's colour
        CHECK(c.programBinds >= 3);
        CHECK(c.framebufferBinds >= 3);
        if (test == VolumeTest::ExactStencil) {
            // Four states a light, the same for every light: most of each state is skipped. A whole-state
            // apply costs 17 calls or more; here each volume draw costs fewer than 8 on average.
            CHECK(c.stateCallsSkipped > c.stateCalls);
            CHECK(c.stateCalls < 8 * second.volumeDrawCalls);
        }
    }
}

TEST_CASE("texture binds go through the cache: counted, an upload binds on the active unit, unbinding empties units",
          "[state][every-gl]") {
    testContext();
    StateCache& cache = StateCache::current();
    const gl::Texture a = gl::Texture::create2D(GL_RGBA8, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE);
    const gl::Texture b = gl::Texture::create2D(GL_RGBA8, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE);
    const long before = cache.counters().textureBinds;
    a.bind(3);
    b.bind(5);
    CHECK(integer(GL_ACTIVE_TEXTURE) == GLint(GL_TEXTURE0 + 5));
    CHECK(integer(GL_TEXTURE_BINDING_2D) == GLint(b.id()));
    glActiveTexture(GL_TEXTURE0 + 1);
    const std::vector<uint8_t> texels(4 * 4 * 4, 200);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    a.upload(4, 4, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());  // on unit 1, left bound there
    CHECK(integer(GL_TEXTURE_BINDING_2D) == GLint(a.id()));
    CHECK(cache.counters().textureBinds == before + 3);
    cache.unbindTextures({3, 5});
    cache.unbindTextures(1, 1);
    CHECK(cache.counters().textureBinds == before + 6);
    CHECK(integer(GL_ACTIVE_TEXTURE) == GLint(GL_TEXTURE0));
    for (GLenum unit : {1u, 3u, 5u}) {
        glActiveTexture(GL_TEXTURE0 + unit);
        CHECK(integer(GL_TEXTURE_BINDING_2D) == 0);
    }
    glActiveTexture(GL_TEXTURE0);
    checkGl("texture binds test");
}

TEST_CASE("a uniform no shader declares is an error naming it; one the compiler removed is a harmless -1",
          "[state][resources][every-gl]") {
    testContext();
    const std::string vertex = "#version 120\nattribute vec3 aPosition;\nvoid main() { gl_Position = vec4(aPosition, 1.0); }\n";
    const std::string fragment =
        "#version 120\n"
        "uniform float uUsed; // uniform float uInComment;\n"
        "uniform vec4 uUnused, uArray[3];\n"
        "/* uniform vec4 uInBlockComment; */\n"
        "void main() { gl_FragColor = vec4(uUsed) + uArray[2]; }\n";
    const gl::Program program =
        gl::Program::create("uniform-check", vertex, fragment, {{"aPosition", gl::kPosition}});
    CHECK(program.declares("uUsed"));
    CHECK(program.declares("uUnused"));
    CHECK(program.declares("uArray"));
    CHECK_FALSE(program.declares("uInComment"));
    CHECK_FALSE(program.declares("uInBlockComment"));
    REQUIRE_THROWS_WITH(program.uniform<float>("uUsd"), Catch::Contains("'uUsd'") && Catch::Contains("uniform-check"));
    REQUIRE_THROWS_AS(program.set("uInComment", 1.0f), Error);
    CHECK(program.uniform<glm::vec4>("uUnused").location() == -1);  // declared, unused: removed by the compiler

    program.use();
    const auto used = program.uniform<float>("uUsed");
    REQUIRE(used.location() >= 0);
    used.set(0.625f);
    const glm::vec4 values[3] = {glm::vec4(1.0f), glm::vec4(2.0f), glm::vec4(0.25f, 0.5f, 0.75f, 1.0f)};
    program.uniform<glm::vec4>("uArray").setArray(values, 3);
    program.uniform<glm::vec4>("uUnused").set(glm::vec4(9.0f));  // -1: nothing happens, no GL error
    GLfloat read = 0.0f;
    glGetUniformfv(program.id(), used.location(), &read);
    CHECK(read == 0.625f);
    GLfloat element[4] = {};
    glGetUniformfv(program.id(), glGetUniformLocation(program.id(), "uArray[2]"), element);
    CHECK(glm::vec4(element[0], element[1], element[2], element[3]) == values[2]);
    glUseProgram(0);
    checkGl("uniform check test");
}
