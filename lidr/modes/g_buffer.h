#pragma once
// The deferred modes' G-buffer (doc/deferred.md): four colour targets beside the frame's depth-stencil, filled in one
// geometry pass through multiple render targets (glDrawBuffers, GL 2.0; EXT_draw_buffers / WEBGL_draw_buffers on
// OpenGL ES 2.0 / WebGL 1), holding what lidrShadeLight and lidrAmbient need (shaders/modes/g_buffer.glsl has the
// layout): albedo + GGX alpha, F0 + F90, the octahedral normal + the window depth (split in two values), emission +
// occlusion. The position comes from the depth. Formats: RGBA16F (8 bytes a target, the default where the context
// renders to half floats) or RGBA32F (16); RGBA8 (ES 2.0 / WebGL 1 without float colour buffers, the default there)
// is another layout, five 8-bit targets (lidr/modes/g_buffer_unorm8.h), which this class holds in place of its own.
// Deferred shading's accumulation target (the lights' sum) lives here too, in the G-buffer's format; the RGBA8
// G-buffer's is RGBA16F where renderable, else RGBA8 (clamped at 1: each light's term rounds to 1/255).
#include <memory>
#include <string>
#include <vector>

#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/render_targets.h"
#include "lidr/gl/shader_source.h"
#include "lidr/gl/full_screen_triangle.h"
#include "lidr/render/gpu_scene.h"
#include "lidr/scene/camera.h"

namespace lidr {

class GBufferUnorm8;

// Auto: Half where the context renders to half floats (GlInfo::halfFloatColorBuffer), else Unorm8.
enum class GBufferFormat { Half, Float, Unorm8, Auto };
const char* gBufferFormatName(GBufferFormat format);  // "rgba16f", "rgba32f", "rgba8", "auto"
const std::vector<std::string>& gBufferFormatNames();  // every format's name, the default (auto) first
// One of gBufferFormatNames(); lidr::Error naming the valid ones for another name.
GBufferFormat parseGBufferFormat(const std::string& name);
// The format a G-buffer of `format` has on this context (Auto resolved; the others as they are).
GBufferFormat resolveGBufferFormat(const GlInfo& info, GBufferFormat format);

// The geometry pass of the four-target layout (g_buffer.glsl), single-sampled or multisampled alike: `fbo`'s four
// targets cleared to "no surface", the opaque meshes drawn with `program` where the pre-pass depth is EQUAL.
void drawGBufferGeometry(GLuint fbo, int width, int height, const gl::Program& program, const GpuScene& scene,
                         const CameraMatrices& camera);

class GBuffer {
public:
    static constexpr int kTargets = 4;
    GBuffer() = default;
    GBuffer(GBuffer&&) noexcept;
    GBuffer& operator=(GBuffer&&) noexcept;
    ~GBuffer();
    // Throws UnsupportedError where the context has fewer than 4 draw buffers (naming glDrawBuffers or
    // EXT_draw_buffers / WEBGL_draw_buffers; the RGBA8 layout splits its geometry pass instead), no colour buffers
    // of `format`, or the driver answers a framebuffer status other than complete. `accumulation`: also the
    // light-sum target (deferred; tiled deferred needs none).
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

    GBufferFormat format() const { return format_; }  // resolved: never Auto
    static int bytesPerPixel(GBufferFormat format);     // the targets' (Auto: throws lidr::Error)
    int bytesPerPixel() const { return bytesPerPixel(format_); }
    int accumulationBytesPerPixel() const { return accumulation_ ? accumulationBytes_ : 0; }
    // The light sum's format: the G-buffer's, or for RGBA8 "rgba16f" where renderable, else "rgba8".
    const char* accumulationFormatName() const;
    bool eightBitAccumulation() const { return accumulation_ && accumulationBytes_ == 4; }
    // What the lighting programs that read this G-buffer add to their defines (the RGBA8 layout's decoding, the
    // 8-bit light sum's count step).
    ShaderDefines shaderDefines() const;
    int geometryPasses() const;  // 1, or the RGBA8 layout's split passes
    size_t bytes() const { return size_t(width_) * height_ * (bytesPerPixel() + accumulationBytesPerPixel()); }

private:
    gl::Texture target(const GlInfo& info) const;

    GBufferFormat format_ = GBufferFormat::Half;
    int width_ = 0, height_ = 0;
    int accumulationBytes_ = 0;
    std::unique_ptr<GBufferUnorm8> unorm8_;  // the RGBA8 layout, in place of targets_, fbo_ and program_
    gl::Texture targets_[kTargets];
    gl::Texture accumulation_;
    gl::Framebuffer fbo_, accumulationFbo_;
    gl::Program program_;
    FullScreenTriangle triangle_;
};

}  // namespace lidr
