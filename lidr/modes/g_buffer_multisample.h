#pragma once
// The deferred modes under MSAA (doc/deferred.md, "MSAA"): the G-buffer of lidr/modes/g_buffer.h (the same four
// targets, formats and encoding) as multisample textures beside the frame's multisampled depth-stencil, and the
// light sum too. The geometry pass runs once a fragment, as the forward modes shade, and writes that fragment's
// surface into every sample it covers; the lighting passes run once a sample (gl_SampleID: texelFetch of the
// sample's surface, shaders/modes/g_buffer_multisample.glsl), the composite applies the output transform to each
// sample, and the frame's resolve averages them: the forward modes' order (shade per fragment into the MSAA target,
// output transform, resolve), so the image is the reference's.
//
// Needs multisample textures (GL 3.2 / ARB_texture_multisample) read per sample (GL 4.0 / ARB_sample_shading):
// deferredMsaaRefusal says why a context cannot (GL 2.1 proper, OpenGL ES 2.0, WebGL 1). The shaders are GLSL
// 1.50 compatibility files of their own (shaders/modes/*_multisample.*), chosen at run time; the GL 2.1 path's
// files are untouched.
//
// DeferredGBuffer is what the deferred renderers hold: this one or the single-sample GBuffer.
#include <memory>
#include <string>
#include <vector>

#include "lidr/modes/g_buffer.h"

namespace lidr {

// Why a deferred mode (`mode` starts the message) cannot shade `samples` MSAA samples on this context; empty where
// it can (or samples is 0).
std::string deferredMsaaRefusal(const GlInfo& info, int samples, const std::string& mode);

// One sample of every pixel read back (tests): rows from the bottom, as GL's.
struct GBufferSampleReadback {
    std::vector<float> depth;        // the window depth the sample's surface was stored at; 1 where it has none
    std::vector<float> lightCounts;  // the light shaders run at the sample (the accumulation's alpha; 0 without one)
};

// The G-buffer a deferred mode draws with, single-sample or multisampled (the calls of GBuffer's).
class DeferredGBuffer {
public:
    virtual ~DeferredGBuffer() = default;
    virtual void draw(const GpuScene& scene, const CameraMatrices& camera) const = 0;
    virtual PassDescription accumulationPass() const = 0;
    // Binds the accumulation target, cleared to 0, with the depth-stencil the light volumes test against: the
    // frame's (single-sample); multisampled, each sample's shaded surface depth (GBufferMultisample).
    virtual void beginAccumulation() const = 0;
    virtual void bind(const gl::Program& program, const CameraMatrices& camera) const = 0;
    virtual void unbind() const = 0;
    virtual void drawFullScreen() const = 0;
    // Single-sample: GBuffer::readLightCounts. Multisampled: lidr::Error (readSample gives each sample's).
    virtual std::vector<float> readLightCounts() const = 0;
    // Multisampled: sample `sample`'s stored depth and light count. Single-sample: lidr::Error.
    virtual GBufferSampleReadback readSample(int sample) const = 0;
    virtual GBufferFormat format() const = 0;
    virtual int samples() const = 0;  // 0: single-sample; else the samples the textures hold (>= those asked)
    // The four targets' bytes a pixel, every sample counted (GBuffer::bytesPerPixel x samples).
    virtual int bytesPerPixel() const = 0;
    virtual int accumulationBytesPerPixel() const = 0;  // the light sum's, every sample counted; 0 without one
    // The light sum's format (GBuffer::accumulationFormatName; multisampled: the G-buffer's own) and whether it is
    // the 8-bit one, clamped at 1 (the RGBA8 G-buffer where no half float renders).
    virtual const char* accumulationFormatName() const = 0;
    virtual bool eightBitAccumulation() const = 0;
    // What the lighting programs that read it add to their defines (GBuffer::shaderDefines: the RGBA8 layout's).
    virtual ShaderDefines shaderDefines() const = 0;
    virtual int geometryPasses() const = 0;  // 1, or the RGBA8 layout's split passes
    // Every target's bytes (multisampled: with the light sum's own depth-stencil, 4 bytes a sample).
    virtual size_t bytes() const = 0;
};

// "rgba16f, 32 bytes a pixel" or, multisampled, "rgba16f x 4 samples, 128 bytes a pixel (32 a sample)": the
// deferred modes' summary line.
std::string gBufferDescription(const DeferredGBuffer& g);

// GBuffer without MSAA (targets.samples() == 0), GBufferMultisample with it (`format` Auto resolved first: rgba16f
// where it renders; the RGBA8 layout is single-sample only). Throws UnsupportedError as they do.
std::unique_ptr<DeferredGBuffer> makeDeferredGBuffer(const GlInfo& info, const RenderTargets& targets,
                                                     GBufferFormat format, bool accumulation);

class GBufferMultisample final : public DeferredGBuffer {
public:
    // targets.samples() > 0. Throws UnsupportedError where deferredMsaaRefusal says why, the context has no colour
    // buffers of `format`, or the driver answers a framebuffer status other than complete.
    GBufferMultisample(const GlInfo& info, const RenderTargets& targets, GBufferFormat format, bool accumulation);

    // The geometry pass into the four multisample targets with the targets' MSAA depth-stencil (depth EQUAL, once a
    // fragment: the fragment's surface goes to every sample it covers).
    void draw(const GpuScene& scene, const CameraMatrices& camera) const override;
    PassDescription accumulationPass() const override;
    // The light sum's own depth-stencil gets, per sample, the window depth of the surface the sample stores (the
    // pixel centre's, where the shading puts it; 1 without one), not the sample position's depth: light volumes
    // grown by a pixel's width at their distance (DeferredRenderer) then pass the depth test, and cover the sample,
    // wherever the light reaches the shaded point. The frame's MSAA depth stays for the transparent meshes.
    void beginAccumulation() const override;
    // The sample textures (uGBufferSamples0..3, uLightSumSamples) and g_buffer.glsl's uGBufferInvSize and
    // uInverseViewProj.
    void bind(const gl::Program& program, const CameraMatrices& camera) const override;
    void unbind() const override;
    void drawFullScreen() const override;
    std::vector<float> readLightCounts() const override;
    GBufferSampleReadback readSample(int sample) const override;
    GBufferFormat format() const override { return format_; }
    int samples() const override { return samples_; }
    int bytesPerPixel() const override { return GBuffer::bytesPerPixel(format_) * samples_; }
    int accumulationBytesPerPixel() const override {
        return accumulation_ ? GBuffer::bytesPerPixel(format_) / GBuffer::kTargets * samples_ : 0;
    }
    const char* accumulationFormatName() const override { return gBufferFormatName(format_); }
    bool eightBitAccumulation() const override { return false; }
    ShaderDefines shaderDefines() const override { return {}; }
    int geometryPasses() const override { return 1; }
    size_t bytes() const override {
        return size_t(width_) * height_ * (bytesPerPixel() + accumulationBytesPerPixel() + (accumulation_ ? 4 * samples_ : 0));
    }

private:
    GBufferFormat format_ = GBufferFormat::Half;
    int width_ = 0, height_ = 0, samples_ = 0;
    gl::Texture targets_[GBuffer::kTargets];
    gl::Texture accumulation_;
    gl::Renderbuffer accumulationDepth_;  // the shaded surfaces' depths (beginAccumulation)
    gl::Framebuffer fbo_, accumulationFbo_;
    gl::Program program_, depthProgram_;
    FullScreenTriangle triangle_;
    mutable gl::Program readProgram_;  // readSample's, made on first use
};

}  // namespace lidr
