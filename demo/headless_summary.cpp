#include "headless_summary.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "lidr/base/error.h"
#include "lidr/base/image.h"
#include "lidr/render/material_variants.h"
#include "lidr/render/shadow_atlas.h"

namespace lidr::demo {

// A number with `digits` decimals, without touching the stream it is written to (its precision stays).
std::string formatFixed(double v, int digits) {
    std::ostringstream o;
    o << std::fixed << std::setprecision(digits) << v;
    return o.str();
}


namespace {
double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}
}  // namespace

void MedianTimes::add(const std::vector<PassTime>& passes) {
    double total = 0.0;
    for (const PassTime& p : passes) {
        if (!samples.count(p.pass)) order.push_back(p.pass);
        samples[p.pass].push_back(p.milliseconds);
        total += p.milliseconds;
    }
    if (!samples.count("frame")) order.push_back("frame");
    samples["frame"].push_back(total);
}

nlohmann::json MedianTimes::json() const {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& name : order) j[name] = median(samples.at(name));
    return j;
}

nlohmann::json errorJson(const ImageError& e) {
    return {{"max_abs_error", e.maxAbsError},       {"rmse", e.rmse},
            {"psnr_db", std::isinf(e.psnr) ? 999.0 : e.psnr}, {"differing_pixels", e.differingPixels},
            {"pixels_over_1", e.pixelsOverThreshold}, {"compared_pixels", e.comparedPixels}};
}

// A frame's GL calls through the state cache (FrameStats::glCalls): summary.json's "gl_calls" and the text line.
nlohmann::json glCallsJson(const GlCallCounters& c) {
    return {{"state_calls", c.stateCalls}, {"state_calls_skipped", c.stateCallsSkipped}, {"draw_calls", c.drawCalls},
            {"clears", c.clears}, {"program_binds", c.programBinds}, {"texture_binds", c.textureBinds},
            {"framebuffer_binds", c.framebufferBinds}};
}

std::string glCallsLine(const GlCallCounters& c) {
    std::ostringstream s;
    s << "gl calls   " << c.stateCalls << " state calls (" << c.stateCallsSkipped << " skipped as redundant), "
      << c.drawCalls << " draws, " << c.clears << " clears, " << c.programBinds << " program, " << c.textureBinds
      << " texture, " << c.framebufferBinds << " framebuffer binds a frame\n";
    return s.str();
}

// The last frame's passes: draws, state calls and fragment shader invocations each (FrameTimer; fragments only
// where the context has ARB_pipeline_statistics_query).
nlohmann::json passCountsJson(const std::vector<PassTime>& passes) {
    nlohmann::json j = nlohmann::json::array();
    for (const PassTime& p : passes) {
        j.push_back({{"pass", p.pass}, {"draw_calls", p.drawCalls}, {"state_calls", p.stateCalls}});
        if (p.fragments >= 0) j.back()["fragments"] = p.fragments;
    }
    return j;
}

std::string passCountsLine(const std::vector<PassTime>& passes) {
    if (passes.empty()) return "";
    std::ostringstream s;
    s << "per pass  ";
    bool counted = false;
    for (const PassTime& p : passes) {
        s << " " << p.pass << ": " << p.drawCalls << " draws, " << p.stateCalls << " state calls";
        if (p.fragments >= 0) {
            s << ", " << std::fixed << std::setprecision(3) << double(p.fragments) * 1e-6 << std::defaultfloat
              << " M fragments";
            counted = true;
        }
        s << ";";
    }
    s << (counted ? " (fragments: fragment shader invocations)\n"
                  : " (fragments not counted: no ARB_pipeline_statistics_query)\n");
    return s.str();
}

std::string path(const std::string& dir, const std::string& file) {
    return (std::filesystem::path(dir) / file).string();
}

// Creates `dir` and proves it writable with a probe file, so an unwritable --out or --dump fails before any
// rendering, naming the folder and the system's reason.
void prepareWritableFolder(const std::string& dir, const std::string& option) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw Error(option + ": cannot create folder '" + dir + "': " + ec.message());
    if (!std::filesystem::is_directory(dir, ec)) throw Error(option + ": '" + dir + "' is not a folder");
    const std::string probe = path(dir, ".lidr-write-test");
    errno = 0;
    std::FILE* file = std::fopen(probe.c_str(), "wb");
    if (!file) throw Error(option + ": cannot write into '" + dir + "': " + std::strerror(errno));
    std::fclose(file);
    std::filesystem::remove(probe, ec);
}



HeadlessStart startHeadless(const Scene& scene, const std::string& outDir, const demo::RendererChoice& rc,
                            const demo::ShadowChoice& shadowChoice) {
    HeadlessStart start{scene.lightsAt(scene.time), sceneShading(scene, rc.outputTransform()), nullptr, scene.warnings};
    shadowChoice.apply(scene, start.lights, start.shading);
    prepareWritableFolder(outDir, "--out");
    start.context = GlContext::create(rc.contextOptions());
    std::cout << "GL: " << start.context->info().summary() << "\n";
    for (const std::string& w : textureUnitWarnings(scene, start.context->info().maxTextureUnits))
        start.warnings.push_back(w);
    return start;
}

// Every mode but lidr: the image, the reference and the error, and for tiled and clustered the grid and its heat map.
// The shadow atlas as a picture (the viewer's and the page's debug view, ShadowAtlas::image), where the frame drew
// one and the context can read it (ES 2.0 reads no depth texture back).
void writeShadowAtlas(const Renderer& renderer, const GlInfo& info, const std::string& outDir) {
    const ShadowAtlas* atlas = renderer.shadowAtlas();
    if (!atlas || (info.gles && !atlas->packed())) return;
    writePng(path(outDir, "shadow_atlas.png"), atlas->image(1024));
}

// The frame's shadows for summary.json and the text summary: casters, maps drawn by the first frame and by the
// last (0 when nothing moved: the maps are drawn once for a static scene).
void addShadowSummary(nlohmann::json& summary, std::ostream& s, const demo::ShadowChoice& choice,
                      const ShadingParameters& shading, int firstFrameMaps, const FrameStats& last) {
    if (choice.casters == demo::ShadowChoice::Casters::Off) return;
    summary["shadows"] = {{"setting", choice.describe(shading.shadows)}, {"casters", last.shadowCasters},
                          {"maps_first_frame", firstFrameMaps}, {"maps_last_frame", last.shadowMapsDrawn},
                          {"atlas_size", shading.shadows.atlas.size}, {"tile_size", shading.shadows.atlas.tileSize}};
    s << "shadows    " << last.shadowCasters << " casters (" << choice.describe(shading.shadows) << "), "
      << firstFrameMaps << " maps drawn on the first frame, " << last.shadowMapsDrawn << " on the last\n";
}

// The camera as three.js's PerspectiveCamera takes it (scripts/threejs_compare.py renders the same view).
namespace {
nlohmann::json cameraJson(const Camera& c) {
    return {{"position", {c.position.x, c.position.y, c.position.z}}, {"target", {c.target.x, c.target.y, c.target.z}},
            {"up", {c.up.x, c.up.y, c.up.z}}, {"fov_y_degrees", c.fovYDegrees}, {"near", c.nearPlane}, {"far", c.farPlane}};
}
}  // namespace

// The environment light as the frame looked it up (FrameStats::environment): summary.json's "environment" and
// the text line.
void addEnvironmentSummary(nlohmann::json& summary, std::ostream& s, const Scene& scene, const FrameStats& last) {
    summary["environment"] = {{"description", last.environment},
                              {"name", scene.environment ? scene.environment->name : std::string("none")},
                              {"intensity", scene.environmentIntensity}};
    s << "environment " << last.environment << "\n";
}

// summary.json's "gl" and "scene", and the text summary's first lines: the scene, its warnings, the renderer.
void describeRun(nlohmann::json& summary, std::ostream& s, const GlInfo& info, const Scene& scene, size_t lights,
                 const std::vector<std::string>& warnings) {
    summary["gl"] = {{"backend", info.backend}, {"version", info.version}, {"renderer", info.renderer},
                     {"vendor", info.vendor}, {"glsl", info.glslVersion}};
    summary["scene"] = {{"name", scene.name}, {"width", scene.width}, {"height", scene.height},
                        {"camera", cameraJson(scene.camera)},
                        {"triangles", scene.triangleCount()}, {"lights", lights}, {"time", scene.time},
                        {"warnings", warnings}};
    s << "scene      " << scene.name << ", " << scene.width << "x" << scene.height << ", " << scene.triangleCount()
      << " triangles, " << lights << " lights\n";
    for (const std::string& warning : warnings) s << "warning    " << warning << "\n";
    s << "renderer   " << info.renderer << " (" << info.version << ")\n";
}

namespace {
nlohmann::json statisticJson(const ModeStatistic::Value& value) {
    return std::visit([](const auto& v) { return nlohmann::json(v); }, value);
}
}  // namespace

// summary.json's section and the text summary's line for what the mode adds (Renderer::modeStatistics).
void addModeStatistics(nlohmann::json& summary, std::ostream& s, const ModeStatistics& m) {
    if (m.section.empty()) return;
    nlohmann::json& section = summary[m.section];
    for (const ModeStatistic& v : m.values) section[v.name] = statisticJson(v.value);
    s << m.line << "\n";
}

}  // namespace lidr::demo
