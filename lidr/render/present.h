#pragma once
// Putting a finished frame into the caller's framebuffer: the default framebuffer of a window (0) or an FBO
// the program owns. Every mode renders into its own targets (it needs its own depth-stencil and, for LIDR,
// index targets); FramePresenter then draws that colour image over a rectangle of the caller's framebuffer
// with one textured triangle (GL 2.1, no blit extension needed), leaving every piece of GL state as found.
#include "lidr/base/gl_types.h"
#include "lidr/gl/full_screen_triangle.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/render_targets.h"
#include "lidr/render/output_transform.h"

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
    FullScreenTriangle triangle_;
};

// The output transform (exposure, tone map, sRGB) applied to a frame of linear light: multi-pass forward sums
// its lights by additive blending, so no one shader sees a pixel's whole sum. From a half-float target
// (HalfFloatTarget) the sum is drawn through output_encode.frag into the colour target; where the context has
// none, the sum was blended into the 8-bit colour target itself, rounded to 8 bits per pass and clamped at 1,
// and is copied to a scratch texture (glCopyTexSubImage2D, GL 1.1 / ES 2.0) and drawn back (doc/colour.md).
class OutputEncodePass {
public:
    OutputEncodePass();  // compiles its program; needs the context current
    // Into targets.color() (after any MSAA resolve), through the single-sample colour FBO. Leaves the state
    // cache's pass at that FBO with default state.
    void run(const RenderTargets& targets, const OutputTransform& output);
    // The same from `linearFrame` (the targets' size; read at texel centres, no filtering) into targets.color().
    // A multisample `linearFrame` (the targets' samples; HalfFloatTarget::multisampleTexture) is encoded sample
    // by sample (GLSL 1.50, sample shading) into the targets' multisample colour (colorPass()): resolve after.
    void run(const RenderTargets& targets, const OutputTransform& output, const gl::Texture& linearFrame);

private:
    gl::Program program_;
    gl::Program perSampleProgram_;  // compiled on first use
    FullScreenTriangle triangle_;
    gl::Texture scratch_;
};

}  // namespace lidr
