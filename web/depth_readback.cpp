#include "lidr/base/gl.h"

#include "depth_readback.h"

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"
#include "lidr/render/depth_prepass.h"

namespace lidr::web {

DepthReadback::DepthReadback(const GlInfo& info, const Scene& scene, int width, int height)
    : width_(width), height_(height), scene_(scene) {
    GLint range[2] = {0, 0}, precision = 0;
    glGetShaderPrecisionFormat(GL_FRAGMENT_SHADER, GL_HIGH_FLOAT, range, &precision);
    if (precision < 23)
        throw UnsupportedError("depth read-back by drawing needs fp32 fragment floats (highp, 23 bits); " +
                               info.renderer + " gives " + std::to_string(precision) + " bits");
    program_ = gl::Program::create("web-depth-readback", buildShaderSource("geometry.vert"),
                                   buildShaderSource("depth_rgba8.frag"), geometryAttributes());
    color_ = gl::Texture::create2D(GL_RGBA, width, height, GL_RGBA, GL_UNSIGNED_BYTE);
    depth_ = gl::Renderbuffer::create(GL_DEPTH_COMPONENT16, width, height);
    fbo_ = gl::Framebuffer::create();
    fbo_.attachTexture(GL_COLOR_ATTACHMENT0, color_);
    fbo_.attachRenderbuffer(GL_DEPTH_ATTACHMENT, depth_);
    fbo_.checkComplete("web depth read-back");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

ImageFloat DepthReadback::read(const CameraMatrices& camera) const {
    fbo_.bind();
    glViewport(0, 0, width_, height_);
    RenderState s;
    s.depthTest = true;
    s.depthFunc = GL_LESS;  // the pre-pass's test: the nearest surface wins
    s.depthWrite = true;
    applyRenderState(s);
    glClearColor(1.0f, 1.0f, 1.0f, 1.0f);  // decodes to 16777215: depth 1, no surface
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    program_.use();
    program_.set("uViewProj", camera.viewProjection);
    scene_.draw(program_, DrawFilter::Opaque, false);
    applyRenderState(RenderState{});
    const ImageRGBA8 encoded = readPixelsRGBA8(width_, height_);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    checkGl("web depth read-back");
    ImageFloat depth(width_, height_);
    for (size_t p = 0; p < depth.pixels.size(); ++p) {
        const uint8_t* c = &encoded.pixels[p * 4];
        depth.pixels[p] = float(double((uint32_t(c[0]) << 16) | (uint32_t(c[1]) << 8) | c[2]) / 16777215.0);
    }
    return depth;
}

}  // namespace lidr::web
