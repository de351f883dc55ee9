// lidr-demo: renders a scene with LIDR (or --mode tiled, clustered, forward-multipass, forward-brute) and writes what a
// person needs to judge it.
//   --headless (default): render the default room (or --scene FILE) offscreen, compare with the brute-force
//   reference, write images and a summary to --out DIR; --dump DIR adds the raw artefacts.
//   --window: an interactive GLFW window (needs a display) that animates the scene.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iomanip>
#include <map>
#include <optional>

#include <nlohmann/json.hpp>

#include "demo_options.h"
#include "demo_soak.h"
#include "frame_views.h"
#include "lidr/base/gl.h"
#include "lidr/eval/artefacts.h"
#include "lidr/base/error.h"
#include "lidr/eval/frame_evaluation.h"
#include "lidr/eval/light_coverage.h"
#include "lidr/modes/reference_renderer.h"
#include "lidr/modes/auto_mode_renderer.h"
#include "lidr/modes/render_mode.h"
#include "lidr/render/material_variants.h"
#include "lidr/render/present.h"
#include "lidr/render/shadow_atlas.h"
#include "lidr/scene/sphere_bounds.h"
#include "lidr/base/visualize.h"

#if LIDR_HAVE_GLFW
#include <GLFW/glfw3.h>
#endif

using namespace lidr;

namespace {
// A number with `digits` decimals, without touching the stream it is written to (its precision stays).
std::string formatFixed(double v, int digits) {
    std::ostringstream o;
    o << std::fixed << std::setprecision(digits) << v;
    return o.str();
}


struct MedianTimes {
    std::vector<std::string> order;
    std::map<std::string, std::vector<double>> samples;
    void add(const std::vector<PassTime>& passes) {
        double total = 0.0;
        for (const PassTime& p : passes) {
            if (!samples.count(p.pass)) order.push_back(p.pass);
            samples[p.pass].push_back(p.milliseconds);
            total += p.milliseconds;
        }
        if (!samples.count("frame")) order.push_back("frame");
        samples["frame"].push_back(total);
    }
    static double median(std::vector<double> v) {
        if (v.empty()) return 0.0;
        std::sort(v.begin(), v.end());
        return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
    }
    nlohmann::json json() const {
        nlohmann::json j = nlohmann::json::object();
        for (const auto& name : order) j[name] = median(samples.at(name));
        return j;
    }
};

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

// What every headless run starts with: the scene's lights and shading with the shadow choice applied (before the
// context: the reference renders with the same lights), the output folder, the GL context, and the scene's
// warnings with the textures this context has no unit for.
struct HeadlessStart {
    std::vector<PointLight> lights;
    ShadingParameters shading;
    std::unique_ptr<GlContext> context;
    std::vector<std::string> warnings;
};

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
nlohmann::json cameraJson(const Camera& c) {
    return {{"position", {c.position.x, c.position.y, c.position.z}}, {"target", {c.target.x, c.target.y, c.target.z}},
            {"up", {c.up.x, c.up.y, c.up.z}}, {"fov_y_degrees", c.fovYDegrees}, {"near", c.nearPlane}, {"far", c.farPlane}};
}

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

// The deferred modes' G-buffer (doc/deferred.md): its format and bytes a pixel beside the light sum's, and, for
// deferred, the last frame's lighting computations (its per-pixel count of light shaders run, read back).
void describeDeferred(const Renderer& renderer, nlohmann::json& summary, std::ostream& s) {
    const auto* deferred = dynamic_cast<const DeferredRenderer*>(&renderer);
    const auto* tiledDeferred = dynamic_cast<const TiledDeferredRenderer*>(&renderer);
    if (!deferred && !tiledDeferred) return;
    const GBuffer& g = deferred ? deferred->gBuffer() : tiledDeferred->gBuffer();
    nlohmann::json j = {{"g_buffer_format", gBufferFormatName(g.format())},
                        {"g_buffer_bytes_per_pixel", g.bytesPerPixel()},
                        {"light_sum_bytes_per_pixel", g.accumulationBytesPerPixel()}};
    s << "g-buffer   " << gBufferFormatName(g.format()) << ", " << g.bytesPerPixel() << " bytes a pixel";
    if (deferred) {
        double computations = 0.0;
        if (!renderer.frame().info.gles)  // ES 2.0 reads no float pixels back
            for (float c : g.readLightCounts()) computations += c;
        j["stencil"] = deferred->options().stencil;
        j["lighting_computations"] = renderer.frame().info.gles ? -1.0 : computations;
        s << " + " << g.accumulationBytesPerPixel() << " for the light sum ("
          << gBufferFormatName(g.format()) << "), stencil " << (deferred->options().stencil ? "on" : "off");
        if (!renderer.frame().info.gles) s << ", " << long(computations) << " lighting computations";
    }
    s << "\n";
    summary["deferred"] = j;
}

int runHeadlessMode(const Scene& scene, const RenderModeOptions& mo, const std::string& outDir, int frames,
                    bool withReference, const demo::RendererChoice& rc, const demo::ShadowChoice& shadowChoice) {
    const auto [lights, shading, context, warnings] = startHeadless(scene, outDir, rc, shadowChoice);
    const GlInfo& info = context->info();
    std::unique_ptr<Renderer> renderer = createRenderer(mo, info, scene, scene.width, scene.height);
    renderer->setTiming(true, true);  // each frame's own pass times (waits for GPU queries)
    MedianTimes times;
    const int firstFrameMaps = renderer->render(scene.camera, lights, shading).shadowMapsDrawn;  // warm-up
    auto* autoMode = dynamic_cast<AutoModeRenderer*>(renderer.get());
    while (autoMode && autoMode->measuring()) renderer->render(scene.camera, lights, shading);  // its trial frames
    for (int i = 0; i < frames; ++i) times.add(renderer->render(scene.camera, lights, shading).passes);
    const FrameStats stats = renderer->lastFrame();
    const ImageRGBA8 image = renderer->targets().readColor();
    const std::string imageFile = mo.mode + ".png";
    writePng(path(outDir, imageFile), image);
    writeShadowAtlas(*renderer, info, outDir);

    nlohmann::json summary;
    std::ostringstream s;
    describeRun(summary, s, info, scene, lights.size(), warnings);
    summary["mode"] = {{"name", renderer->modeName()}, {"drawn_lights", stats.drawnLights},
                       {"light_data_bytes", renderer->lightDataBytes()}};
    summary["timing"] = {{"method", stats.timingMethod}, {"frames", frames}, {"median_ms", times.json()}};
    summary["gl_calls"] = glCallsJson(stats.glCalls);
    summary["pass_counts"] = passCountsJson(stats.passes);
    s << "mode       " << renderer->modeName() << ", " << stats.drawnLights << " lights drawn\n";
    addShadowSummary(summary, s, shadowChoice, shading, firstFrameMaps, stats);
    addEnvironmentSummary(summary, s, scene, stats);
    if (autoMode) {
        summary["auto_mode"] = {{"chosen", autoMode->lastMode()}, {"reason", autoMode->reason()},
                                {"candidates", autoMode->candidates()}};
        s << "auto mode  " << autoMode->reason() << "\n";
    }
    std::string outputs = imageFile;
    if (renderer->shadowAtlas() && !(info.gles && !renderer->shadowAtlas()->packed())) outputs += ", shadow_atlas.png";
    const auto* tiled = dynamic_cast<const TiledRenderer*>(renderer.get());
    if (tiled) {
        const LightGridStats& g = tiled->frameInfo().grid;
        summary["tiled"] = {{"tile_size", tiled->options().tileSize}, {"tiles_x", tiled->grid().tilesX()},
                            {"tiles_y", tiled->grid().tilesY()}, {"depth_bounds", tiled->frameInfo().depthBoundsUsed}, {"half_z", tiled->options().halfZ},
                            {"msaa_samples", tiled->targets().samples()},
                            {"depth_format", depthReductionFormatName(tiled->depthFormat())},
                            {"max_opaque_lights", g.maxOpaqueLights}, {"max_transparent_lights", g.maxTransparentLights},
                            {"opaque_entries", g.opaqueEntries}, {"transparent_entries", g.transparentEntries},
                            {"loop_bound", tiled->frameInfo().loopBound},
                            {"list_texture_rows", tiled->frameInfo().listTextureRows},
                            {"grid_bytes", tiled->gridBytes()}, {"list_bytes", tiled->listBytes()},
                            {"depth_reduction_bytes", tiled->depthReductionBytes()},
                            {"light_table_bytes", tiled->frame().lightTable.bytes()},
                            {"cpu_assign_ms_last_frame", tiled->frameInfo().assignMilliseconds}};
        writePng(path(outDir, "tile_heatmap.png"), tiled->tileHeatMap(16));
        outputs += ", tile_heatmap.png";
        const TiledOptions& to = tiled->options();
        s << "tiled      " << to.tileSize << " px tiles (" << tiled->grid().tilesX() << "x" << tiled->grid().tilesY()
          << "), depth bounds "
          << (tiled->frameInfo().depthBoundsUsed ? (to.halfZ ? "half-Z" : "min/max") : "off")
          << ", longest list " << g.maxOpaqueLights << " (transparent " << g.maxTransparentLights << "), "
          << g.opaqueEntries << " entries, CPU assignment " << tiled->frameInfo().assignMilliseconds << " ms\n";
    }
    const auto* clustered = dynamic_cast<const ClusteredRenderer*>(renderer.get());
    if (clustered) {
        const ClusteredFrameInfo& f = clustered->frameInfo();
        const ClusteredOptions& co = clustered->options();
        summary["clustered"] = {{"tile_size", co.tileSize}, {"tiles_x", clustered->grid().tilesX()},
                                {"tiles_y", clustered->grid().tilesY()}, {"slices", f.slicing.count},
                                {"slicing", clusterSlicingName(co.slicing)}, {"occupancy", f.occupancyUsed},
                                {"msaa_samples", clustered->targets().samples()},
                                {"clusters", clustered->grid().clusterCount()},
                                {"active_clusters", f.grid.activeClusters}, {"listed_clusters", f.grid.listedClusters},
                                {"max_cluster_lights", f.grid.maxLights}, {"entries", f.grid.entries},
                                {"cell_tests", f.grid.cellTests}, {"index_bits", f.indexBits},
                                {"loop_bound", f.loopBound}, {"list_texture_rows", f.listTextureRows},
                                {"grid_bytes", clustered->gridBytes()}, {"list_bytes", clustered->listBytes()},
                                {"light_table_bytes", clustered->frame().lightTable.bytes()},
                                {"cpu_assign_ms_last_frame", f.assignMilliseconds},
                                {"cpu_occupancy_ms_last_frame", f.occupancyMilliseconds}};
        if (clustered->targets().samples() == 0) {
            writePng(path(outDir, "cluster_heatmap.png"), clustered->clusterHeatMap(16));
            outputs += ", cluster_heatmap.png";
        }
        s << "clustered  " << co.tileSize << " px tiles (" << clustered->grid().tilesX() << "x"
          << clustered->grid().tilesY() << ") x " << f.slicing.count << " " << clusterSlicingName(co.slicing)
          << " slices, occupancy " << (f.occupancyUsed ? "on" : "off") << ", longest list " << f.grid.maxLights << ", "
          << f.grid.entries << " entries in " << f.grid.listedClusters << " clusters, " << f.indexBits
          << "-bit indices, CPU assignment " << f.assignMilliseconds << " ms"
          << (f.occupancyUsed ? ", occupancy " + std::to_string(f.occupancyMilliseconds) + " ms" : std::string()) << "\n";
    }
    if (const auto* multipass = dynamic_cast<const MultipassForwardRenderer*>(renderer.get())) {
        // Where its passes summed their light (doc/colour.md): half float, or the 8-bit target and why.
        summary["multipass"] = {{"accumulation", multipass->accumulation()},
                                {"accumulation_note", multipass->accumulationNote()}};
        s << "multi-pass accumulation: " << multipass->accumulation()
          << (multipass->accumulationNote().empty() ? "" : " (" + multipass->accumulationNote() + ")") << "\n";
    }
    describeDeferred(*renderer, summary, s);
    s << glCallsLine(stats.glCalls) << passCountsLine(stats.passes);
    s << "timing     " << stats.timingMethod << ", median of " << frames << " frames (ms):";
    for (const auto& [k, v] : summary["timing"]["median_ms"].items()) s << " " << k << "=" << v.get<double>();
    s << "\n";
    if (withReference) {
        // Rendered the way the mode renders: same MSAA, transparency where the mode draws it.
        auto reference = demo::makeReference(info, scene, mo, scene.width, scene.height, int(lights.size()));
        reference->setTiming(true, true);
        reference->render(scene.camera, lights, shading);
        const ImageRGBA8 refImage = reference->targets().readColor();
        writePng(path(outDir, "reference.png"), refImage);
        writePng(path(outDir, "difference.png"), differenceImage(image, refImage));
        outputs += ", reference.png, difference.png";
        const ImageError e = compareImages(image, refImage);
        summary["error"] = {{"whole_image", errorJson(e)}};
        s << "error      max " << e.maxAbsError << ", RMSE " << e.rmse << ", PSNR " << (std::isinf(e.psnr) ? 999.0 : e.psnr)
          << " dB, pixels differing by >1: " << e.pixelsOverThreshold << "\n";
        if (tiled && mo.msaaSamples == 0) {  // every light that touches an opaque pixel must be in its tile's list
            // (from the single-sample depth buffer, which MSAA frames do not fill)
            const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
            const CoverageTruth truth = computeCoverage(tiled->targets().readDepth(), cam, lights);
            long missing = 0;
            for (int y = 0; y < scene.height; ++y)
                for (int x = 0; x < scene.width; ++x) {
                    const size_t p = size_t(y) * scene.width + x;
                    const std::vector<uint32_t> list = tiled->grid().opaqueList(tiled->grid().tileOf(x, scene.height - 1 - y));
                    for (uint32_t k = truth.offsets[p]; k < truth.offsets[p + 1]; ++k)
                        missing += !std::binary_search(list.begin(), list.end(), truth.lights[k]);
                }
            summary["tiled"]["missing_light_pixels"] = missing;
            summary["tiled"]["max_overlap_touching"] = truth.maxOverlap();
            s << "lists      light-pixels missing from tile lists: " << missing << ", max overlap "
              << truth.maxOverlap() << "\n";
        }
        if (clustered && mo.msaaSamples == 0) {  // every light that touches an opaque pixel in its cluster's list
            const CameraMatrices cam = cameraMatrices(scene.camera, scene.width, scene.height);
            const CoverageTruth truth = computeCoverage(clustered->targets().readDepth(), cam, lights);
            const ClusterGrid& g = clustered->grid();
            const std::vector<int> gpuSlices = clustered->pixelSlices();
            std::vector<int> pixelClusters(gpuSlices.size(), -1);
            // Slice boundaries: pixels whose GPU slice is not the slice of their depth buffer's view depth, and how
            // near a boundary the farthest of them lies (relative; the cell margins cover the GPU's rounding).
            const ImageFloat depth = clustered->targets().readDepth();
            const ClusterSlices& slicing = clustered->frameInfo().slicing;
            long sliceMismatches = 0;
            double worstMismatch = 0.0;
            for (int y = 0; y < scene.height; ++y)
                for (int x = 0; x < scene.width; ++x) {
                    const size_t p = size_t(y) * size_t(scene.width) + size_t(x);
                    if (gpuSlices[p] < 0) continue;
                    pixelClusters[p] = g.clusterOf(g.tileOf(x, scene.height - 1 - y), gpuSlices[p]);
                    const double d = viewDepthFromWindowDepth(cam, depth.pixels[p]);
                    const int cpu = slicing.sliceOf(d);
                    if (cpu == gpuSlices[p]) continue;
                    ++sliceMismatches;
                    worstMismatch = std::max(worstMismatch, std::abs(d / slicing.boundary(std::max(cpu, gpuSlices[p])) - 1.0));
                }
            summary["clustered"]["slice_mismatch_pixels"] = sliceMismatches;
            summary["clustered"]["slice_mismatch_worst_relative"] = worstMismatch;
            const PixelListCheck c = checkPixelLists(truth, pixelClusters, g.entries(), g.offsets(), g.counts());
            summary["clustered"]["missing_light_pixels"] = c.missingPairs;
            summary["clustered"]["true_light_pixels"] = c.truthPairs;
            summary["clustered"]["extra_light_pixels"] = c.extraPairs;
            summary["clustered"]["extra_per_true_pair"] = c.extraPerTruePair();
            summary["clustered"]["max_overlap_touching"] = truth.maxOverlap();
            s << "lists      light-pixels missing from cluster lists: " << c.missingPairs << " of " << c.truthPairs
              << "; extra (listed, not touching the surface): " << c.extraPairs << ", " << c.extraPerTruePair()
              << " per true pair; max overlap " << truth.maxOverlap() << "\n";
            s << "slices     pixels in another slice than their depth buffer's view depth: " << sliceMismatches
              << " (at most " << worstMismatch << " relative from the boundary)\n";
        }
    }
    s << "outputs    " << outDir << "/{" << outputs << "}, summary.json\n";
    std::ofstream(path(outDir, "summary.json")) << summary.dump(2) << "\n";
    std::ofstream(path(outDir, "summary.txt")) << s.str();
    std::cout << s.str();
    return 0;
}

int runHeadless(const demo::SceneChoice& sceneChoice, const demo::RendererChoice& rc, const std::string& outDir,
                const std::string& dumpDir, int frames, bool withReference) {
    const Scene scene = sceneChoice.load();
    const RenderModeOptions modeOptions = rc.renderModeOptions(scene);
    const demo::ShadowChoice shadowChoice = rc.shadowChoice(modeOptions.mode);
    demo::checkTargetMemory(scene, modeOptions);  // before the context: an oversized request fails at once
    if (modeOptions.mode != "lidr" && !dumpDir.empty())
        throw Error("--dump writes LIDR index targets; it needs --mode lidr");
    if (!dumpDir.empty()) prepareWritableFolder(dumpDir, "--dump");  // before rendering, not after it
    if (modeOptions.mode != "lidr") {
        return runHeadlessMode(scene, modeOptions, outDir, frames, withReference, rc, shadowChoice);
    }
    const LidrOptions options = rc.lidrOptions(scene);
    const auto [lights, shading, context, warnings] = startHeadless(scene, outDir, rc, shadowChoice);
    const GlInfo& info = context->info();

    LidrRenderer renderer(info, scene, options, scene.width, scene.height);
    renderer.setTiming(true, true);
    std::cout << "LIDR: "
              << (options.packing.autoBudget() || options.packing.autoIndexBits() ? "automatic, first frame " : "")
              << renderer.scheme().describe() << ", volume test " << volumeTestName(options.volumeTest)
              << ", light table " << (renderer.frame().lightTable.format() == LightTableFormat::Float ? "float" : "fixed16")
              << "\n";

    MedianTimes lidrTimes;
    const int firstFrameMaps = renderer.render(scene.camera, lights, shading).shadowMapsDrawn;  // warm-up: shader
                                                                                                // compiles, uploads
    for (int i = 0; i < frames; ++i) lidrTimes.add(renderer.render(scene.camera, lights, shading).passes);
    const FrameStats stats = renderer.lastFrame();
    const ImageRGBA8 image = renderer.targets().readColor();
    writePng(path(outDir, "lidr.png"), image);
    writeShadowAtlas(renderer, info, outDir);

    nlohmann::json summary;
    std::ostringstream s;  // a short human summary on stdout and in summary.txt
    describeRun(summary, s, info, scene, lights.size(), warnings);
    const AutoDecision& decision = stats.autoDecision;
    const int budget = renderer.scheme().config().budget;
    summary["lidr"] = {{"scheme", packingSchemeName(renderer.scheme().config().scheme)}, {"budget", budget},
                       {"index_bits", renderer.scheme().config().indexBits}, {"targets", renderer.scheme().targetCount()},
                       {"volume_test", volumeTestName(options.volumeTest)},
                       {"msaa_samples", options.msaaSamples},
                       {"transparency", renderer.drawsTransparency()},
                       {"index_memory_bytes", renderer.indexTargets().bytes()},
                       {"stencil_use", renderer.scheme().stencilUse()},
                       {"volume_passes", renderer.scheme().geometryPasses()},
                       {"light_table_bytes", renderer.frame().lightTable.bytes()},
                       {"drawn_lights", stats.drawnLights}, {"volume_draw_calls", stats.volumeDrawCalls},
                       {"transparent_volume_lights", stats.transparentVolumeLights}};
    summary["auto"] = {{"budget_automatic", decision.autoBudget}, {"index_bits_automatic", decision.autoIndexBits},
                       {"visible_lights", decision.visibleLights}, {"budget", decision.budget},
                       {"index_bits", decision.indexBits}, {"measured_budget", decision.measuredBudget},
                       {"budget_fallback", decision.budgetFallback},
                       {"overflow_pixels", decision.overflowPixels}, {"repacks", decision.repacks},
                       {"transparent_budget", decision.transparentBudget},
                       {"measured_transparent_budget", decision.measuredTransparentBudget},
                       {"transparent_volume_pass_skipped", stats.transparentVolumePassSkipped},
                       {"volume_pass_skipped", stats.volumePassSkipped},
                       {"volume_area_per_pixel", decision.volumeAreaPerPixel}, {"area_bound", decision.areaBound},
                       {"tile_saving_screens", decision.tileSavingScreens},
                       {"tiles_skipped_for_saving", decision.tilesSkippedForSaving}};
    summary["timing"] = {{"method", stats.timingMethod}, {"frames", frames}, {"lidr_median_ms", lidrTimes.json()}};
    summary["gl_calls"] = glCallsJson(stats.glCalls);
    summary["pass_counts"] = passCountsJson(stats.passes);

    if (renderer.options().perSampleIndices && !dumpDir.empty())
        throw Error("--dump reads the index targets back, which per-sample (multisample) targets do not allow");
    FrameArtefacts artefacts;
    if (!renderer.options().perSampleIndices) artefacts.indexTargets = renderer.readIndexTargets();
    artefacts.depth = renderer.targets().readDepth();
    artefacts.lightCounts = renderer.readLightCounts();
    artefacts.camera = cameraMatrices(scene.camera, scene.width, scene.height);
    artefacts.lights = lights;
    if (!renderer.frameLightIndices().empty()) {
        // Compact numbering: the dump holds the frame's own light table (index k is entry k), so that an outside
        // decoder reads it as it reads any frame.
        artefacts.lights.clear();
        for (uint32_t sceneIndex : renderer.frameLightIndices())  // 0: an unused entry (region-local numbering)
            artefacts.lights.push_back(sceneIndex ? lights[sceneIndex - 1] : PointLight{glm::vec3(0.0f), 1.0f, glm::vec3(0.0f), 0.0f});
    }
    artefacts.drawOrder = LidrRenderer::drawOrder(artefacts.lights);

    if (withReference) {
        auto reference = demo::makeReference(info, scene, modeOptions, scene.width, scene.height, int(lights.size()));
        reference->setTiming(true, true);
        MedianTimes refTimes;
        reference->render(scene.camera, lights, shading);
        for (int i = 0; i < std::max(1, frames / 2); ++i) refTimes.add(reference->render(scene.camera, lights, shading).passes);
        const ImageRGBA8 refImage = reference->targets().readColor();
        writePng(path(outDir, "reference.png"), refImage);
        writePng(path(outDir, "difference.png"), differenceImage(image, refImage));
        summary["timing"]["reference_median_ms"] = refTimes.json();

        const FrameEvaluation ev = evaluateFrame(renderer, scene.camera, lights, image, refImage);
        if (renderer.options().perSampleIndices) {
            summary["lights"] = {{"visible_lights", stats.drawnLights},
                                 {"lists_checked", false},
                                 {"why", "per-sample index targets are multisample textures; only the image is judged"}};
        } else {
            const demo::LidrViews views = demo::lidrViews(ev, scene.width, scene.height, budget);
            writePng(path(outDir, "index_lists.png"), views.indexLists);
            writePng(path(outDir, "overlap.png"), views.overlap);
            writePng(path(outDir, "marked.png"), views.marked);
            summary["lights"] = {{"visible_lights", stats.drawnLights},
                                 {"max_overlap_touching", ev.maxTruthOverlap},
                                 {"max_marked_by_volume_test", ev.maxMarked},
                                 {"pixels_marked_over_budget", ev.pixelsOverBudget},
                                 {"dropped_light_pixels", ev.lists.droppedLightPixels},
                                 {"pixels_with_drops", ev.lists.pixelsWithDrops},
                                 {"max_dropped_per_pixel", ev.lists.maxDroppedPerPixel},
                                 {"invalid_slots", ev.lists.invalidSlots},
                                 {"mean_slots_used", double(ev.lists.slotsUsed) / double(ev.lists.decoded.size())},
                                 {"max_slots_used", ev.lists.maxSlotsUsed}};
        }
        summary["error"] = {{"whole_image", errorJson(ev.error)},
                            {"pixels_within_budget", errorJson(ev.errorWithinBudget)}};
    }
    if (!dumpDir.empty()) writeFrameArtefacts(dumpDir, artefacts, renderer.scheme());

    s << "lidr       " << renderer.scheme().describe() << ", volume test " << volumeTestName(options.volumeTest)
      << ", MSAA " << options.msaaSamples << "x, transparency " << (renderer.drawsTransparency() ? "on" : "off")
      << ", " << stats.drawnLights << " lights in " << stats.volumeDrawCalls << " volume draws\n";
    addShadowSummary(summary, s, shadowChoice, shading, firstFrameMaps, stats);
    addEnvironmentSummary(summary, s, scene, stats);
    if (decision.autoBudget || decision.autoIndexBits || *decision.budgetFallback) {
        s << "auto       " << decision.visibleLights << " visible lights, " << decision.indexBits << "-bit indices"
          << (decision.autoIndexBits ? " (narrowest)" : " (fixed)")
          << (decision.indexRegions > 0 ? " numbered in " + std::to_string(decision.indexRegions) + " screen regions" : "")
          << ", budget " << decision.budget;
        if (decision.autoBudget)
            s << " (measured: " << (decision.measuredBudget ? "overlap fits " + std::to_string(decision.measuredBudget)
                                                            : "overlap above 16, " + std::to_string(decision.overflowPixels) +
                                                                  " pixels over")
              << ", repacked " << decision.repacks << "x)";
        else if (*decision.budgetFallback)
            s << " (" << decision.budgetFallback << ")";
        else
            s << " (fixed)";
        if (stats.volumePassSkipped)
            s << ", no light reaches a visible surface: no volume pass, no index read";
        else if (decision.volumeAreaPerPixel >= 0.0)
            s << ", volume quads " << formatFixed(decision.volumeAreaPerPixel, 2) << " px per pixel"
              << (decision.areaBound ? " (area-bound: tiled forward may be faster here; --mode auto times both)" : "")
              << ", tiles saved " << formatFixed(decision.tileSavingScreens, 2) << " screens of volume pixels";
        else if (decision.tilesSkippedForSaving)
            s << ", volume meshes (tiles saved " << formatFixed(decision.tileSavingScreens, 2) << " screens when last measured, under "
              << formatFixed(LidrRenderer::kTileCullingMinSaving, 2) << ": not worth their depth read-back)";
        if (renderer.drawsTransparency())
            s << ", transparent volume pass "
              << (stats.transparentVolumePassSkipped ? std::string("skipped (none in view)")
                                                     : "budget " + std::to_string(decision.transparentBudget));
        s << "\n";
    }
    s << glCallsLine(stats.glCalls) << passCountsLine(stats.passes);
    s << "timing     " << stats.timingMethod << ", median of " << frames << " frames (ms):";
    for (const auto& [k, v] : summary["timing"]["lidr_median_ms"].items()) s << " " << k << "=" << v.get<double>();
    s << "\n";
    if (withReference) {
        const auto& L = summary["lights"];
        const auto& E = summary["error"];
        const bool listsChecked = !renderer.options().perSampleIndices;
        s << "reference  brute force " << summary["timing"]["reference_median_ms"]["frame"].get<double>() << " ms\n";
        if (listsChecked) s << "lights     visible " << L["visible_lights"] << ", max overlap " << L["max_overlap_touching"]
          << " (marked " << L["max_marked_by_volume_test"] << "), pixels over budget " << L["pixels_marked_over_budget"]
          << ", dropped light-pixels " << L["dropped_light_pixels"] << ", invalid slots " << L["invalid_slots"] << "\n";
        s << "error      whole image: max " << E["whole_image"]["max_abs_error"] << ", RMSE "
          << E["whole_image"]["rmse"].get<double>() << ", PSNR " << E["whole_image"]["psnr_db"].get<double>()
          << " dB; within budget: max " << E["pixels_within_budget"]["max_abs_error"] << ", PSNR "
          << E["pixels_within_budget"]["psnr_db"].get<double>() << " dB, pixels differing by >1: "
          << E["pixels_within_budget"]["pixels_over_1"] << "\n";
    }
    s << "outputs    " << outDir << "/{lidr,reference,difference,index_lists,overlap,marked}.png, summary.json\n";
    std::ofstream(path(outDir, "summary.json")) << summary.dump(2) << "\n";
    std::ofstream(path(outDir, "summary.txt")) << s.str();
    std::cout << s.str();
    return 0;
}

// --list-passes MODE|all: each mode's frame as its passes in order (Renderer::passes(): what each reads and writes,
// and when it runs where not every frame), as the other options build the mode for this scene on this context; the
// automatic mode lists each candidate's. Nothing is drawn.
int listPasses(const demo::SceneChoice& sceneChoice, demo::RendererChoice rc, const std::string& which) {
    if (which != "all" && !isRenderModeName(which))
        throw Error("--list-passes takes a render mode (" + renderModeList() + ") or all; got '" + which + "'");
    const Scene scene = sceneChoice.load();
    std::vector<RenderModeOptions> modes;
    for (const std::string& name : which == "all" ? renderModeNames() : std::vector<std::string>{which}) {
        rc.mode = name;
        modes.push_back(rc.renderModeOptions(scene));  // checked before the context
    }
    const std::unique_ptr<GlContext> context = GlContext::create(rc.contextOptions());
    std::cout << "GL: " << context->info().summary() << "\n";
    auto print = [&](const std::string& mode, const std::vector<FramePass>& passes) {
        std::cout << "\n" << mode << " (" << scene.width << "x" << scene.height << "): " << passes.size()
                  << " passes in frame order: what each reads -> what it writes ([x]: where the frame has x)\n"
                  << describePasses(passes);
    };
    for (const RenderModeOptions& mo : modes) {
        const std::unique_ptr<Renderer> renderer = createRenderer(mo, context->info(), scene, scene.width, scene.height);
        const auto* automatic = dynamic_cast<const AutoModeRenderer*>(renderer.get());
        if (!automatic) {
            print(mo.mode, renderer->passes());
            continue;
        }
        std::cout << "\nauto: its frames are those of the candidate it picks by time, one of these:\n";
        for (size_t i = 0; i < automatic->candidates().size(); ++i)
            print("auto: " + automatic->candidates()[i], automatic->renderer(i).passes());
    }
    return 0;
}

int runWindow(const demo::SceneChoice& sceneChoice, demo::RendererChoice rc) {
#if LIDR_HAVE_GLFW
    ContextOptions co = rc.contextOptions();
    if (co.backend != ContextBackend::Auto && co.backend != ContextBackend::Glfw && co.backend != ContextBackend::GlfwGles2)
        throw Error("--window opens a GLFW window: --context must be glfw, glfw-gles2 (OpenGL ES 2.0) or auto, got '" +
                    rc.context + "'");
    if (co.backend == ContextBackend::Auto) co.backend = ContextBackend::Glfw;
    Scene scene = sceneChoice.load();
    demo::checkTargetMemory(scene, rc.renderModeOptions(scene));
    const demo::ShadowChoice shadowChoice = rc.shadowChoice(rc.renderModeOptions(scene).mode);  // before the window
    co.visibleWindow = true;
    co.windowWidth = scene.width;
    co.windowHeight = scene.height;
    co.windowTitle = "lidr-demo";
    auto context = GlContext::create(co);
    std::cout << "GL: " << context->info().summary() << std::endl;
    std::unique_ptr<Renderer> renderer = createRenderer(rc.renderModeOptions(scene), context->info(), scene,
                                                        scene.width, scene.height);
    renderer->setTiming(true);  // interactive: GPU times a frame or more late, never stalling
    const ShadingParameters sceneShadingParameters = sceneShading(scene, rc.outputTransform());
    auto* window = static_cast<GLFWwindow*>(context->nativeWindow());
    // ES 2.0 has no glBlitFramebuffer: the frame goes to the window as one textured triangle there.
    std::optional<FramePresenter> presenter;
    if (context->info().gles) presenter.emplace();
    const double start = glfwGetTime();
    double lastReport = start;
    int framesSinceReport = 0;
    while (!context->shouldClose()) {
        const double now = glfwGetTime();
        // A keyframed scene plays its range over and over: moving meshes re-placed, lights and camera at the time.
        const SceneAnimation& animation = scene.animation;
        float t = scene.time + float(now - start);
        if (animation.end > animation.start && t > animation.end)
            t = animation.start + std::fmod(t - animation.start, animation.end - animation.start);
        placeAnimatedObjects(*renderer, scene, t);
        std::vector<PointLight> lights = scene.lightsAt(t);
        ShadingParameters shading = sceneShadingParameters;
        const Camera camera = cameraAt(scene, t);
        shadowChoice.apply(cameraMatrices(camera, scene.width, scene.height), lights, shading);  // K brightest: again
        const FrameStats& st = renderer->render(camera, lights, shading);
        int fw = 0, fh = 0;
        glfwGetFramebufferSize(window, &fw, &fh);
        if (presenter) {
            if (fw > 0 && fh > 0) presenter->present(renderer->targets(), 0, 0, 0, fw, fh);
        } else {
            glBindFramebuffer(GL_READ_FRAMEBUFFER, renderer->targets().colorFramebuffer().id());
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
            glBlitFramebuffer(0, 0, scene.width, scene.height, 0, 0, fw, fh, GL_COLOR_BUFFER_BIT, GL_LINEAR);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
        }
        context->swapBuffers();
        context->pollEvents();
        if (glfwGetKey(window, GLFW_KEY_ESCAPE) == GLFW_PRESS) break;
        ++framesSinceReport;
        if (now - lastReport > 1.0) {
            std::printf("%.1f fps, frame %.2f ms (%s), %d lights drawn, %d shadow casters, %d maps drawn\n",
                        framesSinceReport / (now - lastReport), st.frameMilliseconds(), st.timingMethod, st.drawnLights,
                        st.shadowCasters, st.shadowMapsDrawn);
            std::fflush(stdout);
            lastReport = now;
            framesSinceReport = 0;
        }
    }
    return 0;
#else
    (void)sceneChoice;
    (void)rc;
    throw UnsupportedError("lidr-demo was built without GLFW; --window is not available");
#endif
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"lidr-demo: Light Indexed Deferred Rendering on a GL 2.1-class pipeline"};
    demo::SceneChoice sceneChoice;
    demo::RendererChoice rc;
    sceneChoice.addOptions(app);
    rc.addOptions(app);
    bool headless = false, window = false, noReference = false;
    std::string outDir = "out", dumpDir;
    int frames = 5;
    app.add_flag("--headless", headless, "Render offscreen and write images and a summary (the default)");
    app.add_flag("--window", window, "Open an interactive window (needs a display)");
    app.add_option("--out", outDir, "Folder for images and summary")->capture_default_str();
    app.add_option("--dump", dumpDir, "Also write raw artefacts (index targets, depth, lights, camera) here");
    app.add_option("--frames", frames, "Timed frames (median reported); with --time-step up to 1000000 frames")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000000));
    std::optional<double> timeStep;
    app.add_option("--time-step", timeStep,
                   "Soak run: frame k shows time + k * S seconds; writes soak.csv (image hash, memory, GL objects "
                   "per frame) and soak.json instead of the usual images");
    app.add_flag("--no-reference", noReference, "Skip the brute-force reference and the error figures");
    std::string listPassesMode;
    app.add_option("--list-passes", listPassesMode,
                   "Print the passes of MODE's frame (" + renderModeList() + ", or all) in order, with what each reads "
                   "and writes and when it runs, as the other options build it for the scene on this context; then "
                   "exit without drawing");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    try {
        if (window && headless) throw Error("--window and --headless exclude each other");
        if (!listPassesMode.empty()) return listPasses(sceneChoice, rc, listPassesMode);
        if (window) return runWindow(sceneChoice, rc);
        if (timeStep) {
            if (!std::isfinite(*timeStep) || *timeStep < 0.0)
                throw Error("--time-step must be a finite number of seconds >= 0, got " + std::to_string(*timeStep));
            if (!dumpDir.empty()) throw Error("--dump does not apply to a soak run (--time-step)");
            if (rc.shadows != "off") throw Error("--shadows applies to --headless and --window runs, not a soak run (--time-step)");
            return demo::runSoak(sceneChoice, rc, outDir, frames, *timeStep);
        }
        if (frames > 1000) throw Error("--frames must be in [1, 1000] without --time-step, got " + std::to_string(frames));
        // A dump holds one light table for the frame: global numbering (doc/architecture.md, region-local indices).
        if (!dumpDir.empty()) rc.regionalIndices = "off";
        return runHeadless(sceneChoice, rc, outDir, dumpDir, frames, !noReference);
    } catch (const std::exception& e) {
        std::cerr << "lidr-demo: error: " << e.what() << "\n";
        return 1;
    }
}
