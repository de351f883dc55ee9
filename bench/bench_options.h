#pragma once
// lidr-bench's command line: the sweep lists, made from the renderer's table of options (lidr::renderOptions(): each
// element of --budgets 4,8 is one value of the "budget" row, checked by it), the presets, and how a run is measured.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench_config.h"

namespace lidr::bench {

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

// A sweep list of renderer settings: --OPTION a,b,c, each element a value of the table's row `row`.
struct SweepList {
    const char* option;  // "--budgets"
    const char* row;     // "budget" (lidr/modes/render_options.h)
    std::vector<std::string> values;  // as typed (comma-separated lists), else the bench's default
};

struct BenchOptions {
    std::vector<std::string> scenes{"room"}, environments{"none"}, resolutions{"1024x768"};
    std::vector<SweepList> lists;  // the renderer settings' lists, in --help order (sweepLists())
    std::string outDir = "bench-out", context = "auto";
    Settings settings;
    std::vector<std::string> sweeps;
    bool quick = false, full = false, noProgress = false, noPlots = false, dryRun = false, list = false;
    bool listOptions = false;
    unsigned seed = 1;
    int extraLights = 0;
    double extraLightRadius = 0.0;
    int camera = -1;
    int animationFrames = 0, referenceFrames = 8;
    std::string bart;
    // The list of `option` ("--budgets"), split at commas.
    std::vector<std::string> listOf(const std::string& option) const;
};

// Declares every option on `app`, bound to `o`.
void addBenchOptions(CLI::App& app, BenchOptions& o);
// lidr-bench --list-options: each sweep list as OPTION, ROW, DEFAULT ("-": the library's), tab-separated.
void printSweepLists(const BenchOptions& o);
// The sweep to run: a preset (--quick, --full, --sweep) with its measuring defaults, or the lists. Throws
// lidr::Error for a bad value (the table's message, after the list's option) or lists given with a preset.
std::vector<SweepGroup> chosenSweep(const CLI::App& app, BenchOptions& o);
// "a,b", "c" -> a, b, c (trimmed, empty parts dropped).
std::vector<std::string> splitList(const std::vector<std::string>& items);

}  // namespace lidr::bench
