#include "lidr/modes/g_buffer_multisample.h"
#include "lidr/base/gl.h"

#include <cstdio>

#include "lidr/base/error.h"
#include "lidr/gl/bindings.h"
#include "lidr/gl/shader_source.h"
#include "lidr/render/depth_prepass.h"

namespace lidr {

namespace {
constexpr const char* kSampleSamplers[GBuffer::kTargets] = {"uGBufferSamples0", "uGBufferSamples1",
                                                            "uGBufferSamples2", "uGBufferSamples3"};

GLint sampleFormat(GBufferFormat format) {
    if (format == GBufferFormat::Half) return GL_RGBA16F;
    if (format == GBufferFormat::Float) return GL_RGBA32F;
    throw UnsupportedError(std::string("a multisampled G-buffer is rgba16f or rgba32f, not ") +
                           gBufferFormatName(format));
}

// GBuffer as a DeferredGBuffer: the single-sample frame.
class SingleSampleGBuffer final : public DeferredGBuffer {
public:
    SingleSampleGBuffer(const GlInfo& info, const RenderTargets& targets, GBufferFormat format, bool accumulation)
        : g_(info, targets, format, accumulation) {}
    void draw(const GpuScene& scene, const CameraMatrices& camera) const override { g_.draw(scene, camera); }
    PassDescription accumulationPass() const override { return g_.accumulationPass(); }
    void beginAccumulation() const override { StateCache::current().beginPass(g_.accumulationPass()); }
    void bind(const gl::Program& program, const CameraMatrices& camera) const override { g_.bind(program, camera); }
    void unbind() const override { g_.unbind(); }
    void drawFullScreen() const override { g_.drawFullScreen(); }
    std::vector<float> readLightCounts() const override { return g_.readLightCounts(); }
    GBufferSampleReadback readSample(int) const override {
        throw Error("a single-sample G-buffer has no samples to read: readLightCounts");
    }
    GBufferFormat format() const override { return g_.format(); }
    int samples() const override { return 0; }
    int bytesPerPixel() const override { return g_.bytesPerPixel(); }
    int accumulationBytesPerPixel() const override { return g_.accumulationBytesPerPixel(); }
    size_t bytes() const override { return g_.bytes(); }
    const char* accumulationFormatName() const override { return g_.accumulationFormatName(); }
    bool eightBitAccumulation() const override { return g_.eightBitAccumulation(); }
    ShaderDefines shaderDefines() const override { return g_.shaderDefines(); }
    int geometryPasses() const override { return g_.geometryPasses(); }

private:
    GBuffer g_;
};
}  // namespace

std::string deferredMsaaRefusal(const GlInfo& info, int samples, const std::string& mode) {
    if (samples <= 0) return {};
    const std::string start = mode + ": MSAA needs a G-buffer per sample, read per sample: ";
    if (info.gles)
        return start + "OpenGL ES 2.0 and WebGL 1 have neither multisample textures nor per-sample shading "
                       "(use lidr, tiled or clustered)";
    if (!info.multisampleTexture)
        return start + "this context (OpenGL " + info.version + ", GLSL " + std::to_string(info.glsl) +
               ") lacks multisample textures (GL 3.2 / ARB_texture_multisample with GLSL 1.50); use lidr, tiled "
               "or clustered";
    if (!info.sampleShading)
        return start + "this context (OpenGL " + info.version + ") lacks per-sample shading (GL 4.0 / "
                       "ARB_sample_shading: gl_SampleID); use lidr, tiled or clustered";
    if (samples > info.maxColorTextureSamples)
        return start + "this context's multisample colour textures hold at most " +
               std::to_string(info.maxColorTextureSamples) + " samples (GL_MAX_COLOR_TEXTURE_SAMPLES), " +
               std::to_string(samples) + " asked";
    return {};
}

std::string gBufferDescription(const DeferredGBuffer& g) {
    const std::string format = gBufferFormatName(g.format());
    if (g.samples() == 0) return format + ", " + std::to_string(g.bytesPerPixel()) + " bytes a pixel";
    return format + " x " + std::to_string(g.samples()) + " samples, " + std::to_string(g.bytesPerPixel()) +
           " bytes a pixel (" + std::to_string(g.bytesPerPixel() / g.samples()) + " a sample)";
}

std::unique_ptr<DeferredGBuffer> makeDeferredGBuffer(const GlInfo& info, const RenderTargets& targets,
                                                     GBufferFormat format, bool accumulation) {
    if (targets.samples() > 0)
        return std::make_unique<GBufferMultisample>(info, targets, resolveGBufferFormat(info, format), accumulation);
    return std::make_unique<SingleSampleGBuffer>(info, targets, format, accumulation);
}

GBufferMultisample::GBufferMultisample(const GlInfo& info, const RenderTargets& targets, GBufferFormat format,
                                       bool accumulation)
    : format_(format), width_(targets.width()), height_(targets.height()), samples_(targets.samples()) {
    const std::string refusal = deferredMsaaRefusal(info, samples_, "the G-buffer");
    if (!refusal.empty()) throw UnsupportedError(refusal);
    if (format == GBufferFormat::Half && !info.halfFloatColorBuffer)
        throw UnsupportedError("an RGBA16F G-buffer needs half-float colour buffers (GL 3.0)");
    const GLint internalFormat = sampleFormat(format);
    const std::string what = std::to_string(samples_) + "x " + gBufferFormatName(format);
    fbo_ = gl::Framebuffer::create();
    for (int i = 0; i < GBuffer::kTargets; ++i) {
        targets_[i] = gl::Texture::create2DMultisample(internalFormat, width_, height_, samples_);
        fbo_.attachTexture(GL_COLOR_ATTACHMENT0 + i, targets_[i]);
    }
    // The driver may hold more samples than asked (llvmpipe makes 2x 4x): the summary and readSample take the
    // count the textures have. (WebGL has no glGetTexLevelParameteriv, and never gets here: refused above.)
#ifndef __EMSCRIPTEN__
    StateCache::current().bindTexture(GL_TEXTURE_2D_MULTISAMPLE, targets_[0].id());
    GLint held = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D_MULTISAMPLE, 0, GL_TEXTURE_SAMPLES, &held);
    StateCache::current().bindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    if (held > samples_) samples_ = held;
#endif
    fbo_.attachDepthStencil(targets.multisampleDepthStencil(), targets.multisampleSeparateStencil());
    fbo_.requireComplete("the multisampled G-buffer (4 " + what + " targets)", info.renderer);
    if (accumulation) {
        accumulation_ = gl::Texture::create2DMultisample(internalFormat, width_, height_, samples_);
        accumulationFbo_ = gl::Framebuffer::create();
        accumulationFbo_.attachTexture(GL_COLOR_ATTACHMENT0, accumulation_);
        accumulationDepth_ = gl::Renderbuffer::create(GL_DEPTH24_STENCIL8, width_, height_, samples_);
        accumulationFbo_.attachDepthStencil(accumulationDepth_);
        accumulationFbo_.requireComplete("the multisampled G-buffer (the " + what + " light sum)", info.renderer);
        depthProgram_ = gl::Program::create("g-buffer-sample-depth", buildShaderSource("deferred_fullscreen.vert"),
                                            buildShaderSource("g_buffer_sample_depth.frag"), geometryAttributes());
    }
    // The single-sample geometry pass's shaders: once a fragment, its surface to every covered sample.
    program_ = gl::Program::create("g-buffer-multisample", buildShaderSource("geometry.vert"),
                                   buildShaderSource("g_buffer.frag"), geometryAttributes());
    triangle_ = FullScreenTriangle::create();
    checkGl("GBufferMultisample");
}

void GBufferMultisample::draw(const GpuScene& scene, const CameraMatrices& camera) const {
    drawGBufferGeometry(fbo_.id(), width_, height_, program_, scene, camera);
}

PassDescription GBufferMultisample::accumulationPass() const {
    PassDescription pass{accumulationFbo_.id(), glm::ivec4(0, 0, width_, height_), {GL_COLOR_ATTACHMENT0}, {}};
    pass.clear.color = true;
    return pass;
}

void GBufferMultisample::beginAccumulation() const {
    PassDescription pass = accumulationPass();
    pass.clear.depth = pass.clear.stencil = true;
    StateCache& cache = StateCache::current();
    cache.beginPass(pass);
    RenderState s;  // every sample: its stored surface's depth, no colour
    s.depthTest = true;
    s.depthFunc = GL_ALWAYS;
    s.depthWrite = true;
    s.colorMask = glm::bvec4(false);
    s.sampleShading = true;
    cache.apply(s);
    depthProgram_.use();
    targets_[2].bind(gl::kUnitGBuffer0 + 2);
    depthProgram_.set("uGBufferSamples2", gl::kUnitGBuffer0 + 2);
    drawFullScreen();
    cache.apply(RenderState{});
}

void GBufferMultisample::bind(const gl::Program& program, const CameraMatrices& camera) const {
    for (int i = 0; i < GBuffer::kTargets; ++i) {
        targets_[i].bind(gl::kUnitGBuffer0 + i);
        program.set(kSampleSamplers[i], gl::kUnitGBuffer0 + i);
    }
    program.set("uGBufferInvSize", glm::vec2(1.0f / float(width_), 1.0f / float(height_)));
    program.set("uInverseViewProj", camera.inverseViewProjection);
    if (accumulation_ && program.declares("uLightSumSamples")) {
        accumulation_.bind(gl::kUnitLightSum);
        program.set("uLightSumSamples", int(gl::kUnitLightSum));
    }
}

void GBufferMultisample::unbind() const {
    StateCache& cache = StateCache::current();
    for (int unit = gl::kUnitGBuffer0; unit <= gl::kUnitLightSum; ++unit) {
        glActiveTexture(GL_TEXTURE0 + GLenum(unit));
        cache.bindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    }
    glActiveTexture(GL_TEXTURE0);
}

void GBufferMultisample::drawFullScreen() const { triangle_.draw(); }

std::vector<float> GBufferMultisample::readLightCounts() const {
    throw Error("GBufferMultisample::readLightCounts: the light counts are per sample (readSample)");
}

GBufferSampleReadback GBufferMultisample::readSample(int sample) const {
    if (sample < 0 || sample >= samples_)
        throw Error("GBufferMultisample::readSample: sample " + std::to_string(sample) + " of " +
                    std::to_string(samples_));
    if (!readProgram_)
        readProgram_ = gl::Program::create("g-buffer-sample-read", buildShaderSource("deferred_fullscreen.vert"),
                                           buildShaderSource("g_buffer_sample_read.frag"), geometryAttributes());
    const gl::Texture out = gl::Texture::create2D(GL_RGBA32F, width_, height_, GL_RGBA, GL_FLOAT);
    gl::Framebuffer fbo = gl::Framebuffer::create();
    fbo.attachTexture(GL_COLOR_ATTACHMENT0, out);
    StateCache& cache = StateCache::current();
    cache.beginPass({fbo.id(), glm::ivec4(0, 0, width_, height_), {GL_COLOR_ATTACHMENT0}, {}});
    cache.apply(RenderState{});
    readProgram_.use();
    targets_[2].bind(gl::kUnitGBuffer0 + 2);
    readProgram_.set("uGBufferSamples2", gl::kUnitGBuffer0 + 2);
    readProgram_.set("uSample", sample);
    readProgram_.set("uHasLightSum", accumulation_ ? 1.0f : 0.0f);
    if (accumulation_) accumulation_.bind(gl::kUnitLightSum);
    readProgram_.set("uLightSumSamples", int(gl::kUnitLightSum));
    drawFullScreen();
    std::vector<float> rgba(size_t(width_) * height_ * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, rgba.data());
    cache.bindFramebuffer(0);
    unbind();
    checkGl("GBufferMultisample::readSample");
    GBufferSampleReadback r;
    r.depth.resize(size_t(width_) * height_);
    r.lightCounts.resize(r.depth.size());
    for (size_t i = 0; i < r.depth.size(); ++i) {
        r.depth[i] = rgba[i * 4];
        r.lightCounts[i] = rgba[i * 4 + 1];
    }
    return r;
}

}  // namespace lidr
