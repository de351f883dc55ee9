#pragma once
// --mode auto: picks, by measuring, the fastest of the modes that draw this scene the same way (LIDR with its
// automatic configuration, tiled forward, clustered forward, and multi-pass forward where nothing transparent is
// drawn), and measures again when the frame changes enough to move the answer (doc/auto.md). A candidate whose
// trial frames report dropped lights (LIDR's pixels over its largest budget) is chosen only if every one does.
//
// A cost model calibrated once would be wrong on the next machine (llvmpipe and a discrete GPU rank the modes
// differently, doc/benchmarks.md), so the model is the machine itself: each candidate renders a few trial
// frames timed with glFinish, taking turns, and the fastest is kept. Trial frames are ordinary frames (every candidate draws the
// same image), so nothing is wasted but the glFinish.
#include <memory>
#include <string>
#include <vector>

#include "lidr/modes/render_mode.h"

namespace lidr {

struct AutoModeOptions {
    // Per candidate; the first is a warm-up (shader compiles, first uploads), the best of the rest counts. Five:
    // with the best of two, modes 10 % apart were ranked wrongly on the 2-core VM (doc/benchmarks.md, "Region-local
    // indices"); a candidate measured at over twice the fastest sits out its remaining turns.
    int trialFrames = 5;
    int remeasureFrames = 600;   // measure again after this many frames
    double lightChange = 0.25;   // ... or when the visible lights change by this fraction since the choice
};

class AutoModeRenderer final : public Renderer {
public:
    AutoModeRenderer(const GlInfo& info, const Scene& scene, const RenderModeOptions& options, int width, int height,
                     const AutoModeOptions& autoOptions = {});
    std::string modeName() const override { return "auto"; }
    const FrameStats& render(const Camera& camera, const std::vector<PointLight>& lights,
                             const ShadingParameters& shading) override;
    const FrameResources& frame() const override { return lastRenderer().frame(); }
    // Its frames are its candidates': the passes of the candidate that drew the last frame (lidr's before any).
    std::vector<FramePass> passes() const override { return lastRenderer().passes(); }
    size_t lightDataBytes() const override { return renderers_[size_t(last_)]->lightDataBytes(); }
    void setTiming(bool on, bool waitForResults = false) override {  // every candidate's pass times
        for (auto& r : renderers_) r->setTiming(on, waitForResults);
    }

    const std::vector<std::string>& candidates() const { return candidates_; }
    // The mode the last frame was drawn with, and why ("measuring", or the trial times).
    const std::string& lastMode() const { return candidates_[size_t(last_)]; }
    const std::string& reason() const { return reason_; }
    bool measuring() const { return chosen_ < 0; }
    ModeStatistics modeStatistics() const override;  // "auto_mode": chosen, reason, candidates
    // The renderer of a candidate, to inspect (e.g. the LidrRenderer's decisions).
    const Renderer& renderer(size_t candidate) const { return *renderers_[candidate]; }
    // The candidate that drew the last frame (its index lists, tiles and decisions are that frame's).
    const Renderer& lastRenderer() const { return *renderers_[size_t(last_)]; }

    std::vector<GpuScene*> gpuScenes() override;
    void checkObjectMaterial(const Material& material) const override;

private:
    AutoModeOptions options_;
    std::vector<std::string> candidates_;
    std::vector<std::unique_ptr<Renderer>> renderers_;
    std::vector<double> bestMs_;
    std::vector<bool> measured_, dropped_;  // this measurement: measured after its warm-up; sitting out
    std::vector<long> overBudget_;          // ... the most pixels over its light budget a trial frame reported
    static constexpr double kDropFactor = 2.0;
    int chosen_ = -1, last_ = 0;
    int trial_ = 0;  // trial frames drawn in this measurement (candidates in turn)
    int framesSinceChoice_ = 0, lightsAtChoice_ = 0;
    std::string reason_ = "measuring";
};

}  // namespace lidr
