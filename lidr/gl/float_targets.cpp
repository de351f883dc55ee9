#include "lidr/gl/float_targets.h"
#include "lidr/base/gl.h"

#include <cstdio>
#include <string>

#include "lidr/base/error.h"

namespace lidr {

namespace {
GLenum completeness(const gl::Framebuffer& fbo) {
    StateCache::current().bindFramebuffer(fbo.id());
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    StateCache::current().bindFramebuffer(0);
    return status;
}
}  // namespace

FloatTargets::FloatTargets(const GlInfo& info, const RenderTargets& targets, GLenum format, int count)
    : width_(targets.width()), height_(targets.height()), samples_(targets.samples()), format_(format) {
    if (info.gles || !info.halfFloatColorBuffer)
        throw UnsupportedError("no float colour buffers (GL 3.0, or ARB_texture_float + ARB_color_buffer_float)");
    if (samples_ < 2) throw Error("FloatTargets: the targets are not multisampled");
    if (count < 1 || count > info.maxDrawBuffers)
        throw UnsupportedError("FloatTargets: " + std::to_string(count) + " draw buffers, the context has " +
                               std::to_string(info.maxDrawBuffers));
    msaaFbo_ = gl::Framebuffer::create();
    for (int i = 0; i < count; ++i) {
        msaaColors_.push_back(gl::Renderbuffer::create(format, width_, height_, samples_));
        msaaFbo_.attachRenderbuffer(GLenum(GL_COLOR_ATTACHMENT0 + i), msaaColors_.back());
        textures_.push_back(gl::Texture::create2D(GLint(format), width_, height_, GL_RGBA, GL_FLOAT));
        resolveFbos_.push_back(gl::Framebuffer::create());
        resolveFbos_.back().attachTexture(GL_COLOR_ATTACHMENT0, textures_.back());
    }
    msaaFbo_.attachDepthStencil(targets.multisampleDepthStencil(), targets.multisampleSeparateStencil());
    GLenum status = completeness(msaaFbo_);
    for (const gl::Framebuffer& f : resolveFbos_)
        if (status == GL_FRAMEBUFFER_COMPLETE) status = completeness(f);
    checkGl("float targets");
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04x", status);
        throw UnsupportedError(std::to_string(count) + " multisampled " + (format == GL_RGBA32F ? "RGBA32F" : "RGBA16F") +
                               " colour targets with the depth-stencil are incomplete on " + info.renderer +
                               " (status " + code + ")");
    }
    samples_ = std::max(samples_, msaaFbo_.samples());
}

PassDescription FloatTargets::pass(const ClearAction& clear) const {
    std::vector<GLenum> buffers;
    for (size_t i = 0; i < textures_.size(); ++i) buffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
    return {msaaFbo_.id(), glm::ivec4(0, 0, width_, height_), buffers, clear};
}

void FloatTargets::resolve() const {
    for (size_t i = 0; i < textures_.size(); ++i) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, msaaFbo_.id());
        glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + i));
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolveFbos_[i].id());
        drawToColorAttachment0();
        glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, msaaFbo_.id());
    readFromColorAttachment0();
    StateCache::current().bindFramebuffer(0);
    checkGl("float targets: MSAA resolve");
}

}  // namespace lidr
