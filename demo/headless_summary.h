#pragma once
// What lidr-demo's headless runs share: the output folder, the start of a run (lights, shading, context), and the
// pieces of summary.json and summary.txt (timings, GL calls, shadows, environment, the mode's own statistics).
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "demo_options.h"
#include "lidr/eval/image_compare.h"
#include "lidr/platform/context.h"
#include "lidr/render/renderer.h"

namespace lidr::demo {

// A number with `digits` decimals, without touching the stream it is written to (its precision stays).
std::string formatFixed(double v, int digits);

// Each pass's median over the frames added, and the frame's.
struct MedianTimes {
    std::vector<std::string> order;
    std::map<std::string, std::vector<double>> samples;
    void add(const std::vector<PassTime>& passes);
    nlohmann::json json() const;
};

nlohmann::json errorJson(const ImageError& e);
nlohmann::json glCallsJson(const GlCallCounters& c);
std::string glCallsLine(const GlCallCounters& c);
nlohmann::json passCountsJson(const std::vector<PassTime>& passes);
std::string passCountsLine(const std::vector<PassTime>& passes);
std::string path(const std::string& dir, const std::string& file);
// Creates `dir` and proves it writable with a probe file, so an unwritable --out or --dump fails before any
// rendering, naming the folder and the system's reason.
void prepareWritableFolder(const std::string& dir, const std::string& option);

// What every headless run starts with: the scene's lights and shading with the shadow choice applied (before the
// context: the reference renders with the same lights), the output folder, the GL context, and the scene's
// warnings with the textures this context has no unit for.
struct HeadlessStart {
    std::vector<PointLight> lights;
    ShadingParameters shading;
    std::unique_ptr<GlContext> context;
    std::vector<std::string> warnings;
};
HeadlessStart startHeadless(const Scene& scene, const std::string& outDir, const RendererChoice& rc,
                            const ShadowChoice& shadowChoice);

// The shadow atlas as a picture, where the frame drew one and the context can read it back.
void writeShadowAtlas(const Renderer& renderer, const GlInfo& info, const std::string& outDir);
// The frame's shadows, environment, the run's scene and GL, and the mode's own statistics: each into summary.json
// and a line of the text summary.
void addShadowSummary(nlohmann::json& summary, std::ostream& s, const ShadowChoice& choice,
                      const ShadingParameters& shading, int firstFrameMaps, const FrameStats& last);
void addEnvironmentSummary(nlohmann::json& summary, std::ostream& s, const Scene& scene, const FrameStats& last);
void describeRun(nlohmann::json& summary, std::ostream& s, const GlInfo& info, const Scene& scene, size_t lights,
                 const std::vector<std::string>& warnings);
void addModeStatistics(nlohmann::json& summary, std::ostream& s, const ModeStatistics& m);

}  // namespace lidr::demo
