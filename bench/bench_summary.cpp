// summary.md: the run's settings and steadiness, the targets (bench_targets.cpp), one table per scene and size,
// the shadow scenes, the plots and what was skipped.
#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "bench_report.h"
#include "bench_report_text.h"
#include "bench_targets.h"
#include "lidr/base/error.h"

namespace lidr::bench {

namespace {

namespace fs = std::filesystem;

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

// summary.md's opening: status, run metadata, timing methods, and what the columns mean.
void writeSummaryHeader(std::ostream& o, const RunInfo& info, const std::vector<Row>& rows_) {
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
}

void writeSteadiness(std::ostream& o, const std::vector<Row>& rows_) {
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
}

// One table per scene and size, in measurement order.
void writeSceneTables(std::ostream& o, const std::vector<Row>& rows_) {
    const std::vector<std::string> order = sceneOrder(rows_);
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
}

// The plots' links, and the skipped combinations collapsed by the library's reason.
void writePlotsAndSkipped(std::ostream& o, const RunInfo& info, const std::vector<std::string>& plots,
                          const std::string& plotMessage, const std::string& dir_) {
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
}

}  // namespace

void ReportWriter::writeSummary(const RunInfo& info, const std::vector<std::string>& plots,
                                const std::string& plotMessage) const {
    std::ostringstream o;
    writeSummaryHeader(o, info, rows_);
    writeSteadiness(o, rows_);
    writeTargets(o, rows_);
    writeSceneTables(o, rows_);
    shadowSection(o, rows_);
    writePlotsAndSkipped(o, info, plots, plotMessage, dir_);
    std::ofstream out(fs::path(dir_) / "summary.md");
    out << o.str();
    if (!out) throw Error("cannot write summary.md in '" + dir_ + "'");
}

}  // namespace lidr::bench
