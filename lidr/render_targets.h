#pragma once
// The colour and depth-stencil targets a frame renders into. Depth-stencil is one packed
// DEPTH24_STENCIL8 renderbuffer that the LIDR index targets attach too, so the pre-pass depth is shared.
#include "lidr/context.h"
#include "lidr/gl_resources.h"
#include "lidr/image.h"

namespace lidr {

class RenderTargets {
public:
    RenderTargets() = default;
    // Throws UnsupportedError for a context without FBOs, lidr::Error for a size the driver cannot hold.
    RenderTargets(const GlInfo& info, int width, int height);
    void bindColor() const;  // the colour FBO, viewport set
    const gl::Renderbuffer& depthStencil() const { return depthStencil_; }
    const gl::Texture& color() const { return color_; }
    const gl::Framebuffer& colorFramebuffer() const { return colorFbo_; }
    int width() const { return width_; }
    int height() const { return height_; }
    ImageRGBA8 readColor() const;
    ImageFloat readDepth() const;
    std::vector<uint8_t> readStencil() const;

private:
    int width_ = 0, height_ = 0;
    gl::Renderbuffer depthStencil_;
    gl::Texture color_;
    gl::Framebuffer colorFbo_;
};

// Checks a resolution against the context before anything is allocated.
void checkResolution(const GlInfo& info, int width, int height);

}  // namespace lidr
