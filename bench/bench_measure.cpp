#include "bench_measure.h"

#include "frame_accuracy.h"

#include <algorithm>
#include <csignal>
#include <cstdio>

#include "lidr/base/gl.h"
#include "lidr/eval/bench_scenes.h"
#include "lidr/eval/frame_evaluation.h"
#include "lidr/eval/light_coverage.h"
#include "lidr/modes/auto_mode_renderer.h"
#include "lidr/modes/clustered_renderer.h"
#include "lidr/modes/tiled_renderer.h"
#include "lidr/technique/lidr_renderer.h"

namespace lidr::bench {

// ---- measuring -------------------------------------------------------------------------------------------
struct Reference {
    ImageRGBA8 image;
    int maxOverlap = 0;
};

struct Measured {
    std::vector<FrameStats> frames;
    std::vector<double> wallMs;
    int warmupFrames = 0;
};

constexpr int kMaxWarmupFrames = 1000;

// One configuration of a scene set.
struct Slot {
    const Run* run = nullptr;
    std::unique_ptr<Renderer> renderer;
    Measured m;
    std::vector<double> roundMs;  // frame time per round (empty for `once`)
    std::vector<double> ratios;   // over the baseline's frame time in the same round
    bool once = false;  // its first frame took longer than maxSeconds / frames: that frame is its one measurement
    // Shadow maps drawn by its first frame (with that pass's time) and at most by any frame after it: a static
    // scene draws its maps once, so the later frames draw 0 (doc/shadows.md).
    int shadowMapsFirst = -1, shadowMapsLater = 0;
    double shadowMapsFirstMs = 0.0;
    void noteShadowMaps() {
        const FrameStats& f = renderer->lastFrame();
        if (shadowMapsFirst >= 0) {
            shadowMapsLater = std::max(shadowMapsLater, f.shadowMapsDrawn);
            return;
        }
        shadowMapsFirst = f.shadowMapsDrawn;
        for (const PassTime& p : f.passes)  // the bench's renderers wait for their timings: this frame's own
            if (p.pass == "shadow-maps") shadowMapsFirstMs = p.milliseconds;
    }
};

namespace {
// ---- interruption: SIGINT/SIGTERM finish the current row, then the outputs are written -----------------
volatile std::sig_atomic_t g_stop = 0;
extern "C" void onSignal(int) { g_stop = 1; }
void installSignals() {
    struct sigaction sa {};
    sa.sa_handler = onSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND;  // a second signal ends the process the default way
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
}



// The scene's shading, shadows on where a light casts (the -shadows-K scenes, scene files' "shadow"): one 4096^2
// atlas of 128-texel tiles, 1,024 maps, room for 128 point lights' 768 (doc/shadows.md, "Casters, tools and cost").
ShadingParameters benchShading(const Scene& scene) {
    ShadingParameters shading = sceneShading(scene);
    shading.shadows.enabled =
        std::any_of(scene.lights.begin(), scene.lights.end(), [](const PointLight& l) { return l.castsShadow; });
    shading.shadows.atlas.size = 4096;
    shading.shadows.atlas.tileSize = 128;
    return shading;
}

// Renders one frame and waits for it; returns the wall time in ms.
double renderFrame(Renderer& renderer, const Scene& scene, const std::vector<PointLight>& lights) {
    const double t0 = nowMilliseconds();
    renderer.render(scene.camera, lights, benchShading(scene));
    glFinish();
    return nowMilliseconds() - t0;
}

// Warm-up of one configuration: at least s.warmup frames and s.warmupMs after the first frame (which compiles
// shaders and uploads). `firstWallMs` >= 0: the first frame was already rendered (the reference image) and
// took that long. A first frame over `onceMs` is the configuration's one measured frame: it sits out the
// rounds (brute force over thousands of lights: shader compiles are a rounding error of such a frame).
void warmUp(Slot& slot, const Scene& scene, const std::vector<PointLight>& lights, const Settings& s, double onceMs,
            double firstWallMs) {
    double warmupStart = nowMilliseconds();
    for (int i = 0; !g_stop && i < kMaxWarmupFrames &&
                    (i < s.warmup || (s.warmupMs > 0.0 && (i == 0 || nowMilliseconds() - warmupStart < s.warmupMs)));
         ++i) {
        const bool rendered = !(i == 0 && firstWallMs >= 0.0);  // else noted with the reference frame
        const double wall = rendered ? renderFrame(*slot.renderer, scene, lights) : firstWallMs;
        if (rendered) slot.noteShadowMaps();
        if (i == 0 && wall > onceMs) {
            slot.once = true;
            slot.m.frames.push_back(slot.renderer->lastFrame());
            slot.m.wallMs.push_back(wall);
            return;
        }
        ++slot.m.warmupFrames;
        if (i == 0) warmupStart = nowMilliseconds();
    }
    // --mode auto times each candidate in trial frames: those belong to the warm-up, not to the rounds.
    if (auto* autoMode = dynamic_cast<AutoModeRenderer*>(slot.renderer.get()))
        for (int i = 0; !g_stop && autoMode->measuring() && i < kMaxWarmupFrames; ++i) {
            renderFrame(*slot.renderer, scene, lights);
            slot.noteShadowMaps();
            ++slot.m.warmupFrames;
        }
}

void fillTiming(Row& row, const Measured& m) {
    row.warmupFrames = m.warmupFrames;
    row.frames = int(m.frames.size());
    row.timingMethod = m.frames.back().timingMethod;
    std::vector<double> frame, vol;
    std::vector<std::string> order;
    std::map<std::string, std::vector<double>> perPass;
    for (const FrameStats& f : m.frames) {
        frame.push_back(f.frameMilliseconds());
        double v = 0.0;
        for (const PassTime& p : f.passes) {
            if (!perPass.count(p.pass)) order.push_back(p.pass);
            perPass[p.pass].push_back(p.milliseconds);
            if (p.pass.rfind("light-volumes", 0) == 0) v += p.milliseconds;
        }
        vol.push_back(v);
    }
    row.frameMs = Stat::of(frame);
    row.wallMs = Stat::of(m.wallMs);
    row.lightVolumeMs = Stat::of(vol).median;
    for (const std::string& p : order) {
        PassStat stat{p, Stat::of(perPass[p])};
        for (const PassTime& last : m.frames.back().passes)
            if (last.pass == p) stat.drawCalls = last.drawCalls, stat.stateCalls = last.stateCalls, stat.fragments = last.fragments;
        row.passes.push_back(stat);
    }
    row.drawnLights = m.frames.back().drawnLights;
    row.glCalls = m.frames.back().glCalls;
    const AutoDecision& decision = m.frames.back().autoDecision;
    if (decision.budget > 0) row.hiddenSkip = decision.hiddenFragmentSkip ? 1 : 0;  // a LIDR frame
    if (decision.autoBudget || decision.autoIndexBits) {
        row.autoBudget = decision.budget;
        row.autoIndexBits = decision.indexBits;
        row.autoRepacks = 0;
        for (const FrameStats& f : m.frames) row.autoRepacks += f.autoDecision.repacks;
    }
}

std::string refKey(const Run& r) {
    return r.scene + "|" + std::to_string(r.width) + "x" + std::to_string(r.height) + "|" +
           referenceConfigFor(r.config).key();
}

// LIDR's frame against the reference: the image, and each pixel's index list against the CPU truth.
void judgeLidrLists(LidrRenderer& lidrRenderer, const Scene& scene, const std::vector<PointLight>& lights,
                    const ImageRGBA8& image, const ImageRGBA8& reference, Row& row) {
    const FrameEvaluation ev = evaluateFrame(lidrRenderer, scene.camera, lights, image, reference);
    row.error = ev.error;
    // Per-sample index targets are multisample textures: evaluateFrame judges only the image.
    row.hasLists = !lidrRenderer.options().perSampleIndices;
    row.droppedLightPixels = ev.lists.droppedLightPixels;
    row.pixelsWithDrops = ev.lists.pixelsWithDrops;
    row.pixelsOverBudget = ev.pixelsOverBudget;
    row.invalidSlots = ev.lists.invalidSlots;
    row.maxMarked = ev.maxMarked;
    row.psnrWithinBudget = ev.errorWithinBudget.psnr;
    if (!row.hasLists) return;
    row.lightingComputations = ev.lists.slotsUsed;  // the forward pass shades every filled slot
    row.trueLightPixels = 0;
    for (size_t p = 0; p < ev.truth.surface.size(); ++p)
        if (ev.truth.surface[p]) row.trueLightPixels += ev.truth.count(p);
    for (const PassStat& pass : row.passes)
        if (pass.pass == "light-volumes" && pass.fragments >= 0)
            row.volumeFragments = std::max(0L, row.volumeFragments) + pass.fragments;
}

// Tiled and clustered: each pixel's list (its tile's, its cluster's) against the CPU truth: missing pairs
// (dropped) and the pairs the conservative test adds (extra). The grids are the modes' own data, not statistics.
void judgeGridLists(const Renderer& renderer, const Scene& scene, const std::vector<PointLight>& lights,
                    const Run& run, Row& row) {
    const auto* tiled = dynamic_cast<const TiledRenderer*>(&renderer);
    const auto* clustered = dynamic_cast<const ClusteredRenderer*>(&renderer);
    if (!tiled && !clustered) return;
    const CoverageTruth truth = computeCoverage(renderer.targets().readDepth(),
                                                cameraMatrices(scene.camera, run.width, run.height), lights);
    const PixelListCheck check = checkGridLists(renderer, truth, run.width, run.height);
    row.hasPixelLists = true;
    row.droppedLightPixels = check.missingPairs;
    row.pixelsWithDrops = check.pixelsWithMissing;
    row.trueLightPixels = check.truthPairs;
    row.extraLightPixels = check.extraPairs;
    row.lightingComputations = check.listPairs;  // each surface pixel loops over its list
}

}  // namespace

void installSignalHandlers() { installSignals(); }
bool stopRequested() { return g_stop != 0; }

// ---- progress ----------------------------------------------------------------------------------------------
std::string duration(double seconds) {
    const long s = long(seconds + 0.5);
    char buf[32];
    if (s >= 3600) std::snprintf(buf, sizeof buf, "%ldh%02ldm", s / 3600, (s / 60) % 60);
    else if (s >= 60) std::snprintf(buf, sizeof buf, "%ldm%02lds", s / 60, s % 60);
    else std::snprintf(buf, sizeof buf, "%lds", s);
    return buf;
}

Progress::Progress(bool enabled, const std::vector<double>& weights) : enabled_(enabled), weights_(weights) {
        for (double w : weights_) totalWeight_ += w;
        start_ = nowMilliseconds();
    }
void Progress::show(size_t done, const std::string& what) {
        if (!enabled_) return;
        const double elapsed = (nowMilliseconds() - start_) / 1000.0;
        if (elapsed < 3.0 && !shown_) return;
        shown_ = true;
        double doneWeight = 0.0;
        for (size_t i = 0; i < done && i < weights_.size(); ++i) doneWeight += weights_[i];
        std::string left = "?";
        if (done > 0 && doneWeight > 0) left = "~" + duration(elapsed * (totalWeight_ - doneWeight) / doneWeight);
        const int width = 24;
        const int filled = int(width * (totalWeight_ > 0 ? doneWeight / totalWeight_ : 0.0));
        std::string bar(size_t(filled), '#');
        bar.resize(width, '.');
        std::string line = "\r[" + bar + "] " + std::to_string(done) + "/" + std::to_string(weights_.size()) + " " +
                           duration(elapsed) + " elapsed, " + left + " left | " + what;
        if (line.size() > 118) line.resize(118);
        std::fprintf(stderr, "%s\033[K", line.c_str());
        std::fflush(stderr);
    }
void Progress::finish() {
    if (shown_) std::fprintf(stderr, "\n");
}

double expectedCost(const Run& r, const Scene& scene) {
    const double pixels = double(r.width) * r.height * (r.config.msaa > 0 ? 1.5 : 1.0);
    const double lights = double(scene.lights.size());
    if (r.config.mode == "forward-brute") return pixels * (1.0 + lights / 16.0);
    if (r.config.mode == "forward-multipass") return pixels * (1.0 + lights / 32.0);
    return pixels * 2.0;
}

std::vector<std::vector<const Run*>> sceneSets(const Plan& plan) {
    std::vector<std::vector<const Run*>> sets;
    std::map<std::string, size_t> setIndex;
    for (const Run& r : plan.runs) {
        const std::string k = r.scene + " " + std::to_string(r.width) + "x" + std::to_string(r.height);
        auto [it, added] = setIndex.emplace(k, sets.size());
        if (added) sets.emplace_back();
        sets[it->second].push_back(&r);
    }
    return sets;
}

// The renderers, references and baseline of one scene set, shared by its parts.
struct SetMeasurer::SetState {
    const Run& first;
    const Scene& scene;
    std::vector<PointLight> lights;
    double onceMs = 0.0;
    const Run* baselineRun = nullptr;
    std::map<std::string, Reference> references;
    std::set<const Run*> written;
};

SetMeasurer::SetMeasurer(const GlInfo& info, const Settings& settings, const std::map<std::string, Scene>& scenes,
                         Progress& progress, ReportWriter& writer, RunInfo& runInfo)
    : info_(info), settings_(settings), scenes_(scenes), progress_(progress), writer_(writer), runInfo_(runInfo) {}

SetMeasurer::~SetMeasurer() = default;

// The scene's maximum overlap at this size, from single-sample depth: from `depthSource` when it has
// no MSAA, else from a plain forward-brute frame rendered for it once.
int SetMeasurer::maxOverlapFor(const Run& run, const Scene& scene, const std::vector<PointLight>& lights,
                               const Renderer* depthSource) {
    const std::string overlapKey = run.scene + "|" + std::to_string(run.width) + "x" + std::to_string(run.height);
    if (!maxOverlaps_.count(overlapKey)) {
        std::unique_ptr<Renderer> plain;
        if (!depthSource || run.config.msaa > 0) {
            ModeConfig plainConfig = referenceConfigFor(run.config);
            plainConfig.msaa = 0;
            plainConfig.perSample = false;
            plain = createBenchRenderer(plainConfig, info_, scene, run.width, run.height);
            renderFrame(*plain, scene, lights);
            depthSource = plain.get();
        }
        maxOverlaps_[overlapKey] = computeCoverage(depthSource->targets().readDepth(),
                                                   cameraMatrices(scene.camera, run.width, run.height), lights)
                                       .maxOverlap();
    }
    return maxOverlaps_.at(overlapKey);
}

void SetMeasurer::measure(const std::vector<const Run*>& wholeSet) {
    const Run& first = *wholeSet.front();
    const Scene& scene = scenes_.at(first.scene);
    SetState set{first, scene, scene.lightsAt(scene.time), 0.0, nullptr, {}, {}};
    set.onceMs = 1000.0 * settings_.maxSeconds / settings_.frames;
    // The baseline: forward-multipass where the set has it, else its first configuration.
    set.baselineRun = wholeSet.front();
    for (const Run* r : wholeSet)
        if (r->config.mode == "forward-multipass") {
            set.baselineRun = r;
            break;
        }
    // A set with more configurations than --max-live is measured in parts, the baseline in each (its
    // row comes from the first part; in the others it only divides).
    std::vector<std::vector<const Run*>> parts;
    for (const Run* r : wholeSet) {
        if (r == set.baselineRun) continue;
        if (parts.empty() || int(parts.back().size()) + 1 >= settings_.maxLive) parts.push_back({set.baselineRun});
        parts.back().push_back(r);
    }
    if (parts.empty()) parts.push_back({set.baselineRun});
    for (size_t part = 0; part < parts.size() && !g_stop; ++part) {
        const std::string setKey =
            first.scene + " " + std::to_string(first.width) + "x" + std::to_string(first.height) +
            (parts.size() > 1 ? " part " + std::to_string(part + 1) + "/" + std::to_string(parts.size()) : "");
        if (!measurePart(set, parts[part], setKey)) break;
        if (settings_.interruptAfter >= 0 && nextId_ - 1 >= settings_.interruptAfter) std::raise(SIGINT);
    }
}

bool SetMeasurer::measurePart(SetState& set, const std::vector<const Run*>& part, const std::string& setKey) {
    // Every renderer of the part, built once.
    std::vector<Slot> slots(part.size());
    for (size_t i = 0; i < part.size(); ++i) {
        progress_.show(runsDone_, setKey + ": building " + part[i]->config.key());
        slots[i].run = part[i];
        slots[i].renderer = createBenchRenderer(part[i]->config, info_, set.scene, set.first.width, set.first.height);
    }
    std::vector<double> firstWall(slots.size(), -1.0);
    renderReferences(set, slots, firstWall, setKey);

    // Warm-up, one configuration after the other.
    for (size_t i = 0; i < slots.size() && !g_stop; ++i) {
        progress_.show(runsDone_, setKey + ": warming up " + slots[i].run->config.key());
        warmUp(slots[i], set.scene, set.lights, settings_, set.onceMs, firstWall[i]);
    }

    // The baseline: forward-multipass where the set has it (and it takes part in the rounds), else the
    // first configuration that does.
    std::vector<size_t> active;
    for (size_t i = 0; i < slots.size(); ++i)
        if (!slots[i].once) active.push_back(i);
    size_t baseline = active.empty() ? 0 : active.front();
    for (size_t i : active)
        if (slots[i].run == set.baselineRun) baseline = i;

    const int rounds = runRounds(set, slots, active, baseline, setKey);
    if (rounds == 0 && !active.empty()) return false;  // interrupted before any round: nothing of this set to write
    // Configurations measured once divide by the baseline's median (or its one frame).
    std::vector<double> baseFrames;
    for (const FrameStats& f : slots[baseline].m.frames) baseFrames.push_back(f.frameMilliseconds());
    const double baseMedian = Stat::of(baseFrames).median;
    for (Slot& s : slots)
        if (s.once && baseMedian > 0) s.ratios.push_back(s.m.frames.front().frameMilliseconds() / baseMedian);

    // Rows, in plan order, each judged against its reference.
    for (Slot& slot : slots) {
        if (slot.m.frames.empty() || !set.written.insert(slot.run).second) continue;
        progress_.show(runsDone_, setKey + ": evaluating " + slot.run->config.key());
        Row row = rowFor(set, slot, slots[baseline], rounds);
        row.setKey = setKey;
        writer_.add(row, runInfo_);
        ++runsDone_;
    }
    return true;
}

// References (forward-brute with the same MSAA and transparency), rendered once: by the set's own
// forward-brute configuration where it has one (that frame is then its first warm-up frame).
void SetMeasurer::renderReferences(SetState& set, std::vector<Slot>& slots, std::vector<double>& firstWall,
                                   const std::string& setKey) {
    for (size_t i = 0; i < slots.size() && !g_stop; ++i) {
        const Run& run = *slots[i].run;
        if (!run.reference || set.references.count(refKey(run))) continue;
        progress_.show(runsDone_, setKey + ": reference for " + run.config.key());
        const ModeConfig refConfig = referenceConfigFor(run.config);
        size_t own = slots.size();
        for (size_t k = 0; k < slots.size(); ++k)
            if (slots[k].run->config.key() == refConfig.key()) own = k;
        std::unique_ptr<Renderer> separate;
        Renderer* ref = nullptr;
        if (own < slots.size()) {
            ref = slots[own].renderer.get();
            firstWall[own] = renderFrame(*ref, set.scene, set.lights);
            slots[own].noteShadowMaps();
        } else {
            separate = createBenchRenderer(refConfig, info_, set.scene, set.first.width, set.first.height);
            ref = separate.get();
            renderFrame(*ref, set.scene, set.lights);
        }
        Reference r;
        r.image = ref->targets().readColor();
        r.maxOverlap = maxOverlapFor(run, set.scene, set.lights, ref);
        set.references.emplace(refKey(run), std::move(r));
    }
}

int SetMeasurer::runRounds(SetState& set, std::vector<Slot>& slots, const std::vector<size_t>& active, size_t baseline,
                           const std::string& setKey) {
    int rounds = 0;
    const double roundsStart = nowMilliseconds();
    for (int r = 0; r < settings_.frames && !g_stop && !active.empty(); ++r) {
        progress_.show(runsDone_, setKey + ": round " + std::to_string(r + 1) + "/" + std::to_string(settings_.frames) +
                                      " of " + std::to_string(active.size()) + " configurations");
        for (size_t k = 0; k < active.size(); ++k) {
            Slot& slot = slots[active[(k + size_t(r)) % active.size()]];  // the start rotates each round
            const double wall = renderFrame(*slot.renderer, set.scene, set.lights);
            slot.noteShadowMaps();
            slot.m.frames.push_back(slot.renderer->lastFrame());
            slot.m.wallMs.push_back(wall);
            slot.roundMs.push_back(slot.m.frames.back().frameMilliseconds());
        }
        ++rounds;
        const double base = slots[baseline].roundMs.back();
        for (size_t i : active)
            if (base > 0) slots[i].ratios.push_back(slots[i].roundMs.back() / base);
        ++roundsDone_;
        if (settings_.interruptAfterRounds >= 0 && roundsDone_ >= settings_.interruptAfterRounds) std::raise(SIGINT);
        // At least one round; then stop on a signal (after the round) or past the set's time cap.
        if ((nowMilliseconds() - roundsStart) / 1000.0 > settings_.maxSeconds) break;
    }
    return rounds;
}

Row SetMeasurer::rowFor(SetState& set, Slot& slot, const Slot& baseline, int rounds) {
    const Run& run = *slot.run;
    Row row;
    row.id = nextId_++;
    row.run = run;
    row.sceneLights = int(set.lights.size());
    row.sceneTriangles = sceneTriangleCount(set.scene);
    fillTiming(row, slot.m);
    row.shadowCasters = slot.m.frames.back().shadowCasters;
    row.shadowMapsFirst = std::max(0, slot.shadowMapsFirst);
    row.shadowMapsFirstMs = slot.shadowMapsFirstMs;
    row.shadowMapsLater = slot.shadowMapsLater;
    row.rounds = slot.once ? 1 : rounds;
    row.roundMs = slot.roundMs;
    row.baseline = baseline.run->config.key();
    row.ratio = Stat::of(slot.ratios);
    row.lightDataBytes = slot.renderer->lightDataBytes();
    const ModeStatistics modeStats = slot.renderer->modeStatistics();
    if (modeStats.section == "multipass")
        row.multipassAccumulation = std::get<std::string>(modeStats.at("accumulation"));
    judge(set, slot, row, baseline.renderer.get());
    return row;
}

// The row's error against its reference and, for LIDR, tiled and clustered, each pixel's light list against the
// CPU truth.
void SetMeasurer::judge(SetState& set, Slot& slot, Row& row, const Renderer* baselineRenderer) {
    const Run& run = *slot.run;
    const Scene& scene = set.scene;
    const std::vector<PointLight>& lights = set.lights;
    const ImageRGBA8 image = slot.renderer->targets().readColor();
    if (!run.reference) {
        row.hasError = false;
        row.maxOverlap = maxOverlapFor(run, scene, lights, baselineRenderer);
        return;
    }
    const Reference& reference = set.references.at(refKey(run));
    row.maxOverlap = reference.maxOverlap;
    if (auto* lidrRenderer = dynamic_cast<LidrRenderer*>(slot.renderer.get())) {
        judgeLidrLists(*lidrRenderer, scene, lights, image, reference.image, row);
        return;
    }
    if (run.config.mode == "deferred" || run.config.mode == "tiled-deferred") {
        // Tiled deferred's lists, deferred's count of light shaders run per pixel (frame_accuracy.cpp).
        const FrameAccuracy a = judgeFrame(*slot.renderer, scene.camera, lights, image, reference.image);
        row.error = a.error;
        row.hasPixelLists = a.hasLists;
        row.droppedLightPixels = a.droppedLightPixels;
        row.pixelsWithDrops = a.pixelsWithDrops;
        row.trueLightPixels = a.trueLightPixels;
        row.extraLightPixels = a.shadedLightPixels - (a.trueLightPixels - a.droppedLightPixels);
        row.lightingComputations = a.lightingComputations;
        return;
    }
    row.error = compareImages(image, reference.image);
    if (run.config.msaa == 0) judgeGridLists(*slot.renderer, scene, lights, run, row);
    if (run.config.mode == "forward-multipass" || run.config.mode == "forward-brute") {  // counted, no lists
        const FrameAccuracy a = judgeFrame(*slot.renderer, scene.camera, lights, image, image);
        row.lightingComputations = a.lightingComputations;
        if (a.trueLightPixels > 0) row.trueLightPixels = a.trueLightPixels;
    }
}

}  // namespace lidr::bench
