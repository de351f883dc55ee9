#pragma once
// The targets a frame renders into. A single-sample colour texture plus one packed DEPTH24_STENCIL8
// renderbuffer that the LIDR index targets attach too, so the pre-pass depth is shared. With 16-bit depth
// (depthBits 16) the depth is a DEPTH_COMPONENT16 renderbuffer and the stencil a STENCIL_INDEX8 one beside it
// (GL has no packed 16-bit depth-stencil format), where the driver accepts that pair (checkDepthBits). With MSAA, shading
// goes to multisampled colour and depth-stencil renderbuffers and is resolved into the colour texture; the
// single-sample depth-stencil still serves the light-volume pass (LIDR's index texture is single-sample).
#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/gl_state.h"
#include "lidr/base/image.h"

#include <string>

namespace lidr {

class RenderTargets {
public:
    RenderTargets() = default;
    // Throws UnsupportedError for a context without FBOs or without the samples asked for, lidr::Error for
    // a size the driver cannot hold. samples: 0 (no MSAA) or 2..info.maxSamples. depthBits: 24 (packed
    // DEPTH24_STENCIL8) or 16 (checkDepthBits: refused where the driver cannot hold that depth with a stencil).
    RenderTargets(const GlInfo& info, int width, int height, int samples = 0, int depthBits = 24);
    // Where shading goes: the MSAA FBO when samples > 0, the whole target, colour attachment 0; then `clear`.
    PassDescription colorPass(const ClearAction& clear = {}) const;
    // The single-sample colour FBO with the shared depth-stencil.
    PassDescription singleSamplePass(const ClearAction& clear = {}) const;
    void bindColor() const;         // StateCache::current().beginPass(colorPass()): no clear
    void bindSingleSample() const;  // the same for singleSamplePass()
    void resolve() const;           // MSAA colour into color(); nothing without MSAA
    // resolve() timed as the "msaa-resolve" pass; nothing (and no pass) without MSAA.
    void resolve(class FrameTimer& timer) const;
    int samples() const { return samples_; }
    int depthBits() const { return depthBits_; }
    // The depth (and, with 24 bits, stencil) renderbuffer; with 16 bits the stencil is separateStencil().
    const gl::Renderbuffer& depthStencil() const { return depthStencil_; }
    // The STENCIL_INDEX8 beside a 16-bit depth (nullptr with 24 bits: the stencil is packed with the depth).
    const gl::Renderbuffer* separateStencil() const { return stencil_ ? &stencil_ : nullptr; }
    const gl::Renderbuffer* multisampleSeparateStencil() const { return msaaStencil_ ? &msaaStencil_ : nullptr; }
    // The MSAA depth-stencil (per-sample index targets attach it); empty without MSAA.
    const gl::Renderbuffer& multisampleDepthStencil() const { return msaaDepthStencil_; }
    const gl::Texture& color() const { return color_; }
    const gl::Framebuffer& colorFramebuffer() const { return colorFbo_; }
    int width() const { return width_; }
    int height() const { return height_; }
    ImageRGBA8 readColor() const;             // the (resolved) image
    ImageFloat readDepth() const;             // single-sample depth
    std::vector<uint8_t> readStencil() const; // single-sample stencil

private:
    int width_ = 0, height_ = 0, samples_ = 0, depthBits_ = 24;
    gl::Renderbuffer depthStencil_, stencil_;
    gl::Texture color_;
    gl::Framebuffer colorFbo_;
    gl::Renderbuffer msaaColor_, msaaDepthStencil_, msaaStencil_;
    gl::Framebuffer msaaFbo_;
};

// Colour attachment 0 of the multisample `from` resolved into that of `to` (glBlitFramebuffer, both width x
// height); leaves framebuffer 0 bound. `what` names the resolve in a GL error.
void resolveColor(const gl::Framebuffer& from, const gl::Framebuffer& to, int width, int height, const char* what);

// Checks a resolution against the context before anything is allocated.
void checkResolution(const GlInfo& info, int width, int height);
// Checks a depth precision against the context before anything is allocated: 24 (always) or 16, which needs a
// DEPTH_COMPONENT16 renderbuffer with a separate STENCIL_INDEX8 one in a complete framebuffer (every pass
// uses the stencil). 16 is probed on a 1 x 1 framebuffer; a driver that refuses the pair (Mesa's Gallium
// drivers, llvmpipe and softpipe included, answer GL_FRAMEBUFFER_UNSUPPORTED) throws UnsupportedError naming
// the status. Another value throws lidr::Error.
void checkDepthBits(const GlInfo& info, int depthBits);
// Checks an MSAA sample count against the context: 0, or a power of two 2, 4, 8, ... up to maxSamples with
// multisample FBOs.
void checkSamples(const GlInfo& info, int samples);
// The same without a context: 0 or a power of two from 2 to 64 (the largest any driver offers); `what` starts
// the message ("--msaa"). Throws lidr::Error.
void checkSampleCount(int samples, const std::string& what);

// Render-target memory is estimated before any context renders, so an oversized request fails at once with
// the numbers instead of as an out-of-memory error (or a swapping machine) part-way through.
constexpr unsigned long long maxRenderTargetBytes = 2ull << 30;  // 2 GiB
// width x height x (colour 4 + depth-stencil 4 + index targets + samples x (colour 4 + depth-stencil 4)
// [+ samples x index targets when the index lists are per sample]) bytes. indexBytesPerPixel: the LIDR index
// targets of one sample (0 for other modes).
unsigned long long estimateRenderTargetBytes(int width, int height, int samples, int indexBytesPerPixel,
                                             bool perSampleIndices = false);
// Throws lidr::Error naming the estimate, its parts and the limit when the estimate is above maxRenderTargetBytes.
void checkRenderTargetMemory(int width, int height, int samples, int indexBytesPerPixel, bool perSampleIndices = false);
// Index-target bytes per pixel of `budget` slots of `indexBits` bits, in RGBA8 targets (4 bytes each).
int indexBytesPerPixel(int budget, int indexBits);

}  // namespace lidr
