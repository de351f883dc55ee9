#pragma once
// Window depth of a scene's opaque surfaces, read back where glReadPixels cannot read depth (WebGL 1): the
// scene drawn again into an RGBA8 target with the depth encoded in colour (shaders/web/depth_rgba8.frag).
// Same vertex shader, geometry and matrices as the depth pre-pass, so the same surfaces at the same depth
// (to the 24-bit step); the page's CPU truth (lidr::computeCoverage) reads it.
#include "lidr/base/image.h"
#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/render/gpu_scene.h"
#include "lidr/scene/camera.h"

namespace lidr::web {

class DepthReadback {
public:
    // Throws UnsupportedError where fragment floats are not fp32 (the 24-bit encoding needs them).
    DepthReadback(const GlInfo& info, const Scene& scene, int width, int height);
    // Depth in [0, 1] per pixel, rows top to bottom as lidr::readDepth gives them; 1 where nothing was drawn.
    ImageFloat read(const CameraMatrices& camera) const;

private:
    int width_, height_;
    GpuScene scene_;
    gl::Program program_;
    gl::Texture color_;
    gl::Renderbuffer depth_;
    gl::Framebuffer fbo_;
};

}  // namespace lidr::web
