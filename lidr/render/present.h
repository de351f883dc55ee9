#pragma once
// Putting a finished frame into the caller's framebuffer: the default framebuffer of a window (0) or an FBO
// the program owns. Every mode renders into its own targets (it needs its own depth-stencil and, for LIDR,
// index targets); FramePresenter then draws that colour image over a rectangle of the caller's framebuffer
// with one textured triangle (GL 2.1, no blit extension needed), leaving every piece of GL state as found.
#include "lidr/base/gl_types.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/render_targets.h"

namespace lidr {

class FramePresenter {
public:
    FramePresenter();  // compiles its program; needs the context current
    // Draws targets.color() into `framebuffer` over the window-coordinate rectangle (x, y, width, height):
    // no blending, depth or stencil test, every channel written. The same size as the targets copies pixel
    // for pixel; another size scales (nearest texel). Throws lidr::Error for an empty rectangle, GlError on
    // a GL error.
    void present(const RenderTargets& targets, GLuint framebuffer, int x, int y, int width, int height) const;
    // The whole target at (0, 0), the targets' size.
    void present(const RenderTargets& targets, GLuint framebuffer = 0) const {
        present(targets, framebuffer, 0, 0, targets.width(), targets.height());
    }

private:
    gl::Program program_;
    gl::Buffer triangle_;
};

}  // namespace lidr
