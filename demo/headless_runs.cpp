#include "headless_runs.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "frame_views.h"
#include "headless_summary.h"
#include "lidr/base/error.h"
#include "lidr/base/visualize.h"
#include "lidr/eval/artefacts.h"
#include "lidr/eval/frame_evaluation.h"
#include "lidr/eval/light_coverage.h"
#include "lidr/modes/auto_mode_renderer.h"
#include "lidr/modes/reference_renderer.h"
#include "lidr/modes/render_mode.h"
#include "lidr/render/shadow_atlas.h"
#include "lidr/scene/sphere_bounds.h"

namespace lidr::demo {

namespace {

// The volume test, and under MSAA where sphere-span learns the samples' surfaces (auto resolved).
std::string volumeTestDescription(const LidrRenderer& renderer) {
    const LidrOptions& o = renderer.options();
    std::string s = volumeTestName(o.volumeTest);
    if (o.volumeTest == VolumeTest::SphereSpan)
        s += std::string(" (") + depthSpanStorageName(o.msaaSpans) + " spans" +
             (renderer.skippedHiddenFragments() ? ", hidden fragments skip their lists)" : ")");
    return s;
}

// Renders the warm-up frame (shader compiles, uploads; the automatic mode's trial frames after it), then `frames`
// timed ones; returns the shadow maps the first frame drew.
int timeFrames(Renderer& renderer, const Scene& scene, const HeadlessStart& start, int frames, MedianTimes& times) {
    const int firstFrameMaps = renderer.render(scene.camera, start.lights, start.shading).shadowMapsDrawn;
    auto* autoMode = dynamic_cast<AutoModeRenderer*>(&renderer);
    while (autoMode && autoMode->measuring()) renderer.render(scene.camera, start.lights, start.shading);
    for (int i = 0; i < frames; ++i) times.add(renderer.render(scene.camera, start.lights, start.shading).passes);
    return firstFrameMaps;
}

// The tiled and clustered grids' heat maps (the modes' own data, not statistics); returns the files written.
std::string writeGridHeatMaps(const Renderer& renderer, const std::string& outDir) {
    std::string written;
    if (const auto* tiled = dynamic_cast<const TiledRenderer*>(&renderer)) {
        writePng(path(outDir, "tile_heatmap.png"), tiled->tileHeatMap(16));
        written += ", tile_heatmap.png";
    }
    const auto* clustered = dynamic_cast<const ClusteredRenderer*>(&renderer);
    if (clustered && clustered->targets().samples() == 0) {
        writePng(path(outDir, "cluster_heatmap.png"), clustered->clusterHeatMap(16));
        written += ", cluster_heatmap.png";
    }
    return written;
}

// Every light that touches an opaque pixel must be in its tile's list (from the single-sample depth buffer, which
// MSAA frames do not fill).
void checkTileLists(nlohmann::json& summary, std::ostream& s, const TiledRenderer* tiled, const Scene& scene,
                    const std::vector<PointLight>& lights) {
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

// Every light that touches an opaque pixel in its cluster's list, and the pixels whose GPU slice is not their
// depth's.
void checkClusterLists(nlohmann::json& summary, std::ostream& s, const ClusteredRenderer* clustered,
                       const Scene& scene, const std::vector<PointLight>& lights) {
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

// The mode's image against forward-brute's, rendered the way the mode renders (same MSAA, transparency where the
// mode draws it); for tiled and clustered without MSAA, their lists against the CPU truth.
void compareWithReference(nlohmann::json& summary, std::ostream& s, std::string& outputs, const GlInfo& info,
                          const Scene& scene, const RenderModeOptions& mo, const HeadlessStart& start,
                          const Renderer& renderer, const ImageRGBA8& image, const std::string& outDir) {
    const std::vector<PointLight>& lights = start.lights;
    auto reference = makeReference(info, scene, mo, scene.width, scene.height, int(lights.size()));
    reference->setTiming(true, true);
    reference->render(scene.camera, lights, start.shading);
    const ImageRGBA8 refImage = reference->targets().readColor();
    writePng(path(outDir, "reference.png"), refImage);
    writePng(path(outDir, "difference.png"), differenceImage(image, refImage));
    outputs += ", reference.png, difference.png";
    const ImageError e = compareImages(image, refImage);
    summary["error"] = {{"whole_image", errorJson(e)}};
    s << "error      max " << e.maxAbsError << ", RMSE " << e.rmse << ", PSNR " << (std::isinf(e.psnr) ? 999.0 : e.psnr)
      << " dB, pixels differing by >1: " << e.pixelsOverThreshold << "\n";
    if (mo.msaaSamples != 0) return;
    if (const auto* tiled = dynamic_cast<const TiledRenderer*>(&renderer)) checkTileLists(summary, s, tiled, scene, lights);
    if (const auto* clustered = dynamic_cast<const ClusteredRenderer*>(&renderer))
        checkClusterLists(summary, s, clustered, scene, lights);
}

void writeSummaries(const nlohmann::json& summary, const std::ostringstream& s, const std::string& outDir) {
    std::ofstream(path(outDir, "summary.json")) << summary.dump(2) << "\n";
    std::ofstream(path(outDir, "summary.txt")) << s.str();
    std::cout << s.str();
}

// Any mode but LIDR, through the Renderer interface: its image, timings, statistics (Renderer::modeStatistics) and,
// with a reference, its error; tiled and clustered add their heat maps and list checks.
int runHeadlessOtherMode(const Scene& scene, const RenderModeOptions& mo, const std::string& outDir, int frames,
                         bool withReference, const RendererChoice& rc, const ShadowChoice& shadowChoice) {
    const HeadlessStart start = startHeadless(scene, outDir, rc, shadowChoice);
    const GlInfo& info = start.context->info();
    std::unique_ptr<Renderer> renderer = createRenderer(mo, info, scene, scene.width, scene.height);
    renderer->setTiming(true, true);  // each frame's own pass times (waits for GPU queries)
    MedianTimes times;
    const int firstFrameMaps = timeFrames(*renderer, scene, start, frames, times);
    const FrameStats stats = renderer->lastFrame();
    const ImageRGBA8 image = renderer->targets().readColor();
    const std::string imageFile = mo.mode + ".png";
    writePng(path(outDir, imageFile), image);
    writeShadowAtlas(*renderer, info, outDir);

    nlohmann::json summary;
    std::ostringstream s;
    describeRun(summary, s, info, scene, start.lights.size(), start.warnings);
    summary["mode"] = {{"name", renderer->modeName()}, {"drawn_lights", stats.drawnLights},
                       {"light_data_bytes", renderer->lightDataBytes()}};
    summary["timing"] = {{"method", stats.timingMethod}, {"frames", frames}, {"median_ms", times.json()}};
    summary["gl_calls"] = glCallsJson(stats.glCalls);
    summary["pass_counts"] = passCountsJson(stats.passes);
    s << "mode       " << renderer->modeName() << ", " << stats.drawnLights << " lights drawn\n";
    addShadowSummary(summary, s, shadowChoice, start.shading, firstFrameMaps, stats);
    addEnvironmentSummary(summary, s, scene, stats);
    addModeStatistics(summary, s, renderer->modeStatistics());
    addLightingComputations(summary, s, *renderer, scene.camera, start.lights);
    std::string outputs = imageFile;
    if (renderer->shadowAtlas() && !(info.gles && !renderer->shadowAtlas()->packed())) outputs += ", shadow_atlas.png";
    outputs += writeGridHeatMaps(*renderer, outDir);
    s << glCallsLine(stats.glCalls) << passCountsLine(stats.passes);
    s << "timing     " << stats.timingMethod << ", median of " << frames << " frames (ms):";
    for (const auto& [k, v] : summary["timing"]["median_ms"].items()) s << " " << k << "=" << v.get<double>();
    s << "\n";
    if (withReference) compareWithReference(summary, s, outputs, info, scene, mo, start, *renderer, image, outDir);
    s << "outputs    " << outDir << "/{" << outputs << "}, summary.json\n";
    writeSummaries(summary, s, outDir);
    return 0;
}

// summary.json's "lidr" (the configuration the frame ran with) and "auto" (what the automatic choices decided).
void addLidrSummary(nlohmann::json& summary, const LidrRenderer& renderer, const LidrOptions& options,
                    const FrameStats& stats) {
    const AutoDecision& decision = stats.autoDecision;
    const int budget = renderer.scheme().config().budget;
    summary["lidr"] = {{"scheme", packingSchemeName(renderer.scheme().config().scheme)}, {"budget", budget},
                       {"index_bits", renderer.scheme().config().indexBits}, {"targets", renderer.scheme().targetCount()},
                       {"volume_test", volumeTestName(options.volumeTest)},
                       {"msaa_spans", renderer.options().volumeTest == VolumeTest::SphereSpan
                                          ? depthSpanStorageName(renderer.options().msaaSpans) : "none"},
                       {"msaa_skip_hidden", renderer.skippedHiddenFragments()},
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
}

// The frame's artefacts for --dump: index targets, depth, light counts, camera, and the frame's own light table.
FrameArtefacts lidrArtefacts(const LidrRenderer& renderer, const Scene& scene, const std::vector<PointLight>& lights) {
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

    return artefacts;
}

// LIDR's image against forward-brute's, and each pixel's index list against the CPU truth (not with per-sample
// index targets), with the debug views.
void compareLidrWithReference(nlohmann::json& summary, const GlInfo& info, const Scene& scene,
                              const RenderModeOptions& modeOptions, const HeadlessStart& start,
                              const LidrRenderer& renderer, const FrameStats& stats, const ImageRGBA8& image,
                              int frames, const std::string& outDir) {
    const std::vector<PointLight>& lights = start.lights;
    const ShadingParameters& shading = start.shading;
    const int budget = renderer.scheme().config().budget;
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

// The text summary's "auto" line: what the automatic choices decided this frame, where any was automatic.
void addAutoDecisionLine(std::ostream& s, const LidrRenderer& renderer, const FrameStats& stats) {
    const AutoDecision& decision = stats.autoDecision;
    if (decision.autoBudget || decision.autoIndexBits || *decision.budgetFallback) {
        s << "auto       " << decision.visibleLights << " visible lights, " << decision.indexBits << "-bit indices"
          << (decision.autoIndexBits ? " (narrowest)" : " (fixed)")
          << (decision.indexRegions > 0 ? " numbered in " + std::to_string(decision.indexRegions) + " screen regions" : "")
          << ", budget " << decision.budget;
        if (decision.autoBudget)
            // measuredBudget 0: over every budget lidr has (32); one above the frame's budget: its largest at this
            // index width (16 at 16 bits). Either way the pixels over it are counted.
            s << " (measured: "
              << (decision.measuredBudget ? "overlap fits " + std::to_string(decision.measuredBudget) : std::string("overlap above 32"))
              << (decision.overflowPixels > 0 ? ", " + std::to_string(decision.overflowPixels) + " pixels over" : std::string())
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
}

// The text summary's reference, lists and error lines, from summary.json's figures.
void addLidrReferenceLines(std::ostream& s, const nlohmann::json& summary, const LidrRenderer& renderer) {
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

// LIDR, the main mode: its configuration, index lists and debug views, the automatic choices, and --dump.
int runHeadlessLidr(const Scene& scene, const RenderModeOptions& modeOptions, const RendererChoice& rc,
                    const ShadowChoice& shadowChoice, const std::string& outDir, const std::string& dumpDir,
                    int frames, bool withReference) {
    const LidrOptions options = rc.lidrOptions(scene);
    const HeadlessStart start = startHeadless(scene, outDir, rc, shadowChoice);
    const GlInfo& info = start.context->info();

    LidrRenderer renderer(info, scene, options, scene.width, scene.height);
    renderer.setTiming(true, true);
    std::cout << "LIDR: "
              << (options.packing.autoBudget() || options.packing.autoIndexBits() ? "automatic, first frame " : "")
              << renderer.scheme().describe() << ", volume test " << volumeTestDescription(renderer)
              << ", light table " << (renderer.frame().lightTable.format() == LightTableFormat::Float ? "float" : "fixed16")
              << "\n";
    MedianTimes lidrTimes;
    const int firstFrameMaps = timeFrames(renderer, scene, start, frames, lidrTimes);
    const FrameStats stats = renderer.lastFrame();
    const ImageRGBA8 image = renderer.targets().readColor();
    writePng(path(outDir, "lidr.png"), image);
    writeShadowAtlas(renderer, info, outDir);

    nlohmann::json summary;
    std::ostringstream s;  // a short human summary on stdout and in summary.txt
    describeRun(summary, s, info, scene, start.lights.size(), start.warnings);
    addLidrSummary(summary, renderer, options, stats);
    summary["timing"] = {{"method", stats.timingMethod}, {"frames", frames}, {"lidr_median_ms", lidrTimes.json()}};
    summary["gl_calls"] = glCallsJson(stats.glCalls);
    summary["pass_counts"] = passCountsJson(stats.passes);
    if (renderer.options().perSampleIndices && !dumpDir.empty())
        throw Error("--dump reads the index targets back, which per-sample (multisample) targets do not allow");
    const FrameArtefacts artefacts = lidrArtefacts(renderer, scene, start.lights);
    if (withReference)
        compareLidrWithReference(summary, info, scene, modeOptions, start, renderer, stats, image, frames, outDir);
    if (!dumpDir.empty()) writeFrameArtefacts(dumpDir, artefacts, renderer.scheme());

    s << "lidr       " << renderer.scheme().describe() << ", volume test " << volumeTestDescription(renderer)
      << ", MSAA " << options.msaaSamples << "x, transparency " << (renderer.drawsTransparency() ? "on" : "off")
      << ", " << stats.drawnLights << " lights in " << stats.volumeDrawCalls << " volume draws\n";
    addShadowSummary(summary, s, shadowChoice, start.shading, firstFrameMaps, stats);
    addEnvironmentSummary(summary, s, scene, stats);
    addAutoDecisionLine(s, renderer, stats);
    addLightingComputations(summary, s, renderer, scene.camera, start.lights);
    s << glCallsLine(stats.glCalls) << passCountsLine(stats.passes);
    s << "timing     " << stats.timingMethod << ", median of " << frames << " frames (ms):";
    for (const auto& [k, v] : summary["timing"]["lidr_median_ms"].items()) s << " " << k << "=" << v.get<double>();
    s << "\n";
    if (withReference) addLidrReferenceLines(s, summary, renderer);
    s << "outputs    " << outDir << "/{lidr,reference,difference,index_lists,overlap,marked}.png, summary.json\n";
    writeSummaries(summary, s, outDir);
    return 0;
}

}  // namespace

int runHeadless(const SceneChoice& sceneChoice, const RendererChoice& rc, const std::string& outDir,
                const std::string& dumpDir, int frames, bool withReference) {
    const Scene scene = sceneChoice.load();
    const RenderModeOptions modeOptions = rc.renderModeOptions(scene);
    const ShadowChoice shadowChoice = rc.shadowChoice(modeOptions.mode);
    checkTargetMemory(scene, modeOptions);  // before the context: an oversized request fails at once
    if (modeOptions.mode != "lidr" && !dumpDir.empty())
        throw Error("--dump writes LIDR index targets; it needs --mode lidr");
    if (!dumpDir.empty()) prepareWritableFolder(dumpDir, "--dump");  // before rendering, not after it
    if (modeOptions.mode != "lidr")
        return runHeadlessOtherMode(scene, modeOptions, outDir, frames, withReference, rc, shadowChoice);
    return runHeadlessLidr(scene, modeOptions, rc, shadowChoice, outDir, dumpDir, frames, withReference);
}

}  // namespace lidr::demo
