#include "lidr/modes/g_buffer.h"
#include "lidr/base/gl.h"

#include <cstdint>
#include <cstdio>

#include "lidr/base/error.h"
#include "lidr/gl/bindings.h"
#include "lidr/gl/shader_source.h"
#include "lidr/modes/g_buffer_unorm8.h"
#include "lidr/render/depth_prepass.h"

namespace lidr {

namespace {
constexpr GLenum kHalfFloatOes = 0x8D61;  // OES_texture_half_float's type (ES 2.0)
constexpr const char* kSamplers[GBuffer::kTargets] = {"uGBuffer0", "uGBuffer1", "uGBuffer2", "uGBuffer3"};

// What the context must have before any GL object is made.
void checkContext(const GlInfo& info, GBufferFormat format) {
    if (format == GBufferFormat::Unorm8) return;  // any context: RGBA8 targets, the geometry pass split as needed
    if (!info.drawBuffers || info.maxDrawBuffers < GBuffer::kTargets)
        throw UnsupportedError(std::string("deferred shading writes 4 G-buffer targets at once: ") +
                               (info.gles ? "this OpenGL ES 2.0 / WebGL 1 context lacks EXT_draw_buffers "
                                            "(WEBGL_draw_buffers) with 4 draw buffers"
                                          : "this context has fewer than 4 draw buffers (glDrawBuffers)"));
    if (format == GBufferFormat::Half && !info.halfFloatColorBuffer)
        throw UnsupportedError(info.gles ? "an RGBA16F G-buffer needs half-float colour buffers (OES_texture_half_float "
                                           "+ EXT_color_buffer_half_float); --g-buffer rgba8 (or auto) needs none"
                                         : "an RGBA16F G-buffer needs half-float colour buffers (GL 3.0, or "
                                           "ARB_texture_float + ARB_color_buffer_float); --g-buffer rgba8 (or auto) "
                                           "needs none");
    if (format == GBufferFormat::Float && !info.textureFloat)
        throw UnsupportedError("an RGBA32F G-buffer needs float textures (ARB_texture_float / OES_texture_float)");
}
}  // namespace

const char* gBufferFormatName(GBufferFormat format) {
    switch (format) {
    case GBufferFormat::Half: return "rgba16f";
    case GBufferFormat::Float: return "rgba32f";
    case GBufferFormat::Unorm8: return "rgba8";
    case GBufferFormat::Auto: break;
    }
    return "auto";
}

const std::vector<std::string>& gBufferFormatNames() {
    static const std::vector<std::string> names = {"auto", "rgba16f", "rgba32f", "rgba8"};
    return names;
}

GBufferFormat parseGBufferFormat(const std::string& name) {
    for (GBufferFormat f : {GBufferFormat::Auto, GBufferFormat::Half, GBufferFormat::Float, GBufferFormat::Unorm8})
        if (name == gBufferFormatName(f)) return f;
    throw Error("unknown G-buffer format '" + name + "' (valid: auto, rgba16f, rgba32f, rgba8)");
}

GBufferFormat resolveGBufferFormat(const GlInfo& info, GBufferFormat format) {
    if (format != GBufferFormat::Auto) return format;
    return info.halfFloatColorBuffer ? GBufferFormat::Half : GBufferFormat::Unorm8;
}

int GBuffer::bytesPerPixel(GBufferFormat format) {
    switch (format) {
    case GBufferFormat::Half: return kTargets * 8;
    case GBufferFormat::Float: return kTargets * 16;
    case GBufferFormat::Unorm8: return GBufferUnorm8::kBytesPerPixel;
    case GBufferFormat::Auto: break;
    }
    throw Error("GBuffer::bytesPerPixel: the automatic format has no size until a context resolves it");
}

GBuffer::GBuffer(GBuffer&&) noexcept = default;
GBuffer& GBuffer::operator=(GBuffer&&) noexcept = default;
GBuffer::~GBuffer() = default;

const char* GBuffer::accumulationFormatName() const {
    if (format_ != GBufferFormat::Unorm8) return gBufferFormatName(format_);
    return accumulationBytes_ == 4 ? "rgba8" : "rgba16f";
}

ShaderDefines GBuffer::shaderDefines() const {
    ShaderDefines d;
    if (unorm8_) d = GBufferUnorm8::shaderDefines();
    if (eightBitAccumulation()) d.push_back({"LIDR_LIGHT_COUNT_STEP", "(1.0 / 255.0)"});
    return d;
}

int GBuffer::geometryPasses() const { return unorm8_ ? unorm8_->geometryPasses() : 1; }

gl::Texture GBuffer::target(const GlInfo& info) const {
    if (format_ == GBufferFormat::Unorm8)  // the light sum of the RGBA8 layout: half float where renderable
        return info.halfFloatColorBuffer
                   ? gl::Texture::create2D(GL_RGBA16F, width_, height_, GL_RGBA, info.gles ? kHalfFloatOes : GL_FLOAT)
                   : gl::Texture::create2D(GL_RGBA, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE);
    if (format_ == GBufferFormat::Half)
        return gl::Texture::create2D(GL_RGBA16F, width_, height_, GL_RGBA, info.gles ? kHalfFloatOes : GL_FLOAT);
    return gl::Texture::create2D(info.gles ? GL_RGBA : GL_RGBA32F, width_, height_, GL_RGBA, GL_FLOAT);
}

GBuffer::GBuffer(const GlInfo& info, const RenderTargets& targets, GBufferFormat format, bool accumulation)
    : format_(resolveGBufferFormat(info, format)), width_(targets.width()), height_(targets.height()) {
    checkContext(info, format_);
    if (format_ == GBufferFormat::Unorm8) {
        unorm8_ = std::make_unique<GBufferUnorm8>(info, targets);
    } else {
        fbo_ = gl::Framebuffer::create();
        for (int i = 0; i < kTargets; ++i) {
            targets_[i] = target(info);
            fbo_.attachTexture(GL_COLOR_ATTACHMENT0 + i, targets_[i]);
        }
        fbo_.attachDepthStencil(targets.depthStencil(), targets.separateStencil());
        fbo_.requireComplete(std::string("the G-buffer (4 ") + gBufferFormatName(format_) + " targets)", info.renderer);
    }
    if (accumulation) {
        accumulationBytes_ = format_ != GBufferFormat::Unorm8 ? bytesPerPixel(format_) / kTargets
                                                               : (info.halfFloatColorBuffer ? 8 : 4);
        accumulation_ = target(info);
        accumulationFbo_ = gl::Framebuffer::create();
        accumulationFbo_.attachTexture(GL_COLOR_ATTACHMENT0, accumulation_);
        accumulationFbo_.attachDepthStencil(targets.depthStencil(), targets.separateStencil());
        accumulationFbo_.requireComplete(std::string("the G-buffer (the ") + accumulationFormatName() + " light sum)",
                                         info.renderer);
    }
    if (!unorm8_)
        program_ = gl::Program::create("g-buffer", buildShaderSource("geometry.vert"),
                                       buildShaderSource("g_buffer.frag"), geometryAttributes());
    triangle_ = FullScreenTriangle::create();
    checkGl("GBuffer");
}

void GBuffer::draw(const GpuScene& scene, const CameraMatrices& camera) const {
    if (unorm8_) return unorm8_->draw(scene, camera);
    drawGBufferGeometry(fbo_.id(), width_, height_, program_, scene, camera);
}

void drawGBufferGeometry(GLuint fbo, int width, int height, const gl::Program& program, const GpuScene& scene,
                         const CameraMatrices& camera) {
    PassDescription pass{fbo, glm::ivec4(0, 0, width, height),
                         {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3}, {}};
    pass.clear.color = true;
    pass.clear.colorValue = glm::vec4(0.0f, 0.0f, 2.0f, 0.0f);  // depth hi 2: no surface (g_buffer.glsl)
    StateCache& cache = StateCache::current();
    cache.beginPass(pass);
    RenderState s;
    s.depthTest = true;
    s.depthFunc = GL_EQUAL;  // one fragment a pixel (each sample's, multisampled): the pre-pass's
    cache.apply(s);
    program.use();
    program.set("uViewProj", camera.viewProjection);
    program.setIfDeclared("uEyePosition", camera.eye);
    program.setIfDeclared("uMaterialTexture", int(gl::kUnitMaterial));
    scene.draw(program, DrawFilter::Opaque, true, &camera, 0);
}

PassDescription GBuffer::accumulationPass() const {
    PassDescription pass{accumulationFbo_.id(), glm::ivec4(0, 0, width_, height_), {GL_COLOR_ATTACHMENT0}, {}};
    pass.clear.color = true;
    return pass;
}

void GBuffer::bind(const gl::Program& program, const CameraMatrices& camera) const {
    if (unorm8_) unorm8_->bind(program);
    for (int i = 0; i < kTargets && !unorm8_; ++i) {
        targets_[i].bind(gl::kUnitGBuffer0 + i);
        program.set(kSamplers[i], gl::kUnitGBuffer0 + i);
    }
    program.set("uGBufferInvSize", glm::vec2(1.0f / float(width_), 1.0f / float(height_)));
    program.set("uInverseViewProj", camera.inverseViewProjection);
    if (accumulation_ && program.declares("uLightSum")) {
        accumulation_.bind(gl::kUnitLightSum);
        program.set("uLightSum", int(gl::kUnitLightSum));
    }
}

void GBuffer::unbind() const {
    StateCache::current().unbindTextures(gl::kUnitGBuffer0, kTargets + 1);  // and the light sum's unit above them
    if (unorm8_) StateCache::current().unbindTextures(gl::kUnitGBuffer4, 1);
}

std::vector<float> GBuffer::readLightCounts() const {
    if (!accumulation_) throw Error("GBuffer::readLightCounts: this G-buffer has no accumulation target");
    std::vector<float> rgba(size_t(width_) * height_ * 4);
    std::vector<uint8_t> bytes(eightBitAccumulation() ? rgba.size() : 0);  // counted in 1/255 (deferred_light.frag)
    StateCache::current().bindFramebuffer(accumulationFbo_.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    if (bytes.empty())
        glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, rgba.data());
    else
        glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
    StateCache::current().bindFramebuffer(0);
    checkGl("GBuffer::readLightCounts");
    std::vector<float> counts(size_t(width_) * height_);
    for (size_t i = 0; i < counts.size(); ++i) counts[i] = bytes.empty() ? rgba[i * 4 + 3] : float(bytes[i * 4 + 3]);
    return counts;
}

void GBuffer::drawFullScreen() const { triangle_.draw(); }

}  // namespace lidr
