#include "lidr/base/gl.h"

#include "stencil_readback.h"

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"

namespace lidr::web {

StencilReadback::StencilReadback() {
    program_ = gl::Program::create("web-stencil-readback", buildShaderSource("fullscreen.vert"),
                                   buildShaderSource("stencil_bit.frag"), {{"aPosition", gl::kPosition}});
    const float triangle[] = {-1.0f, -1.0f, 0.0f, 3.0f, -1.0f, 0.0f, -1.0f, 3.0f, 0.0f};
    triangle_ = gl::Buffer::create(GL_ARRAY_BUFFER, triangle, sizeof triangle);
}

std::vector<uint8_t> StencilReadback::read(const RenderTargets& targets) const {
    targets.bindSingleSample();
    applyRenderState(RenderState{});
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    RenderState s;
    s.stencilTest = true;
    s.stencil.func = GL_EQUAL;
    s.stencil.writeMask = 0;
    s.blend = true;  // ONE + ONE: the bits' values add up exactly in 8-bit unorm
    s.blendDstRgb = s.blendDstAlpha = GL_ONE;
    program_.use();
    glBindBuffer(GL_ARRAY_BUFFER, triangle_.id());
    glEnableVertexAttribArray(gl::kPosition);
    glVertexAttribPointer(gl::kPosition, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    for (int bit = 0; bit < 8; ++bit) {
        s.stencil.ref = 1 << bit;
        s.stencil.readMask = GLuint(1 << bit);
        applyRenderState(s);
        program_.set("uValue", float(1 << bit) / 255.0f);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glDisableVertexAttribArray(gl::kPosition);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    applyRenderState(RenderState{});
    const ImageRGBA8 sums = readPixelsRGBA8(targets.width(), targets.height());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    checkGl("web stencil read-back");
    std::vector<uint8_t> counts(size_t(targets.width()) * targets.height());
    for (size_t p = 0; p < counts.size(); ++p) counts[p] = sums.pixels[p * 4];
    return counts;
}

}  // namespace lidr::web
