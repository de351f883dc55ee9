#pragma once
// lidr-bench's results and how they are written: CSV rows as they are measured (results.csv, passes.csv),
// results.json rewritten after every row, summary.md with the tables and the targets, and gnuplot
// plots (PNG) when gnuplot is installed.
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench_config.h"
#include "lidr/eval/image_compare.h"
#include "lidr/gl/gl_state.h"

namespace lidr::bench {

struct Stat {
    double median = 0.0, min = 0.0, max = 0.0;
    static Stat of(std::vector<double> samples);
};

struct PassStat {
    std::string pass;
    Stat ms;
    // The last measured frame's: draws and state calls in the pass, fragment shader invocations (-1: not counted,
    // the context has no ARB_pipeline_statistics_query).
    long drawCalls = 0, stateCalls = 0, fragments = -1;
};

struct Row {
    int id = 0;
    Run run;
    int sceneLights = 0;
    int maxOverlap = 0;                // most lights touching one surface pixel (CPU truth, reference depth)
    std::string timingMethod;
    int warmupFrames = 0, frames = 0;
    Stat frameMs, wallMs;              // frame: sum of the passes; wall: CPU clock around render + glFinish
    std::vector<PassStat> passes;
    double lightVolumeMs = 0.0;        // median of the light-volume passes' sum (LIDR), else 0
    size_t lightDataBytes = 0;
    std::string multipassAccumulation;  // forward-multipass: where its passes summed ("half-float", "8-bit")
    int drawnLights = 0;
    GlCallCounters glCalls;            // the last measured frame's, through the state cache (lidr/gl/gl_state.h)
    // LIDR's automatic configuration, last measured frame: budget and width chosen, re-packs over all frames.
    int autoBudget = 0, autoIndexBits = 0, autoRepacks = 0;
    // LIDR frames: 1 where the last measured frame's opaque pass skipped hidden fragments' lists (MSAA with the
    // samples' distances, AutoDecision::hiddenFragmentSkip), 0 where not; -1 for other modes.
    int hiddenSkip = -1;
    bool hasError = true;              // false: a timing-only sweep (SweepGroup::reference), no error columns
    ImageError error;                  // against forward-brute with the same MSAA and transparency
    // LIDR only: the decoded index lists against the CPU truth.
    bool hasLists = false;
    long droppedLightPixels = 0, pixelsWithDrops = 0, pixelsOverBudget = 0, invalidSlots = 0;
    int maxMarked = 0;
    double psnrWithinBudget = 0.0;
    // LIDR only: the light-pixel pairs of the CPU truth (the sum of the true list lengths) and the fragments the
    // volume pass rasterised (the opaque light-volume pass; -1: not counted). Their ratio is the volume pass's
    // efficiency (1: it touches only what it lights).
    long trueLightPixels = -1, volumeFragments = -1;
    double volumeEfficiency() const {
        return trueLightPixels > 0 && volumeFragments >= 0 ? double(volumeFragments) / double(trueLightPixels) : -1.0;
    }
    // Tiled and clustered (no MSAA): each pixel's list against the CPU truth. droppedLightPixels and
    // pixelsWithDrops: pairs missing from it; trueLightPixels: the truth's pairs; extraLightPixels: listed lights
    // that do not touch the pixel's surface (the conservative test's overhead, clustered's counterpart of LIDR's
    // volume fragments per pair).
    bool hasPixelLists = false;
    long extraLightPixels = -1;
    // How many times the frame ran the lighting function (the paper's Figure 3; frame_accuracy.h says how each mode
    // is counted); -1: not counted. Per true light-pixel pair: 1 is the least an exact frame can do.
    long lightingComputations = -1;
    double lightingPerTruePair() const {
        return trueLightPixels > 0 && lightingComputations >= 0 ? double(lightingComputations) / double(trueLightPixels)
                                                                : -1.0;
    }
    double extraPerTruePair() const {
        return trueLightPixels > 0 && extraLightPixels >= 0 ? double(extraLightPixels) / double(trueLightPixels) : -1.0;
    }
    long sceneTriangles = 0;
    // Shadows (the -shadows-K scenes): casters, maps drawn by the first frame and that pass's time, the most maps
    // any later frame drew (0: a static scene's maps are drawn once).
    int shadowCasters = 0, shadowMapsFirst = 0, shadowMapsLater = 0;
    double shadowMapsFirstMs = 0.0;
    // Interleaved rounds (doc/benchmarks.md): every configuration of one scene and size renders one measured
    // frame per round, in turn. `rounds`: the rounds its scene set ran; roundMs[r]: this configuration's frame
    // time in round r (empty when it was measured once, outside the rounds: a first frame over the cap).
    int rounds = 0;
    std::vector<double> roundMs;
    std::string setKey;                // "scene WxH": rows with the same key were measured in the same rounds
    std::string baseline;              // the configuration (key) the ratios divide by
    Stat ratio;                        // frame time / baseline's frame time in the same round, over rounds
    double frameSpread() const {       // (max - min) / median of its frame times over the rounds
        return frameMs.median > 0 ? (frameMs.max - frameMs.min) / frameMs.median : 0.0;
    }
    double lightVolumeShare() const { return frameMs.median > 0 ? lightVolumeMs / frameMs.median : 0.0; }
};

struct RunInfo {
    nlohmann::json meta;               // machine, GL, commit, command line, settings
    std::vector<Skipped> skipped;
    bool interrupted = false;
    bool complete = false;
    size_t planned = 0;
};

// How steady the machine was over the run: the median over configurations (measured in >= 2 rounds) of
// (max - min) / median of their frame times across rounds, and the same for their ratios to the baseline
// (baselines themselves excluded). verdict: "steady", "noisy: ratios within X%", or why it is unknown.
struct Steadiness {
    int configurations = 0;            // rows that had >= 2 rounds
    double frameSpread = 0.0;          // median relative spread of frame times
    double ratioSpread = 0.0;          // median relative spread of the ratios
    double worstRatioSpread = 0.0;
    int roundsMin = 0, roundsMax = 0;
    std::string verdict;
};
Steadiness steadiness(const std::vector<Row>& rows);
// Ratio of A's to B's frame time: the median over their common rounds when both were measured in the same
// rounds (`inRounds` true, min/max over rounds in `range`); else, in two parts of one scene set (same
// baseline), the ratio of their ratio medians; else the ratio of their frame-time medians.
double pairRatio(const Row& a, const Row& b, bool* inRounds = nullptr, Stat* range = nullptr);

// PSNR of identical images is infinite; the files write 999 for it (as lidr-demo does).
double finitePsnr(double psnr);

class ReportWriter {
public:
    // Creates `dir` and opens the CSV files: throws lidr::Error if the folder cannot be written, before the
    // sweep starts.
    explicit ReportWriter(const std::string& dir);
    // Creates `dir` if needed and checks a file can be written there (then removes it); throws lidr::Error.
    // Run before the sweep is checked, so a bad folder is reported first and nothing in it is replaced.
    static void checkWritable(const std::string& dir);
    const std::string& dir() const { return dir_; }
    void add(const Row& row, const RunInfo& info);  // appends to the CSVs (flushed) and rewrites the JSON
    void writeJson(const RunInfo& info) const;
    // summary.md: settings, the targets, one table per scene, the plots (paths relative to dir), what was
    // skipped.
    void writeSummary(const RunInfo& info, const std::vector<std::string>& plots, const std::string& plotMessage) const;
    // Plots via gnuplot; returns the PNGs written, or nothing with `message` saying why.
    std::vector<std::string> writePlots(std::string& message) const;
    const std::vector<Row>& rows() const { return rows_; }

private:
    std::string dir_;
    std::ofstream csv_, passesCsv_;
    std::vector<Row> rows_;
};

// The columns of results.csv, in order (the test checks them).
const std::vector<std::string>& resultColumns();
const std::vector<std::string>& passColumns();

}  // namespace lidr::bench
