#include "lidr/render_targets.h"

#include "lidr/error.h"

namespace lidr {

void checkResolution(const GlInfo& info, int width, int height) {
    if (width <= 0 || height <= 0)
        throw Error("resolution must be positive, got " + std::to_string(width) + "x" + std::to_string(height));
    GLint maxRb = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRb);
    const int limit = std::min(info.maxTextureSize, int(maxRb));
    if (width > limit || height > limit)
        throw Error("resolution " + std::to_string(width) + "x" + std::to_string(height) +
                    " exceeds this driver's limit of " + std::to_string(limit) + " pixels per side");
}

RenderTargets::RenderTargets(const GlInfo& info, int width, int height) : width_(width), height_(height) {
    if (!info.framebufferObject)
        throw UnsupportedError("this context has no framebuffer objects (GL 3.0 or ARB_framebuffer_object); "
                               "lidr needs GL 2.1 + FBOs");
    checkResolution(info, width, height);
    depthStencil_ = gl::Renderbuffer::create(GL_DEPTH24_STENCIL8, width, height);
    color_ = gl::Texture::create2D(GL_RGBA8, width, height, GL_RGBA, GL_UNSIGNED_BYTE);
    colorFbo_ = gl::Framebuffer::create();
    colorFbo_.attachTexture(GL_COLOR_ATTACHMENT0, color_);
    colorFbo_.attachRenderbuffer(GL_DEPTH_STENCIL_ATTACHMENT, depthStencil_);
    colorFbo_.checkComplete("scene colour");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void RenderTargets::bindColor() const {
    colorFbo_.bind();
    glDrawBuffer(GL_COLOR_ATTACHMENT0);
    glViewport(0, 0, width_, height_);
}

ImageRGBA8 RenderTargets::readColor() const {
    colorFbo_.bind();
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    return readPixelsRGBA8(width_, height_);
}

ImageFloat RenderTargets::readDepth() const {
    colorFbo_.bind();
    return lidr::readDepth(width_, height_);
}

std::vector<uint8_t> RenderTargets::readStencil() const {
    colorFbo_.bind();
    return lidr::readStencil(width_, height_);
}

}  // namespace lidr
