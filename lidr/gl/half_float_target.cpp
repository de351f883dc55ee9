#include "lidr/gl/half_float_target.h"
#include "lidr/base/gl.h"

#include <cstdio>

#include "lidr/base/error.h"

namespace lidr {

namespace {
constexpr GLenum kHalfFloatOes = 0x8D61;  // OES_texture_half_float's type (desktop GL_HALF_FLOAT is 0x140B)
}  // namespace

HalfFloatTarget::HalfFloatTarget(const GlInfo& info, const RenderTargets& targets)
    : width_(targets.width()), height_(targets.height()), samples_(targets.samples()) {
    if (!info.halfFloatColorBuffer)
        throw UnsupportedError(info.gles ? "no half-float colour buffers (OES_texture_half_float + "
                                           "EXT_color_buffer_half_float)"
                                         : "no half-float colour buffers (GL 3.0, or ARB_texture_float + "
                                           "ARB_color_buffer_float)");
    // ES 2.0 takes the unsized RGBA with the OES type (Texture::create2D passes the format as internal format);
    // desktop GL the sized RGBA16F, uploaded from nothing.
    texture_ = gl::Texture::create2D(GL_RGBA16F, width_, height_, GL_RGBA, info.gles ? kHalfFloatOes : GL_FLOAT);
    fbo_ = gl::Framebuffer::create();
    fbo_.attachTexture(GL_COLOR_ATTACHMENT0, texture_);
    fbo_.attachDepthStencil(targets.depthStencil(), targets.separateStencil());
    fbo_.requireComplete("an RGBA16F colour texture with the depth-stencil", info.renderer);
    if (samples_ > 0) {
        const bool perSample =
            info.multisampleTexture && info.sampleShading && samples_ <= info.maxColorTextureSamples;
        msaaFbo_ = gl::Framebuffer::create();
        if (perSample) {
            msaaTexture_ = gl::Texture::create2DMultisample(GL_RGBA16F, width_, height_, samples_);
            msaaFbo_.attachTexture(GL_COLOR_ATTACHMENT0, msaaTexture_);
        } else {
            msaaColor_ = gl::Renderbuffer::create(GL_RGBA16F, width_, height_, samples_);
            msaaFbo_.attachRenderbuffer(GL_COLOR_ATTACHMENT0, msaaColor_);
        }
        msaaFbo_.attachDepthStencil(targets.multisampleDepthStencil(), targets.multisampleSeparateStencil());
        msaaFbo_.requireComplete("a " + std::to_string(samples_) + "x RGBA16F colour " +
                                     (perSample ? "texture" : "renderbuffer") + " with the depth-stencil",
                                 info.renderer);
    }
}

PassDescription HalfFloatTarget::pass(const ClearAction& clear) const {
    return {samples_ > 0 ? msaaFbo_.id() : fbo_.id(), glm::ivec4(0, 0, width_, height_), {GL_COLOR_ATTACHMENT0},
            clear};
}

void HalfFloatTarget::resolve() const {
    if (samples_ > 0) resolveColor(msaaFbo_, fbo_, width_, height_, "half-float MSAA resolve");
}

}  // namespace lidr
