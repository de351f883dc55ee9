// lidr-bench's plots: gnuplot scripts kept next to the PNGs they draw (time against error, per-pass breakdowns,
// frame time against overlap, light count and triangles).
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "bench_report.h"
#include "bench_report_text.h"

namespace lidr::bench {

namespace fs = std::filesystem;

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
    if (c.mode == "clustered") return c.label();
    if (c.mode == "forward-multipass") return c.mode;
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

using PlotJobs = std::vector<std::pair<std::string, std::string>>;  // png name, gnuplot script

// Per scene and size: time against error and the per-pass breakdown; the controlled-overlap scenes' rows as lines
// against k.
using OverlapLines = std::map<std::string, std::vector<std::pair<int, double>>>;
void addScenePlots(PlotJobs& jobs, const std::vector<Row>& rows_, OverlapLines& overlapLines,
                   OverlapLines& overlapErrors) {
    const std::vector<std::string> order = sceneOrder(rows_);
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
}

// The scaling sweeps: many-N-fp scenes against N, the room and heavy-T scenes against their triangles.
void addSweepPlots(PlotJobs& jobs, const std::vector<Row>& rows_) {
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
}

// Frame time and error against the overlap k of the controlled-overlap scenes.
void addOverlapPlots(PlotJobs& jobs, const OverlapLines& overlapLines, const OverlapLines& overlapErrors) {
    if (!overlapLines.empty()) {
        jobs.push_back({"overlap_time.png", overlapPlot(overlapLines, "frame time against overlap k (controlled-overlap scenes)",
                                                        "", "frame time, ms (median, log scale)", true)});
        jobs.push_back({"overlap_error.png", overlapPlot(overlapErrors, "error against overlap k (controlled-overlap scenes)",
                                                         "", "RMSE against forward-brute (8-bit steps)", false)});
    }
}

// Writes each job's script next to its PNG and runs gnuplot on it; returns the PNGs written, and the failures.
std::vector<std::string> runGnuplot(PlotJobs& jobs, const fs::path& plotDir, std::string& failures) {
    std::vector<std::string> written;
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
    return written;
}

}  // namespace

std::vector<std::string> ReportWriter::writePlots(std::string& message) const {
    if (rows_.empty()) {
        message = "no rows measured, no plots";
        return {};
    }
    if (!haveGnuplot()) {
        message = "gnuplot not found: no plots written (CSV, JSON and summary.md are complete). Install Debian's "
                  "gnuplot-nox (scripts/setup.sh does) and run lidr-bench again.";
        return {};
    }
    const fs::path plotDir = fs::path(dir_) / "plots";
    fs::create_directories(plotDir);
    PlotJobs jobs;
    OverlapLines overlapLines, overlapErrors;
    addScenePlots(jobs, rows_, overlapLines, overlapErrors);
    addSweepPlots(jobs, rows_);
    addOverlapPlots(jobs, overlapLines, overlapErrors);
    std::string failures;
    const std::vector<std::string> written = runGnuplot(jobs, plotDir, failures);
    message = std::to_string(written.size()) + " plots in " + plotDir.string() +
              (failures.empty() ? "" : "; gnuplot failed on " + failures + " (see the .gp.log files)");
    return written;
}

}  // namespace lidr::bench
