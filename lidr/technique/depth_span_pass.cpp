#include "lidr/technique/depth_span_pass.h"

#include <algorithm>
#include "lidr/base/gl.h"

#include "lidr/base/error.h"
#include "lidr/gl/bindings.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"
#include "lidr/render/depth_prepass.h"

namespace lidr {

DepthSpanPass::DepthSpanPass(const GlInfo& info, const RenderTargets& targets, bool packedCentre)
    : width_(targets.width()), height_(targets.height()), samples_(targets.samples()) {
    if (samples_ < 2) throw Error("the MSAA depth spans need multisampled targets");
    try {
        target_ = HalfFloatTarget(info, targets);
    } catch (const UnsupportedError& e) {
        throw UnsupportedError(std::string("the sphere-span volume test (LIDR under MSAA) resolves depth spans in a "
                                           "half-float target: ") + e.what() +
                               "; use --volume-test sphere-ray (whole-ray lists) on this context");
    }
    // The samples the driver gave (it may round a request up: llvmpipe makes 4 of 2): the resolve averages over them.
    StateCache::current().beginPass(target_.pass());
    GLint samples = 0;
    glGetIntegerv(GL_SAMPLES, &samples);
    StateCache::current().bindFramebuffer(0);
    checkGl("MSAA depth spans: sample count");
    samples_ = std::max(samples_, int(samples));
    program_ = gl::Program::create("depth-span", buildShaderSource("geometry.vert"),
                                   buildShaderSource("depth_span.frag", packedCentre ? ShaderDefines{{"LIDR_CENTRE_PACKED", "1"}}
                                                                                     : ShaderDefines{}),
                                   geometryAttributes());
}

void DepthSpanPass::run(const GpuScene& scene, const CameraMatrices& camera, const gl::Texture& centreDepth) const {
    ClearAction clear;
    clear.color = true;  // 0: a sample no surface covers adds nothing to either bound
    clear.depth = clear.stencil = true;
    StateCache& cache = StateCache::current();
    cache.beginPass(target_.pass(clear));
    // The MSAA pre-pass itself (as DepthPrepass, the same vertex shader: the forward pass's EQUAL test holds):
    // the nearest fragment of each sample writes last.
    RenderState s;
    s.depthTest = true;
    s.depthFunc = GL_LESS;
    s.depthWrite = true;
    cache.apply(s);
    program_.use();
    program_.set("uViewProj", camera.viewProjection);
    program_.set("uDepth", gl::kUnitDepthCopy);
    program_.set("uInvTargetSize", 1.0f / glm::vec2(float(width_), float(height_)));
    program_.set("uStoreScale", kStoreScale);
    centreDepth.bind(gl::kUnitDepthCopy);
    scene.draw(program_, DrawFilter::Opaque, false, &camera);
    cache.apply(RenderState{});
    target_.resolve();
    checkGl("MSAA depth spans");
}

std::vector<DepthSpanPass::Span> DepthSpanPass::readSpans(const ImageFloat& centre) const {
    if (centre.width != width_ || centre.height != height_) throw Error("readSpans: depth image size differs");
    std::vector<float> rgba(size_t(width_) * size_t(height_) * 4);
#ifdef __EMSCRIPTEN__
    // WebGL 1 has neither glGetTexImage nor MSAA render targets: no spans are drawn there to read.
    throw Error("readSpans: WebGL 1 has no MSAA, so there are no depth spans to read back");
#else
    texture().bind(0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, rgba.data());
    checkGl("MSAA depth spans read-back");
#endif
    const float scale = boundScale();
    std::vector<Span> spans(rgba.size() / 4);
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const size_t texel = (size_t(height_ - 1 - y) * size_t(width_) + size_t(x)) * 4;  // bottom to top
            const float past = rgba[texel] * scale, before = rgba[texel + 1] * scale;
            const float d = centre.at(x, y);
            Span& s = spans[size_t(y) * size_t(width_) + size_t(x)];
            s.nearDepth = d < 1.0f ? d - before : 1.0f - before;
            s.farDepth = d < 1.0f ? d + past : std::min(past, 1.0f);
        }
    return spans;
}

}  // namespace lidr
