#include "bench_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

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
        "cluster_slicing", "cluster_occupancy", "extra_light_pixels", "extra_per_true_pair"};
    return c;
}

const std::vector<std::string>& passColumns() {
    static const std::vector<std::string> c{"id",     "scene",  "config",     "pass",        "ms_median",
                                            "ms_min", "ms_max", "draw_calls", "state_calls", "fragments"};
    return c;
}

namespace {

std::string num(double v, int precision = 4) {
    std::ostringstream s;
    s << std::setprecision(precision) << std::fixed << v;
    std::string t = s.str();
    if (t.find('.') != std::string::npos) {
        t.erase(t.find_last_not_of('0') + 1);
        if (t.back() == '.') t.pop_back();
    }
    return t;
}

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
            r.hasPixelLists ? num(r.extraPerTruePair(), 3) : ""};
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
        j["lidr"] = {{"scheme", c.scheme}, {"budget", c.budget}, {"index_bits", c.indexBits}, {"volume_test", c.volumeTest}, {"volume_detail", c.volumeDetail}, {"volume_tiles", c.volumeTiles}, {"regional_indices", c.regionalIndices}};
    if (r.autoBudget || r.autoIndexBits)
        j["auto"] = {{"budget", r.autoBudget}, {"index_bits", r.autoIndexBits}, {"repacks", r.autoRepacks}};
    if (c.mode == "tiled") j["tiled"] = {{"depth_bounds", c.tiledDepthBounds}};
    if (c.mode == "clustered") {  // the grid it ran with (the library's defaults where the run left them)
        const ModeConfig grid = c.withClusterDefaults();
        j["clustered"] = {{"tile_size", grid.clusterTileSize}, {"slices", grid.clusterSlices},
                          {"slicing", grid.clusterSlicing}, {"occupancy", grid.clusterOccupancy == 1}};
    }
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
    return j;
}

std::string sceneKey(const Row& r) { return r.run.scene + " " + std::to_string(r.run.width) + "x" + std::to_string(r.run.height); }

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

// ---- summary.md ---------------------------------------------------------------------------------------------

namespace {

const Row* findRow(const std::vector<Row>& rows, const std::string& scene, int w, int h, const std::string& key) {
    for (const Row& r : rows)
        if (r.run.scene == scene && r.run.width == w && r.run.height == h && r.run.config.key() == key) return &r;
    return nullptr;
}

std::string ms(double v) { return v >= 100 ? num(v, 0) : v >= 10 ? num(v, 1) : num(v, 2); }

std::string passBreakdown(const Row& r) {
    std::string s;
    for (const PassStat& p : r.passes) s += (s.empty() ? "" : ", ") + p.pass + " " + ms(p.ms.median);
    return s;
}

void targetsSection(std::ostream& o, const std::vector<Row>& rows, bool transparency) {
    const std::string scene = "room";
    const int w = 1024, h = 768;
    const std::string suffix = transparency ? "" : " opaque";
    const Row* b4 = findRow(rows, scene, w, h, "lidr bitshift b4 8-bit backface" + suffix);
    const Row* b1 = findRow(rows, scene, w, h, "lidr bitshift b1 8-bit backface" + suffix);
    const Row* multipass = findRow(rows, scene, w, h, "forward-multipass" + suffix);
    const Row* brute = findRow(rows, scene, w, h, "forward-brute" + suffix);
    const Row* tiled = findRow(rows, scene, w, h, "tiled min/max" + suffix);
    // The fastest LIDR configuration at budget 4 (any scheme, width, volume test), for comparison.
    const Row* best4 = nullptr;
    for (const Row& r : rows)
        if (r.run.scene == scene && r.run.width == w && r.run.height == h && r.run.config.mode == "lidr" &&
            r.run.config.budget == 4 && r.run.config.msaa == 0 && r.run.config.transparency == transparency &&
            (!best4 || r.frameMs.median < best4->frameMs.median))
            best4 = &r;
    o << "### Default room, 255 lights, 1024x768, no MSAA, transparency " << (transparency ? "on" : "off") << "\n\n";
    o << (transparency ? "forward-multipass draws no transparent meshes, so it has no row here; see the opaque table.\n\n"
                       : "Every mode draws the same opaque geometry: the like-for-like comparison.\n\n");
    o << "LIDR is `bitshift` 8-bit with the back-face test (issue 6's configuration; lidr-demo's default, the automatic one with the `sphere` test, is in the results per scene); \"best b4\" is the fastest "
         "budget-4 LIDR configuration measured.\n\n";
    o << "| target | measured | met? |\n|---|---|---|\n";
    auto ratioLine = [&](const std::string& what, const Row* num_, const Row* den, double goal, bool atLeast) {
        o << "| " << what << " | ";
        if (!num_ || !den) {
            o << "not measured (a configuration is missing from this run) | - |\n";
            return;
        }
        bool inRounds = false;
        Stat range;
        const double ratio = pairRatio(*num_, *den, &inRounds, &range);
        const bool met = atLeast ? ratio >= goal : ratio <= goal;
        o << num(ratio, 2) << "x (";
        if (inRounds)
            o << "median over " << num_->roundMs.size() << " rounds, " << num(range.min, 2) << "-" << num(range.max, 2)
              << "; ";
        o << ms(num_->frameMs.median) << " ms / " << ms(den->frameMs.median) << " ms) | " << (met ? "met" : "**missed**")
          << " |\n";
    };
    if (!transparency) {
        ratioLine("forward-multipass / LIDR budget 4 >= 6", multipass, b4, 6.0, true);
        ratioLine("forward-multipass / LIDR budget 1 >= 10", multipass, b1, 10.0, true);
    }
    ratioLine("forward-brute / LIDR budget 4 >= 20", brute, b4, 20.0, true);
    ratioLine("LIDR budget 4 / tiled min/max <= 1.0", b4, tiled, 1.0, false);
    if (best4 && best4 != b4) {
        if (!transparency)
            ratioLine("forward-multipass / best b4 (" + best4->run.config.label() + ") >= 6", multipass, best4, 6.0, true);
        ratioLine("best b4 / tiled min/max <= 1.0", best4, tiled, 1.0, false);
    }
    o << "| light-volume pass < 20% of the LIDR budget-4 frame | ";
    if (b4)
        o << num(100.0 * b4->lightVolumeShare(), 1) << "% (" << ms(b4->lightVolumeMs) << " of " << ms(b4->frameMs.median)
          << " ms) | " << (b4->lightVolumeShare() < 0.2 ? "met" : "**missed**") << " |\n";
    else
        o << "not measured | - |\n";
    o << "\n";
    if (b4) o << "LIDR budget 4 passes (ms): " << passBreakdown(*b4) << ".\n\n";
    if (tiled) o << "tiled min/max passes (ms): " << passBreakdown(*tiled) << ".\n\n";
    if (multipass) o << "forward-multipass passes (ms): " << passBreakdown(*multipass) << ".\n\n";
}

// Budget at or above the scene's maximum overlap: no drops, PSNR >= 50 dB (every scene in the run).
void overlapTarget(std::ostream& o, const std::vector<Row>& rows) {
    int eligible = 0, passed = 0;
    std::vector<const Row*> failures;
    for (const Row& r : rows)
        if (r.hasLists && r.run.config.budget >= r.maxOverlap) {
            ++eligible;
            if (r.droppedLightPixels == 0 && finitePsnr(r.error.psnr) >= 50.0)
                ++passed;
            else
                failures.push_back(&r);
        }
    o << "### Budget at or above the scene's maximum overlap\n\n";
    o << "Maximum overlap: the most lights whose sphere holds one pixel's surface (CPU truth from the reference "
         "depth). Target: no dropped lights and PSNR >= 50 dB. Measured: " << passed << " of " << eligible
      << " such LIDR rows (all scenes) meet it: " << (eligible == 0 ? "not measured" : failures.empty() ? "met" : "**missed**")
      << ".\n\n";
    if (!failures.empty()) {
        o << "Rows with budget >= max overlap that dropped lights or fell below 50 dB:\n\n"
             "| scene | config | max overlap | max marked | dropped light-px | PSNR dB |\n|---|---|---|---|---|---|\n";
        for (const Row* r : failures)
            o << "| " << sceneKey(*r) << " | " << r->run.config.key() << " | " << r->maxOverlap << " | " << r->maxMarked
              << " | " << r->droppedLightPixels << " | " << num(finitePsnr(r->error.psnr), 1) << " |\n";
        o << "\n";
    }
}

// Deep, occluded scenes (issue 25), per scene and size where LIDR's default configuration was measured opaque:
// its frame over tiled forward's and multi-pass's in the same rounds, the volume pass's fragments per true
// light-pixel pair, its drops, and --mode auto over the fastest mode measured. The targets are judged
// where they apply (hall-255 and hall-1024 at 1024x768; auto and drops everywhere).
void occludedTargets(std::ostream& o, const std::vector<Row>& rows) {
    const std::string lidrKey = "lidr auto sphere opaque";
    std::vector<const Row*> lidrRows;
    for (const Row& r : rows)
        if (r.run.config.key() == lidrKey) lidrRows.push_back(&r);
    const auto find = [&](const Row& like, const std::string& key) {
        return findRow(rows, like.run.scene, like.run.width, like.run.height, key);
    };
    bool any = false;
    for (const Row* l : lidrRows)
        any = any || find(*l, "tiled min/max opaque") || find(*l, "forward-multipass opaque") || find(*l, "auto opaque");
    if (!any) return;
    o << "## Targets (issue 25): LIDR's default configuration against the other modes\n\n"
         "Opaque, per scene and size: LIDR's default (`lidr auto sphere`) frame over tiled forward's (min/max) and "
         "multi-pass forward's in the same rounds (median, min-max over the rounds), the volume pass's rasterised "
         "fragments per true light-pixel pair, its dropped light-pixels, and `--mode auto` over the fastest of the "
         "three. Targets: hall-255 at 1024x768 LIDR <= 0.75x tiled and <= 0.4x multi-pass, <= 3 fragments per pair; "
         "hall-1024 at 1024x768 <= 0.6x tiled; every scene 0 drops and `--mode auto` <= 1.05x the fastest.\n\n"
         "| scene | LIDR ms | LIDR / tiled | LIDR / multi-pass | fragments per pair | dropped | auto / fastest mode | targets |\n"
         "|---|---|---|---|---|---|---|---|\n";
    const auto ratioCell = [](const Row& a, const Row* b, double& value) {
        value = -1.0;
        if (!b) return std::string("-");
        bool inRounds = false;
        Stat range;
        value = pairRatio(a, *b, &inRounds, &range);
        std::string s = num(value, 2);
        if (inRounds && range.max > range.min) s += " (" + num(range.min, 2) + "-" + num(range.max, 2) + ")";
        return s;
    };
    for (const Row* l : lidrRows) {
        const Row* tiled = find(*l, "tiled min/max opaque");
        const Row* multipass = find(*l, "forward-multipass opaque");
        const Row* autoMode = find(*l, "auto opaque");
        const Row* fastest = l;
        for (const Row* r : {tiled, multipass})
            if (r && r->frameMs.median < fastest->frameMs.median) fastest = r;
        double toTiled = -1, toMultipass = -1, autoRatio = -1;
        const std::string tiledCell = ratioCell(*l, tiled, toTiled);
        const std::string multipassCell = ratioCell(*l, multipass, toMultipass);
        const std::string autoCell = autoMode ? ratioCell(*autoMode, fastest, autoRatio) : "-";
        const double perPair = l->volumeEfficiency();
        // The targets that apply to this row: "name met" / "name **missed**"; unmeasured ones are left out.
        std::vector<std::string> verdicts;
        const auto judge = [&](const std::string& what, double value, double goal) {
            if (value >= 0) verdicts.push_back(what + (value <= goal ? " met" : " **missed**"));
        };
        const bool full = l->run.width == 1024 && l->run.height == 768;
        if (full && l->run.scene == "hall-255") {
            judge("tiled <= 0.75", toTiled, 0.75);
            judge("multi-pass <= 0.4", toMultipass, 0.4);
            judge("<= 3 per pair", perPair, 3.0);
        }
        if (full && l->run.scene == "hall-1024") judge("tiled <= 0.6", toTiled, 0.6);
        if (l->hasLists) judge("0 drops", double(l->droppedLightPixels), 0.0);
        judge("auto <= 1.05", autoRatio, 1.05);
        std::string targets;
        for (const std::string& v : verdicts) targets += (targets.empty() ? "" : "; ") + v;
        o << "| " << sceneKey(*l) << " | " << ms(l->frameMs.median) << " | " << tiledCell << " | " << multipassCell
          << " | " << (perPair >= 0 ? num(perPair, 2) : "-") << " | "
          << (l->hasLists ? std::to_string(l->droppedLightPixels) : "-") << " | " << autoCell;
        if (autoMode) o << " of " << fastest->run.config.label();
        o << " | " << (targets.empty() ? "-" : targets) << " |\n";
    }
    o << "\n";
}

}  // namespace

// Scenes with shadow casters (SCENE-shadows-K, doc/shadows.md): the maps' cost on the first frame, what later
// frames draw (0: a static scene's maps are drawn once) and the frame against the same configuration on the same
// scene with 0 casters (SCENE-shadows-0) in this run.
void shadowSection(std::ostream& o, const std::vector<Row>& rows) {
    const auto shadowScene = [](const Row& r) { return r.run.scene.find("-shadows-") != std::string::npos; };
    if (std::none_of(rows.begin(), rows.end(), shadowScene)) return;
    o << "\n## Shadows\n\nPer configuration on the -shadows-K scenes: casters; maps drawn by the first frame and its "
         "shadow-maps pass (ms); the most maps any later frame drew; the later frames' shadow-maps pass and frame "
         "(median ms); the frame over the same configuration's on SCENE-shadows-0 at the same size.\n\n"
         "| scene | config | casters | first-frame maps | first-frame maps ms | later maps | later maps ms | frame ms | x no shadows |\n"
         "|---|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : rows) {
        if (!shadowScene(r)) continue;
        double laterMapsMs = 0.0;
        for (const PassStat& p : r.passes)
            if (p.pass == "shadow-maps") laterMapsMs = p.ms.median;
        const std::string unshadowed = r.run.scene.substr(0, r.run.scene.rfind("-shadows-")) + "-shadows-0";
        std::string ratio = "-";
        for (const Row& b : rows)
            if (b.run.scene == unshadowed && b.run.width == r.run.width && b.run.height == r.run.height &&
                b.run.config.key() == r.run.config.key() && b.frameMs.median > 0)
                ratio = num(r.frameMs.median / b.frameMs.median, 2);
        o << "| " << r.run.scene << " " << r.run.width << "x" << r.run.height << " | " << r.run.config.key() << " | "
          << r.shadowCasters << " | " << r.shadowMapsFirst << " | " << ms(r.shadowMapsFirstMs) << " | "
          << r.shadowMapsLater << " | " << ms(laterMapsMs) << " | " << ms(r.frameMs.median) << " | " << ratio << " |\n";
    }
}

void ReportWriter::writeSummary(const RunInfo& info, const std::vector<std::string>& plots,
                                const std::string& plotMessage) const {
    std::ostringstream o;
    const auto& m = info.meta;
    o << "# lidr-bench results\n\n";
    o << "- status: " << (info.complete ? "complete" : info.interrupted ? "INTERRUPTED (rows so far)" : "incomplete") << ", "
      << rows_.size() << " of " << info.planned << " configurations measured, " << info.skipped.size()
      << " combinations skipped (refused by the library)\n";
    auto metaLine = [&](const char* label, const char* key) {
        if (m.contains(key)) o << "- " << label << ": " << (m[key].is_string() ? m[key].get<std::string>() : m[key].dump()) << "\n";
    };
    metaLine("date (UTC)", "date");
    metaLine("machine", "machine_summary");
    metaLine("GL", "gl_summary");
    metaLine("commit", "commit");
    metaLine("command", "command_line");
    metaLine("frames", "frames_summary");
    metaLine("load average before / after", "load_summary");
    std::set<std::string> methods;
    for (const Row& r : rows_) methods.insert(r.timingMethod);
    o << "- timing method(s): ";
    for (const auto& t : methods) o << t << " ";
    o << "(cpu-glfinish: CPU time around glFinish per pass; gpu-timer-query: GL timer queries)\n";
    o << "- PSNR 999 means identical to the reference; error is against forward-brute with the same MSAA and "
         "transparency; \"dropped\" counts (pixel, light) pairs a LIDR, tiled or clustered list missed against the CPU "
         "truth; \"per pair\": LIDR's volume-pass fragments per true light-pixel pair, tiled's and clustered's extra "
         "pairs (listed lights that do not touch the pixel's surface) per true pair.\n\n";
    const Steadiness st = steadiness(rows_);
    o << "## Steadiness\n\n";
    o << "- verdict: **" << st.verdict << "**\n";
    if (st.configurations > 0)
        o << "- over " << st.configurations << " configurations measured in " << st.roundsMin << "-" << st.roundsMax
          << " interleaved rounds: frame times vary by a median " << num(100.0 * st.frameSpread, 1)
          << "% across rounds ((max - min) / median); ratios to the baseline by a median " << num(100.0 * st.ratioSpread, 1)
          << "% (worst " << num(100.0 * st.worstRatioSpread, 1) << "%)\n";
    o << "- every configuration of a scene and size renders one frame per round, in turn; a ratio divides its frame "
         "time by the baseline's in the same round (forward-multipass where measured), so drift of the machine "
         "cancels out of it\n\n";
    o << "## Targets (issue 6)\n\n";
    const bool roomMeasured = std::any_of(rows_.begin(), rows_.end(), [](const Row& r) {
        return r.run.scene == "room" && r.run.width == 1024 && r.run.height == 768;
    });
    if (roomMeasured) {
        targetsSection(o, rows_, false);
        targetsSection(o, rows_, true);
    } else {
        o << "The speed targets are measured on the default room at 1024x768, which this run did not include.\n\n";
    }
    overlapTarget(o, rows_);
    occludedTargets(o, rows_);

    // One table per scene and size, in measurement order.
    std::vector<std::string> order;
    for (const Row& r : rows_)
        if (std::find(order.begin(), order.end(), sceneKey(r)) == order.end()) order.push_back(sceneKey(r));
    o << "## Results per scene\n\nTimes are the median of the measured frames (min-max in brackets), in ms. "
         "\"ratio\" is the frame time over the baseline's in the same round, median (min-max) over the rounds; "
         "\"once\": a configuration whose first frame took longer than --max-seconds / --frames, measured once "
         "outside the rounds and divided by the baseline's median. \"vol %\" is the light-volume passes' share of "
         "the LIDR frame; memory is the index targets / light grid; \"-\" in the error columns: a timing-only sweep "
         "(no reference).\n";
    for (const std::string& key : order) {
        const Row* first = nullptr;
        for (const Row& r : rows_)
            if (sceneKey(r) == key) { first = &r; break; }
        o << "\n### " << key << " (" << first->sceneLights << " lights, " << first->sceneTriangles << " triangles, max overlap "
          << first->maxOverlap << "; " << first->rounds << " rounds, ratios to " << first->baseline << ")\n\n";
        o << "| config | frame ms | ratio | vol % | memory KiB | RMSE | PSNR dB | max err | differing px | dropped light-px "
             "| per pair |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
        for (const Row& r : rows_) {
            if (sceneKey(r) != key) continue;
            o << "| " << r.run.config.key() << " | " << ms(r.frameMs.median) << " (" << ms(r.frameMs.min) << "-"
              << ms(r.frameMs.max) << ") | " << num(r.ratio.median, 2);
            if (r.ratio.max > r.ratio.min) o << " (" << num(r.ratio.min, 2) << "-" << num(r.ratio.max, 2) << ")";
            if (r.roundMs.empty()) o << " once";
            o << " | " << (r.run.config.mode == "lidr" ? num(100.0 * r.lightVolumeShare(), 1) : "-")
              << " | " << num(double(r.lightDataBytes) / 1024.0, 0) << " | ";
            if (r.hasError)
                o << num(r.error.rmse, 3) << " | " << num(finitePsnr(r.error.psnr), 1) << " | " << r.error.maxAbsError
                  << " | " << r.error.differingPixels;
            else
                o << "- | - | - | -";
            o << " | " << (r.hasLists || r.hasPixelLists ? std::to_string(r.droppedLightPixels) : "-") << " | "
              << (r.volumeEfficiency() >= 0  ? num(r.volumeEfficiency(), 2) + " fragments"
                  : r.hasPixelLists          ? num(r.extraPerTruePair(), 2) + " extra"
                                             : std::string("-"))
              << " |\n";
        }
    }
    shadowSection(o, rows_);
    o << "\n## Plots\n\n";
    if (plots.empty()) o << plotMessage << "\n";
    for (const std::string& p : plots) {
        const std::string rel = fs::relative(p, dir_).generic_string();
        o << "![" << fs::path(p).stem().string() << "](" << rel << ")\n\n";
    }
    if (!info.skipped.empty()) {
        // Collapse the skipped combinations by reason: the list would be long and says the same thing.
        std::map<std::string, std::vector<std::string>> byReason;
        for (const Skipped& s : info.skipped) byReason[s.reason].push_back(s.scene + ": " + s.label);
        o << "\n## Skipped combinations (the library refused them before drawing)\n\n";
        for (const auto& [reason, what] : byReason) {
            o << "- " << what.size() << " x \"" << reason << "\" (e.g. " << what.front() << ")\n";
        }
    }
    std::ofstream out(fs::path(dir_) / "summary.md");
    out << o.str();
    if (!out) throw Error("cannot write summary.md in '" + dir_ + "'");
}

// ---- plots (gnuplot) ----------------------------------------------------------------------------------------

namespace {

std::string fileSafe(std::string s) {
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') c = '_';
    return s;
}

std::string gpString(const std::string& s) {
    std::string q = "\"";
    for (char c : s) {
        if (c == '\n') {
            q += "\\n";
            continue;
        }
        if (c == '"' || c == '\\') q += '\\';
        q += c;
    }
    return q + "\"";
}

std::string shellQuoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

bool haveGnuplot() { return std::system("gnuplot --version >/dev/null 2>&1") == 0; }

const char* kPreamble =
    "set terminal pngcairo size 760,460 font 'sans,8' noenhanced\n"
    "set grid lc rgb '#dddddd'\n"
    "set key outside right top\n";

// Time against error for one scene: every configuration, coloured by mode, Pareto front stepped through.
std::string timeVsError(const std::vector<const Row*>& rows, const std::string& title, const std::string& png) {
    std::ostringstream g;
    g << kPreamble << "set output " << gpString(png) << "\n";
    g << "set title " << gpString(title) << "\nset logscale x\nset xlabel 'frame time, ms (median, log scale)'\n"
         "set ylabel 'RMSE against forward-brute (8-bit steps)'\nset yrange [0:*]\n";
    std::map<std::string, std::vector<const Row*>> byMode;
    for (const Row* r : rows) byMode[r->run.config.mode].push_back(r);
    std::vector<const Row*> sorted = rows;
    std::sort(sorted.begin(), sorted.end(), [](const Row* a, const Row* b) {
        return a->frameMs.median < b->frameMs.median ||
               (a->frameMs.median == b->frameMs.median && a->error.rmse < b->error.rmse);
    });
    std::vector<const Row*> front;
    double best = 1e300;
    for (const Row* r : sorted)
        if (r->error.rmse < best) {
            front.push_back(r);
            best = r->error.rmse;
        }
    int block = 0;
    for (const auto& [mode, list] : byMode) {
        g << "$M" << block++ << " << EOD\n";
        for (const Row* r : list) g << r->frameMs.median << " " << r->error.rmse << "\n";
        g << "EOD\n";
    }
    g << "$FRONT << EOD\n";
    for (const Row* r : front) g << r->frameMs.median << " " << r->error.rmse << " " << gpString(r->run.config.key()) << "\n";
    g << "EOD\nplot ";
    block = 0;
    for (const auto& [mode, list] : byMode)
        g << "$M" << block++ << " using 1:2 with points pt 7 ps 1.1 title " << gpString(mode) << ", ";
    g << "$FRONT using 1:2 with steps lw 2 lc rgb '#cc0000' title 'Pareto front', "
         "$FRONT using 1:2:3 with labels left offset 0.6,0.5 font ',7' notitle\n";
    return g.str();
}

// Frame time against the controlled overlap k, one line per configuration.
std::string overlapPlot(const std::map<std::string, std::vector<std::pair<int, double>>>& lines, const std::string& title,
                        const std::string& png, const std::string& ylabel, bool logY) {
    std::ostringstream g;
    g << kPreamble << "set output " << gpString(png) << "\n";
    g << "set terminal pngcairo size 900,520 font 'sans,8' noenhanced\n";
    g << "set title " << gpString(title) << "\nset logscale x 2\n" << (logY ? "set logscale y 2\n" : "set yrange [0:*]\n")
      << "set xtics (1,2,4,8,16)\nset xrange [0.8:20]\n"
         "set xlabel 'lights on every lit pixel (k)'\nset ylabel " << gpString(ylabel) << "\n"
         "set key outside right top font ',7' spacing 0.9\n";
    int block = 0;
    for (const auto& [label, pts] : lines) {
        g << "$L" << block++ << " << EOD\n";
        for (const auto& [k, t] : pts) g << k << " " << t << "\n";
        g << "EOD\n";
    }
    g << "plot ";
    block = 0;
    for (const auto& [label, pts] : lines) {
        g << (block ? ", " : "") << "$L" << block << " using 1:2 with linespoints pt 7 ps 0.7 title " << gpString(label);
        ++block;
    }
    g << "\n";
    return g.str();
}

// Stacked per-pass breakdown for one scene; configurations far slower than LIDR and tiled go off scale and
// are named in the title instead.
// The bars of a per-pass plot: one setting of MSAA and transparency (no MSAA, opaque where measured, as
// every mode draws that), and for LIDR one index width per scheme, budget and volume test (the narrowest:
// widths change the unpack arithmetic, not the passes). Everything is in the CSV; the plot stays readable.
std::vector<const Row*> passPlotRows(const std::vector<const Row*>& rows) {
    bool anyOpaque = false;
    for (const Row* r : rows) anyOpaque |= r->run.config.msaa == 0 && !r->run.config.transparency;
    std::map<std::string, const Row*> narrowest;
    std::vector<const Row*> out;
    for (const Row* r : rows) {
        const ModeConfig& c = r->run.config;
        if (c.msaa != 0 || c.transparency == anyOpaque) continue;
        if (c.mode != "lidr") {
            out.push_back(r);
            continue;
        }
        const std::string key = c.scheme + "|" + std::to_string(c.budget) + "|" + c.volumeTest;
        auto it = narrowest.find(key);
        if (it == narrowest.end() || c.indexBits < it->second->run.config.indexBits) narrowest[key] = r;
    }
    for (const Row* r : rows)
        if (r->run.config.mode == "lidr" && r->run.config.msaa == 0 && r->run.config.transparency != anyOpaque &&
            narrowest.at(r->run.config.scheme + "|" + std::to_string(r->run.config.budget) + "|" + r->run.config.volumeTest) == r)
            out.push_back(r);
    return out;
}

std::string passesPlot(const std::vector<const Row*>& allRows, const std::string& title, const std::string& png) {
    const std::vector<const Row*> rows = passPlotRows(allRows);
    double cap = 0.0;
    for (const Row* r : rows)
        if (r->run.config.mode == "lidr" || r->run.config.mode == "tiled" || r->run.config.mode == "clustered")
            cap = std::max(cap, r->frameMs.median);
    cap = cap > 0 ? 3.0 * cap : 1e300;
    std::vector<const Row*> shown;
    std::string offScale;
    for (const Row* r : rows) {
        if (r->frameMs.median <= cap)
            shown.push_back(r);
        else
            offScale += (offScale.empty() ? "" : ", ") + r->run.config.key() + " " + ms(r->frameMs.median) + " ms";
    }
    std::vector<std::string> passNames;
    for (const Row* r : shown)
        for (const PassStat& p : r->passes)
            if (std::find(passNames.begin(), passNames.end(), p.pass) == passNames.end()) passNames.push_back(p.pass);
    std::ostringstream g;
    const int width = std::clamp(380 + 30 * int(shown.size()), 720, 1400);
    g << "set terminal pngcairo size " << width << ",520 font 'sans,8' noenhanced\nset output " << gpString(png) << "\n";
    g << "set title " << gpString(title + (offScale.empty() ? "" : "\noff scale: " + offScale)) << "\n";
    g << "set style data histograms\nset style histogram rowstacked\nset style fill solid 0.85 border -1\n"
         "set boxwidth 0.75\nset xtics rotate by -40 left font ',7'\nset ylabel 'ms (median per pass)'\n"
         "set key outside right top\nset grid ytics lc rgb '#dddddd'\nset yrange [0:*]\nset bmargin 12\n";
    g << "$P << EOD\n";
    for (const Row* r : shown) {
        g << gpString(r->run.config.key());
        for (const std::string& name : passNames) {
            double v = 0.0;
            for (const PassStat& p : r->passes)
                if (p.pass == name) v = p.ms.median;
            g << " " << v;
        }
        g << "\n";
    }
    g << "EOD\nplot ";
    for (size_t i = 0; i < passNames.size(); ++i)
        g << (i ? ", " : "") << "$P using " << (i + 2) << (i == 0 ? ":xtic(1)" : "") << " title " << gpString(passNames[i]);
    g << "\n";
    return g.str();
}

// Frame time against a scene size (light count, triangles), one line per configuration, log x.
std::string scalingPlot(const std::map<std::string, std::vector<std::pair<double, double>>>& lines,
                        const std::string& title, const std::string& xlabel, bool logY) {
    std::ostringstream g;
    g << kPreamble << "set output \"\"\n";
    g << "set terminal pngcairo size 900,520 font 'sans,8' noenhanced\n";
    g << "set title " << gpString(title) << "\nset logscale x 2\n" << (logY ? "set logscale y\n" : "set yrange [0:*]\n")
      << "set xlabel " << gpString(xlabel) << "\nset ylabel "
      << gpString(std::string("frame time, ms (median over rounds") + (logY ? ", log scale)" : ")")) << "\n"
      << "set key outside right top font ',7' spacing 0.9\n";
    int block = 0;
    for (const auto& [label, pts] : lines) {
        g << "$S" << block++ << " << EOD\n";
        for (const auto& [x, t] : pts) g << x << " " << t << "\n";
        g << "EOD\n";
    }
    g << "plot ";
    block = 0;
    for (const auto& [label, pts] : lines) {
        g << (block ? ", " : "") << "$S" << block << " using 1:2 with linespoints pt 7 ps 0.7 title " << gpString(label);
        ++block;
    }
    g << "\n";
    return g.str();
}

// The configurations of the scaling sweeps (sweepPreset): LIDR bitshift at budgets 4 and 8 with any volume
// test, tiled min/max, clustered, forward-multipass; no MSAA, opaque. The line's name leaves out the index width (8-bit
// up to 255 lights, 16-bit past that).
std::string sweepLine(const Row& r) {
    const ModeConfig& c = r.run.config;
    if (c.msaa != 0 || c.transparency || c.volumeDetail) return "";
    if (c.mode == "lidr" && c.scheme == "bitshift" && (c.budget == 4 || c.budget == 8))
        return "lidr bitshift b" + std::to_string(c.budget) + " " + c.volumeTest;
    if (c.mode == "tiled" && c.tiledDepthBounds) return c.label();
    if (c.mode == "clustered" || c.mode == "forward-multipass") return c.label();
    return "";
}

// Lines of frame time against x (x(row) <= 0: not in this plot), suffixed with the size where the rows
// have several; lines with one point dropped.
std::map<std::string, std::vector<std::pair<double, double>>> sweepLines(const std::vector<Row>& rows,
                                                                         const std::function<double(const Row&)>& x) {
    std::set<std::string> sizes;
    for (const Row& r : rows)
        if (x(r) > 0 && !sweepLine(r).empty()) sizes.insert(std::to_string(r.run.width) + "x" + std::to_string(r.run.height));
    std::map<std::string, std::vector<std::pair<double, double>>> lines;
    for (const Row& r : rows) {
        const std::string line = sweepLine(r);
        if (x(r) <= 0 || line.empty()) continue;
        const std::string size = std::to_string(r.run.width) + "x" + std::to_string(r.run.height);
        lines[line + (sizes.size() > 1 ? " " + size : "")].push_back({x(r), r.frameMs.median});
    }
    // A line needs two x values: rows of one scene alone (the room's other groups: widths, transparency) are no
    // scaling line.
    for (auto it = lines.begin(); it != lines.end();) {
        std::sort(it->second.begin(), it->second.end());
        const bool oneX = it->second.front().first == it->second.back().first;
        it = oneX ? lines.erase(it) : std::next(it);
    }
    return lines;
}

}  // namespace

std::vector<std::string> ReportWriter::writePlots(std::string& message) const {
    std::vector<std::string> written;
    if (rows_.empty()) {
        message = "no rows measured, no plots";
        return written;
    }
    if (!haveGnuplot()) {
        message = "gnuplot not found: no plots written (CSV, JSON and summary.md are complete). Install Debian's "
                  "gnuplot-nox (scripts/setup.sh does) and run lidr-bench again.";
        return written;
    }
    const fs::path plotDir = fs::path(dir_) / "plots";
    fs::create_directories(plotDir);
    std::vector<std::pair<std::string, std::string>> jobs;  // png name, script
    std::vector<std::string> order;
    for (const Row& r : rows_)
        if (std::find(order.begin(), order.end(), sceneKey(r)) == order.end()) order.push_back(sceneKey(r));
    std::map<std::string, std::vector<std::pair<int, double>>> overlapLines, overlapErrors;
    std::string overlapSize;
    for (const std::string& key : order) {
        std::vector<const Row*> rows;
        for (const Row& r : rows_)
            if (sceneKey(r) == key) rows.push_back(&r);
        const std::string base = fileSafe(key);
        const bool overlapScene = rows.front()->run.scene.rfind("overlap-", 0) == 0;
        std::vector<const Row*> judged;
        for (const Row* r : rows)
            if (r->hasError) judged.push_back(r);
        if ((!overlapScene || rows.front()->run.scene == "overlap-16") && !judged.empty()) {
            jobs.push_back({"time_vs_error_" + base + ".png",
                            timeVsError(judged, "time against error: " + key + " (" +
                                                  std::to_string(rows.front()->sceneLights) + " lights)", "")});
        }
        if (!overlapScene || rows.front()->run.scene == "overlap-16") {
            jobs.push_back({"passes_" + base + ".png", passesPlot(rows, "per-pass breakdown: " + key, "")});
        }
        if (overlapScene) {
            const int k = std::atoi(rows.front()->run.scene.c_str() + 8);
            for (const Row* r : rows)
                // One line per configuration at 8-bit indices (4-bit holds overlap-1 only, widths change no
                // pass): about twenty lines, a legible key.
                if (r->run.config.msaa == 0 && (r->run.config.mode != "lidr" || r->run.config.indexBits == 8)) {
                    const std::string line = r->run.config.key();
                    overlapLines[line].push_back({k, r->frameMs.median});
                    if (r->run.config.mode != "forward-brute" && r->hasError) overlapErrors[line].push_back({k, r->error.rmse});
                }
        }
    }
    // The scaling sweeps: many-N-fp scenes against N, the room and heavy-T scenes against their triangles.
    const auto lightLines = sweepLines(rows_, [](const Row& r) {
        const std::string& s = r.run.scene;
        return s.rfind("many-", 0) == 0 && s.size() > 3 && s.substr(s.size() - 3) == "-fp" ? double(r.sceneLights) : 0.0;
    });
    if (!lightLines.empty())
        jobs.push_back({"lights_time.png", scalingPlot(lightLines, "frame time against light count (many-N-fp scenes)",
                                                       "lights in the scene (log scale)", true)});
    const auto hallLines = sweepLines(rows_, [](const Row& r) {
        return r.run.scene.rfind("hall-", 0) == 0 && r.run.group == "hall" ? double(r.sceneLights) : 0.0;
    });
    if (!hallLines.empty())
        jobs.push_back({"hall_lights_time.png", scalingPlot(hallLines, "frame time against light count (hall-N scenes)",
                                                            "lights in the scene (log scale)", true)});
    const auto triangleLines = sweepLines(rows_, [](const Row& r) {
        return r.run.scene == "room" || r.run.scene.rfind("heavy-", 0) == 0 ? double(r.sceneTriangles) : 0.0;
    });
    if (!triangleLines.empty())
        jobs.push_back({"triangles_time.png",
                        scalingPlot(triangleLines, "frame time against scene triangles (room, heavy-T scenes; 255 lights)",
                                    "triangles in the scene (log scale)", false)});
    if (!overlapLines.empty()) {
        jobs.push_back({"overlap_time.png", overlapPlot(overlapLines, "frame time against overlap k (controlled-overlap scenes)",
                                                        "", "frame time, ms (median, log scale)", true)});
        jobs.push_back({"overlap_error.png", overlapPlot(overlapErrors, "error against overlap k (controlled-overlap scenes)",
                                                         "", "RMSE against forward-brute (8-bit steps)", false)});
    }
    std::string failures;
    for (auto& [png, script] : jobs) {
        const fs::path pngPath = plotDir / png;
        const fs::path gp = plotDir / (png.substr(0, png.size() - 4) + ".gp");
        // The scripts are kept next to the PNGs: edit and re-run `gnuplot FILE.gp` in that folder.
        const std::string marker = "set output \"\"";
        const size_t at = script.find(marker);
        if (at != std::string::npos) script.replace(at, marker.size(), "set output " + gpString(png));
        std::ofstream(gp) << script;
        const std::string cmd = "cd " + shellQuoted(plotDir.string()) + " && gnuplot " +
                                shellQuoted(gp.filename().string()) + " 2>" + shellQuoted(gp.filename().string() + ".log");
        if (std::system(cmd.c_str()) == 0 && fs::exists(pngPath) && fs::file_size(pngPath) > 0) {
            written.push_back(pngPath.string());
            fs::remove(plotDir / (gp.filename().string() + ".log"));
        } else {
            failures += (failures.empty() ? "" : ", ") + png;
        }
    }
    message = std::to_string(written.size()) + " plots in " + plotDir.string() +
              (failures.empty() ? "" : "; gnuplot failed on " + failures + " (see the .gp.log files)");
    return written;
}

}  // namespace lidr::bench
