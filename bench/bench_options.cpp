#include "bench_options.h"

#include <cmath>
#include <iostream>
#include <sstream>

#include "lidr/base/error.h"
#include "lidr/gl/render_targets.h"
#include "lidr/modes/render_options.h"
#include "lidr/technique/packing_scheme.h"

namespace lidr::bench {

namespace {
std::string trim(std::string s) {
    s.erase(0, s.find_first_not_of(" \t"));
    s.erase(s.find_last_not_of(" \t") + 1);
    return s;
}

// The sweep lists, in --help order, with the bench's defaults (empty: what the library has, or its default).
std::vector<SweepList> sweepLists() {
    return {{"--modes", "mode", {}},
            {"--schemes", "scheme", {}},
            {"--budgets", "budget", {"1,2,4,8,16"}},
            {"--index-bits", "index-bits", {"4,8,16"}},
            {"--volume-tests", "volume-test", {"sphere,backface,exact,frontface"}},
            {"--msaa", "msaa", {"0"}},
            {"--per-sample", "msaa-per-sample", {"off"}},
            {"--msaa-spans", "msaa-spans", {"auto"}},
            {"--transparency", "transparency", {"on"}},
            {"--tiled-depth-bounds", "no-depth-bounds", {"on,off"}},  // on: depth bounds (the flag's opposite)
            {"--cluster-tile-sizes", "cluster-tile-size", {}},
            {"--cluster-slices", "cluster-slices", {}},
            {"--cluster-slicings", "cluster-slicing", {}},
            {"--cluster-occupancy", "cluster-occupancy", {}},
            {"--multipass-accumulation", "multipass-accumulation", {"auto"}},
            {"--deferred-stencil", "deferred-stencil", {"off"}},
            {"--volume-detail", "volume-detail", {"off"}},
            {"--volume-tiles", "volume-tiles", {"on"}},
            {"--regional-indices", "regional-indices", {"on"}},
            {"--volume-tile-size", "volume-tile-size", {"16"}}};
}

std::vector<int> intList(const std::vector<std::string>& items, const char* what) {
    std::vector<int> out;
    for (const std::string& s : items) {
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

std::vector<bool> onOffList(const std::vector<std::string>& items) {
    std::vector<bool> out;
    for (const std::string& s : items) out.push_back(s == "on" || s == "1" || s == "true");  // checked: a flag row
    return out;
}

void addSceneOptions(CLI::App& app, BenchOptions& o) {
    app.add_option("--scenes,--scene", o.scenes, "Scenes: " + sceneNameHelp())->capture_default_str();
    app.add_option("--environment", o.environments,
                   "Environment light of every --scenes scene: none (default: the scene's own look), default (the "
                   "built-in studio room: the scene runs as SCENE+environment), or none,default for both in one run "
                   "(doc/benchmarks.md, \"Environment light\")")
        ->capture_default_str();
    o.lists = sweepLists();
    for (SweepList& list : o.lists) {
        const RenderOption& row = *findRenderOption(list.row);
        CLI::Option* option = app.add_option(list.option, list.values, "Comma-separated, each measured: " + row.help);
        if (!list.values.empty()) option->capture_default_str();
    }
    app.add_option("--resolution", o.resolutions, "WIDTHxHEIGHT, or 'scene' for the scene's own")->capture_default_str();
}

void addMeasuringOptions(CLI::App& app, Settings& s) {
    app.add_option("--warmup", s.warmup, "Warm-up frames per configuration (at least)")->capture_default_str()->check(CLI::Range(0, 100));
    app.add_option("--warmup-ms", s.warmupMs,
                   "Warm-up lasts at least this long per configuration after its first frame, so that a GPU's clocks "
                   "rise from idle (0: frames only; at most 1000 warm-up frames)")
        ->capture_default_str()->check(CLI::Range(0.0, 60000.0));
    app.add_option("--frames", s.frames,
                   "Interleaved rounds per scene set = measured frames per configuration (median, min, max and the "
                   "ratio to the baseline reported)")
        ->capture_default_str()->check(CLI::Range(1, 1000));
    app.add_option("--max-seconds", s.maxSeconds,
                   "Per scene set (one scene and size): start no round after the rounds took this many seconds (at "
                   "least one round); a configuration whose first frame takes over MAX-SECONDS / FRAMES is measured "
                   "once, outside the rounds")
        ->capture_default_str()->check(CLI::Range(0.001, 36000.0));
    app.add_option("--max-live", s.maxLive,
                   "Renderers alive at once: a scene set with more configurations is measured in parts of this many, "
                   "the baseline in each (memory: ~30 MB a renderer at 1024x768 on llvmpipe)")
        ->capture_default_str()->check(CLI::Range(2, 100000));
}

void addRunOptions(CLI::App& app, BenchOptions& o) {
    app.add_option("--out", o.outDir, "Output folder: results.csv, passes.csv, results.json, summary.md, plots/")->capture_default_str();
    app.add_option("--seed", o.seed, "Seed of the room's and many-light scenes' lights")->capture_default_str();
    app.add_option("--lights", o.extraLights,
                   "Scatter N more seeded point lights over every --scenes scene's surfaces (lidr::scatterLights, "
                   "as lidr-demo --lights N)")
        ->check(CLI::Range(1, 65535));
    app.add_option("--light-radius", o.extraLightRadius,
                   "Radius of --lights in scene units (default: chosen from the scene's size and N, doc/colour.md)");
    app.add_option("--camera", o.camera,
                   "View every --scenes glTF file through its camera N (the index in the file's cameras array, from 0; "
                   "default: its first camera in node order); a scene without camera N is an error")
        ->check(CLI::Range(0, 1 << 30));
    app.add_option("--context", o.context, "GL context: auto, egl, egl-device, egl-gles2, glfw, osmesa (env LIDR_CONTEXT)")->capture_default_str();
}

void addPresetOptions(CLI::App& app, BenchOptions& o) {
    auto* quickFlag = app.add_flag("--quick", o.quick, "Seconds-long smoke run: tiny resolution, few configurations, one frame");
    auto* fullFlag = app.add_flag("--full", o.full, "The documented full sweep of doc/benchmarks.md, the scaling sweeps included (takes minutes)")->excludes(quickFlag);
    app.add_option("--sweep", o.sweeps,
                   "Scaling sweeps instead of the lists: " + joinNames(sweepNames()) +
                       " (frame time against light count / scene triangles / hall light count / shadow casters in the hall; the "
                       "clustered grid's tile sizes, slices, slicings and occupancy on the bench scenes; LIDR's default "
                       "against tiled, clustered, multi-pass and --mode auto on issue 37's scenes, the best-peer targets); "
                       "with --quick, their seconds-long versions")
        ->excludes(fullFlag);
    app.add_flag("--no-progress", o.noProgress, "No progress bar (it is also off when stderr is not a terminal)");
    app.add_flag("--no-plots", o.noPlots, "Do not run gnuplot");
    o.bart = std::string(LIDR_SOURCE_DIR) + "/../shared/bart-robots";
    app.add_option("--animation", o.animationFrames,
                   "Time every mode over the scene's animation: N frames sampled evenly over its time range, each mode "
                   "drawing each frame in turn (default resolution 1920x1080; doc/bart.md); writes animation.csv, "
                   ".json, .md and plots");
    app.add_option("--reference-frames", o.referenceFrames,
                   "With --animation: frames judged against forward-brute (PSNR, dropped light-pixels), spread evenly")
        ->capture_default_str();
    app.add_option("--bart", o.bart, "Where bart-robots-many / -few are read from: a folder with aff/Robot.aff, or an AFF file")
        ->capture_default_str();
    app.add_flag("--dry-run", o.dryRun, "Check everything, print the configurations that would run and the skipped ones, measure nothing");
    app.add_flag("--list", o.list, "Print the valid mode, scheme, volume-test and scene names and exit");
    app.add_flag("--list-options", o.listOptions,
                 "Print the sweep lists of renderer settings (OPTION, the lidr::renderOptions() row, the default list; "
                 "tab-separated) and exit");
    app.add_option("--interrupt-after", o.settings.interruptAfter, "Testing aid: act as if interrupted after this many rows")
        ->group("");
    app.add_option("--interrupt-after-rounds", o.settings.interruptAfterRounds,
                   "Testing aid: act as if interrupted at the end of this many rounds")
        ->group("");
}

// The lists given on the command line, as one sweep group; each element checked by its table row.
SweepGroup commandLineGroup(const CLI::App& app, const BenchOptions& o) {
    SweepGroup g;
    g.name = "command-line";
    for (const std::string& scene : splitList(o.scenes))
        for (const std::string& environment : splitList(o.environments)) {
            if (environment != "none" && environment != "default")
                throw Error("--environment must be none, default or both (none,default), got '" + environment + "'");
            g.scenes.push_back(environment == "none" ? scene : scene + "+environment");
        }
    for (const SweepList& list : o.lists)
        for (const std::string& value : o.listOf(list.option)) try {
                checkRenderOption(*findRenderOption(list.row), value);
            } catch (const Error& e) {
                throw Error(std::string(list.option) + ": " + e.what());
            }
    g.modes = o.listOf("--modes").empty() ? availableModes() : o.listOf("--modes");
    g.schemes = o.listOf("--schemes").empty() ? packingSchemeNames() : o.listOf("--schemes");
    g.budgets = intList(o.listOf("--budgets"), "budget");
    g.indexBits = intList(o.listOf("--index-bits"), "index width");
    g.volumeTests = o.listOf("--volume-tests");
    g.msaa = intList(o.listOf("--msaa"), "MSAA sample count");
    for (int samples : g.msaa) checkSampleCount(samples, "--msaa");
    g.perSample = onOffList(o.listOf("--per-sample"));
    g.msaaSpans = o.listOf("--msaa-spans");
    g.transparency.clear();
    for (const std::string& t : o.listOf("--transparency"))
        if (t == "scene") throw Error("--transparency: on or off (a sweep has no scene's own), got 'scene'");
        else g.transparency.push_back(t == "on");
    g.tiledDepthBounds = onOffList(o.listOf("--tiled-depth-bounds"));
    g.multipassEightBit.clear();
    for (const std::string& a : o.listOf("--multipass-accumulation")) g.multipassEightBit.push_back(a == "8-bit");
    g.deferredStencil = onOffList(o.listOf("--deferred-stencil"));
    g.volumeDetail = onOffList(o.listOf("--volume-detail"));
    g.volumeTiles = onOffList(o.listOf("--volume-tiles"));
    g.volumeTileSizes = intList(o.listOf("--volume-tile-size"), "--volume-tile-size value");
    g.regionalIndices = onOffList(o.listOf("--regional-indices"));
    if (!o.listOf("--cluster-tile-sizes").empty())
        g.clusterTileSizes = intList(o.listOf("--cluster-tile-sizes"), "--cluster-tile-sizes value");
    if (!o.listOf("--cluster-slices").empty())
        g.clusterSlices = intList(o.listOf("--cluster-slices"), "--cluster-slices value");
    if (!o.listOf("--cluster-slicings").empty()) g.clusterSlicings = o.listOf("--cluster-slicings");
    if (!o.listOf("--cluster-occupancy").empty()) {
        g.clusterOccupancy.clear();
        for (bool on : onOffList(o.listOf("--cluster-occupancy"))) g.clusterOccupancy.push_back(on);
    }
    for (const std::string& r : splitList(o.resolutions)) g.resolutions.push_back(parseResolution(r));
    // Lists left at their defaults sweep "whatever the library supports"; typed lists are strict.
    const std::pair<const char*, const char*> typed[] = {
        {"--modes", "mode"}, {"--schemes", "scheme"}, {"--budgets", "budget"}, {"--index-bits", "index width"},
        {"--volume-tests", "volume test"}, {"--msaa", "MSAA"}, {"--per-sample", "per-sample"},
        {"--transparency", "transparency"}};
    for (const auto& [option, dimension] : typed)
        if (app.count(option)) g.strictDimensions.insert(dimension);
    return g;
}
}  // namespace

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

std::vector<std::string> BenchOptions::listOf(const std::string& option) const {
    for (const SweepList& list : lists)
        if (option == list.option) return splitList(list.values);
    throw Error("lidr-bench: no list " + option);
}

void addBenchOptions(CLI::App& app, BenchOptions& o) {
    addSceneOptions(app, o);
    addMeasuringOptions(app, o.settings);
    addRunOptions(app, o);
    addPresetOptions(app, o);
}

void printSweepLists(const BenchOptions& o) {
    for (const SweepList& list : o.lists) {
        std::string values;
        for (const std::string& v : splitList(list.values)) values += (values.empty() ? "" : ",") + v;
        std::cout << list.option << "\t" << list.row << "\t" << (values.empty() ? "-" : values) << "\n";
    }
}

std::vector<SweepGroup> chosenSweep(const CLI::App& app, BenchOptions& o) {
    bool listsGiven = app.count("--scenes") || app.count("--environment") || app.count("--resolution");
    for (const SweepList& list : o.lists) listsGiven = listsGiven || app.count(list.option);
    if ((o.quick || o.full || !o.sweeps.empty()) && listsGiven)
        throw Error(std::string("--") + (!o.sweeps.empty() ? "sweep" : o.quick ? "quick" : "full") +
                    " is a fixed sweep; drop the --scenes/--modes/... lists, or drop the preset");
    Settings& s = o.settings;
    std::vector<SweepGroup> groups;
    if (!o.sweeps.empty()) {
        for (const std::string& name : splitList(o.sweeps))
            for (const SweepGroup& g : sweepPreset(name, o.quick)) groups.push_back(g);  // throws on a bad name
        if (groups.empty()) throw Error("--sweep needs a name (valid: " + joinNames(sweepNames()) + ")");
        s.warmup = app.count("--warmup") ? s.warmup : 1;
        s.warmupMs = app.count("--warmup-ms") || !o.quick ? s.warmupMs : 0.0;
        s.frames = app.count("--frames") ? s.frames : o.quick ? 1 : 5;
        s.maxSeconds = app.count("--max-seconds") ? s.maxSeconds : 120.0;
    } else if (o.quick) {
        groups = quickPreset();
        s.warmup = app.count("--warmup") ? s.warmup : 1;
        s.warmupMs = app.count("--warmup-ms") ? s.warmupMs : 0.0;
        s.frames = app.count("--frames") ? s.frames : 1;
    } else if (o.full) {
        groups = fullPreset();
        s.warmup = app.count("--warmup") ? s.warmup : 1;
        s.frames = app.count("--frames") ? s.frames : 5;
        s.maxSeconds = app.count("--max-seconds") ? s.maxSeconds : 120.0;
    } else {
        groups.push_back(commandLineGroup(app, o));
    }
    return groups;
}

}  // namespace lidr::bench
