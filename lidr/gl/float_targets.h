#pragma once
// Several RGBA float colour targets of one format drawn together (glDrawBuffers, GL 2.0) beside a RenderTargets'
// multisampled depth-stencil, each resolved (averaged over its samples) into a single-sample texture: what
// LIDR's MSAA depth spans write per sample (lidr/technique/depth_span_pass.h). Desktop GL only (ES 2.0 / WebGL 1
// have no MSAA render targets). All targets share one format: GL 2.1's EXT_framebuffer_object wants one format
// for every colour attachment.
#include <vector>

#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/render_targets.h"

namespace lidr {

class FloatTargets {
public:
    FloatTargets() = default;
    // Throws UnsupportedError where the context has no float colour buffers, `targets` are not multisampled, or
    // the driver does not answer complete for the attachments (the status in the message). format: GL_RGBA16F
    // or GL_RGBA32F.
    FloatTargets(const GlInfo& info, const RenderTargets& targets, GLenum format, int count);
    explicit operator bool() const { return bool(msaaFbo_); }
    GLenum format() const { return format_; }
    int samples() const { return samples_; }  // what the driver gave (it may round a request up)
    // Every target drawn at once, with the targets' multisampled depth-stencil; then `clear`.
    PassDescription pass(const ClearAction& clear = {}) const;
    void resolve() const;  // each target's samples averaged into texture(i)
    const gl::Texture& texture(int i) const { return textures_[size_t(i)]; }

private:
    int width_ = 0, height_ = 0, samples_ = 0;
    GLenum format_ = 0;
    std::vector<gl::Renderbuffer> msaaColors_;
    gl::Framebuffer msaaFbo_;
    std::vector<gl::Texture> textures_;
    std::vector<gl::Framebuffer> resolveFbos_;
};

}  // namespace lidr
