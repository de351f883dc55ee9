#pragma once
// The RGBA8 G-buffer (GBufferFormat::Unorm8, `--g-buffer rgba8`; doc/deferred.md) for contexts without float colour
// buffers: OpenGL ES 2.0 / WebGL 1 without EXT_color_buffer_half_float. GBuffer owns one in place of its float
// targets. Five RGBA8 targets (20 bytes a pixel; shaders/modes/g_buffer_unorm8.glsl has the layout): the depth
// packed at 24 bits (the frame's depth-stencil is a renderbuffer GL 2.1 and ES 2.0 cannot sample), the normal
// octahedral at 12 + 12 bits, albedo, F0 and GGX alpha as square roots, F90, occlusion, and the emission with a
// shared exponent (its range is above 1). The lighting shaders read it through the same lidrGBufferSurface, built
// with LIDR_GBUFFER_UNORM8 (shaderDefines()), so lidrShadeLight shades what the forward modes shade, to the layout's
// rounding. Where the context draws fewer than five buffers at once (WEBGL_draw_buffers guarantees 4; no
// EXT_draw_buffers: 1) the geometry pass is split: ceil(5 / max draw buffers) passes, each over the opaque meshes
// with depth EQUAL (geometryPasses()).
#include <vector>

#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/render_targets.h"
#include "lidr/gl/shader_source.h"
#include "lidr/render/gpu_scene.h"
#include "lidr/scene/camera.h"

namespace lidr {

class GBufferUnorm8 {
public:
    static constexpr int kTargets = 5;
    static constexpr int kBytesPerPixel = 4 * kTargets;
    // Throws UnsupportedError where the context has no highp fragment floats (the packing needs integers to 2^24),
    // too few texture units for the lighting passes (the fifth target takes unit gl::kUnitGBuffer4) or the driver
    // answers a framebuffer status other than complete.
    GBufferUnorm8(const GlInfo& info, const RenderTargets& targets);

    // The geometry pass(es): the targets cleared to 0 (no surface), the opaque meshes drawn with depth EQUAL.
    void draw(const GpuScene& scene, const CameraMatrices& camera) const;
    // The five targets to their units and samplers.
    void bind(const gl::Program& program) const;
    int geometryPasses() const { return int(passes_.size()); }
    // What the lighting programs add to read this layout.
    static ShaderDefines shaderDefines() { return {{"LIDR_GBUFFER_UNORM8", "1"}}; }

private:
    struct GeometryPass {
        gl::Framebuffer fbo;
        gl::Program program;
        int first = 0, count = 0;
    };
    int width_ = 0, height_ = 0;
    gl::Texture targets_[kTargets];
    std::vector<GeometryPass> passes_;
};

}  // namespace lidr
