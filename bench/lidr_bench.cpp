// lidr-bench: run time against error for every render mode, packing scheme, budget, index width and volume
// test, on controlled-overlap, default-room and many-light scenes, in one process. Writes results.csv,
// passes.csv, results.json, summary.md and gnuplot plots into --out. See doc/benchmarks.md.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include <sys/utsname.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include "bench_animation.h"
#include "bench_config.h"
#include "bench_report.h"
#include "lidr/base/error.h"
#include "lidr/modes/auto_mode_renderer.h"
#include "lidr/modes/multipass_forward_renderer.h"
#include "lidr/gl/render_targets.h"
#include "lidr/eval/frame_evaluation.h"
#include "lidr/base/gl.h"
#include "lidr/eval/light_coverage.h"
#include "lidr/technique/packing_scheme.h"
#include "lidr/eval/bench_scenes.h"

using namespace lidr;
using namespace lidr::bench;

namespace {

// ---- interruption: SIGINT/SIGTERM finish the current row, then the outputs are written -----------------
volatile std::sig_atomic_t g_stop = 0;
extern "C" void onSignal(int) { g_stop = 1; }
void installSignalHandlers() {
    struct sigaction sa {};
    sa.sa_handler = onSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND;  // a second signal ends the process the default way
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
}

// ---- run metadata ----------------------------------------------------------------------------------------
std::string trim(std::string s) {
    const size_t a = s.find_first_not_of(" \t\r\n"), b = s.find_last_not_of(" \t\r\n");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

std::string commandOutput(const std::string& cmd) {
    std::string out;
    if (FILE* p = popen(cmd.c_str(), "r")) {
        char buf[256];
        while (fgets(buf, sizeof buf, p)) out += buf;
        if (pclose(p) != 0) return "";
    }
    return trim(out);
}

std::string readLoadAverage() {
    std::ifstream f("/proc/loadavg");
    std::string a, b, c;
    f >> a >> b >> c;
    return f ? a + " " + b + " " + c : "unknown";
}

nlohmann::json machineJson() {
    nlohmann::json m;
    std::ifstream cpu("/proc/cpuinfo");
    std::string line, model;
    int processors = 0;
    while (std::getline(cpu, line)) {
        if (line.rfind("processor", 0) == 0) ++processors;
        if (model.empty() && line.rfind("model name", 0) == 0) model = trim(line.substr(line.find(':') + 1));
    }
    m["cpu_model"] = model.empty() ? "unknown" : model;
    m["cpu_cores"] = processors > 0 ? processors : int(std::thread::hardware_concurrency());
    std::ifstream mem("/proc/meminfo");
    while (std::getline(mem, line))
        if (line.rfind("MemTotal:", 0) == 0) m["memory"] = trim(line.substr(9));
    utsname u{};
    if (uname(&u) == 0) m["kernel"] = std::string(u.sysname) + " " + u.release + " " + u.machine;
    return m;
}

std::string shellWord(const std::string& s) {
    if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_=./,:+@") ==
                          std::string::npos)
        return s;
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string utcNow() {
    const std::time_t t = std::time(nullptr);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S", std::gmtime(&t));
    return buf;
}

// ---- progress ----------------------------------------------------------------------------------------------
std::string duration(double seconds) {
    const long s = long(seconds + 0.5);
    char buf[32];
    if (s >= 3600) std::snprintf(buf, sizeof buf, "%ldh%02ldm", s / 3600, (s / 60) % 60);
    else if (s >= 60) std::snprintf(buf, sizeof buf, "%ldm%02lds", s / 60, s % 60);
    else std::snprintf(buf, sizeof buf, "%lds", s);
    return buf;
}

// A one-line bar on stderr with the time left, estimated from the configurations done so far weighted by
// their expected cost (pixels x lights for forward modes, pixels for the rest). Shown only on a terminal,
// and only once the sweep has run a few seconds.
class Progress {
public:
    Progress(bool enabled, const std::vector<double>& weights) : enabled_(enabled), weights_(weights) {
        for (double w : weights_) totalWeight_ += w;
        start_ = nowMilliseconds();
    }
    void show(size_t done, const std::string& what) {
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
    void finish() {
        if (shown_) std::fprintf(stderr, "\n");
    }

private:
    bool enabled_, shown_ = false;
    std::vector<double> weights_;
    double totalWeight_ = 0.0, start_ = 0.0;
};

double expectedCost(const Run& r, const Scene& scene) {
    const double pixels = double(r.width) * r.height * (r.config.msaa > 0 ? 1.5 : 1.0);
    const double lights = double(scene.lights.size());
    if (r.config.mode == "forward-brute") return pixels * (1.0 + lights / 16.0);
    if (r.config.mode == "forward-multipass") return pixels * (1.0 + lights / 32.0);
    return pixels * 2.0;
}

// ---- measuring -------------------------------------------------------------------------------------------
// The configurations of one scene and size are measured together, in interleaved rounds: every renderer is
// built and warmed up, then each round renders one measured frame of every configuration in turn (the
// starting one rotating from round to round), so a machine that speeds up or slows down during the set
// shifts every configuration of a round alike and their ratios to the round's baseline stay put.
struct Settings {
    int warmup = 1, frames = 5;  // frames: the rounds, i.e. measured frames per configuration
    // Warm-up also lasts at least this long: a GPU idle during the previous configuration's CPU-side
    // evaluation clocks down, and frame-count warm-up alone measured the next frames at idle clocks.
    double warmupMs = 300.0;
    double maxSeconds = 60.0;  // per scene set: no round starts after the rounds took this long (>= 1 round)
    int maxLive = 64;  // renderers alive at once: a larger scene set is measured in parts
    int interruptAfter = -1;        // testing aid: raise SIGINT after this many rows
    int interruptAfterRounds = -1;  // testing aid: raise SIGINT at the end of this round (of any set)
};

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

// ---- command line ----------------------------------------------------------------------------------------
std::vector<std::string> splitList(const std::vector<std::string>& items) {
    std::vector<std::string> out;
    for (const std::string& item : items) {
        std::stringstream ss(item);
        std::string part;
        while (std::getline(ss, part, ','))
            if (!trim(part).empty()) out.push_back(trim(part));
    }
    return out;
}

std::vector<int> intList(const std::vector<std::string>& items, const char* what) {
    std::vector<int> out;
    for (const std::string& s : splitList(items)) {
        try {
            size_t used = 0;
            const int v = std::stoi(s, &used);
            if (used != s.size()) throw std::invalid_argument(s);
            out.push_back(v);
        } catch (const std::exception&) {
            throw Error(std::string("bad ") + what + " '" + s + "': expected whole numbers separated by commas");
        }
    }
    return out;
}

std::vector<bool> onOffList(const std::vector<std::string>& items, const char* what) {
    std::vector<bool> out;
    for (const std::string& s : splitList(items)) {
        if (s == "on" || s == "1" || s == "true") out.push_back(true);
        else if (s == "off" || s == "0" || s == "false") out.push_back(false);
        else throw Error(std::string("bad ") + what + " '" + s + "' (valid: on, off)");
    }
    return out;
}

void printNames() {
    std::cout << "render modes:   " << joinNames(availableModes()) << "\n"
              << "packing schemes: " << joinNames(packingSchemeNames()) << "\n"
              << "budgets, index widths: any; each scheme refuses what it cannot do (see --dry-run)\n"
              << "volume tests:   sphere (the library's default; sphere-span under MSAA), sphere-span, sphere-ray, backface, exact, frontface\n"
              << "cluster slicings: exponential, near-slice (clustered mode; tile sizes 4..256, slices 1..64)\n"
              << "scenes:         " << sceneNameHelp() << "\n";
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"lidr-bench: run time against error for every render mode, packing scheme, budget, index width and "
                 "volume test. Lists are comma-separated; every combination of the lists is measured (combinations "
                 "the library refuses are skipped and listed)."};
    std::vector<std::string> scenes{"room"}, modes, schemes, budgets{"1,2,4,8,16"}, indexBits{"4,8,16"},
        volumeTests{"sphere,backface,exact,frontface"}, msaa{"0"}, environments{"none"}, perSample{"off"}, transparency{"on"}, tiledBounds{"on,off"}, multipassAccumulation{"auto"}, volumeDetail{"off"}, volumeTiles{"on"}, volumeTileSizes{"16"}, regionalIndices{"on"}, resolutions{"1024x768"}, clusterTileSizes, clusterSlices,
        clusterSlicings, clusterOccupancy;
    std::string outDir = "bench-out", context = "auto";
    Settings settings;
    std::vector<std::string> sweeps;
    bool quick = false, full = false, noProgress = false, noPlots = false, dryRun = false, list = false;
    unsigned seed = 1;
    app.add_option("--scenes,--scene", scenes, "Scenes: " + sceneNameHelp())->capture_default_str();
    app.add_option("--environment", environments,
                   "Environment light of every --scenes scene: none (default: the scene's own look), default (the "
                   "built-in studio room: the scene runs as SCENE+environment), or none,default for both in one run "
                   "(doc/benchmarks.md, \"Environment light\")")
        ->capture_default_str();
    app.add_option("--modes", modes, "Render modes (default: all the library has)");
    app.add_option("--schemes", schemes, "Packing schemes for mode lidr (default: all the library has)");
    app.add_option("--budgets", budgets, "LIDR light slots per pixel")->capture_default_str();
    app.add_option("--index-bits", indexBits, "LIDR light index widths")->capture_default_str();
    app.add_option("--volume-tests", volumeTests, "LIDR volume tests: sphere (the library's default; sphere-span under MSAA), sphere-span, sphere-ray, backface, exact, frontface")->capture_default_str();
    app.add_option("--msaa", msaa, "MSAA sample counts (0 = off); LIDR's sphere test becomes sphere-span under MSAA (every sample's surface)")->capture_default_str();
    app.add_option("--per-sample", perSample, "With MSAA: LIDR per-sample index lists (GL 3.2) off, on")->capture_default_str();
    app.add_option("--transparency", transparency, "Transparent materials: on, off")->capture_default_str();
    app.add_option("--tiled-depth-bounds", tiledBounds, "Tiled mode with / without per-tile min/max depth: on, off")->capture_default_str();
    app.add_option("--cluster-tile-sizes", clusterTileSizes,
                   "Clustered mode: screen tile sizes in pixels, 4..256 (default: the library's, ClusteredOptions)");
    app.add_option("--cluster-slices", clusterSlices,
                   "Clustered mode: view-depth slice counts, 1..64 (default: the library's)");
    app.add_option("--cluster-slicings", clusterSlicings,
                   "Clustered mode: exponential (Doom's), near-slice (Filament's) (default: the library's)");
    app.add_option("--cluster-occupancy", clusterOccupancy,
                   "Clustered mode: lists only for clusters holding a surface (the pre-Z depth read back): on, off "
                   "(default: the library's)");
    app.add_option("--multipass-accumulation", multipassAccumulation,
                   "Multi-pass forward sums its passes in: auto (half float where the context renders to it, else "
                   "8-bit), 8-bit (the 8-bit colour target; row 'forward-multipass 8-bit')")
        ->capture_default_str();
    app.add_option("--volume-detail", volumeDetail,
                   "LIDR coarse light volumes for lights small on screen (LidrOptions::volumeDetail): off, on")
        ->capture_default_str();
    app.add_option("--volume-tiles", volumeTiles,
                   "LIDR sphere test over depth-culled screen tiles (LidrOptions::tileCulledVolumes; off: volume meshes): "
                   "on, off")
        ->capture_default_str();
    app.add_option("--regional-indices", regionalIndices,
                   "LIDR over 255 lights with tiles and the automatic width: 8-bit indices numbered per screen region "
                   "(on) or 16-bit global ones (off) (LidrOptions::regionalIndices): on, off")
        ->capture_default_str();
    app.add_option("--volume-tile-size", volumeTileSizes,
                   "LIDR tile-culled volumes: tile sizes in pixels, 4..256 (LidrOptions::volumeTileSize)")
        ->capture_default_str();
    app.add_option("--resolution", resolutions, "WIDTHxHEIGHT, or 'scene' for the scene's own")->capture_default_str();
    app.add_option("--warmup", settings.warmup, "Warm-up frames per configuration (at least)")->capture_default_str()->check(CLI::Range(0, 100));
    app.add_option("--warmup-ms", settings.warmupMs,
                   "Warm-up lasts at least this long per configuration after its first frame, so that a GPU's clocks "
                   "rise from idle (0: frames only; at most 1000 warm-up frames)")
        ->capture_default_str()->check(CLI::Range(0.0, 60000.0));
    app.add_option("--frames", settings.frames,
                   "Interleaved rounds per scene set = measured frames per configuration (median, min, max and the "
                   "ratio to the baseline reported)")
        ->capture_default_str()->check(CLI::Range(1, 1000));
    app.add_option("--max-seconds", settings.maxSeconds,
                   "Per scene set (one scene and size): start no round after the rounds took this many seconds (at "
                   "least one round); a configuration whose first frame takes over MAX-SECONDS / FRAMES is measured "
                   "once, outside the rounds")
        ->capture_default_str()->check(CLI::Range(0.001, 36000.0));
    app.add_option("--max-live", settings.maxLive,
                   "Renderers alive at once: a scene set with more configurations is measured in parts of this many, "
                   "the baseline in each (memory: ~30 MB a renderer at 1024x768 on llvmpipe)")
        ->capture_default_str()->check(CLI::Range(2, 100000));
    app.add_option("--out", outDir, "Output folder: results.csv, passes.csv, results.json, summary.md, plots/")->capture_default_str();
    app.add_option("--seed", seed, "Seed of the room's and many-light scenes' lights")->capture_default_str();
    int extraLights = 0;
    double extraLightRadius = 0.0;
    app.add_option("--lights", extraLights,
                   "Scatter N more seeded point lights over every --scenes scene's surfaces (lidr::scatterLights, "
                   "as lidr-demo --lights N)")
        ->check(CLI::Range(1, 65535));
    app.add_option("--light-radius", extraLightRadius,
                   "Radius of --lights in scene units (default: chosen from the scene's size and N, doc/colour.md)");
    int camera = -1;
    app.add_option("--camera", camera,
                   "View every --scenes glTF file through its camera N (the index in the file's cameras array, from 0; "
                   "default: its first camera in node order); a scene without camera N is an error")
        ->check(CLI::Range(0, 1 << 30));
    app.add_option("--context", context, "GL context: auto, egl, egl-device, egl-gles2, glfw, osmesa (env LIDR_CONTEXT)")->capture_default_str();
    auto* quickFlag = app.add_flag("--quick", quick, "Seconds-long smoke run: tiny resolution, few configurations, one frame");
    auto* fullFlag = app.add_flag("--full", full, "The documented full sweep of doc/benchmarks.md, the scaling sweeps included (takes minutes)")->excludes(quickFlag);
    app.add_option("--sweep", sweeps,
                   "Scaling sweeps instead of the lists: " + joinNames(sweepNames()) +
                       " (frame time against light count / scene triangles / hall light count / shadow casters in the hall; the "
                       "clustered grid's tile sizes, slices, slicings and occupancy on the bench scenes; LIDR's default "
                       "against tiled, clustered, multi-pass and --mode auto on issue 37's scenes, the best-peer targets); "
                       "with --quick, their seconds-long versions")
        ->excludes(fullFlag);
    app.add_flag("--no-progress", noProgress, "No progress bar (it is also off when stderr is not a terminal)");
    app.add_flag("--no-plots", noPlots, "Do not run gnuplot");
    int animationFrames = 0, referenceFrames = 8;
    std::string bart = std::string(LIDR_SOURCE_DIR) + "/../shared/bart-robots";
    app.add_option("--animation", animationFrames,
                   "Time every mode over the scene's animation: N frames sampled evenly over its time range, each mode "
                   "drawing each frame in turn (default resolution 1920x1080; doc/bart.md); writes animation.csv, "
                   ".json, .md and plots");
    app.add_option("--reference-frames", referenceFrames,
                   "With --animation: frames judged against forward-brute (PSNR, dropped light-pixels), spread evenly")
        ->capture_default_str();
    app.add_option("--bart", bart, "Where bart-robots-many / -few are read from: a folder with aff/Robot.aff, or an AFF file")
        ->capture_default_str();
    app.add_flag("--dry-run", dryRun, "Check everything, print the configurations that would run and the skipped ones, measure nothing");
    app.add_flag("--list", list, "Print the valid mode, scheme, volume-test and scene names and exit");
    app.add_option("--interrupt-after", settings.interruptAfter, "Testing aid: act as if interrupted after this many rows")
        ->group("");
    app.add_option("--interrupt-after-rounds", settings.interruptAfterRounds,
                   "Testing aid: act as if interrupted at the end of this many rounds")
        ->group("");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    if (list) {
        printNames();
        return 0;
    }

    std::string commandLine;
    for (int i = 0; i < argc; ++i) commandLine += (i ? " " : "") + shellWord(argv[i]);
    benchBartFolder() = bart;
    if (app.count("--animation")) {
        try {
            AnimationBenchOptions animation;
            animation.scenes = splitList(scenes);
            animation.frames = animationFrames;
            if (app.count("--resolution")) animation.resolution = parseResolution(splitList(resolutions).at(0));
            animation.modes = splitList(modes);
            animation.referenceFrames = referenceFrames;
            animation.seed = seed;
            animation.bart = bart;
            animation.outDir = outDir;
            animation.context = context;
            animation.commandLine = commandLine;
            animation.plots = !noPlots;
            return runAnimationBench(animation);
        } catch (const std::exception& e) {
            std::cerr << "lidr-bench: error: " << e.what() << "\n";
            return 1;
        }
    }

    try {
        // CLI::Range lets NaN through (every comparison with it is false): numbers are checked here.
        const auto finiteIn = [](const char* option, double value, double lo, double hi) {
            if (!(std::isfinite(value) && value >= lo && value <= hi)) {
                std::ostringstream text;
                text << option << " must be a finite number in [" << lo << ", " << hi << "], got " << value;
                throw Error(text.str());
            }
        };
        finiteIn("--max-seconds", settings.maxSeconds, 0.001, 36000.0);  // as the option's range says
        finiteIn("--warmup-ms", settings.warmupMs, 0.0, 60000.0);
        // ---- the sweep, from a preset or the lists -------------------------------------------------------
        std::vector<SweepGroup> groups;
        const bool listsGiven = app.count("--scenes") || app.count("--environment") || app.count("--modes") || app.count("--schemes") ||
                                app.count("--budgets") || app.count("--index-bits") || app.count("--volume-tests") ||
                                app.count("--msaa") || app.count("--per-sample") || app.count("--transparency") || app.count("--tiled-depth-bounds") || app.count("--multipass-accumulation") || app.count("--volume-detail") ||
                                app.count("--cluster-tile-sizes") || app.count("--cluster-slices") ||
                                app.count("--cluster-slicings") || app.count("--cluster-occupancy") ||
                                app.count("--resolution");
        if ((quick || full || !sweeps.empty()) && listsGiven)
            throw Error(std::string("--") + (!sweeps.empty() ? "sweep" : quick ? "quick" : "full") +
                        " is a fixed sweep; drop the --scenes/--modes/... lists, or drop the preset");
        if (!sweeps.empty()) {
            for (const std::string& name : splitList(sweeps))
                for (const SweepGroup& g : sweepPreset(name, quick)) groups.push_back(g);  // throws on a bad name
            if (groups.empty()) throw Error("--sweep needs a name (valid: " + joinNames(sweepNames()) + ")");
            settings.warmup = app.count("--warmup") ? settings.warmup : 1;
            settings.warmupMs = app.count("--warmup-ms") || !quick ? settings.warmupMs : 0.0;
            settings.frames = app.count("--frames") ? settings.frames : quick ? 1 : 5;
            settings.maxSeconds = app.count("--max-seconds") ? settings.maxSeconds : 120.0;
        } else if (quick) {
            groups = quickPreset();
            settings.warmup = app.count("--warmup") ? settings.warmup : 1;
            settings.warmupMs = app.count("--warmup-ms") ? settings.warmupMs : 0.0;
            settings.frames = app.count("--frames") ? settings.frames : 1;
        } else if (full) {
            groups = fullPreset();
            settings.warmup = app.count("--warmup") ? settings.warmup : 1;
            settings.frames = app.count("--frames") ? settings.frames : 5;
            settings.maxSeconds = app.count("--max-seconds") ? settings.maxSeconds : 120.0;
        } else {
            SweepGroup g;
            g.name = "command-line";
            for (const std::string& scene : splitList(scenes))
                for (const std::string& environment : splitList(environments)) {
                    if (environment != "none" && environment != "default")
                        throw Error("--environment must be none, default or both (none,default), got '" + environment + "'");
                    g.scenes.push_back(environment == "none" ? scene : scene + "+environment");
                }
            g.modes = modes.empty() ? availableModes() : splitList(modes);
            g.schemes = schemes.empty() ? packingSchemeNames() : splitList(schemes);
            g.budgets = intList(budgets, "budget");
            g.indexBits = intList(indexBits, "index width");
            g.volumeTests = splitList(volumeTests);
            g.msaa = intList(msaa, "MSAA sample count");
            for (int samples : g.msaa) checkSampleCount(samples, "--msaa");
            g.perSample = onOffList(perSample, "--per-sample value");
            g.transparency = onOffList(transparency, "--transparency value");
            g.tiledDepthBounds = onOffList(tiledBounds, "--tiled-depth-bounds value");
            g.multipassEightBit.clear();
            for (const std::string& a : splitList(multipassAccumulation)) {
                if (a != "auto" && a != "8-bit")
                    throw Error("--multipass-accumulation value must be auto or 8-bit, got '" + a + "'");
                g.multipassEightBit.push_back(a == "8-bit");
            }
            g.volumeDetail = onOffList(volumeDetail, "--volume-detail value");
            g.volumeTiles = onOffList(volumeTiles, "--volume-tiles value");
            g.volumeTileSizes = intList(volumeTileSizes, "--volume-tile-size value");
            g.regionalIndices = onOffList(regionalIndices, "--regional-indices value");
            if (!clusterTileSizes.empty()) {
                g.clusterTileSizes = intList(clusterTileSizes, "--cluster-tile-sizes value");
                for (int t : g.clusterTileSizes)
                    if (t < ClusterGrid::kMinTileSize || t > ClusterGrid::kMaxTileSize)
                        throw Error("--cluster-tile-sizes: " + std::to_string(t) + " is outside " +
                                    std::to_string(ClusterGrid::kMinTileSize) + ".." +
                                    std::to_string(ClusterGrid::kMaxTileSize));
            }
            if (!clusterSlices.empty()) {
                g.clusterSlices = intList(clusterSlices, "--cluster-slices value");
                for (int s : g.clusterSlices)
                    if (s < 1 || s > ClusterGrid::kMaxSlices)
                        throw Error("--cluster-slices: " + std::to_string(s) + " is outside 1.." +
                                    std::to_string(ClusterGrid::kMaxSlices));
            }
            if (!clusterSlicings.empty()) {
                g.clusterSlicings = splitList(clusterSlicings);
                for (const std::string& s : g.clusterSlicings) parseClusterSlicing(s);  // throws naming the valid ones
            }
            if (!clusterOccupancy.empty()) {
                g.clusterOccupancy.clear();
                for (bool on : onOffList(clusterOccupancy, "--cluster-occupancy value")) g.clusterOccupancy.push_back(on);
            }
            for (const std::string& r : splitList(resolutions)) g.resolutions.push_back(parseResolution(r));
            // Lists left at their defaults sweep "whatever the library supports"; typed lists are strict.
            const std::pair<const char*, const char*> typed[] = {
                {"--modes", "mode"}, {"--schemes", "scheme"}, {"--budgets", "budget"}, {"--index-bits", "index width"},
                {"--volume-tests", "volume test"}, {"--msaa", "MSAA"}, {"--per-sample", "per-sample"},
                {"--transparency", "transparency"}};
            for (const auto& [option, dimension] : typed)
                if (app.count(option)) g.strictDimensions.insert(dimension);
            groups.push_back(g);
        }

        if (extraLightRadius != 0.0 && extraLights == 0)
            throw Error("--light-radius sets the radius of --lights: give --lights N too");
        if (!(std::isfinite(extraLightRadius) && extraLightRadius >= 0.0 && extraLightRadius <= double(maxLightRadius)))
            throw Error("--light-radius must be a finite number > 0, got " + std::to_string(extraLightRadius));

        // ---- outputs first: an unwritable folder fails before any GL work --------------------------------
        if (!dryRun) ReportWriter::checkWritable(outDir);

        ContextOptions co;
        co.backend = parseContextBackend(context);
        auto ctx = GlContext::create(co);
        const GlInfo& info = ctx->info();

        std::map<std::string, Scene> sceneCache;
        LightScatterOptions scatter;
        scatter.count = extraLights;
        scatter.radius = float(extraLightRadius);
        const Plan plan = buildPlan(groups, info, seed, sceneCache, scatter, camera);
        std::cout << "lidr-bench: " << plan.runs.size() << " configurations to measure, " << plan.skipped.size()
                  << " combinations skipped (refused by the library); GL: " << info.renderer << "\n";
        if (dryRun) {
            for (const Run& r : plan.runs)
                std::cout << "  run   " << r.group << " | " << r.scene << " " << r.width << "x" << r.height << " | "
                          << r.config.key() << "\n";
            for (const Skipped& s : plan.skipped)
                std::cout << "  skip  " << s.group << " | " << s.scene << " " << s.width << "x" << s.height << " | "
                          << s.label << ": " << s.reason << "\n";
            return 0;
        }

        auto writer = std::make_unique<ReportWriter>(outDir);
        RunInfo runInfo;
        runInfo.planned = plan.runs.size();
        runInfo.skipped = plan.skipped;
        nlohmann::json& meta = runInfo.meta;
        meta["date"] = utcNow();
        meta["machine"] = machineJson();
        meta["machine_summary"] = meta["machine"]["cpu_model"].get<std::string>() + ", " +
                                  std::to_string(meta["machine"]["cpu_cores"].get<int>()) + " cores";
        meta["gl"] = {{"backend", info.backend}, {"renderer", info.renderer}, {"version", info.version},
                      {"vendor", info.vendor}, {"glsl", info.glslVersion}, {"timer_query", info.timerQuery}};
        meta["gl_summary"] = info.renderer + " (" + info.version + ")";
        std::string commit = commandOutput("git -C " + shellWord(LIDR_SOURCE_DIR) + " rev-parse HEAD 2>/dev/null");
        if (!commit.empty()) {
            // Changes inside the output folder (a tracked doc/bench being rewritten) are this run's own.
            std::string outside;
            std::error_code ec;
            const std::filesystem::path rel =
                std::filesystem::relative(std::filesystem::absolute(outDir, ec), std::filesystem::path(LIDR_SOURCE_DIR), ec);
            if (!ec && !rel.empty() && *rel.begin() != ".." && rel != ".")
                outside = " -- . " + shellWord(":(exclude,literal)" + rel.generic_string());
            if (!commandOutput("git -C " + shellWord(LIDR_SOURCE_DIR) + " status --porcelain --untracked-files=no" +
                               outside + " 2>/dev/null").empty())
                commit += " (with uncommitted changes)";
            // The binary may have been built from another commit than the tree holds now (or was copied).
            const std::string configured = LIDR_CONFIGURE_COMMIT;
            if (!configured.empty() && commit.compare(0, configured.size(), configured) != 0)
                commit += "; this lidr-bench was configured at " + std::string(LIDR_CONFIGURE_COMMIT);
        } else {
            commit = std::string(LIDR_CONFIGURE_COMMIT).empty() ? "unknown" : std::string(LIDR_CONFIGURE_COMMIT) + " (at configure time)";
        }
        meta["commit"] = commit;
        meta["command_line"] = commandLine;
        meta["settings"] = {{"warmup_frames", settings.warmup}, {"warmup_ms", settings.warmupMs}, {"frames", settings.frames},
                            {"max_seconds_per_scene_set", settings.maxSeconds}, {"seed", seed},
                            {"preset", quick ? "quick" : full ? "full" : "none"}, {"sweeps", splitList(sweeps)},
                            {"interleaved_rounds", true}, {"max_live", settings.maxLive}};
        {
            std::ostringstream cap;
            cap << settings.maxSeconds;
            meta["frames_summary"] =
                "interleaved rounds: per scene and size every configuration is built and warmed up (at least " +
                std::to_string(settings.warmup) + " frame(s) and " + std::to_string(int(settings.warmupMs)) +
                " ms, the rows give the count), then up to " + std::to_string(settings.frames) +
                " rounds render one measured frame of each configuration in turn (the first one rotating); no "
                "round starts after the rounds took " + cap.str() + " s (at least 1 round); a configuration whose "
                "first frame takes over " + cap.str() + " s / " + std::to_string(settings.frames) +
                " is measured once, outside the rounds";
        }
        const std::string loadBefore = readLoadAverage();
        meta["load_average_before"] = loadBefore;
        meta["load_summary"] = loadBefore + " / (running)";
        meta["cpu_cores_note"] = "load averages are over 1, 5 and 15 minutes";

        installSignalHandlers();
        // Scene sets: the runs of one scene and size, measured together in interleaved rounds (in the order
        // of the plan, which keeps each reference's runs together).
        std::vector<std::vector<const Run*>> sets;
        {
            std::map<std::string, size_t> setIndex;
            for (const Run& r : plan.runs) {
                const std::string k = r.scene + " " + std::to_string(r.width) + "x" + std::to_string(r.height);
                auto [it, added] = setIndex.emplace(k, sets.size());
                if (added) sets.emplace_back();
                sets[it->second].push_back(&r);
            }
        }
        std::vector<double> weights;  // in the order the rows come: set by set
        for (const auto& set : sets)
            for (const Run* r : set) weights.push_back(expectedCost(*r, sceneCache.at(r->scene)));
        Progress progress(!noProgress && isatty(STDERR_FILENO), weights);

        std::map<std::string, int> maxOverlaps;  // scene|size -> most lights touching one surface pixel
        // The scene's maximum overlap at this size, from single-sample depth: from `depthSource` when it has
        // no MSAA, else from a plain forward-brute frame rendered for it once.
        auto maxOverlapFor = [&](const Run& run, const Scene& scene, const std::vector<PointLight>& lights,
                                 const Renderer* depthSource) {
            const std::string overlapKey = run.scene + "|" + std::to_string(run.width) + "x" + std::to_string(run.height);
            if (!maxOverlaps.count(overlapKey)) {
                std::unique_ptr<Renderer> plain;
                if (!depthSource || run.config.msaa > 0) {
                    ModeConfig plainConfig = referenceConfigFor(run.config);
                    plainConfig.msaa = 0;
                    plainConfig.perSample = false;
                    plain = createBenchRenderer(plainConfig, info, scene, run.width, run.height);
                    renderFrame(*plain, scene, lights);
                    depthSource = plain.get();
                }
                maxOverlaps[overlapKey] = computeCoverage(depthSource->targets().readDepth(),
                                                          cameraMatrices(scene.camera, run.width, run.height), lights)
                                              .maxOverlap();
            }
            return maxOverlaps.at(overlapKey);
        };

        int nextId = 1;
        size_t runsDone = 0;
        int roundsDone = 0;
        for (const std::vector<const Run*>& wholeSet : sets) {
            if (g_stop) break;
            const Run& first = *wholeSet.front();
            const Scene& scene = sceneCache.at(first.scene);
            const std::vector<PointLight> lights = scene.lightsAt(scene.time);
            const double onceMs = 1000.0 * settings.maxSeconds / settings.frames;
            // The baseline: forward-multipass where the set has it, else its first configuration.
            const Run* baselineRun = wholeSet.front();
            for (const Run* r : wholeSet)
                if (r->config.mode == "forward-multipass") {
                    baselineRun = r;
                    break;
                }
            // A set with more configurations than --max-live is measured in parts, the baseline in each (its
            // row comes from the first part; in the others it only divides).
            std::vector<std::vector<const Run*>> parts;
            for (const Run* r : wholeSet) {
                if (r == baselineRun) continue;
                if (parts.empty() || int(parts.back().size()) + 1 >= settings.maxLive) parts.push_back({baselineRun});
                parts.back().push_back(r);
            }
            if (parts.empty()) parts.push_back({baselineRun});
            std::map<std::string, Reference> references;  // per set, shared by its parts
            std::set<const Run*> written;
            for (size_t part = 0; part < parts.size() && !g_stop; ++part) {
            const std::vector<const Run*>& set = parts[part];
            const std::string setKey = first.scene + " " + std::to_string(first.width) + "x" + std::to_string(first.height) +
                                       (parts.size() > 1 ? " part " + std::to_string(part + 1) + "/" + std::to_string(parts.size()) : "");

            // Every renderer of the set, built once.
            std::vector<Slot> slots(set.size());
            for (size_t i = 0; i < set.size(); ++i) {
                progress.show(runsDone, setKey + ": building " + set[i]->config.key());
                slots[i].run = set[i];
                slots[i].renderer = createBenchRenderer(set[i]->config, info, scene, first.width, first.height);
            }

            // References (forward-brute with the same MSAA and transparency), rendered once: by the set's own
            // forward-brute configuration where it has one (that frame is then its first warm-up frame).
            std::vector<double> firstWall(slots.size(), -1.0);
            for (size_t i = 0; i < slots.size() && !g_stop; ++i) {
                const Run& run = *slots[i].run;
                if (!run.reference || references.count(refKey(run))) continue;
                progress.show(runsDone, setKey + ": reference for " + run.config.key());
                const ModeConfig refConfig = referenceConfigFor(run.config);
                size_t own = slots.size();
                for (size_t k = 0; k < slots.size(); ++k)
                    if (slots[k].run->config.key() == refConfig.key()) own = k;
                std::unique_ptr<Renderer> separate;
                Renderer* ref = nullptr;
                if (own < slots.size()) {
                    ref = slots[own].renderer.get();
                    firstWall[own] = renderFrame(*ref, scene, lights);
                    slots[own].noteShadowMaps();
                } else {
                    separate = createBenchRenderer(refConfig, info, scene, first.width, first.height);
                    ref = separate.get();
                    renderFrame(*ref, scene, lights);
                }
                Reference r;
                r.image = ref->targets().readColor();
                r.maxOverlap = maxOverlapFor(run, scene, lights, ref);
                references.emplace(refKey(run), std::move(r));
            }

            // Warm-up, one configuration after the other.
            for (size_t i = 0; i < slots.size() && !g_stop; ++i) {
                progress.show(runsDone, setKey + ": warming up " + slots[i].run->config.key());
                warmUp(slots[i], scene, lights, settings, onceMs, firstWall[i]);
            }

            // The baseline: forward-multipass where the set has it (and it takes part in the rounds), else the
            // first configuration that does.
            std::vector<size_t> active;
            for (size_t i = 0; i < slots.size(); ++i)
                if (!slots[i].once) active.push_back(i);
            size_t baseline = active.empty() ? 0 : active.front();
            for (size_t i : active)
                if (slots[i].run == baselineRun) baseline = i;

            // The rounds.
            int rounds = 0;
            const double roundsStart = nowMilliseconds();
            for (int r = 0; r < settings.frames && !g_stop && !active.empty(); ++r) {
                progress.show(runsDone, setKey + ": round " + std::to_string(r + 1) + "/" + std::to_string(settings.frames) +
                                            " of " + std::to_string(active.size()) + " configurations");
                for (size_t k = 0; k < active.size(); ++k) {
                    Slot& slot = slots[active[(k + size_t(r)) % active.size()]];  // the start rotates each round
                    const double wall = renderFrame(*slot.renderer, scene, lights);
                    slot.noteShadowMaps();
                    slot.m.frames.push_back(slot.renderer->lastFrame());
                    slot.m.wallMs.push_back(wall);
                    slot.roundMs.push_back(slot.m.frames.back().frameMilliseconds());
                }
                ++rounds;
                const double base = slots[baseline].roundMs.back();
                for (size_t i : active)
                    if (base > 0) slots[i].ratios.push_back(slots[i].roundMs.back() / base);
                ++roundsDone;
                if (settings.interruptAfterRounds >= 0 && roundsDone >= settings.interruptAfterRounds) std::raise(SIGINT);
                // At least one round; then stop on a signal (after the round) or past the set's time cap.
                if ((nowMilliseconds() - roundsStart) / 1000.0 > settings.maxSeconds) break;
            }
            if (rounds == 0 && !active.empty()) break;  // interrupted before any round: nothing of this set to write
            // Configurations measured once divide by the baseline's median (or its one frame).
            std::vector<double> baseFrames;
            for (const FrameStats& f : slots[baseline].m.frames) baseFrames.push_back(f.frameMilliseconds());
            const double baseMedian = Stat::of(baseFrames).median;
            for (Slot& s : slots)
                if (s.once && baseMedian > 0) s.ratios.push_back(s.m.frames.front().frameMilliseconds() / baseMedian);

            // Rows, in plan order, each judged against its reference.
            for (Slot& slot : slots) {
                if (slot.m.frames.empty() || !written.insert(slot.run).second) continue;
                const Run& run = *slot.run;
                progress.show(runsDone, setKey + ": evaluating " + run.config.key());
                Row row;
                row.id = nextId++;
                row.run = run;
                row.sceneLights = int(lights.size());
                row.sceneTriangles = sceneTriangleCount(scene);
                fillTiming(row, slot.m);
                row.shadowCasters = slot.m.frames.back().shadowCasters;
                row.shadowMapsFirst = std::max(0, slot.shadowMapsFirst);
                row.shadowMapsFirstMs = slot.shadowMapsFirstMs;
                row.shadowMapsLater = slot.shadowMapsLater;
                row.rounds = slot.once ? 1 : rounds;
                row.roundMs = slot.roundMs;
                row.setKey = setKey;
                row.baseline = slots[baseline].run->config.key();
                row.ratio = Stat::of(slot.ratios);
                row.lightDataBytes = slot.renderer->lightDataBytes();
                if (const auto* multipass = dynamic_cast<const MultipassForwardRenderer*>(slot.renderer.get()))
                    row.multipassAccumulation = multipass->accumulation();
                const ImageRGBA8 image = slot.renderer->targets().readColor();
                if (!run.reference) {
                    row.hasError = false;
                    row.maxOverlap = maxOverlapFor(run, scene, lights, slots[baseline].renderer.get());
                } else {
                    const Reference& reference = references.at(refKey(run));
                    row.maxOverlap = reference.maxOverlap;
                    auto* lidrRenderer = dynamic_cast<LidrRenderer*>(slot.renderer.get());
                    if (lidrRenderer) {
                        const FrameEvaluation ev = evaluateFrame(*lidrRenderer, scene.camera, lights, image, reference.image);
                        row.error = ev.error;
                        // Per-sample index targets are multisample textures: evaluateFrame judges only the image.
                        row.hasLists = !lidrRenderer->options().perSampleIndices;
                        row.droppedLightPixels = ev.lists.droppedLightPixels;
                        row.pixelsWithDrops = ev.lists.pixelsWithDrops;
                        row.pixelsOverBudget = ev.pixelsOverBudget;
                        row.invalidSlots = ev.lists.invalidSlots;
                        row.maxMarked = ev.maxMarked;
                        row.psnrWithinBudget = ev.errorWithinBudget.psnr;
                        if (row.hasLists) {
                            row.trueLightPixels = 0;
                            for (size_t p = 0; p < ev.truth.surface.size(); ++p)
                                if (ev.truth.surface[p]) row.trueLightPixels += ev.truth.count(p);
                            for (const PassStat& pass : row.passes)
                                if (pass.pass == "light-volumes" && pass.fragments >= 0)
                                    row.volumeFragments = std::max(0L, row.volumeFragments) + pass.fragments;
                        }
                    } else {
                        row.error = compareImages(image, reference.image);
                        // Tiled and clustered: each pixel's list (its tile's, its cluster's) against the CPU truth:
                        // missing pairs (dropped) and the pairs the conservative test adds (extra).
                        const auto* tiled = dynamic_cast<TiledRenderer*>(slot.renderer.get());
                        const auto* clustered = dynamic_cast<ClusteredRenderer*>(slot.renderer.get());
                        if ((tiled || clustered) && run.config.msaa == 0) {
                            const CoverageTruth truth =
                                computeCoverage(slot.renderer->targets().readDepth(),
                                                cameraMatrices(scene.camera, run.width, run.height), lights);
                            PixelListCheck check;
                            if (clustered) {
                                const ClusterGrid& g = clustered->grid();
                                check = checkPixelLists(truth, clustered->pixelClusters(), g.entries(), g.offsets(),
                                                        g.counts());
                            } else {
                                const LightGrid& g = tiled->grid();
                                std::vector<int> tileOfPixel(size_t(run.width) * size_t(run.height));
                                for (int y = 0; y < run.height; ++y)
                                    for (int x = 0; x < run.width; ++x)
                                        tileOfPixel[size_t(y) * size_t(run.width) + size_t(x)] =
                                            g.tileOf(x, run.height - 1 - y);
                                check = checkPixelLists(truth, tileOfPixel, g.entries(), g.opaqueOffsets(),
                                                        g.opaqueCounts());
                            }
                            row.hasPixelLists = true;
                            row.droppedLightPixels = check.missingPairs;
                            row.pixelsWithDrops = check.pixelsWithMissing;
                            row.trueLightPixels = check.truthPairs;
                            row.extraLightPixels = check.extraPairs;
                        }
                    }
                }
                writer->add(row, runInfo);
                ++runsDone;
            }
            if (settings.interruptAfter >= 0 && nextId - 1 >= settings.interruptAfter) std::raise(SIGINT);
            }  // parts
        }
        progress.finish();
        runInfo.interrupted = g_stop != 0;
        runInfo.complete = !runInfo.interrupted && writer->rows().size() == plan.runs.size();
        meta["load_average_after"] = readLoadAverage();
        meta["load_summary"] = loadBefore + " / " + meta["load_average_after"].get<std::string>();
        writer->writeJson(runInfo);
        std::string plotMessage = "plots not asked for (--no-plots)";
        std::vector<std::string> plots;
        if (!noPlots) plots = writer->writePlots(plotMessage);
        writer->writeSummary(runInfo, plots, plotMessage);
        std::cout << "lidr-bench: " << writer->rows().size() << " rows"
                  << (runInfo.interrupted ? " (INTERRUPTED: the rows measured so far are kept)" : "") << " in " << outDir
                  << "/{results.csv,passes.csv,results.json,summary.md}; " << plotMessage << "\n";
        return runInfo.interrupted ? 130 : 0;
    } catch (const std::exception& e) {
        std::cerr << "lidr-bench: error: " << e.what() << "\n";
        return 1;
    }
}
