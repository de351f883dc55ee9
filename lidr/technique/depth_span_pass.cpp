#include "lidr/technique/depth_span_pass.h"

#include <algorithm>
#include <cmath>
#include "lidr/base/gl.h"

#include "lidr/base/error.h"
#include "lidr/gl/bindings.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"
#include "lidr/render/depth_prepass.h"

namespace lidr {

glm::vec2 sideBounds(float k, float n, float m1, float m2, glm::vec2 rounding) {
    const float m1Low = std::max(m1 - rounding.y, 0.0f) / (1.0f + rounding.x);
    const float m1High = (m1 + rounding.y) / (1.0f - rounding.x);
    const float m2High = (m2 + rounding.y) / (1.0f - rounding.x);
    const float perSample = n / k;  // means over all samples -> over the side's
    const float meanLow = m1Low * perSample, meanHigh = m1High * perSample;
    const float spread = std::sqrt(std::max((k - 1.0f) * (m2High * perSample - meanLow * meanLow), 0.0f));
    return {std::max(meanLow - spread, 0.0f), meanHigh + spread};
}

const char* depthSpanStorageName(DepthSpanStorage s) {
    switch (s) {
        case DepthSpanStorage::Samples: return "samples";
        case DepthSpanStorage::Moments: return "moments";
        default: return "auto";
    }
}

DepthSpanStorage parseDepthSpanStorage(const std::string& name) {
    for (DepthSpanStorage s : {DepthSpanStorage::Auto, DepthSpanStorage::Samples, DepthSpanStorage::Moments})
        if (name == depthSpanStorageName(s)) return s;
    throw Error("unknown MSAA span storage '" + name + "' (valid: auto, samples, moments)");
}

DepthSpanStorage resolveDepthSpanStorage(DepthSpanStorage requested, const GlInfo& info, int samples) {
    if (requested == DepthSpanStorage::Moments) return requested;
    std::string missing;
    if (info.gles || !info.multisampleTexture || info.glsl < 150)
        missing = "multisample textures read in GLSL 1.50 (GL 3.2 / ARB_texture_multisample)";
    else if (!info.halfFloatColorBuffer)
        missing = "float colour buffers";
    else if (samples > info.maxColorTextureSamples)
        missing = std::to_string(samples) + "-sample textures (the context's most: " +
                  std::to_string(info.maxColorTextureSamples) + ")";
    if (missing.empty() && samples <= DepthSpanPass::kMaxPackedSamples) return DepthSpanStorage::Samples;
    if (requested == DepthSpanStorage::Auto) return DepthSpanStorage::Moments;
    if (missing.empty())
        throw UnsupportedError("--msaa-spans samples packs at most " +
                               std::to_string(DepthSpanPass::kMaxPackedSamples) + " samples' distances a pixel, not " +
                               std::to_string(samples) + ": use moments or auto (which takes moments there)");
    throw UnsupportedError("--msaa-spans samples stores each sample's distance in a multisample texture; this context "
                           "(OpenGL " + info.version + ") lacks " + missing + ": use moments (GL 2.1) or auto");
}

namespace {
// writeCentreDepth's targets: the ranges' near and far (0, 1), then the packed distances.
constexpr GLenum kPackedAttachment = GL_COLOR_ATTACHMENT2;

FloatTargets sideTargets(const GlInfo& info, const RenderTargets& targets) {
    try {
        return FloatTargets(info, targets, GL_RGBA32F, 2);  // float: the moments' bounds stay tight
    } catch (const UnsupportedError&) {
        return FloatTargets(info, targets, GL_RGBA16F, 2);
    }
}
}  // namespace

glm::vec2 DepthSpanPass::sideRoundingOf(bool halfFloat) {
    // A resolved mean went through the sample's rounding, the averaging (a sum of up to 16 in the worst order)
    // and the store: a relative error below 1/128 (16 half-float roundings) or 2^-20 (16 float ones), and half
    // floats' subnormal steps (2^-25 each, 16 of them).
    return halfFloat ? glm::vec2(1.0f / 128.0f, 1.0f / 2097152.0f) : glm::vec2(1.0f / 1048576.0f, 0.0f);
}

glm::vec2 DepthSpanPass::sideRounding() const { return sideRoundingOf(sides_.format() != GL_RGBA32F); }

DepthSpanPass::DepthSpanPass(const GlInfo& info, const RenderTargets& targets, bool packedCentre, bool sideMoments)
    : width_(targets.width()), height_(targets.height()), samples_(targets.samples()) {
    if (samples_ < 2) throw Error("the MSAA depth spans need multisampled targets");
    if (sideMoments && packedCentre) throw Error("DepthSpanPass: side moments read the centre's depth texture");
    try {
        if (sideMoments)
            sides_ = sideTargets(info, targets);
        else
            target_ = HalfFloatTarget(info, targets);
    } catch (const UnsupportedError& e) {
        throw UnsupportedError(std::string("the sphere-span volume test (LIDR under MSAA) resolves depth spans in a "
                                           "half-float target: ") + e.what() +
                               "; use --volume-test sphere-ray (whole-ray lists) on this context");
    }
    // The samples the driver gave (it may round a request up: llvmpipe makes 4 of 2): the resolve averages over them.
    if (sides_) {
        samples_ = sides_.samples();
    } else {
        samples_ = std::max(samples_, gl::Framebuffer::samplesOf(target_.pass().framebuffer));
    }
    ShaderDefines defines;
    if (packedCentre) defines.push_back({"LIDR_CENTRE_PACKED", "1"});
    if (sideMoments) defines.push_back({"LIDR_SPAN_SIDES", "1"});
    program_ = gl::Program::create("depth-span", buildShaderSource("geometry.vert"),
                                   buildShaderSource("depth_span.frag", defines), geometryAttributes());
}

DepthSpanPass::DepthSpanPass(const GlInfo& info, const RenderTargets& targets, DepthSpanStorage storage) {
    if (storage != DepthSpanStorage::Samples) {
        *this = DepthSpanPass(info, targets, false, true);
        return;
    }
    width_ = targets.width();
    height_ = targets.height();
    samples_ = targets.samples();
    if (samples_ < 2) throw Error("the MSAA depth spans need multisampled targets");
    // The same sample count as the depth-stencil renderbuffer (a driver rounds both requests alike; the
    // completeness check says where it does not).
    sampleDistances_ = gl::Texture::create2DMultisample(GL_R32F, width_, height_, samples_);
    sampleFbo_ = gl::Framebuffer::create();
    sampleFbo_.attachTexture(GL_COLOR_ATTACHMENT0, sampleDistances_);
    sampleFbo_.attachDepthStencil(targets.multisampleDepthStencil(), targets.multisampleSeparateStencil());
    sampleFbo_.requireComplete("a multisample R32F texture with the MSAA depth-stencil (--msaa-spans samples)",
                               info.renderer);
    samples_ = std::max(samples_, sampleFbo_.samples());
    program_ = gl::Program::create("depth-span-samples", buildShaderSource("geometry.vert"),
                                   buildShaderSource("depth_span.frag", {{"LIDR_SAMPLE_DISTANCES", "1"}}),
                                   geometryAttributes());
    triangle_ = FullScreenTriangle::create();
}

void DepthSpanPass::run(const GpuScene& scene, const CameraMatrices& camera, const gl::Texture& centreDepth) const {
    ClearAction clear;
    clear.color = true;  // 0: a sample no surface covers adds nothing to either bound (and has no distance)
    clear.depth = clear.stencil = true;
    StateCache& cache = StateCache::current();
    packedWritten_ = false;
    if (sampleDistances_)
        cache.beginPass({sampleFbo_.id(), glm::ivec4(0, 0, width_, height_), {GL_COLOR_ATTACHMENT0}, clear});
    else
        cache.beginPass(sides_ ? sides_.pass(clear) : target_.pass(clear));
    // The MSAA pre-pass itself (as DepthPrepass, the same vertex shader: the forward pass's EQUAL test holds):
    // the nearest fragment of each sample writes last. LEQUAL: at a depth tie the last fragment drawn writes, the
    // one whose colour the forward pass's EQUAL test keeps, so a sample's value is that of the surface it shows.
    RenderState s;
    s.depthTest = true;
    s.depthFunc = GL_LEQUAL;
    s.depthWrite = true;
    cache.apply(s);
    program_.use();
    program_.set("uViewProj", camera.viewProjection);
    program_.set("uDepth", gl::kUnitDepthCopy);
    program_.set("uInvTargetSize", 1.0f / glm::vec2(float(width_), float(height_)));
    program_.set("uStoreScale", kStoreScale);
    // Window depth to view distance, as the volume pass converts it (perspective: P[2][3] = -1).
    const glm::mat4& P = camera.projection;
    if (P[2][3] != -1.0f || P[3][3] != 0.0f) throw Error("the MSAA depth spans need a perspective projection");
    depthToDistance_ = glm::vec2(0.5f * P[3][2], 0.5f * (P[2][2] - 1.0f));
    if (sides_) {
        momentScale_ = 64.0f / camera.farPlane;  // x <= 64 before the far plane: x^2 fits half floats
        program_.set("uDepthToDistance", depthToDistance_);
        program_.set("uMomentScale", momentScale_);
        program_.set("uSideMargin", kSideMargin);
    }
    centreDepth.bind(gl::kUnitDepthCopy);
    scene.draw(program_, DrawFilter::Opaque, false, &camera);
    cache.apply(RenderState{});
    if (sides_)
        sides_.resolve();
    else if (target_)
        target_.resolve();
    else
        cache.bindFramebuffer(0);
    checkGl("MSAA depth spans");
}

std::vector<ImageFloat> DepthSpanPass::readSampleDepths() const {
    if (!sampleDistances_) throw Error("readSampleDepths: the spans are not stored per sample");
    if (!packedWritten_) throw Error("readSampleDepths: writeCentreDepth did not run after this frame's MSAA pre-pass");
    std::vector<ImageFloat> depths;
#ifndef __EMSCRIPTEN__
    StateCache& cache = StateCache::current();
    cache.bindFramebuffer(centreFbo_.id());
    std::vector<float> rgba(size_t(width_) * size_t(height_) * 4);
    auto depthAt = [&](float distance) {  // view distance -> window depth (1: no surface)
        return distance > 0.0f ? std::clamp(depthToDistance_.x / distance - depthToDistance_.y, 0.0f, 1.0f) : 1.0f;
    };
    for (int t = 0; t < packedTextureCount(); ++t) {  // four samples a texel, one per channel
        glReadBuffer(GLenum(kPackedAttachment + t));
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, rgba.data());
        for (int c = 0; c < 4 && 4 * t + c < samples_; ++c) {
            ImageFloat d(width_, height_);
            for (int y = 0; y < height_; ++y)
                for (int x = 0; x < width_; ++x)
                    d.at(x, y) = depthAt(rgba[(size_t(height_ - 1 - y) * size_t(width_) + size_t(x)) * 4 + size_t(c)]);
            depths.push_back(std::move(d));
        }
    }
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    cache.bindFramebuffer(0);
    checkGl("MSAA sample distances read-back");
#endif
    return depths;
}

gl::Program DepthSpanPass::centreProgram(bool ranges) const {
    ShaderDefines defines = {{"LIDR_SPAN_SAMPLES", std::to_string(samples_)}};
    if (ranges) defines.push_back({"LIDR_SPAN_RANGES", "1"});
    return gl::Program::create(ranges ? "depth-span-centre-ranges" : "depth-span-centre",
                               buildShaderSource("fullscreen.vert"),
                               perSampleGlsl150(buildShaderSource("depth_span_centre.frag", defines), false),
                               {{"aPosition", gl::kPosition}});
}

void DepthSpanPass::writeCentreDepth(const gl::Renderbuffer& depthStencil, const gl::Renderbuffer* separateStencil,
                                     bool ranges) const {
    if (!sampleDistances_) throw Error("writeCentreDepth: the spans are not stored per sample");
#ifndef __EMSCRIPTEN__
    if (!centreFbo_) {
        // The ranges' two R32F textures (read back straight into the two arrays VolumeTiles takes) and the packed
        // distances with the targets' single-sample depth-stencil: one pass writes them all.
        centreFbo_ = gl::Framebuffer::create();
        for (int i = 0; i < 2; ++i) {
            rangeTextures_[i] = gl::Texture::create2D(GL_R32F, width_, height_, GL_RED, GL_FLOAT);
            centreFbo_.attachTexture(GLenum(GL_COLOR_ATTACHMENT0 + i), rangeTextures_[i]);
        }
        for (int t = 0; t < packedTextureCount(); ++t) {
            packedDistances_[t] = gl::Texture::create2D(GL_RGBA32F, width_, height_, GL_RGBA, GL_FLOAT);
            centreFbo_.attachTexture(GLenum(kPackedAttachment + t), packedDistances_[t]);
        }
        centreFbo_.attachDepthStencil(depthStencil, separateStencil);
        centreFbo_.checkComplete("MSAA depth ranges (R32F) and packed sample distances (RGBA32F) with the "
                                 "single-sample depth-stencil");
    }
    gl::Program& program = ranges ? centreRangeProgram_ : centreProgram_;
    if (!program) program = centreProgram(ranges);
    // Depth and stencil cleared as a pre-pass clears them; the colour targets need no clear: the pass writes every
    // pixel ((1, 1) in the ranges where no sample has a surface).
    ClearAction clear;
    clear.depth = clear.stencil = true;
    std::vector<GLenum> buffers(2, GLenum(GL_NONE));
    if (ranges) buffers = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    for (int t = 0; t < packedTextureCount(); ++t) buffers.push_back(GLenum(kPackedAttachment + t));
    StateCache& cache = StateCache::current();
    cache.beginPass({centreFbo_.id(), glm::ivec4(0, 0, width_, height_), buffers, clear});
    RenderState s;
    s.depthTest = true;
    s.depthFunc = GL_ALWAYS;
    s.depthWrite = true;
    cache.apply(s);
    program.use();
    sampleDistances_.bind(gl::kUnitDepthSpans);
    program.set("uSampleDistances", gl::kUnitDepthSpans);
    program.set("uDepthToDistance", depthToDistance_);
    triangle_.draw();
    cache.apply(RenderState{});
    cache.bindFramebuffer(0);
    rangesWritten_ = ranges;
    packedWritten_ = true;
    checkGl("MSAA sample distances: the centre's depth");
#else
    (void)depthStencil;
    (void)separateStencil;
    (void)ranges;
#endif
}

void DepthSpanPass::readDepthRanges(std::vector<float>& nearDepth, std::vector<float>& farDepth) const {
    if (!rangesWritten_) throw Error("readDepthRanges: writeCentreDepth did not write this frame's ranges");
#ifndef __EMSCRIPTEN__
    rangesWritten_ = false;
    StateCache& cache = StateCache::current();
    cache.bindFramebuffer(centreFbo_.id());
    const size_t pixels = size_t(width_) * size_t(height_);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    for (int i = 0; i < 2; ++i) {
        std::vector<float>& out = i == 0 ? nearDepth : farDepth;
        out.resize(pixels);
        glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + i));
        glReadPixels(0, 0, width_, height_, GL_RED, GL_FLOAT, out.data());
    }
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    cache.bindFramebuffer(0);
    checkGl("MSAA depth ranges read-back");
#else
    (void)nearDepth;
    (void)farDepth;
#endif
}

void DepthSpanPass::readResolvedSpans(std::vector<float>& rgba) const {
    rgba.resize(size_t(width_) * size_t(height_) * 4);
#ifdef __EMSCRIPTEN__
    // WebGL 1 has neither glGetTexImage nor MSAA render targets: no spans are drawn there to read.
    throw Error("DepthSpanPass: WebGL 1 has no MSAA, so there are no depth spans to read back");
#else
    texture().bind(0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, rgba.data());
    checkGl("MSAA depth spans read-back");
#endif
}

glm::vec2 DepthSpanPass::spanEnds(float centre, const float* texel) const {
    const float past = texel[0] * boundScale(), before = texel[1] * boundScale();
    // Anchored at the centre's depth, or at 0 (past) and 1 (before) where the centre sees no surface.
    return centre < 1.0f ? glm::vec2(centre - before, centre + past) : glm::vec2(1.0f - before, std::min(past, 1.0f));
}

void DepthSpanPass::readMomentRanges(const std::vector<float>& centre, std::vector<float>& nearDepth,
                                     std::vector<float>& farDepth) const {
    if (sampleDistances_) throw Error("readMomentRanges: the spans are stored per sample (readDepthRanges)");
    const size_t pixels = size_t(width_) * size_t(height_);
    if (centre.size() != pixels) throw Error("readMomentRanges: the centre depth's size differs from the spans'");
    readResolvedSpans(spansReadback_);
    nearDepth.resize(pixels);
    farDepth.resize(pixels);
    const glm::vec2 toDistance = depthToDistance_;  // d -> x / (d + y); back: x / distance - y
    auto widened = [&](float d, float factor) {
        const float distance = toDistance.x / (std::clamp(d, 0.0f, 1.0f) + toDistance.y) * factor;
        return std::clamp(toDistance.x / distance - toDistance.y, 0.0f, 1.0f);
    };
    for (size_t i = 0; i < pixels; ++i) {
        const glm::vec2 ends = spanEnds(centre[i], &spansReadback_[i * 4]);
        if (centre[i] >= 1.0f && ends.y <= 0.0f) {  // no sample shades a surface
            nearDepth[i] = farDepth[i] = 1.0f;
            continue;
        }
        nearDepth[i] = widened(ends.x, 1.0f - 1.0f / 4096.0f);
        farDepth[i] = widened(ends.y, 1.0f + 1.0f / 4096.0f);
    }
}

std::vector<DepthSpanPass::Span> DepthSpanPass::readSpans(const ImageFloat& centre) const {
    if (sampleDistances_) throw Error("readSpans: the spans are stored per sample (readSampleDepths)");
    if (centre.width != width_ || centre.height != height_) throw Error("readSpans: depth image size differs");
    std::vector<float> rgba;
    readResolvedSpans(rgba);
    std::vector<Span> spans(rgba.size() / 4);
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const size_t texel = (size_t(height_ - 1 - y) * size_t(width_) + size_t(x)) * 4;  // bottom to top
            const glm::vec2 ends = spanEnds(centre.at(x, y), &rgba[texel]);
            Span& s = spans[size_t(y) * size_t(width_) + size_t(x)];
            s.nearDepth = ends.x;
            s.farDepth = ends.y;
            s.past.samples = int(std::lround(rgba[texel + 2] * float(samples_)));
            s.before.samples = int(std::lround(rgba[texel + 3] * float(samples_)));
        }
    if (sides_) readSides(spans, centre);
    return spans;
}

void DepthSpanPass::readSides(std::vector<Span>& spans, const ImageFloat& centre) const {
#ifndef __EMSCRIPTEN__
    std::vector<float> moments(spans.size() * 4);
    sideTexture().bind(0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, moments.data());
    checkGl("MSAA depth span sides read-back");
    const glm::vec2 rounding = sideRounding();
    const float n = float(samples_);
    auto depthAt = [&](float distance) {  // view distance -> window depth
        return distance > 0.0f ? std::clamp(depthToDistance_.x / distance - depthToDistance_.y, 0.0f, 1.0f) : 0.0f;
    };
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const float* m = &moments[(size_t(height_ - 1 - y) * size_t(width_) + size_t(x)) * 4];
            const float d = centre.at(x, y);
            const float centreDistance = d < 1.0f ? depthToDistance_.x / (d + depthToDistance_.y) : 0.0f;
            Span& s = spans[size_t(y) * size_t(width_) + size_t(x)];
            for (int side = 0; side < 2; ++side) {
                Side& t = side == 0 ? s.past : s.before;
                if (t.samples == 0) continue;
                const float sign = side == 0 ? 1.0f : -1.0f, m1 = m[side * 2], m2 = m[side * 2 + 1];
                const glm::vec2 b = sideBounds(float(t.samples), n, m1, m2, rounding) / momentScale_;
                const float extreme = m1 > 0.0f ? m2 / m1 / momentScale_ : 0.0f;
                const float a = depthAt(centreDistance + sign * b.x), c = depthAt(centreDistance + sign * b.y);
                t.nearDepth = std::min(a, c);
                t.farDepth = std::max(a, c);
                t.surfaceDepth = depthAt(centreDistance + sign * extreme);
                const float mean = m1 * n / float(t.samples);
                t.severalSurfaces = m2 * n / float(t.samples) - mean * mean > 1e-4f * mean * mean + rounding.y;
            }
        }
#else
    (void)spans;
    (void)centre;
#endif
}

}  // namespace lidr
