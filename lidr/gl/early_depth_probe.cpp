#include "lidr/gl/early_depth_probe.h"

#include "lidr/base/error.h"
#include "lidr/base/gl.h"
#include "lidr/gl/full_screen_triangle.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"

#ifndef GL_FRAGMENT_SHADER_INVOCATIONS_ARB
#define GL_FRAGMENT_SHADER_INVOCATIONS_ARB 0x82F4  // ARB_pipeline_statistics_query (never used without it)
#endif

namespace lidr {

bool shadesRejectedMultisampleFragments(const GlInfo& info, int samples) {
#ifdef __EMSCRIPTEN__
    (void)info;
    (void)samples;
    return false;  // WebGL has no pipeline statistics
#else
    if (!info.pipelineStatistics || !info.multisampleFbo || samples < 2 || samples > info.maxSamples) return false;
    const int size = 16;
    const gl::Renderbuffer color = gl::Renderbuffer::create(GL_RGBA8, size, size, samples);
    const gl::Renderbuffer depth = gl::Renderbuffer::create(GL_DEPTH24_STENCIL8, size, size, samples);
    gl::Framebuffer fbo = gl::Framebuffer::create();
    fbo.attachRenderbuffer(GL_COLOR_ATTACHMENT0, color);
    fbo.attachDepthStencil(depth);
    fbo.checkComplete("early depth probe (MSAA)");
    const gl::Program program =
        gl::Program::create("early-depth-probe", buildShaderSource("fullscreen.vert"), buildShaderSource("depth_only.frag"),
                            {{"aPosition", gl::kPosition}});
    const FullScreenTriangle triangle = FullScreenTriangle::create();
    StateCache& cache = StateCache::current();
    ClearAction clear;
    clear.depth = true;
    clear.depthValue = 0.0;  // the triangle (window depth 0.5) fails LESS at every sample
    cache.beginPass({fbo.id(), glm::ivec4(0, 0, size, size), {GL_COLOR_ATTACHMENT0}, clear});
    RenderState s;
    s.depthTest = true;
    s.depthFunc = GL_LESS;
    s.depthWrite = false;
    cache.apply(s);
    program.use();
    gl::Object query(gl::Kind::Query);
    glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, query.id());
    triangle.draw();
    glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
    GLuint invocations = 0;
    glGetQueryObjectuiv(query.id(), GL_QUERY_RESULT, &invocations);
    cache.apply(RenderState{});
    cache.bindFramebuffer(0);
    checkGl("early depth probe");
    return invocations > 0;
#endif
}

}  // namespace lidr
