#include "lidr/modes/auto_mode_renderer.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "lidr/base/error.h"
#include "lidr/gl/frame_timer.h"
#include "lidr/scene/sphere_bounds.h"

namespace lidr {

namespace {
int visibleLights(const Camera& camera, const std::vector<PointLight>& lights, int width, int height) {
    const CameraMatrices cam = cameraMatrices(camera, width, height);
    int n = 0;
    for (const PointLight& l : lights) n += sphereMayBeVisible(cam, l.position, l.radius) ? 1 : 0;
    return n;
}
}  // namespace

AutoModeRenderer::AutoModeRenderer(const GlInfo& info, const Scene& scene, const RenderModeOptions& options, int width,
                                   int height, const AutoModeOptions& autoOptions)
    : options_(autoOptions) {
    if (options_.trialFrames < 2 || options_.trialFrames > 100)
        throw Error("auto mode: trial frames must be in [2, 100], got " + std::to_string(options_.trialFrames));
    if (options_.remeasureFrames < 1) throw Error("auto mode: remeasureFrames must be >= 1");
    if (!(options_.lightChange > 0.0)) throw Error("auto mode: lightChange must be > 0");
    candidates_ = {"lidr", "tiled", "clustered"};
    // Multi-pass forward draws no transparent layers: a candidate only where none is drawn.
    const bool transparentDrawn =
        options.transparency && std::any_of(scene.meshes.begin(), scene.meshes.end(), [&](const Mesh& m) {
            return m.material >= 0 && size_t(m.material) < scene.materials.size() &&
                   scene.materials[size_t(m.material)].opacity < 1.0f;
        });
    if (!transparentDrawn && options.msaaSamples == 0)
        candidates_.push_back("forward-multipass");
    for (const std::string& mode : candidates_) {
        RenderModeOptions o = options;
        o.mode = mode;
        renderers_.push_back(createRenderer(o, info, scene, width, height));
    }
    bestMs_.assign(candidates_.size(), 0.0);
    measured_.assign(candidates_.size(), false);
    dropped_.assign(candidates_.size(), false);
    overBudget_.assign(candidates_.size(), 0);
}

const FrameStats& AutoModeRenderer::render(const Camera& camera, const std::vector<PointLight>& lights,
                                           const ShadingParameters& shading) {
    const RenderTargets& t = renderers_[0]->targets();
    const int visible = visibleLights(camera, lights, t.width(), t.height());
    if (chosen_ >= 0) {
        ++framesSinceChoice_;
        const double change = std::abs(double(visible - lightsAtChoice_)) / std::max(1.0, double(lightsAtChoice_));
        if (framesSinceChoice_ >= options_.remeasureFrames || change > options_.lightChange) {
            chosen_ = -1;
            trial_ = 0;
            reason_ = "measuring";
        }
    }
    if (chosen_ >= 0) {
        last_ = chosen_;
        stats_ = renderers_[size_t(chosen_)]->render(camera, lights, shading);
        return stats_;
    }

    // A trial frame: the candidate's whole frame between two glFinish calls. The candidates take turns (A B C,
    // A B C, ...), so that a machine whose speed drifts during the trial (a shared CPU, a GPU's clocks) slows
    // them alike; each one's first turn is its warm-up (shader compiles, first uploads), the best of the rest
    // counts.
    const int n = int(candidates_.size());
    // Candidates already measured at over kDropFactor x the fastest sit out the remaining turns: a slow mode
    // (multi-pass on a many-light scene can take seconds a frame) costs one measured frame, not trialFrames - 1.
    while (trial_ < n * options_.trialFrames && dropped_[size_t(trial_ % n)]) ++trial_;
    const int candidate = trial_ % n, turn = trial_ / n;
    last_ = candidate;
    glFinish();
    const double start = nowMilliseconds();
    stats_ = renderers_[size_t(candidate)]->render(camera, lights, shading);
    glFinish();
    const double ms = nowMilliseconds() - start;
    if (turn == 1 || (turn > 1 && ms < bestMs_[size_t(candidate)])) bestMs_[size_t(candidate)] = ms;
    // A frame that says it dropped lights (LIDR: pixels over its largest budget) is not chosen while another
    // candidate draws the scene exactly.
    if (turn == 0) overBudget_[size_t(candidate)] = 0;
    overBudget_[size_t(candidate)] = std::max(overBudget_[size_t(candidate)], stats_.autoDecision.overflowPixels);
    if (turn >= 1) {
        measured_[size_t(candidate)] = true;
        double fastest = 0.0;
        for (int c = 0; c < n; ++c)
            if (measured_[size_t(c)] && (fastest == 0.0 || bestMs_[size_t(c)] < fastest)) fastest = bestMs_[size_t(c)];
        for (int c = 0; c < n; ++c)
            if (measured_[size_t(c)] && bestMs_[size_t(c)] > kDropFactor * fastest) dropped_[size_t(c)] = true;
    }
    ++trial_;
    while (trial_ < n * options_.trialFrames && dropped_[size_t(trial_ % n)]) ++trial_;
    if (trial_ >= n * options_.trialFrames) {
        trial_ = 0;
        std::fill(dropped_.begin(), dropped_.end(), false);
        std::fill(measured_.begin(), measured_.end(), false);
        const bool anyExact = std::find(overBudget_.begin(), overBudget_.end(), 0L) != overBudget_.end();
        chosen_ = -1;
        for (int c = 0; c < n; ++c)
            if ((!anyExact || overBudget_[size_t(c)] == 0) && (chosen_ < 0 || bestMs_[size_t(c)] < bestMs_[size_t(chosen_)]))
                chosen_ = c;
        framesSinceChoice_ = 0;
        lightsAtChoice_ = visible;
        std::ostringstream why;
        why << candidates_[size_t(chosen_)] << " fastest" << (anyExact ? " exact" : "") << " in trial frames:";
        for (size_t c = 0; c < candidates_.size(); ++c) {
            why << " " << candidates_[c] << " " << bestMs_[c] << " ms";
            if (overBudget_[c] > 0) why << " (" << overBudget_[c] << " pixels over its light budget)";
        }
        why << " (" << visible << " lights in view)";
        reason_ = why.str();
    }
    return stats_;
}

std::vector<GpuScene*> AutoModeRenderer::gpuScenes() {
    std::vector<GpuScene*> all;
    for (auto& r : renderers_)
        for (GpuScene* s : r->gpuScenes()) all.push_back(s);
    return all;
}

void AutoModeRenderer::checkObjectMaterial(const Material& material) const {
    for (const auto& r : renderers_) r->checkObjectMaterial(material);
}

ModeStatistics AutoModeRenderer::modeStatistics() const {
    return {"auto_mode",
            {modeStatistic("chosen", lastMode()), modeStatistic("reason", reason_),
             modeStatistic("candidates", candidates_)},
            "auto mode  " + reason_};
}

}  // namespace lidr
