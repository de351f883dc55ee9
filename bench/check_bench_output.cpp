// lidr-bench-check DIR [--expect-plots] [--expect-sweep-plots] [--expect-interrupted] [--min-rows N]
// Checks a lidr-bench output folder is well formed: results.csv has the documented columns and every
// numeric cell is a finite number >= 0; passes.csv belongs to those rows; results.json parses, records the
// machine, GL renderer, commit and command line, and the run's steadiness, and agrees with the CSV; the
// interleaved rounds' columns hold (rounds >= 1, a baseline measured in the same scene and size, ratios
// positive and finite with min <= median <= max, 1 for the baseline itself); summary.md exists; with
// --expect-plots the PNGs are there and are PNGs (--expect-sweep-plots: the light-count, triangle and hall plots). Prints each problem and exits 1 if there is any.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench_report.h"

namespace fs = std::filesystem;

namespace {

int problems = 0;
void problem(const std::string& what) {
    std::cerr << "bench output problem: " << what << "\n";
    ++problems;
}

// RFC 4180 records (quoted fields may hold commas, doubled quotes; no newlines in lidr-bench's fields).
std::vector<std::vector<std::string>> readCsv(const fs::path& path) {
    std::vector<std::vector<std::string>> rows;
    std::ifstream in(path);
    if (!in) {
        problem("cannot read " + path.string());
        return rows;
    }
    std::string line;
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::string cell;
        bool quoted = false;
        for (size_t i = 0; i < line.size(); ++i) {
            const char c = line[i];
            if (quoted) {
                if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') cell += '"', ++i;
                else if (c == '"') quoted = false;
                else cell += c;
            } else if (c == '"') {
                quoted = true;
            } else if (c == ',') {
                cells.push_back(cell);
                cell.clear();
            } else {
                cell += c;
            }
        }
        cells.push_back(cell);
        rows.push_back(cells);
    }
    return rows;
}

bool finiteNonNegative(const std::string& s, double& v) {
    char* end = nullptr;
    v = std::strtod(s.c_str(), &end);
    return end && *end == '\0' && !s.empty() && std::isfinite(v) && v >= 0.0;
}

bool isPng(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    char sig[8] = {};
    f.read(sig, 8);
    return f && std::memcmp(sig, "\x89PNG\r\n\x1a\n", 8) == 0;
}

const std::set<std::string> kTextColumns{"group", "scene", "mode", "config", "scheme", "volume_test", "timing_method",
                                        "baseline", "cluster_slicing"};
// Empty in a timing-only sweep (no reference): all of them or none.
const std::set<std::string> kErrorColumns{"rmse", "psnr_db", "max_abs_error", "differing_pixels", "compared_pixels"};

size_t col(const std::string& name) {
    const auto& cs = lidr::bench::resultColumns();
    return size_t(std::find(cs.begin(), cs.end(), name) - cs.begin());
}

// What the rows of results.csv say about each other: each row's set and the baseline it names.
struct RowSets {
    std::set<std::string> configsBySet;                       // "scene|WxH|config"
    std::vector<std::pair<std::string, std::string>> baselines;  // (row id, "scene|WxH|baseline")
};

// One results.csv row: every number finite and >= 0 where the mode has it, the frame and ratio statistics ordered.
void checkResultRow(const std::vector<std::string>& row, RowSets& sets) {
    const auto& columns = lidr::bench::resultColumns();
    const auto& textColumns = kTextColumns;
    const auto& errorColumns = kErrorColumns;
    std::set<std::string>& configsBySet = sets.configsBySet;
    std::vector<std::pair<std::string, std::string>>& baselines = sets.baselines;
    double frames = 0, median = 0, lo = 0, hi = 0;
    size_t emptyErrors = 0;
    for (size_t c = 0; c < columns.size(); ++c) {
        if (textColumns.count(columns[c])) continue;
        double v = 0;
        if (row[c].empty() && errorColumns.count(columns[c])) {
            ++emptyErrors;
            continue;
        }
        if (row[c].empty()) {  // not applicable to the mode: allowed only in the mode-specific columns
            static const std::set<std::string> optional{"budget", "index_bits", "tiled_depth_bounds",
                "light_volume_ms_median", "light_volume_share", "dropped_light_pixels", "pixels_with_drops",
                "pixels_over_budget", "max_marked", "invalid_slots", "psnr_within_budget_db", "auto_budget",
                "auto_index_bits", "auto_repacks", "true_light_pixels", "volume_fragments",
                "volume_fragments_per_light_pixel", "cluster_tile_size", "cluster_slices", "cluster_slicing",
                "cluster_occupancy", "extra_light_pixels", "extra_per_true_pair", "lighting_computations",
                "lighting_computations_per_true_pair", "hidden_skip"};
            if (!optional.count(columns[c])) problem("results.csv row " + row[0] + ": empty " + columns[c]);
            continue;
        }
        if (!finiteNonNegative(row[c], v))
            problem("results.csv row " + row[0] + ": " + columns[c] + " = '" + row[c] + "' is not a finite number >= 0");
        if (columns[c] == "draw_calls" && v < 1)
            problem("results.csv row " + row[0] + ": no draw call counted (the state cache's counters)");
        if (columns[c] == "frames") frames = v;
        if (columns[c] == "frame_ms_median") median = v;
        if (columns[c] == "frame_ms_min") lo = v;
        if (columns[c] == "frame_ms_max") hi = v;
    }
    if (frames < 1) problem("results.csv row " + row[0] + ": no measured frames");
    if (!(lo <= median && median <= hi)) problem("results.csv row " + row[0] + ": frame median outside [min, max]");
    if (row[7] == "lidr" && row[10].empty()) problem("results.csv row " + row[0] + ": a lidr row without a budget");
    if (row[7] == "lidr" && row[9] == "auto" && (row[col("auto_budget")].empty() || row[col("auto_index_bits")].empty()))
        problem("results.csv row " + row[0] + ": a lidr auto row without the budget and width it chose");
    if (emptyErrors != 0 && emptyErrors != errorColumns.size())
        problem("results.csv row " + row[0] + ": some error columns empty, others not");
    // The interleaved rounds.
    const std::string set = row[col("scene")] + "|" + row[col("width")] + "x" + row[col("height")] + "|";
    configsBySet.insert(set + row[col("config")]);
    const std::string& baseline = row[col("baseline")];
    if (baseline.empty()) problem("results.csv row " + row[0] + ": no baseline named");
    else baselines.push_back({row[0], set + baseline});
    double rounds = 0, rMedian = 0, rMin = 0, rMax = 0;
    const bool ok = finiteNonNegative(row[col("rounds")], rounds) &&
                    finiteNonNegative(row[col("ratio_to_baseline_median")], rMedian) &&
                    finiteNonNegative(row[col("ratio_to_baseline_min")], rMin) &&
                    finiteNonNegative(row[col("ratio_to_baseline_max")], rMax);
    if (ok) {
        if (rounds < 1 || rounds != std::floor(rounds)) problem("results.csv row " + row[0] + ": rounds must be a whole number >= 1");
        if (frames > rounds) problem("results.csv row " + row[0] + ": more measured frames than rounds");
        if (!(rMin > 0 && rMedian > 0 && rMax > 0)) problem("results.csv row " + row[0] + ": a ratio to the baseline is not positive");
        if (!(rMin <= rMedian && rMedian <= rMax)) problem("results.csv row " + row[0] + ": ratio median outside [min, max]");
        if (row[col("config")] == baseline && std::fabs(rMedian - 1.0) > 1e-6)
            problem("results.csv row " + row[0] + ": the baseline's ratio to itself is not 1");
    }
}

// results.csv: the documented header, every row well formed, each row's baseline measured with it. Returns the
// row ids and the line count.
std::set<std::string> checkResultsCsv(const fs::path& dir, size_t minRows, size_t& lines) {
    const auto csv = readCsv(dir / "results.csv");
    const auto& columns = lidr::bench::resultColumns();
    std::set<std::string> ids;
    RowSets sets;
    if (csv.empty() || csv[0] != columns) problem("results.csv header is not the documented column list");
    for (size_t r = 1; r < csv.size(); ++r) {
        const auto& row = csv[r];
        if (row.size() != columns.size()) {
            problem("results.csv row " + std::to_string(r) + " has " + std::to_string(row.size()) + " cells");
            continue;
        }
        ids.insert(row[0]);
        checkResultRow(row, sets);
    }
    for (const auto& [id, key] : sets.baselines)
        if (!sets.configsBySet.count(key)) problem("results.csv row " + id + ": baseline " + key + " was not measured with it");
    if (csv.size() < minRows + 1) problem("results.csv has " + std::to_string(csv.size() - (csv.empty() ? 0 : 1)) + " rows, expected at least " + std::to_string(minRows));
    lines = csv.size();
    return ids;
}

void checkPassesCsv(const fs::path& dir, const std::set<std::string>& ids) {
    // passes.csv
    const auto passes = readCsv(dir / "passes.csv");
    if (passes.empty() || passes[0] != lidr::bench::passColumns()) problem("passes.csv header is not the documented column list");
    std::set<std::string> idsWithPasses;
    for (size_t r = 1; r < passes.size(); ++r) {
        const auto& row = passes[r];
        double v = 0;
        if (row.size() != lidr::bench::passColumns().size()) { problem("passes.csv row " + std::to_string(r) + " malformed"); continue; }
        if (!ids.count(row[0])) problem("passes.csv names row id " + row[0] + " that results.csv lacks");
        idsWithPasses.insert(row[0]);
        for (size_t c = 4; c < row.size(); ++c) {
            const bool fragments = lidr::bench::passColumns()[c] == "fragments";  // empty: not counted
            if (fragments && row[c].empty()) continue;
            if (!finiteNonNegative(row[c], v))
                problem("passes.csv row " + std::to_string(r) + ": bad " + lidr::bench::passColumns()[c] + " '" + row[c] + "'");
        }
    }
    for (const auto& id : ids)
        if (!idsWithPasses.count(id)) problem("row " + id + " has no per-pass times");

}

// results.json: the run's metadata, steadiness, rows (as many as results.csv's) and status.
void checkResultsJson(const fs::path& dir, size_t csvLines, bool expectInterrupted) {
    const size_t csvSize = csvLines;
    nlohmann::json j;
    try {
        std::ifstream in(dir / "results.json");
        j = nlohmann::json::parse(in);
    } catch (const std::exception& e) {
        problem(std::string("results.json does not parse: ") + e.what());
    }
    if (j.is_object()) {
        try {
            const auto& meta = j.at("meta");
            if (meta.at("machine").at("cpu_model").get<std::string>().empty()) problem("no CPU model");
            if (meta.at("machine").at("cpu_cores").get<int>() < 1) problem("no core count");
            if (meta.at("gl").at("renderer").get<std::string>().empty()) problem("no GL renderer");
            if (meta.at("commit").get<std::string>().empty()) problem("no commit");
            if (meta.at("command_line").get<std::string>().find("lidr-bench") == std::string::npos) problem("no command line");
            const auto& st = j.at("steadiness");
            if (st.at("verdict").get<std::string>().empty()) problem("no steadiness verdict");
            for (const char* k : {"frame_spread_median", "ratio_spread_median"})
                if (!std::isfinite(st.at(k).get<double>()) || st.at(k).get<double>() < 0) problem(std::string("bad steadiness ") + k);
            const auto& rows = j.at("rows");
            if (rows.size() + 1 != csvSize) problem("results.json and results.csv disagree on the row count");
            for (const auto& row : rows) {
                const auto& t = row.at("timing");
                if (t.at("method").get<std::string>().empty()) problem("a row without its timing method");
                if (!(t.at("frame_ms").at("median").get<double>() >= 0.0)) problem("a negative frame time in JSON");
                if (row.at("width").get<int>() < 1 || row.at("height").get<int>() < 1) problem("a row without a resolution");
                if (t.at("rounds").get<int>() < 1) problem("a row without rounds in JSON");
                if (t.at("baseline").get<std::string>().empty()) problem("a row without a baseline in JSON");
                const double ratio = t.at("ratio_to_baseline").at("median").get<double>();
                if (!std::isfinite(ratio) || ratio <= 0) problem("a non-positive ratio in JSON");
            }
            const auto& status = j.at("status");
            if (expectInterrupted) {
                if (!status.at("interrupted").get<bool>()) problem("status.interrupted should be true");
                if (status.at("complete").get<bool>()) problem("an interrupted run marked complete");
                if (rows.size() >= status.at("planned_runs").get<size_t>()) problem("an interrupted run with every row");
            } else if (!status.at("complete").get<bool>()) {
                problem("status.complete is false");
            }
        } catch (const std::exception& e) {
            problem(std::string("results.json lacks a field: ") + e.what());
        }
    }
}

void checkPlots(const fs::path& dir, bool expectPlots, bool expectSweepPlots) {
    if (expectPlots) {
        int timeVsError = 0, passPlots = 0;
        if (fs::is_directory(dir / "plots"))
            for (const auto& e : fs::directory_iterator(dir / "plots")) {
                const std::string name = e.path().filename().string();
                if (e.path().extension() != ".png") continue;
                if (!isPng(e.path())) problem(name + " is not a PNG");
                if (name.rfind("time_vs_error_", 0) == 0) ++timeVsError;
                if (name.rfind("passes_", 0) == 0) ++passPlots;
            }
        if (timeVsError == 0) problem("no time-against-error plot");
        if (passPlots == 0) problem("no per-pass breakdown plot");
        if (!fs::exists(dir / "plots" / "overlap_time.png")) problem("no overlap plot");
    }
    if (expectSweepPlots)
        for (const char* png : {"lights_time.png", "triangles_time.png", "hall_lights_time.png"})
            if (!fs::exists(dir / "plots" / png) || !isPng(dir / "plots" / png)) problem(std::string("no sweep plot ") + png);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: lidr-bench-check DIR [--expect-plots] [--expect-sweep-plots] [--expect-interrupted] [--min-rows N]\n";
        return 2;
    }
    const fs::path dir = argv[1];
    bool expectPlots = false, expectSweepPlots = false, expectInterrupted = false;
    size_t minRows = 1;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--expect-plots") expectPlots = true;
        else if (a == "--expect-sweep-plots") expectSweepPlots = true;
        else if (a == "--expect-interrupted") expectInterrupted = true;
        else if (a == "--min-rows" && i + 1 < argc) minRows = std::stoul(argv[++i]);
        else { std::cerr << "unknown argument " << a << "\n"; return 2; }
    }
    size_t lines = 0;
    const std::set<std::string> ids = checkResultsCsv(dir, minRows, lines);
    checkPassesCsv(dir, ids);
    checkResultsJson(dir, lines, expectInterrupted);
    if (!fs::exists(dir / "summary.md") || fs::file_size(dir / "summary.md") == 0) problem("no summary.md");
    checkPlots(dir, expectPlots, expectSweepPlots);
    if (problems) {
        std::cerr << problems << " problem(s) in " << dir << "\n";
        return 1;
    }
    std::cout << "bench output in " << dir << " is well formed: " << (lines - 1) << " rows\n";
    return 0;
}
