#pragma once
// lidr's state model. Every pass states all of its fixed-function state in one RenderState, and where it
// draws in one PassDescription (framebuffer, viewport, draw buffers, clear). Both go through the StateCache
// of the current context, which issues only the GL calls whose value differs from what it knows GL holds (the
// sokol_gfx way) and counts what it issued and skipped, so a pass can state its whole state per light
// without paying 16 GL calls per light, and nothing one pass sets leaks into the next.
//
// The embedding contract: lidr draws inside the caller's context and SavedGlState puts the caller's state
// back after every frame, behind the cache's back. So the cache knows nothing at the start of every render()
// (SavedGlState invalidates it on entry and on exit) and applies every field once, then only differences.
#include <initializer_list>
#include <vector>

#include <glm/glm.hpp>

#include "lidr/base/gl_types.h"

namespace lidr {

struct StencilState {
    GLenum func = glc::kAlways;
    GLint ref = 0;
    GLuint readMask = 0xFF;
    GLenum stencilFail = glc::kKeep, depthFail = glc::kKeep, depthPass = glc::kKeep;
    GLuint writeMask = 0xFF;
};

struct RenderState {
    bool depthTest = false;
    GLenum depthFunc = glc::kLess;
    bool depthWrite = false;
    bool depthClamp = false;  // only where the context has ARB/NV_depth_clamp

    bool cull = false;
    GLenum cullFace = glc::kBack;

    bool stencilTest = false;
    StencilState stencil;

    bool blend = false;
    GLenum blendEquation = glc::kFuncAdd;
    GLenum blendSrcRgb = glc::kOne, blendDstRgb = glc::kZero, blendSrcAlpha = glc::kOne, blendDstAlpha = glc::kZero;
    glm::vec4 blendColor{0.0f};

    glm::bvec4 colorMask{true, true, true, true};

    bool sampleShading = false;  // every sample shaded (ARB_sample_shading), for per-sample index reads

    bool scissor = false;
    glm::ivec4 scissorBox{0};

    // Depth offset of filled polygons (glPolygonOffset(factor, units)): the shadow maps' slope-scaled bias.
    bool polygonOffset = false;
    glm::vec2 polygonOffsetFactorUnits{0.0f};
};

// What a pass clears before it draws. Values are GL's clear values; the cache opens the write masks the
// cleared buffers need and clears the whole target (scissor off) or the region.
struct ClearAction {
    bool color = false, depth = false, stencil = false;
    glm::vec4 colorValue{0.0f};
    double depthValue = 1.0;
    GLint stencilValue = 0;
    glm::ivec4 region{0};  // x, y, width, height: clears only this box (scissored); empty: the whole target
    bool any() const { return color || depth || stencil; }
};

// Where a pass draws. framebuffer 0 is the default framebuffer; drawBuffers empty leaves the draw buffers as
// they are (the default framebuffer's, or a caller's FBO), else they are set (GL_COLOR_ATTACHMENTi...).
struct PassDescription {
    GLuint framebuffer = 0;
    glm::ivec4 viewport{0};  // x, y, width, height
    std::vector<GLenum> drawBuffers;
    ClearAction clear;
};

// What a frame asked of GL through the cache (FrameStats::glCalls; lidr-demo's summary, lidr-bench's columns).
struct GlCallCounters {
    long stateCalls = 0;         // state-setting GL calls issued (enables, functions, masks, viewport, clear values, draw buffers)
    long stateCallsSkipped = 0;  // calls left out because GL already held the value
    long drawCalls = 0;          // glDrawArrays / glDrawElements
    long clears = 0;             // glClear
    long programBinds = 0, textureBinds = 0, framebufferBinds = 0;  // counted, never filtered
    GlCallCounters operator-(const GlCallCounters& o) const;
};

class StateCache {
public:
    // The cache of the GL context current on this thread (a GL context is current on one thread at a time;
    // making a lidr context current invalidates it).
    static StateCache& current();

    // Forgets what GL holds: the next apply() and beginPass() set every field once.
    void invalidate();
    bool valid() const { return valid_; }

    // Sets the fields of `s` that differ from what GL holds.
    void apply(const RenderState& s);
    // Binds the framebuffer, sets the viewport and draw buffers, then clears as the pass says.
    void beginPass(const PassDescription& pass);
    // Clears the bound framebuffer: opens the write masks of the cleared buffers and turns the scissor off
    // through the cache (the next apply() closes what the pass wants closed), sets the clear values, glClear.
    void clear(const ClearAction& c);

    // GL_FRAMEBUFFER; always bound (and counted). Another framebuffer than the known one forgets the draw
    // buffers: they are state of the framebuffer object.
    void bindFramebuffer(GLuint framebuffer);
    void setViewport(const glm::ivec4& viewport);
    void setDrawBuffers(const std::vector<GLenum>& buffers);  // one buffer: glDrawBuffer, more (or ES): glDrawBuffers

    void drawArrays(GLenum mode, GLint first, GLsizei count);
    void drawElements(GLenum mode, GLsizei count, GLenum type, const void* offset);
    // Binds made by the GL object wrappers (gl_resources.h) are counted here.
    void countProgramBind() { ++counters_.programBinds; }
    void countFramebufferBind() { ++counters_.framebufferBinds; }
    // Every texture bind of lidr goes through here and is counted, never filtered (but SavedGlState's, which puts
    // the caller's bindings back behind the cache's back): `texture` on the active unit (gl::Texture::bind makes its
    // unit active first; an upload binds where it is and unbinds after).
    void bindTexture(GLenum target, GLuint texture);
    // A pass letting go of its inputs: each unit's 2D texture unbound (counted), then unit 0 active.
    void unbindTextures(std::initializer_list<int> units);
    void unbindTextures(int firstUnit, int count);

    const GlCallCounters& counters() const { return counters_; }
    // What the cache believes GL holds (valid() only); tests compare it with glGet*.
    const RenderState& known() const { return state_; }

private:
    // What the current context is, asked once after each invalidate(): OpenGL ES 2.0 sets draw buffers and the
    // clear depth through other calls, and without EXT_draw_buffers sets none.
    struct Api {
        bool gles = false;
        bool drawBuffers = true;
    };
    const Api& api();

    bool apiKnown_ = false;
    Api api_;
    bool valid_ = false;
    RenderState state_;
    bool sampleShadingTouched_ = false;  // GL_SAMPLE_SHADING is touched only once a pass turned it on
    glm::ivec4 viewport_{0};
    bool viewportValid_ = false;
    std::vector<GLenum> drawBuffers_;  // of the bound framebuffer; empty: unknown
    GLuint framebuffer_ = 0;
    bool framebufferValid_ = false;
    glm::vec4 clearColor_{0.0f};
    double clearDepth_ = 1.0;
    GLint clearStencil_ = 0;
    bool clearColorValid_ = false, clearDepthValid_ = false, clearStencilValid_ = false;
    GlCallCounters counters_;
};

// Counts the GL calls made through the cache while it lives into `out` (a frame's FrameStats::glCalls).
class GlCallCount {
public:
    explicit GlCallCount(GlCallCounters& out) : out_(out), start_(StateCache::current().counters()) {}
    ~GlCallCount() { out_ = StateCache::current().counters() - start_; }
    GlCallCount(const GlCallCount&) = delete;
    GlCallCount& operator=(const GlCallCount&) = delete;

private:
    GlCallCounters& out_;
    GlCallCounters start_;
};

// Sets every field of `s` whatever the cache knew (and the cache then knows it): for code that also changes GL
// state directly (tests, a program's own drawing). lidr's passes use StateCache::current().apply().
void applyRenderState(const RenderState& s);

}  // namespace lidr
