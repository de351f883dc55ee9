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

namespace lidr::bench {

struct Stat {
    double median = 0.0, min = 0.0, max = 0.0;
    static Stat of(std::vector<double> samples);
};

struct PassStat {
    std::string pass;
    Stat ms;
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
    int drawnLights = 0;
    ImageError error;                  // against forward-brute with the same MSAA and transparency
    // LIDR only: the decoded index lists against the CPU truth.
    bool hasLists = false;
    long droppedLightPixels = 0, pixelsWithDrops = 0, pixelsOverBudget = 0, invalidSlots = 0;
    int maxMarked = 0;
    double psnrWithinBudget = 0.0;
    double lightVolumeShare() const { return frameMs.median > 0 ? lightVolumeMs / frameMs.median : 0.0; }
};

struct RunInfo {
    nlohmann::json meta;               // machine, GL, commit, command line, settings
    std::vector<Skipped> skipped;
    bool interrupted = false;
    bool complete = false;
    size_t planned = 0;
};

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
