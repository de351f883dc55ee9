#include "lidr/gl/gl_state.h"
#include "lidr/base/error.h"
#include "lidr/base/gl.h"

#include <cstring>
#include <string>

namespace lidr {

GlCallCounters GlCallCounters::operator-(const GlCallCounters& o) const {
    GlCallCounters d;
    d.stateCalls = stateCalls - o.stateCalls;
    d.stateCallsSkipped = stateCallsSkipped - o.stateCallsSkipped;
    d.drawCalls = drawCalls - o.drawCalls;
    d.clears = clears - o.clears;
    d.programBinds = programBinds - o.programBinds;
    d.textureBinds = textureBinds - o.textureBinds;
    d.framebufferBinds = framebufferBinds - o.framebufferBinds;
    return d;
}

StateCache& StateCache::current() {
    thread_local StateCache cache;
    return cache;
}

const StateCache::Api& StateCache::api() {
    if (!apiKnown_) {
        api_.gles = currentContextIsGles();
        const char* ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
        api_.drawBuffers = !api_.gles || (ext && std::strstr(ext, "GL_EXT_draw_buffers") && hasDrawBuffersEntryPoint());
        apiKnown_ = true;
    }
    return api_;
}

void StateCache::invalidate() {
    apiKnown_ = false;  // another context may be current now
    valid_ = false;
    viewportValid_ = false;
    drawBuffers_.clear();
    framebufferValid_ = false;
    clearColorValid_ = clearDepthValid_ = clearStencilValid_ = false;
}

namespace {
// One GL call per field group: issued when the cache knows nothing or the value differs, else counted as
// skipped. `set` makes the call.
template <typename Set>
void update(bool known, bool same, GlCallCounters& counters, Set set) {
    if (known && same) {
        ++counters.stateCallsSkipped;
        return;
    }
    set();
    ++counters.stateCalls;
}

void enable(GLenum cap, bool on) { on ? glEnable(cap) : glDisable(cap); }

bool sameStencil(const StencilState& a, const StencilState& b, int group) {
    switch (group) {
    case 0: return a.func == b.func && a.ref == b.ref && a.readMask == b.readMask;
    case 1: return a.stencilFail == b.stencilFail && a.depthFail == b.depthFail && a.depthPass == b.depthPass;
    default: return a.writeMask == b.writeMask;
    }
}
}  // namespace

void StateCache::apply(const RenderState& s) {
    const RenderState& k = state_;
    const bool v = valid_;
    GlCallCounters& c = counters_;
    update(v, k.depthTest == s.depthTest, c, [&] { enable(GL_DEPTH_TEST, s.depthTest); });
    update(v, k.depthFunc == s.depthFunc, c, [&] { glDepthFunc(s.depthFunc); });
    update(v, k.depthWrite == s.depthWrite, c, [&] { glDepthMask(s.depthWrite ? GL_TRUE : GL_FALSE); });
    if (GLEW_ARB_depth_clamp || GLEW_NV_depth_clamp)
        update(v, k.depthClamp == s.depthClamp, c, [&] { enable(GL_DEPTH_CLAMP, s.depthClamp); });

    update(v, k.cull == s.cull, c, [&] { enable(GL_CULL_FACE, s.cull); });
    update(v, k.cullFace == s.cullFace, c, [&] { glCullFace(s.cullFace); });

    update(v, k.stencilTest == s.stencilTest, c, [&] { enable(GL_STENCIL_TEST, s.stencilTest); });
    update(v, sameStencil(k.stencil, s.stencil, 0), c,
           [&] { glStencilFunc(s.stencil.func, s.stencil.ref, s.stencil.readMask); });
    update(v, sameStencil(k.stencil, s.stencil, 1), c,
           [&] { glStencilOp(s.stencil.stencilFail, s.stencil.depthFail, s.stencil.depthPass); });
    update(v, sameStencil(k.stencil, s.stencil, 2), c, [&] { glStencilMask(s.stencil.writeMask); });

    update(v, k.blend == s.blend, c, [&] { enable(GL_BLEND, s.blend); });
    update(v, k.blendEquation == s.blendEquation, c, [&] { glBlendEquation(s.blendEquation); });
    update(v,
           k.blendSrcRgb == s.blendSrcRgb && k.blendDstRgb == s.blendDstRgb && k.blendSrcAlpha == s.blendSrcAlpha &&
               k.blendDstAlpha == s.blendDstAlpha,
           c, [&] { glBlendFuncSeparate(s.blendSrcRgb, s.blendDstRgb, s.blendSrcAlpha, s.blendDstAlpha); });
    update(v, k.blendColor == s.blendColor, c,
           [&] { glBlendColor(s.blendColor.r, s.blendColor.g, s.blendColor.b, s.blendColor.a); });

    update(v, k.colorMask == s.colorMask, c,
           [&] { glColorMask(s.colorMask.r, s.colorMask.g, s.colorMask.b, s.colorMask.a); });

    // GL_SAMPLE_SHADING is touched only once a pass asks for it (the per-sample path checked the context
    // for it); an unsupported enum in glDisable would be an error elsewhere. Until then it is left alone.
    if (s.sampleShading || sampleShadingTouched_) {
        update(v && sampleShadingTouched_, k.sampleShading == s.sampleShading, c, [&] {
            enable(GL_SAMPLE_SHADING, s.sampleShading);
            if (s.sampleShading) glMinSampleShading(1.0f);
        });
        sampleShadingTouched_ = true;
    }

    update(v, k.polygonOffset == s.polygonOffset, c, [&] { enable(GL_POLYGON_OFFSET_FILL, s.polygonOffset); });
    update(v, k.polygonOffsetFactorUnits == s.polygonOffsetFactorUnits, c,
           [&] { glPolygonOffset(s.polygonOffsetFactorUnits.x, s.polygonOffsetFactorUnits.y); });

    update(v, k.scissor == s.scissor, c, [&] { enable(GL_SCISSOR_TEST, s.scissor); });
    // The box matters only while the test is on; it is kept (and compared) from the last time it was set.
    RenderState next = s;
    if (s.scissor)
        update(v && k.scissorBox.z >= 0, k.scissorBox == s.scissorBox, c,
               [&] { glScissor(s.scissorBox.x, s.scissorBox.y, s.scissorBox.z, s.scissorBox.w); });
    else
        next.scissorBox = v ? k.scissorBox : glm::ivec4(-1);  // -1: box unknown
    state_ = next;
    valid_ = true;
}

void StateCache::bindFramebuffer(GLuint framebuffer) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    ++counters_.framebufferBinds;
    if (!framebufferValid_ || framebuffer_ != framebuffer) drawBuffers_.clear();
    framebuffer_ = framebuffer;
    framebufferValid_ = true;
}

void StateCache::bindTexture(GLenum target, GLuint texture) {
    glBindTexture(target, texture);
    ++counters_.textureBinds;
}

void StateCache::unbindTextures(std::initializer_list<int> units) {
    for (int unit : units) {
        glActiveTexture(GL_TEXTURE0 + GLenum(unit));
        bindTexture(GL_TEXTURE_2D, 0);
    }
    glActiveTexture(GL_TEXTURE0);
}

void StateCache::unbindTextures(int firstUnit, int count) {
    for (int unit = firstUnit; unit < firstUnit + count; ++unit) {
        glActiveTexture(GL_TEXTURE0 + GLenum(unit));
        bindTexture(GL_TEXTURE_2D, 0);
    }
    glActiveTexture(GL_TEXTURE0);
}

void StateCache::setViewport(const glm::ivec4& viewport) {
    update(viewportValid_, viewport_ == viewport, counters_,
           [&] { glViewport(viewport.x, viewport.y, viewport.z, viewport.w); });
    viewport_ = viewport;
    viewportValid_ = true;
}

void StateCache::setDrawBuffers(const std::vector<GLenum>& buffers) {
    if (buffers.empty()) return;
    const Api& api = this->api();
    if (api.gles && !api.drawBuffers) {
        // OpenGL ES 2.0 without EXT_draw_buffers: an FBO draws to COLOR_ATTACHMENT0, nothing to set.
        if (buffers.size() != 1 || (buffers[0] != GL_COLOR_ATTACHMENT0 && buffers[0] != GL_BACK))
            throw Error("this OpenGL ES context draws to one colour attachment (no EXT_draw_buffers); " +
                        std::to_string(buffers.size()) + " draw buffers were asked for");
        drawBuffers_ = framebufferValid_ ? buffers : std::vector<GLenum>{};
        return;
    }
    update(framebufferValid_ && !drawBuffers_.empty(), drawBuffers_ == buffers, counters_, [&] {
        if (buffers.size() == 1 && !api.gles)
            glDrawBuffer(buffers[0]);  // desktop only; ES (EXT_draw_buffers) sets one through glDrawBuffers
        else
            glDrawBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    });
    drawBuffers_ = framebufferValid_ ? buffers : std::vector<GLenum>{};
}

void StateCache::clear(const ClearAction& a) {
    if (!a.any()) return;
    RenderState open = valid_ ? state_ : RenderState{};
    if (a.color) open.colorMask = glm::bvec4(true);
    if (a.depth) open.depthWrite = true;
    if (a.stencil) open.stencil.writeMask = 0xFF;
    open.scissor = a.region.z > 0 && a.region.w > 0;
    if (open.scissor) open.scissorBox = a.region;
    apply(open);
    GLbitfield bits = 0;
    if (a.color) {
        update(clearColorValid_, clearColor_ == a.colorValue, counters_,
               [&] { glClearColor(a.colorValue.r, a.colorValue.g, a.colorValue.b, a.colorValue.a); });
        clearColor_ = a.colorValue;
        clearColorValid_ = true;
        bits |= GL_COLOR_BUFFER_BIT;
    }
    if (a.depth) {
        update(clearDepthValid_, clearDepth_ == a.depthValue, counters_, [&] { setClearDepth(float(a.depthValue)); });
        clearDepth_ = a.depthValue;
        clearDepthValid_ = true;
        bits |= GL_DEPTH_BUFFER_BIT;
    }
    if (a.stencil) {
        update(clearStencilValid_, clearStencil_ == a.stencilValue, counters_, [&] { glClearStencil(a.stencilValue); });
        clearStencil_ = a.stencilValue;
        clearStencilValid_ = true;
        bits |= GL_STENCIL_BUFFER_BIT;
    }
    glClear(bits);
    ++counters_.clears;
}

void StateCache::beginPass(const PassDescription& pass) {
    bindFramebuffer(pass.framebuffer);
    setViewport(pass.viewport);
    setDrawBuffers(pass.drawBuffers);
    clear(pass.clear);
}

void StateCache::drawArrays(GLenum mode, GLint first, GLsizei count) {
    glDrawArrays(mode, first, count);
    ++counters_.drawCalls;
}

void StateCache::drawElements(GLenum mode, GLsizei count, GLenum type, const void* offset) {
    glDrawElements(mode, count, type, offset);
    ++counters_.drawCalls;
}

void applyRenderState(const RenderState& s) {
    StateCache& cache = StateCache::current();
    cache.invalidate();
    cache.apply(s);
}

}  // namespace lidr
