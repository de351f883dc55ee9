#pragma once
// The deferred modes' G-buffer (doc/deferred.md): four colour targets beside the frame's depth-stencil, filled in one
// geometry pass through multiple render targets (glDrawBuffers, GL 2.0; EXT_draw_buffers / WEBGL_draw_buffers on
// OpenGL ES 2.0 / WebGL 1), holding what lidrShadeLight and lidrAmbient need (shaders/modes/g_buffer.glsl has the
// layout): albedo + GGX alpha, F0 + F90, the octahedral normal + the window depth (split in two values), emission +
// occlusion. The position comes from the depth. Formats: RGBA16F (8 bytes a target, the default) or RGBA32F (16).
// An RGBA8 G-buffer (ES 2.0 / WebGL 1 without float colour buffers) is not implemented: those contexts are refused.
// Deferred shading's accumulation target (the lights' sum) lives here too, in the G-buffer's format.
#include <string>
#include <vector>

#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/render_targets.h"
#include "lidr/render/gpu_scene.h"
#include "lidr/scene/camera.h"

namespace lidr {

enum class GBufferFormat { Half, Float };
const char* gBufferFormatName(GBufferFormat format);  // "rgba16f", "rgba32f"
const std::vector<std::string>& gBufferFormatNames();  // every format's name, the default first
// "rgba16f" or "rgba32f"; lidr::Error naming the valid ones for another name.
GBufferFormat parseGBufferFormat(const std::string& name);

class GBuffer {
public:
    static constexpr int kTargets = 4;
    GBuffer() = default;
    // Throws UnsupportedError where the context has fewer than 4 draw buffers (naming glDrawBuffers or
    // EXT_draw_buffers / WEBGL_draw_buffers), no colour buffers of `format`, or the driver answers a framebuffer
    // status other than complete. `accumulation`: also the light-sum target (deferred; tiled deferred needs none).
    GBuffer(const GlInfo& info, const RenderTargets& targets, GBufferFormat format, bool accumulation);

    // The geometry pass (the "g-buffer" pass): the four targets cleared to "no surface", then the scene's opaque
    // meshes drawn with depth EQUAL against the pre-pass depth in the targets' depth-stencil.
    void draw(const GpuScene& scene, const CameraMatrices& camera) const;
    // Where the light volumes add their terms: the accumulation target with the depth-stencil, cleared to 0.
    PassDescription accumulationPass() const;
    // The G-buffer's textures to their units and g_buffer.glsl's uniforms; with the accumulation, uLightSum too.
    void bind(const gl::Program& program, const CameraMatrices& camera) const;
    void unbind() const;
    // One triangle over the viewport (the full-screen passes), with the state the caller applied.
    void drawFullScreen() const;

    // The accumulation target's alpha per pixel, rows from the bottom (GL's): how many times a light's shader ran
    // there in the last frame (the lighting computations). A read-back that stalls: for tests and the summary.
    std::vector<float> readLightCounts() const;

    GBufferFormat format() const { return format_; }
    static int bytesPerPixel(GBufferFormat format) { return kTargets * (format == GBufferFormat::Half ? 8 : 16); }
    int bytesPerPixel() const { return bytesPerPixel(format_); }
    int accumulationBytesPerPixel() const { return accumulation_ ? bytesPerPixel(format_) / kTargets : 0; }
    size_t bytes() const { return size_t(width_) * height_ * (bytesPerPixel() + accumulationBytesPerPixel()); }

private:
    gl::Texture target(const GlInfo& info) const;

    GBufferFormat format_ = GBufferFormat::Half;
    int width_ = 0, height_ = 0;
    gl::Texture targets_[kTargets];
    gl::Texture accumulation_;
    gl::Framebuffer fbo_, accumulationFbo_;
    gl::Program program_;
    gl::Buffer triangle_;
};

}  // namespace lidr
