#pragma once
// How many lights overlap on screen, measured on the GPU without reading pixels back: after a volume pass
// the stencil holds each pixel's count of lights that mark it (saturating at 255). One full-screen
// triangle per threshold t, stencil-tested "count > t" with colour and depth off, inside an occlusion query,
// counts the pixels over t. The automatic budget (lidr/technique/auto_configuration.h) reads them.
#include <array>

#include "lidr/gl/gl_info.h"
#include "lidr/gl/full_screen_triangle.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/gl_state.h"
#include "lidr/render/depth_prepass.h"
#include "lidr/render/gpu_scene.h"
#include "lidr/scene/camera.h"

namespace lidr {

class OverlapProbe {
public:
    static constexpr int kThresholds = 6;
    static constexpr std::array<int, kThresholds> kThreshold = {1, 2, 4, 8, 16, 32};  // the budgets lidr has

    OverlapProbe() = default;
    // depth: the depth precision the probe over transparent meshes emulates (LidrOptions::emulatedDepthBits).
    explicit OverlapProbe(const GlInfo& info, DepthEmulation depth = {});
    explicit operator bool() const { return static_cast<bool>(program_); }
    static constexpr unsigned kAll = (1u << kThresholds) - 1u;
    // The thresholds that tell whether `budget` was too small or twice what was needed: budget / 2 and budget.
    static unsigned aroundBudget(int budget);
    // Only the threshold that tells whether `budget` was too small.
    static unsigned atBudget(int budget);
    // The thresholds above `budget` (to find how much more an overflowing frame needs).
    static unsigned aboveBudget(int budget);
    // Issues the queries of the thresholds in `which` (bit i: kThreshold[i]) over the bound framebuffer (its
    // stencil holds the counts), within `scissor` when given (x, y, width, height). Leaves the stencil unchanged.
    void issue(unsigned which = kAll, const glm::ivec4* scissor = nullptr);
    // Per threshold, where pixels over it can be (x, y, width, height): width < 0 anywhere, 0 nowhere (that
    // threshold's answer is 0 without a draw), else its draw is scissored to the box. LidrRenderer takes them from
    // the tile-culled volume pass's per-tile bound on the lights that may mark a pixel.
    using Areas = std::array<glm::ivec4, kThresholds>;
    void issue(unsigned which, const Areas& areas);
    // The same over the pixels where `filter`'s meshes are visible (depth-tested against the bound depth, not
    // written): the transparent layers read their lists only there, so only there does their overlap count.
    void issueOverMeshes(const GpuScene& scene, DrawFilter filter, const CameraMatrices& camera, unsigned which = kAll,
                         const glm::ivec4* scissor = nullptr);
    bool issued() const { return issued_ != 0; }
    // Pixels whose count exceeds kThreshold[i] for the thresholds last issued, -1 for the others; waits for the GPU.
    std::array<long, kThresholds> pixelsAbove() const;
    // From counts where -1 means "not measured": the smallest measured threshold no pixel exceeds (the frame
    // needs at most that budget); 0 when the largest, 32, is exceeded; -1 when every measured threshold is
    // exceeded but larger ones were not measured.
    static int smallestBudget(const std::array<long, kThresholds>& above);
    // The thresholds a later measurement `more` took (not -1) written over `into`'s (an overflowing frame's
    // second question, "how far over", completes its first).
    static void merge(std::array<long, kThresholds>& into, const std::array<long, kThresholds>& more);
    long drawCalls() const { return drawCalls_; }

private:
    RenderState stateFor(const glm::ivec4* scissor) const;
    gl::Program program_, meshProgram_;
    FullScreenTriangle triangle_;
    std::array<gl::Object, kThresholds> queries_;
    unsigned issued_ = 0;
    unsigned knownZero_ = 0;  // thresholds issued without a draw: no pixel can exceed them
    long drawCalls_ = 0;
};

}  // namespace lidr
