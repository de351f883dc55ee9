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
#include <sstream>
#include <thread>

#include <sys/utsname.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include "bench_config.h"
#include "bench_report.h"
#include "lidr/base/error.h"
#include "lidr/gl/render_targets.h"
#include "lidr/eval/frame_evaluation.h"
#include "lidr/base/gl.h"
#include "lidr/eval/light_coverage.h"
#include "lidr/technique/packing_scheme.h"

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
struct Settings {
    int warmup = 1, frames = 5;
    // Warm-up also lasts at least this long: a GPU idle during the previous configuration's CPU-side
    // evaluation clocks down, and frame-count warm-up alone measured the next frames at idle clocks.
    double warmupMs = 300.0;
    double maxSeconds = 8.0;
    int interruptAfter = -1;  // testing aid: raise SIGINT after this many rows
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

Measured measure(Renderer& renderer, const Scene& scene, const std::vector<PointLight>& lights, const Settings& s) {
    const ShadingParameters shading{scene.ambient, scene.backgroundColor};
    Measured m;
    double warmupStart = nowMilliseconds();  // from the end of the first frame (shader compiles, uploads)
    for (int i = 0; !g_stop && i < kMaxWarmupFrames &&
                    (i < s.warmup || (s.warmupMs > 0.0 && (i == 0 || nowMilliseconds() - warmupStart < s.warmupMs)));
         ++i) {
        const double t0 = nowMilliseconds();
        const FrameStats& stats = renderer.render(scene.camera, lights, shading);
        glFinish();
        const double wall = nowMilliseconds() - t0;
        if (i == 0 && wall / 1000.0 > s.maxSeconds) {
            // A frame longer than the per-configuration cap (brute force over thousands of lights): shader
            // compiles and first uploads are a rounding error of it, so it is the one measured frame, and the
            // row says there was no warm-up.
            m.frames.push_back(stats);
            m.wallMs.push_back(wall);
            return m;
        }
        ++m.warmupFrames;
        if (i == 0) warmupStart = nowMilliseconds();
    }
    const double start = nowMilliseconds();
    for (int i = 0; i < s.frames; ++i) {
        const double t0 = nowMilliseconds();
        m.frames.push_back(renderer.render(scene.camera, lights, shading));
        glFinish();
        m.wallMs.push_back(nowMilliseconds() - t0);
        // At least one frame; then stop early on a signal or past the per-configuration time cap.
        if (g_stop || (nowMilliseconds() - start) / 1000.0 > s.maxSeconds) break;
    }
    return m;
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
    for (const std::string& p : order) row.passes.push_back({p, Stat::of(perPass[p])});
    row.drawnLights = m.frames.back().drawnLights;
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
              << "volume tests:   backface, exact, frontface\n"
              << "scenes:         " << sceneNameHelp() << "\n";
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"lidr-bench: run time against error for every render mode, packing scheme, budget, index width and "
                 "volume test. Lists are comma-separated; every combination of the lists is measured (combinations "
                 "the library refuses are skipped and listed)."};
    std::vector<std::string> scenes{"room"}, modes, schemes, budgets{"1,2,4,8,16"}, indexBits{"4,8,16"},
        volumeTests{"backface,exact,frontface"}, msaa{"0"}, perSample{"off"}, transparency{"on"}, tiledBounds{"on,off"}, volumeDetail{"off"}, resolutions{"1024x768"};
    std::string outDir = "bench-out", context = "auto";
    Settings settings;
    bool quick = false, full = false, noProgress = false, noPlots = false, dryRun = false, list = false;
    unsigned seed = 1;
    app.add_option("--scenes", scenes, "Scenes: " + sceneNameHelp())->capture_default_str();
    app.add_option("--modes", modes, "Render modes (default: all the library has)");
    app.add_option("--schemes", schemes, "Packing schemes for mode lidr (default: all the library has)");
    app.add_option("--budgets", budgets, "LIDR light slots per pixel")->capture_default_str();
    app.add_option("--index-bits", indexBits, "LIDR light index widths")->capture_default_str();
    app.add_option("--volume-tests", volumeTests, "LIDR volume tests: backface, exact, frontface")->capture_default_str();
    app.add_option("--msaa", msaa, "MSAA sample counts (0 = off); LIDR needs the frontface test for MSAA unless per-sample")->capture_default_str();
    app.add_option("--per-sample", perSample, "With MSAA: LIDR per-sample index lists (GL 3.2) off, on")->capture_default_str();
    app.add_option("--transparency", transparency, "Transparent materials: on, off")->capture_default_str();
    app.add_option("--tiled-depth-bounds", tiledBounds, "Tiled mode with / without per-tile min/max depth: on, off")->capture_default_str();
    app.add_option("--volume-detail", volumeDetail,
                   "LIDR coarse light volumes for lights small on screen (LidrOptions::volumeDetail): off, on")
        ->capture_default_str();
    app.add_option("--resolution", resolutions, "WIDTHxHEIGHT, or 'scene' for the scene's own")->capture_default_str();
    app.add_option("--warmup", settings.warmup, "Warm-up frames per configuration (at least)")->capture_default_str()->check(CLI::Range(0, 100));
    app.add_option("--warmup-ms", settings.warmupMs,
                   "Warm-up lasts at least this long per configuration after its first frame, so that a GPU's clocks "
                   "rise from idle (0: frames only; at most 1000 warm-up frames)")
        ->capture_default_str()->check(CLI::Range(0.0, 60000.0));
    app.add_option("--frames", settings.frames, "Measured frames per configuration (median, min, max reported)")
        ->capture_default_str()->check(CLI::Range(1, 1000));
    app.add_option("--max-seconds", settings.maxSeconds,
                   "Stop measuring a configuration after this many seconds (at least one frame is measured)")
        ->capture_default_str()->check(CLI::Range(0.0, 3600.0));
    app.add_option("--out", outDir, "Output folder: results.csv, passes.csv, results.json, summary.md, plots/")->capture_default_str();
    app.add_option("--seed", seed, "Seed of the room's and many-light scenes' lights")->capture_default_str();
    app.add_option("--context", context, "GL context: auto, egl, egl-device, glfw, osmesa (env LIDR_CONTEXT)")->capture_default_str();
    auto* quickFlag = app.add_flag("--quick", quick, "Seconds-long smoke run: tiny resolution, few configurations, one frame");
    app.add_flag("--full", full, "The documented full sweep of doc/benchmarks.md (takes minutes)")->excludes(quickFlag);
    app.add_flag("--no-progress", noProgress, "No progress bar (it is also off when stderr is not a terminal)");
    app.add_flag("--no-plots", noPlots, "Do not run gnuplot");
    app.add_flag("--dry-run", dryRun, "Check everything, print the configurations that would run and the skipped ones, measure nothing");
    app.add_flag("--list", list, "Print the valid mode, scheme, volume-test and scene names and exit");
    app.add_option("--interrupt-after", settings.interruptAfter, "Testing aid: act as if interrupted after this many rows")
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

    try {
        // CLI::Range lets NaN through (every comparison with it is false): numbers are checked here.
        const auto finiteIn = [](const char* option, double value, double lo, double hi) {
            if (!(std::isfinite(value) && value >= lo && value <= hi)) {
                std::ostringstream text;
                text << option << " must be a finite number in [" << lo << ", " << hi << "], got " << value;
                throw Error(text.str());
            }
        };
        finiteIn("--max-seconds", settings.maxSeconds, 0.0, 3600.0);
        finiteIn("--warmup-ms", settings.warmupMs, 0.0, 60000.0);
        // ---- the sweep, from a preset or the lists -------------------------------------------------------
        std::vector<SweepGroup> groups;
        const bool listsGiven = app.count("--scenes") || app.count("--modes") || app.count("--schemes") ||
                                app.count("--budgets") || app.count("--index-bits") || app.count("--volume-tests") ||
                                app.count("--msaa") || app.count("--per-sample") || app.count("--transparency") || app.count("--tiled-depth-bounds") || app.count("--volume-detail") ||
                                app.count("--resolution");
        if ((quick || full) && listsGiven)
            throw Error(std::string("--") + (quick ? "quick" : "full") +
                        " is a fixed sweep; drop the --scenes/--modes/... lists, or drop the preset");
        if (quick) {
            groups = quickPreset();
            settings.warmup = app.count("--warmup") ? settings.warmup : 1;
            settings.warmupMs = app.count("--warmup-ms") ? settings.warmupMs : 0.0;
            settings.frames = app.count("--frames") ? settings.frames : 1;
        } else if (full) {
            groups = fullPreset();
            settings.warmup = app.count("--warmup") ? settings.warmup : 1;
            settings.frames = app.count("--frames") ? settings.frames : 5;
            settings.maxSeconds = app.count("--max-seconds") ? settings.maxSeconds : 3.0;
        } else {
            SweepGroup g;
            g.name = "command-line";
            g.scenes = splitList(scenes);
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
            g.volumeDetail = onOffList(volumeDetail, "--volume-detail value");
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

        // ---- outputs first: an unwritable folder fails before any GL work --------------------------------
        if (!dryRun) ReportWriter::checkWritable(outDir);

        ContextOptions co;
        co.backend = parseContextBackend(context);
        auto ctx = GlContext::create(co);
        const GlInfo& info = ctx->info();

        std::map<std::string, Scene> sceneCache;
        const Plan plan = buildPlan(groups, info, seed, sceneCache);
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
                            {"max_seconds_per_config", settings.maxSeconds}, {"seed", seed},
                            {"preset", quick ? "quick" : full ? "full" : "none"}};
        meta["frames_summary"] = "warm-up of at least " + std::to_string(settings.warmup) + " frame(s) and " +
                                 std::to_string(int(settings.warmupMs)) + " ms (the rows give the count), then up to " +
                                 std::to_string(settings.frames) +
                                 " measured frames per configuration, measuring stops after " +
                                 std::to_string(int(settings.maxSeconds)) + " s (at least 1 frame); a warm-up "
                                 "frame longer than that is the one measured frame";
        const std::string loadBefore = readLoadAverage();
        meta["load_average_before"] = loadBefore;
        meta["load_summary"] = loadBefore + " / (running)";
        meta["cpu_cores_note"] = "load averages are over 1, 5 and 15 minutes";

        installSignalHandlers();
        std::vector<double> weights;
        for (const Run& r : plan.runs) weights.push_back(expectedCost(r, sceneCache.at(r.scene)));
        Progress progress(!noProgress && isatty(STDERR_FILENO), weights);

        std::map<std::string, Reference> references;
        std::map<std::string, int> maxOverlaps;  // scene|size -> most lights touching one surface pixel
        std::map<std::string, std::vector<PointLight>> lightCache;
        int nextId = 1;
        for (size_t i = 0; i < plan.runs.size() && !g_stop; ++i) {
            const Run& run = plan.runs[i];
            const Scene& scene = sceneCache.at(run.scene);
            if (!lightCache.count(run.scene)) lightCache[run.scene] = scene.lightsAt(scene.time);
            const std::vector<PointLight>& lights = lightCache.at(run.scene);
            progress.show(i, run.scene + " " + run.config.key());

            Row row;
            row.id = nextId;
            row.run = run;
            row.sceneLights = int(lights.size());
            const std::string key = refKey(run);
            const bool isBrute = run.config.mode == "forward-brute";
            if (!references.count(key)) {
                // The reference for this scene, size, MSAA and transparency: rendered once, reused by every row.
                auto ref = createBenchRenderer(referenceConfigFor(run.config), info, scene, run.width, run.height);
                Settings refSettings = settings;
                if (!isBrute) refSettings.warmup = 0, refSettings.frames = 1;
                const Measured m = measure(*ref, scene, lights, refSettings);
                Reference r;
                r.image = ref->targets().readColor();
                // The scene's maximum overlap at this size, from single-sample depth: an MSAA reference has
                // none, so a plain reference frame is rendered for it once.
                const std::string overlapKey = run.scene + "|" + std::to_string(run.width) + "x" + std::to_string(run.height);
                if (!maxOverlaps.count(overlapKey)) {
                    std::unique_ptr<Renderer> plain;
                    const Renderer* depthSource = ref.get();
                    if (run.config.msaa > 0) {
                        ModeConfig plainConfig = referenceConfigFor(run.config);
                        plainConfig.msaa = 0;
                        plainConfig.perSample = false;
                        plain = createBenchRenderer(plainConfig, info, scene, run.width, run.height);
                        plain->render(scene.camera, lights, ShadingParameters{scene.ambient, scene.backgroundColor});
                        depthSource = plain.get();
                    }
                    maxOverlaps[overlapKey] =
                        computeCoverage(depthSource->targets().readDepth(),
                                        cameraMatrices(scene.camera, run.width, run.height), lights)
                            .maxOverlap();
                }
                r.maxOverlap = maxOverlaps.at(overlapKey);
                references.emplace(key, std::move(r));
                if (isBrute) {
                    fillTiming(row, m);
                    row.lightDataBytes = ref->lightDataBytes();
                }
            }
            const Reference& reference = references.at(key);
            row.maxOverlap = reference.maxOverlap;
            if (isBrute && row.frames == 0) {  // its reference came from an earlier row (not in the usual order)
                auto r = createBenchRenderer(run.config, info, scene, run.width, run.height);
                fillTiming(row, measure(*r, scene, lights, settings));
            }
            if (isBrute) {
                row.error = compareImages(reference.image, reference.image);
            } else {
                auto renderer = createBenchRenderer(run.config, info, scene, run.width, run.height);
                const Measured m = measure(*renderer, scene, lights, settings);
                fillTiming(row, m);
                row.lightDataBytes = renderer->lightDataBytes();
                const ImageRGBA8 image = renderer->targets().readColor();
                if (auto* lidrRenderer = dynamic_cast<LidrRenderer*>(renderer.get())) {
                    const FrameEvaluation ev = evaluateFrame(*lidrRenderer, scene.camera, lights, image, reference.image);
                    row.error = ev.error;
                    // Per-sample index targets are multisample textures: evaluateFrame judges only the image.
                    row.hasLists = !lidrRenderer->perSampleIndices();
                    row.droppedLightPixels = ev.lists.droppedLightPixels;
                    row.pixelsWithDrops = ev.lists.pixelsWithDrops;
                    row.pixelsOverBudget = ev.pixelsOverBudget;
                    row.invalidSlots = ev.lists.invalidSlots;
                    row.maxMarked = ev.maxMarked;
                    row.psnrWithinBudget = ev.errorWithinBudget.psnr;
                } else {
                    row.error = compareImages(image, reference.image);
                }
            }
            writer->add(row, runInfo);
            ++nextId;
            if (settings.interruptAfter >= 0 && nextId - 1 >= settings.interruptAfter) std::raise(SIGINT);
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
