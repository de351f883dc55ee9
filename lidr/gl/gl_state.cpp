#include "lidr/gl/gl_state.h"
#include "lidr/base/gl.h"

namespace lidr {

static void enable(GLenum cap, bool on) { on ? glEnable(cap) : glDisable(cap); }

void applyRenderState(const RenderState& s) {
    enable(GL_DEPTH_TEST, s.depthTest);
    glDepthFunc(s.depthFunc);
    glDepthMask(s.depthWrite ? GL_TRUE : GL_FALSE);
    if (GLEW_ARB_depth_clamp || GLEW_NV_depth_clamp) enable(GL_DEPTH_CLAMP, s.depthClamp);

    enable(GL_CULL_FACE, s.cull);
    glCullFace(s.cullFace);

    enable(GL_STENCIL_TEST, s.stencilTest);
    glStencilFunc(s.stencil.func, s.stencil.ref, s.stencil.readMask);
    glStencilOp(s.stencil.stencilFail, s.stencil.depthFail, s.stencil.depthPass);
    glStencilMask(s.stencil.writeMask);

    enable(GL_BLEND, s.blend);
    glBlendEquation(s.blendEquation);
    glBlendFuncSeparate(s.blendSrcRgb, s.blendDstRgb, s.blendSrcAlpha, s.blendDstAlpha);
    glBlendColor(s.blendColor.r, s.blendColor.g, s.blendColor.b, s.blendColor.a);

    glColorMask(s.colorMask.r, s.colorMask.g, s.colorMask.b, s.colorMask.a);

    // GL_SAMPLE_SHADING is touched only by contexts that turned it on (the per-sample path checked the
    // context for it); an unsupported enum in glDisable would be an error elsewhere.
    static bool sampleShadingOn = false;
    if (s.sampleShading || sampleShadingOn) {
        enable(GL_SAMPLE_SHADING, s.sampleShading);
        if (s.sampleShading) glMinSampleShading(1.0f);
        sampleShadingOn = s.sampleShading;
    }

    enable(GL_SCISSOR_TEST, s.scissor);
    if (s.scissor) glScissor(s.scissorBox.x, s.scissorBox.y, s.scissorBox.z, s.scissorBox.w);
}

}  // namespace lidr
