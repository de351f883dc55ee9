#include "lidr/gl/render_targets.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <cstdio>

#include "lidr/base/error.h"
#include "lidr/gl/frame_timer.h"

namespace lidr {

void checkResolution(const GlInfo& info, int width, int height) {
    if (width <= 0 || height <= 0)
        throw Error("resolution must be positive, got " + std::to_string(width) + "x" + std::to_string(height));
    GLint maxRb = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRb);
    const int limit = std::min(info.maxTextureSize, int(maxRb));
    if (width > limit || height > limit)
        throw Error("resolution " + std::to_string(width) + "x" + std::to_string(height) +
                    " exceeds this driver's limit of " + std::to_string(limit) + " pixels per side");
}

void checkSampleCount(int samples, const std::string& what) {
    if (samples == 0) return;
    if (samples < 2 || samples > 64 || (samples & (samples - 1)) != 0)
        throw Error(what + " must be 0 (off) or a power of two 2, 4, 8, ... up to the context's GL_MAX_SAMPLES, got " +
                    std::to_string(samples));
}

unsigned long long estimateRenderTargetBytes(int width, int height, int samples, int indexBytesPerPixel,
                                             bool perSampleIndices) {
    const unsigned long long pixels = (unsigned long long)std::max(width, 0) * (unsigned long long)std::max(height, 0);
    const unsigned long long s = (unsigned long long)std::max(samples, 0);
    const unsigned long long index = (unsigned long long)std::max(indexBytesPerPixel, 0);
    return pixels * (8ull + index + s * 8ull + (perSampleIndices ? s * index : 0ull));
}

void checkRenderTargetMemory(int width, int height, int samples, int indexBytesPerPixel, bool perSampleIndices) {
    const unsigned long long bytes = estimateRenderTargetBytes(width, height, samples, indexBytesPerPixel, perSampleIndices);
    if (bytes <= maxRenderTargetBytes) return;
    const auto mib = [](unsigned long long b) { return std::to_string((b + (1ull << 20) - 1) >> 20) + " MiB"; };
    throw Error("render targets of " + std::to_string(width) + "x" + std::to_string(height) + " with MSAA " +
                std::to_string(samples) + "x and " + std::to_string(indexBytesPerPixel) +
                " index bytes per pixel need about " + mib(bytes) + " (colour + depth + MSAA samples + index targets); " +
                "the limit is " + mib(maxRenderTargetBytes) + " (2 GiB): lower the resolution or the MSAA samples");
}

int indexBytesPerPixel(int budget, int indexBits) {
    const long bits = long(std::max(budget, 0)) * std::max(indexBits, 0);
    const long bytes = (bits + 7) / 8;
    return int(std::max(4L, (bytes + 3) / 4 * 4));
}

void checkDepthBits(const GlInfo& info, int depthBits) {
    if (depthBits != 16 && depthBits != 24)
        throw Error("depth bits must be 16 or 24, got " + std::to_string(depthBits));
    if (depthBits == 24) return;
    if (!info.framebufferObject) return;  // RenderTargets refuses the context itself, naming what it lacks
    // GL has no packed 16-bit depth-stencil format: 16-bit depth is a DEPTH_COMPONENT16 renderbuffer with a
    // STENCIL_INDEX8 one beside it, which drivers may refuse as a combination (FRAMEBUFFER_UNSUPPORTED).
    while (glGetError() != GL_NO_ERROR) {
    }
    GLenum status = 0;
    {
        const gl::Texture color = gl::Texture::create2D(GL_RGBA8, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE);
        const gl::Renderbuffer depth = gl::Renderbuffer::create(GL_DEPTH_COMPONENT16, 1, 1);
        const gl::Renderbuffer stencil = gl::Renderbuffer::create(GL_STENCIL_INDEX8, 1, 1);
        gl::Framebuffer probe = gl::Framebuffer::create();
        probe.attachTexture(GL_COLOR_ATTACHMENT0, color);
        probe.attachDepthStencil(depth, &stencil);
        status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        StateCache::current().bindFramebuffer(0);
    }
    checkGl("16-bit depth probe");
    if (status == GL_FRAMEBUFFER_COMPLETE) return;
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", status);
    const std::string name = status == GL_FRAMEBUFFER_UNSUPPORTED ? "GL_FRAMEBUFFER_UNSUPPORTED" : code;
    throw UnsupportedError("16-bit depth needs a DEPTH_COMPONENT16 depth renderbuffer with a separate STENCIL_INDEX8 "
                           "stencil renderbuffer (GL has no packed 16-bit depth-stencil format, and lidr's passes "
                           "count lights in the stencil); this driver (" + info.renderer + ") refuses that pair: " +
                           name + " (" + code + "). Use 24-bit depth (DEPTH24_STENCIL8)");
}

void checkSamples(const GlInfo& info, int samples) {
    if (samples == 0) return;
    if (samples < 0 || samples == 1)
        throw Error("MSAA samples must be 0 (off) or at least 2, got " + std::to_string(samples));
    if ((samples & (samples - 1)) != 0)
        throw Error("MSAA samples must be 0 (off) or a power of two 2, 4, 8, ..., got " + std::to_string(samples));
    if (!info.multisampleFbo)
        throw UnsupportedError("MSAA needs multisample framebuffers (GL 3.0, ARB_framebuffer_object or "
                               "EXT_framebuffer_multisample); this context has none");
    if (samples > info.maxSamples)
        throw UnsupportedError("MSAA " + std::to_string(samples) + "x asked for, this driver allows at most " +
                               std::to_string(info.maxSamples) + "x (GL_MAX_SAMPLES)");
}

RenderTargets::RenderTargets(const GlInfo& info, int width, int height, int samples, int depthBits)
    : width_(width), height_(height), samples_(samples), depthBits_(depthBits) {
    if (!info.framebufferObject && info.gles)
        throw UnsupportedError("this OpenGL ES context lacks OES_packed_depth_stencil, which lidr's framebuffer "
                               "objects need: the passes share one depth-stencil buffer (depth test and stencil count)");
    if (!info.framebufferObject)
        throw UnsupportedError("this context has no framebuffer objects (GL 3.0 or ARB_framebuffer_object); "
                               "lidr needs GL 2.1 + FBOs");
    checkResolution(info, width, height);
    checkSamples(info, samples);
    checkDepthBits(info, depthBits);
    const bool packed = depthBits == 24;
    depthStencil_ = gl::Renderbuffer::create(packed ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT16, width, height);
    if (!packed) stencil_ = gl::Renderbuffer::create(GL_STENCIL_INDEX8, width, height);
    color_ = gl::Texture::create2D(GL_RGBA8, width, height, GL_RGBA, GL_UNSIGNED_BYTE);
    colorFbo_ = gl::Framebuffer::create();
    colorFbo_.attachTexture(GL_COLOR_ATTACHMENT0, color_);
    colorFbo_.attachDepthStencil(depthStencil_, separateStencil());
    colorFbo_.checkComplete("scene colour");
    if (samples > 0) {
        msaaColor_ = gl::Renderbuffer::create(GL_RGBA8, width, height, samples);
        msaaDepthStencil_ =
            gl::Renderbuffer::create(packed ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT16, width, height, samples);
        if (!packed) msaaStencil_ = gl::Renderbuffer::create(GL_STENCIL_INDEX8, width, height, samples);
        msaaFbo_ = gl::Framebuffer::create();
        msaaFbo_.attachRenderbuffer(GL_COLOR_ATTACHMENT0, msaaColor_);
        msaaFbo_.attachDepthStencil(msaaDepthStencil_, multisampleSeparateStencil());
        msaaFbo_.checkComplete("scene colour MSAA");
    }
    StateCache::current().bindFramebuffer(0);
}

PassDescription RenderTargets::colorPass(const ClearAction& clear) const {
    return {samples_ > 0 ? msaaFbo_.id() : colorFbo_.id(), glm::ivec4(0, 0, width_, height_), {GL_COLOR_ATTACHMENT0},
            clear};
}

PassDescription RenderTargets::singleSamplePass(const ClearAction& clear) const {
    return {colorFbo_.id(), glm::ivec4(0, 0, width_, height_), {GL_COLOR_ATTACHMENT0}, clear};
}

void RenderTargets::bindColor() const { StateCache::current().beginPass(colorPass()); }

void RenderTargets::bindSingleSample() const { StateCache::current().beginPass(singleSamplePass()); }

void resolveColor(const gl::Framebuffer& from, const gl::Framebuffer& to, int width, int height, const char* what) {
    StateCache::current().apply(RenderState{});  // a blit is scissored (and colour-masked) like a draw
    glBindFramebuffer(GL_READ_FRAMEBUFFER, from.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to.id());
    readFromColorAttachment0();
    drawToColorAttachment0();
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    StateCache::current().bindFramebuffer(0);
    checkGl(what);
}

void RenderTargets::resolve() const {
    if (samples_ > 0) resolveColor(msaaFbo_, colorFbo_, width_, height_, "MSAA resolve");
}

void RenderTargets::resolve(FrameTimer& timer) const {
    if (samples_ == 0) return;
    TimedPass msaaResolveTime(timer, "msaa-resolve");
    resolve();
}

ImageRGBA8 RenderTargets::readColor() const {
    colorFbo_.bind();
    readFromColorAttachment0();
    return readPixelsRGBA8(width_, height_);
}

ImageFloat RenderTargets::readDepth() const {
    colorFbo_.bind();
    return lidr::readDepth(width_, height_);
}

std::vector<uint8_t> RenderTargets::readStencil() const {
    colorFbo_.bind();
    return lidr::readStencil(width_, height_);
}

}  // namespace lidr
