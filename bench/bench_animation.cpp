#include "bench_animation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "bench_config.h"
#include "frame_accuracy.h"
#include "lidr/base/error.h"
#include "lidr/modes/reference_renderer.h"
#include "lidr/modes/render_mode.h"
#include "lidr/platform/context.h"
#include "lidr/scene/camera.h"
#include "lidr/scene/io/bart_scene.h"

namespace lidr::bench {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// The lighting-function invocations a mode ran in a frame (the paper's Figure 3) are counted on the judged frames
// (FrameAccuracy::lightingComputations: they read the frame's depth and lists back, so never inside a timed frame).

struct ModeRun {
    std::string label;
    RenderModeOptions options;
    std::unique_ptr<Renderer> renderer;
};

// The modes of the library's registry (so modes added there join without an edit here): forward-brute is the
// reference, auto chooses among the others; tiled runs with its pre-Z pass and per-tile depth bounds (the paper's
// TiledFwd-PreZ) and without either (its TiledFwd: lights culled by the tiles alone, every fragment shaded).
std::vector<ModeRun> chooseModes(const std::vector<std::string>& asked, const Scene& scene) {
    std::vector<std::string> names = asked;
    if (names.empty())
        for (const std::string& n : renderModeNames())
            if (n != "forward-brute" && n != "auto") names.push_back(n);
    std::vector<ModeRun> runs;
    for (const std::string& name : names) {
        if (!isRenderModeName(name)) throw Error("--modes: unknown render mode '" + name + "' (valid: " + renderModeList() + ")");
        ModeRun run;
        run.options.mode = name;
        run.options.transparency = scene.transparency;
        run.options.lidr.transparency = scene.transparency;
        run.label = name;
        if (name == "tiled") {
            run.label = "tiled min/max";
            runs.push_back(std::move(run));
            ModeRun flat;
            flat.options.mode = name;
            flat.options.transparency = scene.transparency;
            flat.options.lidr.transparency = scene.transparency;
            flat.options.tiled.depthBounds = false;
            flat.options.tiled.preZ = false;
            flat.label = "tiled no-pre-Z";
            runs.push_back(std::move(flat));
            continue;
        }
        runs.push_back(std::move(run));
    }
    return runs;
}

struct FrameRecord {
    int frame = 0;
    float time = 0.0f;
    std::string mode;
    double frameMs = 0.0, wallMs = 0.0;
    int drawnLights = 0;
    long lightingComputations = -1;
    std::string passes;  // "pass=ms;pass=ms", the frame's own (FrameStats::passes)
    bool judged = false;
    FrameAccuracy accuracy;
};

struct ModeSummary {
    std::string mode;
    int frames = 0, judged = 0;
    double sumMs = 0.0, minMs = 1e300, maxMs = 0.0;
    int minFrame = 0, maxFrame = 0;
    double worstPsnr = 1e300, worstPsnrWithinBudget = 1e300;
    long dropped = 0, overBudget = 0;
    bool hasLists = false;
    double shaded = 0.0, truth = 0.0;  // summed over the judged frames
    double computations = 0.0;         // lighting computations, summed over the frames that counted them
    int counted = 0;
    double average() const { return frames ? sumMs / frames : 0.0; }
};

std::string fixed(double v, int digits) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << v;
    return s.str();
}

std::string fileSafe(std::string s) {
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') c = '_';
    return s;
}

std::string readLoadAverage() {
    std::ifstream f("/proc/loadavg");
    std::string a, b, c;
    f >> a >> b >> c;
    return f ? a + " " + b + " " + c : "unknown";
}

std::string commandOutput(const std::string& command) {
    std::string out;
    if (FILE* p = popen(command.c_str(), "r")) {
        char buffer[256];
        while (fgets(buffer, sizeof buffer, p)) out += buffer;
        if (pclose(p) != 0) return "";
    }
    while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
    return out;
}

class AnimationBench {
public:
    AnimationBench(const AnimationBenchOptions& o, GlContext& context) : o_(o), gl_(context.info()) {}

    Json runScene(const std::string& name, std::ofstream& csv) {
        std::string lights;
        Scene scene;
        if (!makeBartSceneByName(name, scene, o_.seed, o_.bart, &lights)) scene = loadBenchScene(name, o_.seed);
        const SceneAnimation& a = scene.animation;
        if (!a.moves() && a.lightBindings.empty())
            throw Error("--animation: scene '" + name + "' has no keyframe animation (an AFF file's keyframes, a glTF "
                        "animation) to play");
        scene.width = o_.resolution.first;
        scene.height = o_.resolution.second;
        scene.validate();
        const ShadingParameters shading = sceneShading(scene);
        std::vector<ModeRun> modes = chooseModes(o_.modes, scene);
        std::vector<std::string> skipped;
        for (ModeRun& m : modes) {
            try {
                m.renderer = createRenderer(m.options, gl_, scene, scene.width, scene.height);
                m.renderer->setTiming(true, true);
            } catch (const UnsupportedError& e) {
                skipped.push_back(m.label + ": " + e.what());
            }
        }
        modes.erase(std::remove_if(modes.begin(), modes.end(), [](const ModeRun& m) { return !m.renderer; }), modes.end());
        if (modes.empty()) throw Error("--animation: no mode can render scene '" + name + "' on this context");
        std::unique_ptr<ReferenceRenderer> reference;
        if (o_.referenceFrames > 0)
            reference = std::make_unique<ReferenceRenderer>(gl_, scene, scene.width, scene.height,
                                                            std::max<int>(1, int(scene.lights.size())), false, 0,
                                                            scene.transparency, false);
        const int n = o_.frames;
        std::vector<bool> judgedFrame(size_t(n), false);
        const int k = std::min(o_.referenceFrames, n);
        for (int i = 0; i < k; ++i) judgedFrame[size_t(k == 1 ? 0 : std::lround(double(i) * (n - 1) / (k - 1)))] = true;
        const auto timeOf = [&](int f) { return n == 1 ? a.start : a.start + (a.end - a.start) * float(f) / float(n - 1); };
        // Warm-up: every mode's first frame (shader compiles, uploads) is not measured.
        for (ModeRun& m : modes) renderAt(m, scene, timeOf(0), shading);
        std::vector<FrameRecord> records;
        const bool tty = isatty(STDERR_FILENO);
        for (int f = 0; f < n; ++f) {
            const float t = timeOf(f);
            for (size_t i = 0; i < modes.size(); ++i) {
                ModeRun& m = modes[(size_t(f) + i) % modes.size()];  // the first mode rotates from frame to frame
                records.push_back(renderAt(m, scene, t, shading));
                records.back().frame = f;
                records.back().mode = m.label;
            }
            if (judgedFrame[size_t(f)] && reference) judge(modes, *reference, scene, t, shading, records);
            for (size_t i = records.size() - modes.size(); i < records.size(); ++i) writeCsv(csv, name, records[i]);
            csv.flush();
            if (tty) std::fprintf(stderr, "\r%s: frame %d / %d (t = %.2f s)\033[K", name.c_str(), f + 1, n, double(t));
        }
        if (tty) std::fprintf(stderr, "\n");
        return summarise(name, scene, lights, modes, skipped, records);
    }

private:
    FrameRecord renderAt(ModeRun& m, const Scene& scene, float t, const ShadingParameters& shading) {
        placeAnimatedObjects(*m.renderer, scene, t);
        const auto start = std::chrono::steady_clock::now();
        const FrameStats& stats = m.renderer->render(cameraAt(scene, t), scene.lightsAt(t), shading);
        FrameRecord r;
        r.time = t;
        r.wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        r.frameMs = stats.frameMilliseconds();
        r.drawnLights = stats.drawnLights;
        for (const PassTime& p : stats.passes) r.passes += (r.passes.empty() ? "" : ";") + p.pass + "=" + fixed(p.milliseconds, 2);
        const AutoDecision& d = stats.autoDecision;  // LIDR's automatic configuration of the frame (zeros elsewhere)
        if (d.budget > 0)
            r.passes += ";budget=" + std::to_string(d.budget) + ";index-bits=" + std::to_string(d.indexBits) +
                        ";repacks=" + std::to_string(d.repacks) + ";volume-area-per-pixel=" + fixed(d.volumeAreaPerPixel, 1) +
                        ";tiles-skipped=" + std::to_string(int(d.tilesSkippedForSaving));
        return r;
    }

    // The frame every mode just drew, against the reference's: the last modes.size() records.
    void judge(std::vector<ModeRun>& modes, ReferenceRenderer& reference, const Scene& scene, float t,
               const ShadingParameters& shading, std::vector<FrameRecord>& records) {
        const Camera camera = cameraAt(scene, t);
        const std::vector<PointLight> lights = scene.lightsAt(t);
        placeAnimatedObjects(reference, scene, t);
        reference.render(camera, lights, shading);
        const ImageRGBA8 truth = reference.targets().readColor();
        for (size_t i = records.size() - modes.size(); i < records.size(); ++i) {
            ModeRun& m = *std::find_if(modes.begin(), modes.end(), [&](const ModeRun& r) { return r.label == records[i].mode; });
            records[i].judged = true;
            records[i].accuracy = judgeFrame(*m.renderer, camera, lights, m.renderer->targets().readColor(), truth);
            records[i].lightingComputations = records[i].accuracy.lightingComputations;
        }
    }

    static void writeCsv(std::ofstream& csv, const std::string& scene, const FrameRecord& r) {
        csv << scene << "," << r.frame << "," << r.time << "," << r.mode << "," << fixed(r.frameMs, 3) << ","
            << fixed(r.wallMs, 3) << "," << r.drawnLights << ",";
        if (r.lightingComputations >= 0) csv << r.lightingComputations;
        csv << ",";
        if (r.judged) {
            const double psnr = std::isinf(r.accuracy.error.psnr) ? 999.0 : r.accuracy.error.psnr;
            csv << fixed(psnr, 2) << "," << r.accuracy.error.maxAbsError << "," << r.accuracy.pixelsOverBudget;
            if (r.accuracy.hasLists)
                csv << "," << r.accuracy.droppedLightPixels << "," << r.accuracy.shadedLightPixels << ","
                    << r.accuracy.trueLightPixels;
            else
                csv << ",,,";
        } else {
            csv << ",,,,,";
        }
        csv << "," << r.passes << "\n";
    }

    Json summarise(const std::string& name, const Scene& scene, const std::string& lights, const std::vector<ModeRun>& modes,
                   const std::vector<std::string>& skipped, const std::vector<FrameRecord>& records) {
        std::map<std::string, ModeSummary> by;
        for (const ModeRun& m : modes) by[m.label].mode = m.label;
        for (const FrameRecord& r : records) {
            ModeSummary& s = by[r.mode];
            ++s.frames;
            s.sumMs += r.frameMs;
            if (r.frameMs < s.minMs) s.minMs = r.frameMs, s.minFrame = r.frame;
            if (r.frameMs > s.maxMs) s.maxMs = r.frameMs, s.maxFrame = r.frame;
            if (!r.judged) continue;
            ++s.judged;
            s.worstPsnr = std::min(s.worstPsnr, std::isinf(r.accuracy.error.psnr) ? 999.0 : r.accuracy.error.psnr);
            const double within = r.accuracy.errorWithinBudget.psnr;
            s.worstPsnrWithinBudget = std::min(s.worstPsnrWithinBudget, std::isinf(within) ? 999.0 : within);
            s.overBudget += r.accuracy.pixelsOverBudget;
            if (r.lightingComputations >= 0) s.computations += double(r.lightingComputations), ++s.counted;
            if (r.accuracy.hasLists) {
                s.hasLists = true;
                s.dropped += r.accuracy.droppedLightPixels;
                s.shaded += double(r.accuracy.shadedLightPixels);
                s.truth += double(r.accuracy.trueLightPixels);
            }
        }
        Json j;
        j["scene"] = name;
        j["lights"] = lights.empty() ? std::to_string(scene.lights.size()) + " lights (the scene's own)" : lights;
        j["light_count"] = scene.lights.size();
        j["triangles"] = scene.triangleCount();
        j["width"] = scene.width;
        j["height"] = scene.height;
        j["frames"] = o_.frames;
        j["time_range"] = {scene.animation.start, scene.animation.end};
        j["skipped_modes"] = skipped;
        j["modes"] = Json::array();
        for (const ModeRun& m : modes) {
            const ModeSummary& s = by[m.label];
            Json row = {{"mode", s.mode}, {"frames", s.frames}, {"average_ms", s.average()}, {"min_ms", s.minMs},
                        {"max_ms", s.maxMs}, {"min_frame", s.minFrame}, {"max_frame", s.maxFrame}, {"judged_frames", s.judged}};
            if (s.judged) {
                row["worst_psnr_db"] = s.worstPsnr;
                row["worst_psnr_within_budget_db"] = s.worstPsnrWithinBudget;  // LIDR: where its budget holds
                row["pixels_over_budget"] = s.overBudget;
            }
            if (s.counted) row["lighting_computations_per_counted_frame"] = s.computations / s.counted;
            if (s.hasLists) {
                row["dropped_light_pixels"] = s.dropped;
                row["shaded_light_pixels_per_judged_frame"] = s.shaded / s.judged;
                row["true_light_pixels_per_judged_frame"] = s.truth / s.judged;
            }
            j["modes"].push_back(row);
        }
        if (o_.plots) j["plots"] = plot(name, modes, records);
        return j;
    }

    // Figure 2's frame times and Figure 3's lighting computations (the judged frames' shaded light-pixels), as
    // gnuplot scripts and, where gnuplot is installed, PNGs.
    Json plot(const std::string& name, const std::vector<ModeRun>& modes, const std::vector<FrameRecord>& records) {
        // File names relative to --out, where gnuplot runs: the folder can be moved (doc/results/bart-robots/).
        const std::string base = "animation-" + fileSafe(name);
        const fs::path dir(o_.outDir);
        std::ofstream data((dir / (base + ".dat")).string());
        std::ofstream lists((dir / (base + "-lists.dat")).string());
        data << "# frame time";
        lists << "# frame truth";
        for (const ModeRun& m : modes) data << " '" << m.label << "'", lists << " '" << m.label << "'";
        data << "\n";
        lists << "\n";
        for (size_t i = 0; i < records.size(); i += modes.size()) {
            data << records[i].frame << " " << records[i].time;
            std::map<std::string, const FrameRecord*> of;
            for (size_t k = i; k < i + modes.size() && k < records.size(); ++k) of[records[k].mode] = &records[k];
            for (const ModeRun& m : modes) data << " " << fixed(of[m.label]->frameMs, 3);
            data << "\n";
            if (!records[i].judged) continue;
            long truth = -1;
            for (const auto& [mode, r] : of)
                if (r->accuracy.hasLists) truth = r->accuracy.trueLightPixels;
            lists << records[i].frame << " " << (truth >= 0 ? std::to_string(double(truth) * 1e-6) : "NaN");
            for (const ModeRun& m : modes)
                lists << " " << (of[m.label]->accuracy.hasLists ? std::to_string(double(of[m.label]->accuracy.shadedLightPixels) * 1e-6) : "NaN");
            lists << "\n";
        }
        data.close();  // written out before gnuplot reads them
        lists.close();
        std::ostringstream g;
        g << "set terminal pngcairo size 900,420 font 'sans,9' noenhanced\nset grid lc rgb '#dddddd'\nset key outside right top\n"
          << "set output '" << base << "-frame-times.png'\nset title 'Frame times over the animation: " << name << ", "
          << o_.resolution.first << "x" << o_.resolution.second << " (lidr-bench --animation " << o_.frames << ")'\n"
          << "set xlabel 'frame'\nset ylabel 'frame time, ms'\nset yrange [0:*]\nplot ";
        for (size_t i = 0; i < modes.size(); ++i)
            g << (i ? ", " : "") << "'" << base << ".dat' using 1:" << i + 3 << " with lines lw 1.5 title '" << modes[i].label << "'";
        // The lighting computations of the modes whose lists were checked (a mode without lists has no column values).
        std::vector<size_t> listed;
        for (size_t i = 0; i < modes.size(); ++i)
            if (std::any_of(records.begin(), records.end(), [&](const FrameRecord& r) {
                    return r.mode == modes[i].label && r.judged && r.accuracy.hasLists;
                }))
                listed.push_back(i);
        if (!listed.empty()) {
            g << "\nset output '" << base << "-lighting.png'\nset title 'Lighting computations, judged frames: " << name
              << "'\nset ylabel 'light-pixel pairs shaded, millions (truth: pairs that light a pixel)'\nplot '"
              << base << "-lists.dat' using 1:2 with linespoints lw 2 dt 2 title 'truth'";
            for (size_t i : listed)
                g << ", '" << base << "-lists.dat' using 1:" << i + 3 << " with linespoints title '" << modes[i].label << "'";
        }
        g << "\n";
        std::ofstream((dir / (base + ".gp")).string()) << g.str();
        Json out = {{"script", base + ".gp"}};
        if (std::system("gnuplot --version >/dev/null 2>&1") != 0) {
            out["note"] = "gnuplot not installed: the script is written, no PNG";
        } else if (std::system(("cd '" + o_.outDir + "' && gnuplot '" + base + ".gp' 2>/dev/null").c_str()) == 0) {
            out["frame_times"] = base + "-frame-times.png";
            if (!listed.empty()) out["lighting"] = base + "-lighting.png";
        }
        return out;
    }

    const AnimationBenchOptions& o_;
    const GlInfo& gl_;
};

void writeMarkdown(const std::string& file, const Json& run) {
    std::ofstream md(file);
    md << "# lidr-bench --animation\n\n";
    md << "- command: `" << run["command"].get<std::string>() << "`\n- commit: " << run["commit"].get<std::string>()
       << "\n- GL: " << run["gl"].get<std::string>() << "\n- CPU: " << run["cpu"].get<std::string>()
       << "\n- load average before / after: " << run["load_before"].get<std::string>() << " / "
       << run["load_after"].get<std::string>() << "\n\n";
    for (const Json& scene : run["scenes"]) {
        md << "## " << scene["scene"].get<std::string>() << "\n\n" << scene["lights"].get<std::string>() << "; "
           << scene["triangles"].get<size_t>() << " triangles; " << scene["frames"].get<int>() << " frames over t = "
           << scene["time_range"][0].get<double>() << " .. " << scene["time_range"][1].get<double>() << " s at "
           << scene["width"].get<int>() << "x" << scene["height"].get<int>() << ".\n\n";
        double fastestAverage = 1e300, fastestMax = 1e300;
        for (const Json& m : scene["modes"]) {
            fastestAverage = std::min(fastestAverage, m["average_ms"].get<double>());
            fastestMax = std::min(fastestMax, m["max_ms"].get<double>());
        }
        md << "| mode | average ms | min / max ms (frame) | average / fastest | max / fastest max | judged frames | worst "
              "PSNR dB | dropped light-pixels | shaded light-pixels per judged frame (M) | shaded / truth |\n"
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
        for (const Json& m : scene["modes"]) {
            md << "| " << m["mode"].get<std::string>() << " | " << fixed(m["average_ms"].get<double>(), 1) << " | "
               << fixed(m["min_ms"].get<double>(), 1) << " (" << m["min_frame"].get<int>() << ") / "
               << fixed(m["max_ms"].get<double>(), 1) << " (" << m["max_frame"].get<int>() << ") | "
               << fixed(m["average_ms"].get<double>() / fastestAverage, 2) << " | "
               << fixed(m["max_ms"].get<double>() / fastestMax, 2) << " | " << m["judged_frames"].get<int>() << " | "
               << (m.contains("worst_psnr_db") ? fixed(m["worst_psnr_db"].get<double>(), 1) : "-");
            if (m.contains("pixels_over_budget") && m["pixels_over_budget"].get<long>() > 0)
                md << " (" << fixed(m["worst_psnr_within_budget_db"].get<double>(), 1) << " within the budget; "
                   << m["pixels_over_budget"].get<long>() << " pixels over it)";
            md << " | ";
            if (m.contains("dropped_light_pixels")) {
                const double shaded = m["shaded_light_pixels_per_judged_frame"].get<double>();
                const double truth = m["true_light_pixels_per_judged_frame"].get<double>();
                md << m["dropped_light_pixels"].get<long>() << " | " << fixed(shaded * 1e-6, 2) << " | "
                   << (truth > 0 ? fixed(shaded / truth, 2) : "-") << " |\n";
            } else {
                md << "- | - | - |\n";
            }
        }
        for (const Json& s : scene["skipped_modes"]) md << "\nSkipped: " << s.get<std::string>() << "\n";
        if (scene.contains("plots") && scene["plots"].contains("frame_times"))
            md << "\n![frame times](" << scene["plots"]["frame_times"].get<std::string>() << ")\n";
        if (scene.contains("plots") && scene["plots"].contains("lighting"))
            md << "![lighting computations](" << scene["plots"]["lighting"].get<std::string>() << ")\n";
        md << "\n";
    }
    md << "Frame times are each frame's passes as lidr-bench times them (timer queries, or glFinish around each pass on "
          "llvmpipe), the modes drawing every frame in turn. Judged frames: compared with forward-brute; the lists of "
          "LIDR, tiled and clustered checked against the CPU truth of which lights touch each pixel.\n";
}

}  // namespace

int runAnimationBench(const AnimationBenchOptions& o) {
    if (o.frames < 1 || o.frames > 100000) throw Error("--animation must be 1 .. 100000 frames, got " + std::to_string(o.frames));
    if (o.referenceFrames < 0) throw Error("--reference-frames must be >= 0");
    if (o.scenes.empty()) throw Error("--animation needs --scene (bart-robots-many, bart-robots-few or an .aff file)");
    std::error_code ec;
    fs::create_directories(o.outDir, ec);
    if (ec) throw Error("--out: cannot create folder '" + o.outDir + "': " + ec.message());
    ContextOptions contextOptions;
    contextOptions.backend = parseContextBackend(o.context);
    std::unique_ptr<GlContext> context = GlContext::create(contextOptions);
    std::cout << "GL: " << context->info().summary() << "\n";
    Json run;
    run["command"] = o.commandLine;
    const std::string commit = commandOutput("git -C '" + std::string(LIDR_SOURCE_DIR) + "' rev-parse --short HEAD 2>/dev/null");
    run["commit"] = commit.empty() ? std::string(LIDR_CONFIGURE_COMMIT) : commit;
    run["gl"] = context->info().summary();
    run["cpu"] = commandOutput("grep -m1 'model name' /proc/cpuinfo | cut -d: -f2") + ", " +
                 commandOutput("grep -c ^processor /proc/cpuinfo") + " cores";
    run["load_before"] = readLoadAverage();
    run["seed"] = o.seed;
    run["scenes"] = Json::array();
    std::ofstream csv((fs::path(o.outDir) / "animation.csv").string());
    csv << "scene,frame,time,mode,frame_ms,wall_ms,drawn_lights,lighting_computations,psnr_db,max_error,"
           "pixels_over_budget,dropped_light_pixels,shaded_light_pixels,true_light_pixels,passes\n";
    AnimationBench bench(o, *context);
    for (const std::string& scene : o.scenes) {
        run["scenes"].push_back(bench.runScene(scene, csv));
        std::ofstream((fs::path(o.outDir) / "animation.json").string()) << run.dump(2) << "\n";
    }
    run["load_after"] = readLoadAverage();
    std::ofstream((fs::path(o.outDir) / "animation.json").string()) << run.dump(2) << "\n";
    writeMarkdown((fs::path(o.outDir) / "animation.md").string(), run);
    std::cout << "lidr-bench --animation: " << o.scenes.size() << " scene(s), " << o.frames << " frames each, in "
              << o.outDir << "/{animation.csv,animation.json,animation.md}\n";
    return 0;
}

}  // namespace lidr::bench
