#pragma once
// LIDR under MSAA (the sphere-span volume test): which depths the samples of each pixel shade. An interior pixel
// (every sample on the surface at its centre) shades one depth, and takes the single-sample `sphere` list; an
// edge pixel shades the surfaces its samples see, each at the pixel centre (a fragment runs once per pixel and
// primitive there), between a nearest and a farthest depth, and takes the lights whose sphere meets the eye ray
// between those two. GL 2.1 reads no sample of a multisampled buffer, so the pass writes, per sample, how far
// its surface's depth lies from the centre's (past and before), and the resolve averages them: times the sample
// count each bound holds for every sample. The pass is the MSAA depth pre-pass (depth LESS with writes into the
// targets' multisampled depth-stencil, the forward pass then tests EQUAL) with these colours written, and one
// resolve; exact, with no neighbourhood guess and no sub-pixel fallback. doc/msaa-transparency.md, "Edge pixels".
// With side moments (LIDR's lists) a second target holds, per side of the centre (samples past it, samples before
// it), the first two moments of the samples' distance excess, and the first target's b/a how many samples lie on
// each side: the resolve then bounds each side's samples between Samuelson's bounds (mean -/+ deviation x
// sqrt(k - 1) over its k samples), a point (up to rounding) where they lie on one surface.
// With sample distances (GL 3.2 multisample textures) the pass writes each sample's shaded distance into a
// multisampled R32F texture and nothing is resolved; the full-screen centre pass then copies them, four samples a
// texel, into one or two single-sample RGBA32F textures, which the volume pass (one fetch instead of one per
// sample) and the forward pass's hidden-fragment skip read: the light is tested against each sample's point, so an
// edge pixel's list is exactly its samples' surfaces' lights.
#include <string>
#include <vector>

#include "lidr/base/image.h"
#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/float_targets.h"
#include "lidr/gl/full_screen_triangle.h"
#include "lidr/gl/half_float_target.h"
#include "lidr/gl/render_targets.h"
#include "lidr/render/gpu_scene.h"
#include "lidr/scene/camera.h"

namespace lidr {

// Samuelson's bounds on one side's k samples (k >= 1) from the resolved means over all n samples m1 = E[x] and
// m2 = E[x^2], first widened by their rounding (relative, absolute): every sample's x lies in the returned
// [lowest, highest] (mean -/+ deviation x sqrt(k - 1)); a point, up to rounding, where they are all equal. The
// volume shader (light_volume_sphere.frag, lidrSideBounds) computes the same.
glm::vec2 sideBounds(float k, float n, float m1, float m2, glm::vec2 rounding);

// How sphere-span learns the surfaces of a pixel's samples (LidrOptions::msaaSpans, --msaa-spans).
enum class DepthSpanStorage {
    Auto,     // Samples where the context has them, else Moments
    Samples,  // each sample's shaded distance in a multisample texture (GL 3.2 / ARB_texture_multisample, GLSL 1.50)
    Moments,  // GL 2.1: per-side counts and moments, resolved into float targets (Samuelson's bounds)
};
const char* depthSpanStorageName(DepthSpanStorage s);  // "auto", "samples", "moments"
DepthSpanStorage parseDepthSpanStorage(const std::string& name);  // throws lidr::Error naming the choices
// Auto resolved for a context and sample count; Samples asked for where the context lacks multisample float
// textures of that many samples or GLSL 1.50 throws UnsupportedError naming what is missing.
DepthSpanStorage resolveDepthSpanStorage(DepthSpanStorage requested, const GlInfo& info, int samples);

class DepthSpanPass {
public:
    // Stored values are depth differences times this (half floats keep small values better scaled up).
    static constexpr float kStoreScale = 1024.0f;
    // A resolved mean times (samples x this) bounds each sample's value, half-float rounding included.
    static constexpr float kRoundingMargin = 1.0f + 1.0f / 128.0f;

    DepthSpanPass() = default;
    // Throws UnsupportedError where the context has no float colour buffers (GlInfo::halfFloatColorBuffer) or
    // `targets` are not multisampled. packedCentre: run() takes the centre depth packed in RGBA8
    // (shaders/modes/depth_pack.glsl: tiled forward's pre-Z copy) instead of a depth texture.
    // sideMoments: also the per-side counts and moments (LIDR's volume pass; tiled forward's bounds need none).
    DepthSpanPass(const GlInfo& info, const RenderTargets& targets, bool packedCentre = false, bool sideMoments = false);
    // LIDR's lists: Moments (the constructor above with side moments) or Samples (resolved, not Auto); Samples
    // throws UnsupportedError where the driver does not answer complete for the multisample texture.
    DepthSpanPass(const GlInfo& info, const RenderTargets& targets, DepthSpanStorage storage);
    explicit operator bool() const { return bool(target_) || bool(sides_) || bool(sampleDistances_); }

    // Sample distances: per sample the view distance of the point its fragment shades (at the pixel centre,
    // where the forward pass shades it), 0 where no surface covers it. At most kMaxPackedSamples samples (the
    // packed copies below): more take the moments (resolveDepthSpanStorage).
    static constexpr int kMaxPackedSamples = 8;
    bool storesSamples() const { return bool(sampleDistances_); }
    // After writeCentreDepth: the same distances four samples a texel (samples 4i .. 4i + 3 in texture i, 0 beyond
    // the sample count), single-sample RGBA32F, read with one texelFetch (shaders/technique/sample_distances.glsl).
    int packedTextureCount() const { return (samples_ + 3) / 4; }
    const gl::Texture& packedTexture(int i) const { return packedDistances_[size_t(i)]; }
    // CPU read-back (tests, evaluation) after writeCentreDepth: per sample an image of window depths, rows top to
    // bottom (1: no surface).
    std::vector<ImageFloat> readSampleDepths() const;
    // With sample distances, after run(): sample 0's point as the single-sample depth, the centre the sphere tests
    // read, into `depthStencil` (the targets' single-sample depth-stencil, RenderTargets::depthStencil(); cleared
    // first, stencil too): one full-screen pass in place of the single-sample depth pre-pass, which also writes
    // the packed distances. With `ranges` (tile-culled frames) the same pass also keeps each pixel's depth range
    // for readDepthRanges. Leaves framebuffer 0 bound.
    void writeCentreDepth(const gl::Renderbuffer& depthStencil, const gl::Renderbuffer* separateStencil,
                          bool ranges) const;
    // Tile-culled volumes under MSAA (after writeCentreDepth with ranges, this frame): per pixel, rows bottom to top
    // as glReadPixels gives them, the nearest and farthest window depth of its samples' points (the centre's is
    // sample 0's), widened as the volume shader widens them; 1 in both where the pixel has none
    // (VolumeTiles::buildRanges).
    void readDepthRanges(std::vector<float>& nearDepth, std::vector<float>& farDepth) const;
    // The same with the moments (GL 2.1), after run(): from the pixel centres' window depths `centre` (rows bottom
    // to top, 1 where the centre sees no surface: the single-sample pre-pass, VolumeTiles::readBoundDepth) and the
    // resolved spans, each pixel's [centre - before, centre + past] (from 0 past and 1 before where the centre
    // sees none), which holds every sample's point, widened by 1/4096 of its distance as the volume shader widens
    // its sides; 1 in both where no sample has a surface.
    void readMomentRanges(const std::vector<float>& centre, std::vector<float>& nearDepth,
                          std::vector<float>& farDepth) const;

    // After the single-sample pre-pass (centreDepth: its copy): clears and draws the MSAA depth-stencil of the
    // targets (the MSAA pre-pass) with the spans in colour, and resolves them. Leaves framebuffer 0 bound.
    void run(const GpuScene& scene, const CameraMatrices& camera, const gl::Texture& centreDepth) const;
    // The resolved spans (r: past the anchor, g: before it, times kStoreScale, averaged over the samples).
    const gl::Texture& texture() const { return sides_ ? sides_.texture(0) : target_.texture(); }  // not with samples
    // What turns a resolved value into a bound on every sample's depth difference (the driver's sample count).
    float boundScale() const { return float(samples_) * kRoundingMargin / kStoreScale; }

    // Side moments: a sample more than kSideMargin (window depth) past (before) the centre's depth is on the far
    // (near) side; texture() b/a: the fraction of samples on each; sideTexture(): per side (rg: past, ba: before)
    // the mean over all samples of x and x^2, x = the sample's distance (view depth) from the centre's times
    // momentScale() (the centre's distance is 0 where it sees no surface). Half-float (where the context has no
    // RGBA32F target) or float: sideRounding() = (relative, absolute) error bound of a resolved mean.
    static constexpr float kSideMargin = 1e-6f;
    bool hasSides() const { return bool(sides_); }
    const gl::Texture& sideTexture() const { return sides_.texture(1); }
    float momentScale() const { return momentScale_; }
    glm::vec2 sideRounding() const;
    static glm::vec2 sideRoundingOf(bool halfFloat);
    int samples() const { return samples_; }
    // Window depth d -> view distance x / (d + y) of the last run's (perspective) camera.
    glm::vec2 depthToDistance() const { return depthToDistance_; }

    // CPU read-back of the last run (tests, evaluation): per pixel, rows top to bottom, the window depths
    // [near, far] the samples shade, from the centre depth `centre` (RenderTargets::readDepth()); near > far where
    // no sample shades a surface.
    struct Side {
        int samples = 0;                          // samples on this side (0: none)
        float nearDepth = 1.0f, farDepth = 0.0f;  // window depths the volume pass's bounds give its samples
        // The side's extreme sample as far as the moments tell: the farthest (past side) or nearest (before side)
        // lies at or beyond it (E[x^2] / E[x]); exactly there where the side's samples lie on one surface.
        float surfaceDepth = 1.0f;
        bool severalSurfaces = false;             // the side's samples lie at more than one depth
    };
    struct Span {
        float nearDepth = 1.0f, farDepth = 0.0f;
        Side past, before;  // with side moments
        bool edge(float margin) const { return farDepth - nearDepth > margin; }
    };
    std::vector<Span> readSpans(const ImageFloat& centre) const;

private:
    void readSides(std::vector<Span>& spans, const ImageFloat& centre) const;
    // The resolved spans texture, RGBA floats, rows bottom to top (readSpans, readMomentRanges).
    void readResolvedSpans(std::vector<float>& rgba) const;
    // A pixel's [near, far] window depths from its centre's depth and its resolved texel (r: past, g: before).
    glm::vec2 spanEnds(float centre, const float* texel) const;
    gl::Program centreProgram(bool ranges) const;

    int width_ = 0, height_ = 0, samples_ = 0;
    HalfFloatTarget target_;  // without side moments
    FloatTargets sides_;      // with them: the spans (0) and the moments (1)
    gl::Texture sampleDistances_;   // with sample distances: the multisample R32F texture
    gl::Framebuffer sampleFbo_;     // ... with the targets' multisampled depth-stencil
    mutable gl::Program centreProgram_, centreRangeProgram_;  // writeCentreDepth without and with ranges
    // The ranges' near and far R32F textures (attachments 0, 1) and the packed distances (2, 3) with the
    // single-sample depth-stencil.
    mutable gl::Framebuffer centreFbo_;
    mutable bool rangesWritten_ = false;  // writeCentreDepth wrote ranges since the last readDepthRanges
    mutable bool packedWritten_ = false;  // writeCentreDepth ran since run()
    mutable gl::Texture rangeTextures_[2];
    mutable gl::Texture packedDistances_[2];
    mutable std::vector<float> spansReadback_;  // readMomentRanges' read of the resolved spans
    FullScreenTriangle triangle_;
    mutable float momentScale_ = 1.0f;
    mutable glm::vec2 depthToDistance_{1.0f, 0.0f};
    gl::Program program_;
};

}  // namespace lidr
