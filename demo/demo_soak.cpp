#include "demo_soak.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "lidr/base/error.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/modes/render_mode.h"
#include "lidr/platform/context.h"

namespace lidr::demo {
namespace {

uint64_t fnv1a(const std::vector<uint8_t>& bytes) {
    uint64_t h = 1469598103934665603ull;
    for (uint8_t b : bytes) h = (h ^ b) * 1099511628211ull;
    return h;
}

// Resident set size in KiB (/proc/self/statm), 0 where it cannot be read.
long residentKiB() {
    std::ifstream statm("/proc/self/statm");
    long size = 0, resident = 0;
    if (!(statm >> size >> resident)) return 0;
    return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

std::string hex(uint64_t v) {
    std::ostringstream s;
    s << std::hex << std::setw(16) << std::setfill('0') << v;
    return s.str();
}

}  // namespace

int runSoak(const SceneChoice& sceneChoice, const RendererChoice& rc, const std::string& outDir, int frames,
            double timeStep) {
    const Scene scene = sceneChoice.load();
    const RenderModeOptions modeOptions = rc.renderModeOptions(scene);
    checkTargetMemory(scene, modeOptions);
    const double lastTime = scene.time + double(frames - 1) * timeStep;
    if (!std::isfinite(lastTime) || lastTime > 1e7)
        throw Error("--frames " + std::to_string(frames) + " x --time-step " + std::to_string(timeStep) +
                    " reaches time " + std::to_string(lastTime) + " s; at most 1e7 s are supported");
    std::error_code ec;
    std::filesystem::create_directories(outDir, ec);
    if (ec) throw Error("--out: cannot create folder '" + outDir + "': " + ec.message());
    const std::string csvPath = (std::filesystem::path(outDir) / "soak.csv").string();
    std::ofstream csv(csvPath);
    if (!csv) throw Error("cannot write '" + csvPath + "': " + std::strerror(errno));
    csv << "frame,time,image_fnv1a64,rss_kib,live_gl_objects\n";

    const int objectsBefore = gl::liveGlObjects();
    auto context = GlContext::create(rc.contextOptions());
    std::cout << "GL: " << context->info().summary() << "\n";
    const ShadingParameters shading = sceneShading(scene, rc.outputTransform());
    std::vector<long> rss;
    {
        std::unique_ptr<Renderer> renderer =
            createRenderer(modeOptions, context->info(), scene, scene.width, scene.height);
        for (int k = 0; k < frames; ++k) {
            const double t = scene.time + double(k) * timeStep;
            placeAnimatedObjects(*renderer, scene, float(t));  // keyframed meshes move too (no-op without any)
            renderer->render(cameraAt(scene, float(t)), scene.lightsAt(float(t)), shading);
            const ImageRGBA8 image = renderer->targets().readColor();
            rss.push_back(residentKiB());
            csv << k << "," << std::setprecision(9) << t << "," << hex(fnv1a(image.pixels)) << "," << rss.back() << ","
                << gl::liveGlObjects() << "\n";
        }
    }
    const int objectsAfter = gl::liveGlObjects() - objectsBefore;
    csv.close();
    if (!csv) throw Error("cannot write '" + csvPath + "'");

    // Memory at the start (the largest of the first 10 % after the first 10 frames, when caches have filled)
    // and at the end (the largest of the last 10 %).
    const size_t n = rss.size(), tenth = std::max<size_t>(1, n / 10);
    const size_t startFrom = std::min<size_t>(10, n - 1);
    const long startKiB = *std::max_element(rss.begin() + long(startFrom), rss.begin() + long(std::min(n, startFrom + tenth)));
    const long endKiB = *std::max_element(rss.end() - long(tenth), rss.end());
    nlohmann::json summary = {{"frames", frames},
                              {"time_start", scene.time},
                              {"time_step", timeStep},
                              {"mode", modeOptions.mode},
                              {"width", scene.width},
                              {"height", scene.height},
                              {"rss_start_kib", startKiB},
                              {"rss_end_kib", endKiB},
                              {"rss_growth_kib", endKiB - startKiB},
                              {"gl_objects_left_after_release", objectsAfter}};
    std::ofstream((std::filesystem::path(outDir) / "soak.json").string()) << summary.dump(2) << "\n";
    std::cout << "soak       " << frames << " frames of " << modeOptions.mode << " at " << scene.width << "x"
              << scene.height << ", t = " << scene.time << " + k * " << timeStep << " s\n"
              << "memory     resident " << startKiB << " KiB at the start, " << endKiB << " KiB at the end ("
              << (endKiB - startKiB) << " KiB)\n"
              << "GL objects " << objectsAfter << " left after the renderer was destroyed\n"
              << "outputs    " << outDir << "/soak.csv, soak.json\n";
    return objectsAfter == 0 ? 0 : 1;
}

}  // namespace lidr::demo
