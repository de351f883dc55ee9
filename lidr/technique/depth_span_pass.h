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
#include <vector>

#include "lidr/base/image.h"
#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/half_float_target.h"
#include "lidr/gl/render_targets.h"
#include "lidr/render/gpu_scene.h"
#include "lidr/scene/camera.h"

namespace lidr {

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
    DepthSpanPass(const GlInfo& info, const RenderTargets& targets, bool packedCentre = false);
    explicit operator bool() const { return bool(target_); }

    // After the single-sample pre-pass (centreDepth: its copy): clears and draws the MSAA depth-stencil of the
    // targets (the MSAA pre-pass) with the spans in colour, and resolves them. Leaves framebuffer 0 bound.
    void run(const GpuScene& scene, const CameraMatrices& camera, const gl::Texture& centreDepth) const;
    // The resolved spans (r: past the anchor, g: before it, times kStoreScale, averaged over the samples).
    const gl::Texture& texture() const { return target_.texture(); }
    // What turns a resolved value into a bound on every sample's depth difference (the driver's sample count).
    float boundScale() const { return float(samples_) * kRoundingMargin / kStoreScale; }

    // CPU read-back of the last run (tests, evaluation): per pixel, rows top to bottom, the window depths
    // [near, far] the samples shade, from the centre depth `centre` (RenderTargets::readDepth()); near > far where
    // no sample shades a surface.
    struct Span {
        float nearDepth = 1.0f, farDepth = 0.0f;
        bool edge(float margin) const { return farDepth - nearDepth > margin; }
    };
    std::vector<Span> readSpans(const ImageFloat& centre) const;

private:
    int width_ = 0, height_ = 0, samples_ = 0;
    HalfFloatTarget target_;
    gl::Program program_;
};

}  // namespace lidr
