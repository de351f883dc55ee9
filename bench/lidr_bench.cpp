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
#include "bench_measure.h"
#include "bench_options.h"
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


void printNames() {
    std::cout << "render modes:   " << joinNames(availableModes()) << "\n"
              << "packing schemes: " << joinNames(packingSchemeNames()) << "\n"
              << "budgets, index widths: those lidr::renderOptions() lists (lidr-demo --list-options); each scheme "
                 "refuses what it cannot do (see --dry-run)\n"
              << "volume tests:   sphere (the library's default; sphere-span under MSAA), sphere-span, sphere-ray, backface, "
                 "exact, frontface\n"
              << "cluster slicings: exponential, near-slice (clustered mode; tile sizes 4..256, slices 1..64)\n"
              << "scenes:         " << sceneNameHelp() << "\n";
}

// The commit the run measured: HEAD, marked where the tree has changes outside the output folder or the binary was
// configured at another commit.
std::string commitDescription(const std::string& outDir) {
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
    return commit;
}

// results.json's "meta": date, machine, GL, commit, command line, settings and the load before the run.
void describeRun(nlohmann::json& meta, const GlInfo& info, const BenchOptions& o, const std::string& commandLine) {
    const Settings& settings = o.settings;
    const unsigned seed = o.seed;
    const bool quick = o.quick, full = o.full;
    const std::vector<std::string>& sweeps = o.sweeps;
    meta["date"] = utcNow();
    meta["machine"] = machineJson();
    meta["machine_summary"] = meta["machine"]["cpu_model"].get<std::string>() + ", " +
                              std::to_string(meta["machine"]["cpu_cores"].get<int>()) + " cores";
    meta["gl"] = {{"backend", info.backend}, {"renderer", info.renderer}, {"version", info.version},
                  {"vendor", info.vendor}, {"glsl", info.glslVersion}, {"timer_query", info.timerQuery}};
    meta["gl_summary"] = info.renderer + " (" + info.version + ")";
    meta["commit"] = commitDescription(o.outDir);
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
}

// --animation N: every mode over the scenes' animation (bench_animation.h).
int runAnimation(const CLI::App& app, const BenchOptions& o, const std::string& commandLine) {
    try {
        AnimationBenchOptions animation;
        animation.scenes = splitList(o.scenes);
        animation.frames = o.animationFrames;
        if (app.count("--resolution")) animation.resolution = parseResolution(splitList(o.resolutions).at(0));
        animation.modes = o.listOf("--modes");
        animation.referenceFrames = o.referenceFrames;
        animation.seed = o.seed;
        animation.bart = o.bart;
        animation.outDir = o.outDir;
        animation.context = o.context;
        animation.commandLine = commandLine;
        animation.plots = !o.noPlots;
        return runAnimationBench(animation);
    } catch (const std::exception& e) {
        std::cerr << "lidr-bench: error: " << e.what() << "\n";
        return 1;
    }
}

// The numbers CLI::Range lets through (NaN: every comparison with it is false) and --light-radius without --lights.
void checkNumbers(const BenchOptions& o) {
    const auto finiteIn = [](const char* option, double value, double lo, double hi) {
        if (!(std::isfinite(value) && value >= lo && value <= hi)) {
            std::ostringstream text;
            text << option << " must be a finite number in [" << lo << ", " << hi << "], got " << value;
            throw Error(text.str());
        }
    };
    finiteIn("--max-seconds", o.settings.maxSeconds, 0.001, 36000.0);  // as the option's range says
    finiteIn("--warmup-ms", o.settings.warmupMs, 0.0, 60000.0);
    const double radius = o.extraLightRadius;
    if (radius != 0.0 && o.extraLights == 0)
        throw Error("--light-radius sets the radius of --lights: give --lights N too");
    if (!(std::isfinite(radius) && radius >= 0.0 && radius <= double(maxLightRadius)))
        throw Error("--light-radius must be a finite number > 0, got " + std::to_string(radius));
}

// --dry-run: the configurations that would run and the combinations the library refused.
void printPlan(const Plan& plan) {
    for (const Run& r : plan.runs)
        std::cout << "  run   " << r.group << " | " << r.scene << " " << r.width << "x" << r.height << " | "
                  << r.config.key() << "\n";
    for (const Skipped& s : plan.skipped)
        std::cout << "  skip  " << s.group << " | " << s.scene << " " << s.width << "x" << s.height << " | "
                  << s.label << ": " << s.reason << "\n";
}

// Measures the plan set by set into the report, then writes results.json, the plots and summary.md. Returns the
// exit code: 130 when interrupted (the rows measured so far are kept).
int measureAndReport(const Plan& plan, const GlInfo& info, const BenchOptions& o, const std::string& commandLine,
                     const std::map<std::string, Scene>& sceneCache) {
    auto writer = std::make_unique<ReportWriter>(o.outDir);
    RunInfo runInfo;
    runInfo.planned = plan.runs.size();
    runInfo.skipped = plan.skipped;
    nlohmann::json& meta = runInfo.meta;
    describeRun(meta, info, o, commandLine);
    const std::string loadBefore = meta["load_average_before"].get<std::string>();

    installSignalHandlers();
    const std::vector<std::vector<const Run*>> sets = sceneSets(plan);
    std::vector<double> weights;  // in the order the rows come: set by set
    for (const auto& set : sets)
        for (const Run* r : set) weights.push_back(expectedCost(*r, sceneCache.at(r->scene)));
    Progress progress(!o.noProgress && isatty(STDERR_FILENO), weights);
    SetMeasurer measurer(info, o.settings, sceneCache, progress, *writer, runInfo);
    for (const std::vector<const Run*>& set : sets) {
        if (stopRequested()) break;
        measurer.measure(set);
    }
    progress.finish();
    runInfo.interrupted = stopRequested();
    runInfo.complete = !runInfo.interrupted && writer->rows().size() == plan.runs.size();
    meta["load_average_after"] = readLoadAverage();
    meta["load_summary"] = loadBefore + " / " + meta["load_average_after"].get<std::string>();
    writer->writeJson(runInfo);
    std::string plotMessage = "plots not asked for (--no-plots)";
    std::vector<std::string> plots;
    if (!o.noPlots) plots = writer->writePlots(plotMessage);
    writer->writeSummary(runInfo, plots, plotMessage);
    std::cout << "lidr-bench: " << writer->rows().size() << " rows"
              << (runInfo.interrupted ? " (INTERRUPTED: the rows measured so far are kept)" : "") << " in " << o.outDir
              << "/{results.csv,passes.csv,results.json,summary.md}; " << plotMessage << "\n";
    return runInfo.interrupted ? 130 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"lidr-bench: run time against error for every render mode, packing scheme, budget, index width and "
                 "volume test. Lists are comma-separated; every combination of the lists is measured (combinations "
                 "the library refuses are skipped and listed)."};
    BenchOptions o;
    addBenchOptions(app, o);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    if (o.list) {
        printNames();
        return 0;
    }
    if (o.listOptions) {
        printSweepLists(o);
        return 0;
    }
    std::string commandLine;
    for (int i = 0; i < argc; ++i) commandLine += (i ? " " : "") + shellWord(argv[i]);
    benchBartFolder() = o.bart;
    if (app.count("--animation")) return runAnimation(app, o, commandLine);
    try {
        checkNumbers(o);
        const std::vector<SweepGroup> groups = chosenSweep(app, o);  // a preset or the lists
        if (!o.dryRun) ReportWriter::checkWritable(o.outDir);  // an unwritable folder fails before any GL work
        ContextOptions co;
        co.backend = parseContextBackend(o.context);
        auto ctx = GlContext::create(co);
        const GlInfo& info = ctx->info();
        std::map<std::string, Scene> sceneCache;
        LightScatterOptions scatter;
        scatter.count = o.extraLights;
        scatter.radius = float(o.extraLightRadius);
        const Plan plan = buildPlan(groups, info, o.seed, sceneCache, scatter, o.camera);
        std::cout << "lidr-bench: " << plan.runs.size() << " configurations to measure, " << plan.skipped.size()
                  << " combinations skipped (refused by the library); GL: " << info.renderer << "\n";
        if (o.dryRun) {
            printPlan(plan);
            return 0;
        }
        return measureAndReport(plan, info, o, commandLine, sceneCache);
    } catch (const std::exception& e) {
        std::cerr << "lidr-bench: error: " << e.what() << "\n";
        return 1;
    }
}
