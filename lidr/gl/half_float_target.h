#pragma once
// An RGBA16F colour target beside a RenderTargets, sharing its depth-stencil: where multi-pass forward sums its
// lights in linear light before the output transform (lidr/modes/multipass_forward_renderer.h). Single-sample,
// a texture the encode pass reads. With MSAA, shading goes to multisampled RGBA16F with the targets'
// multisampled depth-stencil: a multisample texture where the context can read one per sample (GL 3.2
// multisample textures + ARB_sample_shading: GlInfo::multisampleTexture, sampleShading), so each sample is
// encoded on its own; else a multisample renderbuffer, resolved (averaged in linear light) into the texture.
// On OpenGL ES 2.0 / WebGL 1 the texture is RGBA + HALF_FLOAT_OES (EXT_color_buffer_half_float); no MSAA there.
#include <string>

#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/render_targets.h"

namespace lidr {

class HalfFloatTarget {
public:
    HalfFloatTarget() = default;
    // Throws UnsupportedError where the context has no half-float colour buffers (GlInfo::halfFloatColorBuffer)
    // or the driver answers a framebuffer status other than complete for the attachments (named in the message).
    HalfFloatTarget(const GlInfo& info, const RenderTargets& targets);
    explicit operator bool() const { return bool(fbo_); }
    // Where shading goes: the MSAA FBO with the targets' samples, else the texture's; then `clear`.
    PassDescription pass(const ClearAction& clear = {}) const;
    // The samples as a multisample texture, read per sample (empty without MSAA or where the context reads
    // none): encode it sample by sample instead of resolving.
    const gl::Texture& multisampleTexture() const { return msaaTexture_; }
    void resolve() const;  // the MSAA samples averaged into texture(); nothing without MSAA
    const gl::Texture& texture() const { return texture_; }

private:
    int width_ = 0, height_ = 0, samples_ = 0;
    gl::Texture texture_;
    gl::Framebuffer fbo_;
    gl::Texture msaaTexture_;        // MSAA where read per sample
    gl::Renderbuffer msaaColor_;     // MSAA elsewhere
    gl::Framebuffer msaaFbo_;
};

}  // namespace lidr
