// lidr-bench's rows and their files: statistics over rounds, results.csv and passes.csv as rows are measured,
// results.json. summary.md is written by bench_summary.cpp (its targets by bench_targets.cpp), the plots by
// bench_plots.cpp.
#include "bench_report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

#include "bench_report_text.h"
#include "lidr/base/error.h"

namespace lidr::bench {

namespace fs = std::filesystem;

Stat Stat::of(std::vector<double> v) {
    Stat s;
    if (v.empty()) return s;
    std::sort(v.begin(), v.end());
    s.min = v.front();
    s.max = v.back();
    s.median = v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
    return s;
}

double finitePsnr(double psnr) { return std::isfinite(psnr) ? psnr : 999.0; }

Steadiness steadiness(const std::vector<Row>& rows) {
    Steadiness s;
    std::vector<double> frame, ratio;
    for (const Row& r : rows) {
        if (s.roundsMin == 0 || r.rounds < s.roundsMin) s.roundsMin = r.rounds;
        s.roundsMax = std::max(s.roundsMax, r.rounds);
        if (r.roundMs.size() < 2) continue;
        ++s.configurations;
        frame.push_back(r.frameSpread());
        if (r.run.config.key() != r.baseline && r.ratio.median > 0) {
            ratio.push_back((r.ratio.max - r.ratio.min) / r.ratio.median);
            s.worstRatioSpread = std::max(s.worstRatioSpread, ratio.back());
        }
    }
    s.frameSpread = Stat::of(frame).median;
    s.ratioSpread = Stat::of(ratio).median;
    if (s.configurations == 0) {
        s.verdict = "unknown: no configuration was measured in two or more rounds (--frames 3 or more)";
        return s;
    }
    const double spread = ratio.empty() ? s.frameSpread : s.ratioSpread;
    std::ostringstream pct;  // one decimal below 10%, whole percents above
    pct << std::fixed << std::setprecision(100.0 * spread < 10.0 ? 1 : 0) << 100.0 * spread;
    const std::string within = std::string(ratio.empty() ? "frame times" : "ratios") + " within " + pct.str() + "%";
    s.verdict = spread <= 0.05 ? "steady (" + within + ")" : "noisy: " + within;
    return s;
}

double pairRatio(const Row& a, const Row& b, bool* inRounds, Stat* range) {
    if (inRounds) *inRounds = false;
    if (a.setKey == b.setKey && !a.setKey.empty() && a.roundMs.size() == b.roundMs.size() && !a.roundMs.empty()) {
        std::vector<double> r;
        for (size_t i = 0; i < a.roundMs.size(); ++i)
            if (b.roundMs[i] > 0) r.push_back(a.roundMs[i] / b.roundMs[i]);
        if (!r.empty()) {
            if (inRounds) *inRounds = true;
            const Stat s = Stat::of(r);
            if (range) *range = s;
            return s.median;
        }
    }
    // Parts of one set (--max-live) share the baseline: divide the ratios. Else the medians.
    const bool sameBaseline = a.run.scene == b.run.scene && a.run.width == b.run.width && a.run.height == b.run.height &&
                              !a.baseline.empty() && a.baseline == b.baseline && a.ratio.median > 0 && b.ratio.median > 0;
    const double ratio = sameBaseline ? a.ratio.median / b.ratio.median
                                      : b.frameMs.median > 0 ? a.frameMs.median / b.frameMs.median : 0.0;
    if (range) *range = Stat{ratio, ratio, ratio};
    return ratio;
}

const std::vector<std::string>& resultColumns() {
    static const std::vector<std::string> c{
        "id", "group", "scene", "width", "height", "scene_lights", "max_overlap", "mode", "config", "scheme",
        "budget", "index_bits", "volume_test", "tiled_depth_bounds", "msaa", "per_sample", "transparency", "timing_method",
        "warmup_frames", "frames", "frame_ms_median", "frame_ms_min", "frame_ms_max", "wall_ms_median",
        "light_volume_ms_median", "light_volume_share", "light_data_bytes", "drawn_lights", "rmse", "psnr_db",
        "max_abs_error", "differing_pixels", "compared_pixels", "dropped_light_pixels", "pixels_with_drops",
        "pixels_over_budget", "max_marked", "invalid_slots", "psnr_within_budget_db", "scene_triangles", "rounds",
        "baseline", "ratio_to_baseline_median", "ratio_to_baseline_min", "ratio_to_baseline_max", "auto_budget",
        "auto_index_bits", "auto_repacks", "state_calls", "state_calls_skipped", "draw_calls", "true_light_pixels",
        "volume_fragments", "volume_fragments_per_light_pixel", "shadow_casters", "shadow_maps_first_frame",
        "shadow_maps_first_frame_ms", "shadow_maps_later_frames", "cluster_tile_size", "cluster_slices",
        "cluster_slicing", "cluster_occupancy", "extra_light_pixels", "extra_per_true_pair", "lighting_computations",
        "lighting_computations_per_true_pair", "hidden_skip"};
    return c;
}

const std::vector<std::string>& passColumns() {
    static const std::vector<std::string> c{"id",     "scene",  "config",     "pass",        "ms_median",
                                            "ms_min", "ms_max", "draw_calls", "state_calls", "fragments"};
    return c;
}

std::string num(double v, int precision) {
    std::ostringstream s;
    s << std::setprecision(precision) << std::fixed << v;
    std::string t = s.str();
    if (t.find('.') != std::string::npos) {
        t.erase(t.find_last_not_of('0') + 1);
        if (t.back() == '.') t.pop_back();
    }
    return t;
}

std::string ms(double v) { return v >= 100 ? num(v, 0) : v >= 10 ? num(v, 1) : num(v, 2); }

std::string sceneKey(const Row& r) { return r.run.scene + " " + std::to_string(r.run.width) + "x" + std::to_string(r.run.height); }

std::vector<std::string> sceneOrder(const std::vector<Row>& rows) {
    std::vector<std::string> order;
    for (const Row& r : rows)
        if (std::find(order.begin(), order.end(), sceneKey(r)) == order.end()) order.push_back(sceneKey(r));
    return order;
}

const Row* findRow(const std::vector<Row>& rows, const std::string& scene, int w, int h, const std::string& key) {
    for (const Row& r : rows)
        if (r.run.scene == scene && r.run.width == w && r.run.height == h && r.run.config.key() == key) return &r;
    return nullptr;
}

namespace {

// CSV field: quoted when it holds a comma, quote or space-sensitive text.
std::string field(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

std::vector<std::string> csvCells(const Row& r) {
    const ModeConfig& c = r.run.config;
    const bool lidr = c.mode == "lidr";
    auto lists = [&](auto v) { return r.hasLists ? std::to_string(v) : std::string(); };
    auto dropped = [&](auto v) { return r.hasLists || r.hasPixelLists ? std::to_string(v) : std::string(); };
    const bool clustered = c.mode == "clustered";
    const ModeConfig grid = c.withClusterDefaults();
    auto err = [&](const std::string& v) { return r.hasError ? v : std::string(); };
    return {std::to_string(r.id), r.run.group, r.run.scene, std::to_string(r.run.width), std::to_string(r.run.height),
            std::to_string(r.sceneLights), std::to_string(r.maxOverlap), c.mode, c.key(), lidr ? c.scheme : "",
            // auto: the budget and width its last measured frame used
            lidr ? std::to_string(r.autoBudget ? r.autoBudget : c.budget) : "",
            lidr ? std::to_string(r.autoIndexBits ? r.autoIndexBits : c.indexBits) : "", lidr ? c.volumeTest : "",
            c.mode == "tiled" ? (c.tiledDepthBounds ? "1" : "0") : "", std::to_string(c.msaa),
            c.perSample ? "1" : "0", c.transparency ? "1" : "0", r.timingMethod, std::to_string(r.warmupFrames), std::to_string(r.frames),
            num(r.frameMs.median), num(r.frameMs.min), num(r.frameMs.max), num(r.wallMs.median),
            lidr ? num(r.lightVolumeMs) : "", lidr ? num(r.lightVolumeShare()) : "", std::to_string(r.lightDataBytes),
            std::to_string(r.drawnLights), err(num(r.error.rmse, 5)), err(num(finitePsnr(r.error.psnr), 3)),
            err(std::to_string(r.error.maxAbsError)), err(std::to_string(r.error.differingPixels)),
            err(std::to_string(r.error.comparedPixels)), dropped(r.droppedLightPixels), dropped(r.pixelsWithDrops),
            lists(r.pixelsOverBudget), lists(r.maxMarked), lists(r.invalidSlots),
            r.hasLists ? num(finitePsnr(r.psnrWithinBudget), 3) : "", std::to_string(r.sceneTriangles),
            std::to_string(r.rounds), r.baseline, num(r.ratio.median), num(r.ratio.min), num(r.ratio.max),
            r.autoBudget ? std::to_string(r.autoBudget) : "", r.autoIndexBits ? std::to_string(r.autoIndexBits) : "",
            r.autoBudget || r.autoIndexBits ? std::to_string(r.autoRepacks) : "",
            std::to_string(r.glCalls.stateCalls), std::to_string(r.glCalls.stateCallsSkipped),
            std::to_string(r.glCalls.drawCalls), r.trueLightPixels >= 0 ? std::to_string(r.trueLightPixels) : "",
            r.volumeFragments >= 0 ? std::to_string(r.volumeFragments) : "",
            r.volumeEfficiency() >= 0 ? num(r.volumeEfficiency(), 3) : "", std::to_string(r.shadowCasters),
            std::to_string(r.shadowMapsFirst), num(r.shadowMapsFirstMs), std::to_string(r.shadowMapsLater),
            clustered ? std::to_string(grid.clusterTileSize) : "", clustered ? std::to_string(grid.clusterSlices) : "",
            clustered ? grid.clusterSlicing : "", clustered ? std::to_string(grid.clusterOccupancy) : "",
            r.hasPixelLists ? std::to_string(r.extraLightPixels) : "",
            r.hasPixelLists ? num(r.extraPerTruePair(), 3) : "",
            r.lightingComputations >= 0 ? std::to_string(r.lightingComputations) : "",
            r.lightingPerTruePair() >= 0 ? num(r.lightingPerTruePair(), 3) : "",
            r.hiddenSkip >= 0 ? std::to_string(r.hiddenSkip) : ""};
}

nlohmann::json statJson(const Stat& s) { return {{"median", s.median}, {"min", s.min}, {"max", s.max}}; }

nlohmann::json rowJson(const Row& r) {
    const ModeConfig& c = r.run.config;
    nlohmann::json j;
    j["id"] = r.id;
    j["group"] = r.run.group;
    j["scene"] = r.run.scene;
    j["width"] = r.run.width;
    j["height"] = r.run.height;
    j["scene_lights"] = r.sceneLights;
    j["max_overlap"] = r.maxOverlap;
    j["mode"] = c.mode;
    j["config"] = c.key();
    if (c.mode == "lidr")
        j["lidr"] = {{"scheme", c.scheme}, {"budget", c.budget}, {"index_bits", c.indexBits}, {"volume_test", c.volumeTest}, {"volume_detail", c.volumeDetail}, {"volume_tiles", c.volumeTiles}, {"regional_indices", c.regionalIndices}, {"msaa_spans", c.msaaSpans}};
    if (r.autoBudget || r.autoIndexBits)
        j["auto"] = {{"budget", r.autoBudget}, {"index_bits", r.autoIndexBits}, {"repacks", r.autoRepacks},
                     {"hidden_skip", r.hiddenSkip > 0}};
    if (c.mode == "tiled") j["tiled"] = {{"depth_bounds", c.tiledDepthBounds}};
    if (c.mode == "clustered") {  // the grid it ran with (the library's defaults where the run left them)
        const ModeConfig grid = c.withClusterDefaults();
        j["clustered"] = {{"tile_size", grid.clusterTileSize}, {"slices", grid.clusterSlices},
                          {"slicing", grid.clusterSlicing}, {"occupancy", grid.clusterOccupancy == 1}};
    }
    if (!r.multipassAccumulation.empty()) j["multipass"] = {{"accumulation", r.multipassAccumulation}};
    j["msaa"] = c.msaa;
    j["per_sample"] = c.perSample;
    j["transparency"] = c.transparency;
    j["timing"] = {{"method", r.timingMethod}, {"warmup_frames", r.warmupFrames}, {"frames", r.frames},
                   {"frame_ms", statJson(r.frameMs)}, {"wall_ms", statJson(r.wallMs)}};
    nlohmann::json passes = nlohmann::json::array();
    for (const PassStat& p : r.passes) {
        passes.push_back({{"pass", p.pass}, {"ms", statJson(p.ms)}, {"draw_calls", p.drawCalls},
                          {"state_calls", p.stateCalls}});
        if (p.fragments >= 0) passes.back()["fragments"] = p.fragments;
    }
    j["timing"]["passes"] = passes;
    j["timing"]["rounds"] = r.rounds;
    j["timing"]["round_frame_ms"] = r.roundMs;
    j["timing"]["baseline"] = r.baseline;
    j["timing"]["ratio_to_baseline"] = statJson(r.ratio);
    j["scene_triangles"] = r.sceneTriangles;
    if (c.mode == "lidr") j["timing"]["light_volume_share"] = r.lightVolumeShare();
    j["light_data_bytes"] = r.lightDataBytes;
    j["drawn_lights"] = r.drawnLights;
    j["shadows"] = {{"casters", r.shadowCasters}, {"maps_first_frame", r.shadowMapsFirst},
                    {"maps_first_frame_ms", r.shadowMapsFirstMs}, {"maps_later_frames", r.shadowMapsLater}};
    j["gl_calls"] = {{"state_calls", r.glCalls.stateCalls}, {"state_calls_skipped", r.glCalls.stateCallsSkipped},
                     {"draw_calls", r.glCalls.drawCalls}};
    if (!r.hasError)
        j["error"] = nullptr;  // a timing-only sweep: no reference rendered
    else
    j["error"] = {{"rmse", r.error.rmse}, {"psnr_db", finitePsnr(r.error.psnr)}, {"max_abs_error", r.error.maxAbsError},
                  {"differing_pixels", r.error.differingPixels}, {"compared_pixels", r.error.comparedPixels}};
    if (r.hasLists)
        j["lists"] = {{"dropped_light_pixels", r.droppedLightPixels}, {"pixels_with_drops", r.pixelsWithDrops},
                      {"pixels_over_budget", r.pixelsOverBudget}, {"max_marked", r.maxMarked},
                      {"invalid_slots", r.invalidSlots}, {"psnr_within_budget_db", finitePsnr(r.psnrWithinBudget)},
                      {"true_light_pixels", r.trueLightPixels}, {"volume_fragments", r.volumeFragments},
                      {"volume_fragments_per_light_pixel", r.volumeEfficiency()}};
    if (r.hasPixelLists)
        j["pixel_lists"] = {{"dropped_light_pixels", r.droppedLightPixels}, {"pixels_with_drops", r.pixelsWithDrops},
                            {"true_light_pixels", r.trueLightPixels}, {"extra_light_pixels", r.extraLightPixels},
                            {"extra_per_true_pair", r.extraPerTruePair()}};
    if (r.lightingComputations >= 0)
        j["lighting_computations"] = {{"count", r.lightingComputations}, {"per_true_pair", r.lightingPerTruePair()}};
    return j;
}

}  // namespace

void ReportWriter::checkWritable(const std::string& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) throw Error("cannot create output folder '" + dir + "': " + (ec ? ec.message() : "not a folder"));
    const fs::path probe = fs::path(dir) / ".lidr-bench-write-test";
    {
        std::ofstream f(probe);
        f << "x";
        if (!f) throw Error("cannot write into output folder '" + dir + "'");
    }
    fs::remove(probe, ec);
}

ReportWriter::ReportWriter(const std::string& dir) : dir_(dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) throw Error("cannot create output folder '" + dir + "': " + (ec ? ec.message() : "not a folder"));
    csv_.open(fs::path(dir) / "results.csv");
    passesCsv_.open(fs::path(dir) / "passes.csv");
    if (!csv_ || !passesCsv_) throw Error("cannot write into output folder '" + dir + "'");
    std::ofstream probe(fs::path(dir) / "results.json");
    if (!probe) throw Error("cannot write '" + (fs::path(dir) / "results.json").string() + "'");
    for (size_t i = 0; i < resultColumns().size(); ++i) csv_ << (i ? "," : "") << resultColumns()[i];
    csv_ << "\n";
    for (size_t i = 0; i < passColumns().size(); ++i) passesCsv_ << (i ? "," : "") << passColumns()[i];
    passesCsv_ << std::endl;
    if (!csv_ || !passesCsv_) throw Error("cannot write into output folder '" + dir + "'");
}

void ReportWriter::add(const Row& row, const RunInfo& info) {
    rows_.push_back(row);
    const auto cells = csvCells(row);
    for (size_t i = 0; i < cells.size(); ++i) csv_ << (i ? "," : "") << field(cells[i]);
    csv_ << std::endl;  // flushed: an interrupted or killed sweep keeps its rows
    for (const PassStat& p : row.passes)
        passesCsv_ << row.id << "," << field(row.run.scene) << "," << field(row.run.config.key()) << "," << field(p.pass)
                   << "," << num(p.ms.median) << "," << num(p.ms.min) << "," << num(p.ms.max) << "," << p.drawCalls
                   << "," << p.stateCalls << "," << (p.fragments >= 0 ? std::to_string(p.fragments) : std::string())
                   << "\n";
    passesCsv_.flush();
    if (!csv_ || !passesCsv_) throw Error("writing the CSV files in '" + dir_ + "' failed");
    writeJson(info);
}

void ReportWriter::writeJson(const RunInfo& info) const {
    nlohmann::json j;
    j["meta"] = info.meta;
    j["status"] = {{"complete", info.complete}, {"interrupted", info.interrupted}, {"planned_runs", info.planned},
                   {"measured_runs", rows_.size()}};
    const Steadiness st = steadiness(rows_);
    j["steadiness"] = {{"verdict", st.verdict}, {"configurations", st.configurations},
                       {"frame_spread_median", st.frameSpread}, {"ratio_spread_median", st.ratioSpread},
                       {"ratio_spread_max", st.worstRatioSpread}, {"rounds_min", st.roundsMin},
                       {"rounds_max", st.roundsMax},
                       {"definition", "spread = (max - min) / median over the rounds; the medians over configurations "
                                      "measured in >= 2 rounds (ratios: baselines excluded); steady when <= 5%"}};
    j["rows"] = nlohmann::json::array();
    for (const Row& r : rows_) j["rows"].push_back(rowJson(r));
    j["skipped"] = nlohmann::json::array();
    for (const Skipped& s : info.skipped)
        j["skipped"].push_back({{"group", s.group}, {"scene", s.scene}, {"width", s.width}, {"height", s.height},
                                {"config", s.label}, {"reason", s.reason}});
    // Written beside, then renamed: a kill mid-write leaves the previous complete file.
    const fs::path final = fs::path(dir_) / "results.json", tmp = fs::path(dir_) / "results.json.tmp";
    {
        std::ofstream out(tmp);
        out << j.dump() << "\n";  // compact: results.csv is the file to read and diff
        if (!out) throw Error("cannot write '" + tmp.string() + "'");
    }
    fs::rename(tmp, final);
}

}  // namespace lidr::bench
