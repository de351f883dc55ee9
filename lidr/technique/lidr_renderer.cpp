#include "lidr/technique/lidr_renderer.h"
#include "lidr/base/gl.h"
#include "lidr/gl/saved_gl_state.h"

#include <algorithm>

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/render/shading_pass.h"
#include "lidr/scene/sphere_bounds.h"

namespace lidr {

namespace {
// LIDR's passes (passes(), render(); doc/architecture.md, "One frame of LIDR"), between FrameResources' shadow-maps and
// msaa-resolve. Where a pass reads or writes more in some configurations, its variants share its name; [x]: read
// where the configuration or the frame has it.
constexpr FramePass kDepthPrepass{"depth-prepass", "scene", "depth, stencil"};
constexpr FramePass kDepthPrepassCopy{"depth-prepass", "scene",
                                      "depth, stencil, depth copy (the sphere tests read it)"};
constexpr FramePass kVolumeTiles{"volume-tiles", "depth (read back)", "volume tiles (depth per tile)",
                                 "the tile decision takes tiles: the lights cover enough screens and tiles pay"};
constexpr FramePass kFramePlan{"light-table", "lights, [shadow atlas], [volume tiles], mesh bounds",
                               "frame plan (indices, index width, regions), light table"};
constexpr FramePass kLightVolumesTransparent{"light-volumes-transparent", "frame plan, depth, [depth copy]",
                                             "transparent index targets, stencil count",
                                             "lights reach transparent meshes in view"};
constexpr FramePass kLightVolumes{"light-volumes",
                                  "frame plan, depth, [depth copy], [volume tiles], [shadow atlas]",
                                  "index targets, stencil count",
                                  "a light reaches a visible surface; again at each re-pack"};
constexpr FramePass kOverlapProbe{"overlap-probe", "stencil count", "overlap measure (occlusion queries)",
                                  "automatic budget"};
constexpr FramePass kMsaaDepthPrepass{"msaa-depth-prepass", "scene", "depth (MSAA)"};
constexpr FramePass kDepthSpans{"depth-spans", "scene, depth copy",
                                "depth (MSAA), depth spans (the depths each pixel's samples shade)",
                                "sphere-span (MSAA): the MSAA pre-pass"};
// sphere-span with the samples' distances (DepthSpanStorage::Samples): the MSAA pre-pass first, then the
// single-sample depth from its sample 0.
constexpr FramePass kDepthSpanSamples{"depth-spans", "scene",
                                      "depth (MSAA), sample distances (the point each sample shades)",
                                      "sphere-span (MSAA): the MSAA pre-pass"};
constexpr FramePass kDepthFromSample{"depth-prepass", "sample distances",
                                     "depth, stencil (sample 0's point: the centre the tests read)"};
constexpr FramePass kForward{"forward",
                             "scene, depth, index targets, light table, [shadow atlas], [environment]", "colour"};
constexpr FramePass kForwardTransparent{"forward-transparent",
                                        "transparent meshes, depth, transparent index targets, light table, "
                                        "[shadow atlas], [environment]",
                                        "colour", "transparent meshes in the scene"};

// The probe's thresholds a volume pass asks about this frame (bit i: OverlapProbe::kThreshold[i]). Steady frames
// ask over the budget (re-pack) and, every autoNarrowingInterval frames, over half of it (may narrow); only an
// overflowing frame asks how far over (measuredNeed), and a renderer's first frame asks everything at once.
unsigned thresholdsToAsk(const AutoConfiguration& a, int budget, bool& narrowingAsked) {
    narrowingAsked = a.asksNarrowing();
    return !a.measured() ? OverlapProbe::kAll
           : narrowingAsked ? OverlapProbe::aroundBudget(budget)
                            : OverlapProbe::atBudget(budget);
}
}  // namespace

std::vector<FramePass> LidrRenderer::passes() const {
    std::vector<FramePass> p{pass::kShadowMaps};
    if (depthSpans_.storesSamples()) {
        p.push_back(kDepthSpanSamples);
        p.push_back(kDepthFromSample);
    } else {
        if (options_.depthPrepass) p.push_back(depthTexture_ ? kDepthPrepassCopy : kDepthPrepass);
        if (depthSpans_) p.push_back(kDepthSpans);
    }
    if (volumeTiles_ && options_.depthPrepass) p.push_back(kVolumeTiles);
    p.push_back(kFramePlan);
    if (transparentIndexTargets_) p.push_back(kLightVolumesTransparent);
    p.push_back(kLightVolumes);
    if (options_.packing.autoBudget()) p.push_back(kOverlapProbe);
    if (frame_.targets.samples() > 0 && options_.depthPrepass && !options_.perSampleIndices && !depthSpans_)
        p.push_back(kMsaaDepthPrepass);
    p.push_back(kForward);
    if (drawTransparent_) p.push_back(kForwardTransparent);
    if (frame_.targets.samples() > 0) p.push_back(pass::kMsaaResolve);
    return p;
}

LidrRenderer::Variant& LidrRenderer::variant(int budget, int indexBits) {
    Variant& v = variants_[{budget, indexBits}];
    if (!v.scheme) {
        PackingConfig c = options_.packing;
        if (c.autoScheme()) c.scheme = PackingSchemeKind::BitShift;
        c.budget = budget;
        c.indexBits = indexBits;
        v.scheme = createPackingScheme(c, frame_.info);
        v.forward = std::make_unique<ForwardPass>(*v.scheme, frame_.lightTable, options_.perSampleIndices,
                                                  options_.materialShader, DepthEmulation{options_.emulatedDepthBits});
    }
    return v;
}

IndexTargets& LidrRenderer::indexTargetsFor(std::map<int, IndexTargets>& cache, int count) {
    auto it = cache.find(count);
    if (it == cache.end()) {
        const bool perSample = options_.perSampleIndices;
        it = cache.emplace(count, IndexTargets(count, frame_.targets.width(), frame_.targets.height(),
                                               perSample ? frame_.targets.multisampleDepthStencil() : frame_.targets.depthStencil(),
                                               perSample ? options_.msaaSamples : 0,
                                               perSample ? frame_.targets.multisampleSeparateStencil()
                                                         : frame_.targets.separateStencil())).first;
    }
    return it->second;
}

void LidrRenderer::selectVariant(int budget, int indexBits) {
    current_ = &variant(budget, indexBits);
    indexTargets_ = &indexTargetsFor(indexTargetCache_, current_->scheme->targetCount());
    if (!transparentIndexTargets_) currentTransparent_ = current_;  // transparent layers read the main lists
}

void LidrRenderer::selectTransparentVariant(int budget, int indexBits) {
    if (!(drawTransparent_ && !isFrontFaceVolumeTest(options_.volumeTest))) {
        currentTransparent_ = current_;
        return;
    }
    currentTransparent_ = &variant(budget, indexBits);
    transparentIndexTargets_ = &indexTargetsFor(transparentTargetCache_, currentTransparent_->scheme->targetCount());
}

size_t LidrRenderer::lightDataBytes() const {
    return indexTargets_->bytes() + (transparentIndexTargets_ ? transparentIndexTargets_->bytes() : 0);
}

const IndexTargets& LidrRenderer::transparentIndexTargets() const {
    return transparentIndexTargets_ ? *transparentIndexTargets_ : *indexTargets_;
}

const FrameStats& LidrRenderer::render(const Camera& camera, const std::vector<PointLight>& lights,
                                       const ShadingParameters& shading) {
    checkLights(lights);
    const CameraMatrices cam = cameraMatrices(camera, frame_.targets.width(), frame_.targets.height());
    checkShadingParameters(shading);
    const FrameScope scope(stats_, frame_.timer, lights.size());
    volumeQuadPixels_ = volumeStepLights_ = 0;  // this frame's, summed over its volume passes

    // 0. shadow-maps first (they draw into the atlas): the lights' first tiles by scene index (empty: none cast).
    const std::vector<int>& shadowTiles = frame_.drawShadowMaps(lights, shading, stats_);
    const bool volumeShadows = useVolumeShadows(shadowTiles, shading);
    // 1. The tile decision (whether the light volumes are culled by the pre-pass depth per tile), depth-prepass,
    //    and volume-tiles.
    const TileDecision::Choice tiles = decideTiles(cam, lights);
    depthPrepass(cam, tiles.tiles);
    cullByTiles(cam, tiles);
    // 2. The frame plan (the light-table pass): which lights get an index, their numbers, regions and index width;
    //    the light table and the packing follow it.
    TimedPass lightTableTime(frame_.timer, kFramePlan.name);
    plan_ = plan(cam, lights, tiles.tiles, volumeShadows ? &shadowTiles : nullptr);
    loadPlan(lights, shadowTiles);
    selectPacking();
    lightTableTime.end();
    // 3. The light volumes into the index targets (light-volumes-transparent, light-volumes, overlap-probe), 4. the
    //    forward passes that read them ([msaa-depth-prepass], forward, forward-transparent), and 5. with an
    //    automatic budget, the re-pack of a frame measured over the budget it was packed with (3 and 4 again).
    //    Nothing for nothing: a frame where no light can reach a visible surface draws no volume, measures nothing
    //    and reads no index.
    if (plan_.lightless()) {
        shade(cam, shading, false);
    } else {
        const int needTransparent = drawVolumes(cam, plan_.volumes);
        shade(cam, shading);
        if (options_.packing.autoBudget()) repackWhileOver(cam, shading, needTransparent);
    }
    // 6. The record: what the tiles saved (the next tile decision's measure) and the frame's statistics; then
    //    msaa-resolve.
    recordFrame(tiles);
    frame_.targets.resolve(frame_.timer);  // the forward passes left the default state (ForwardPass::unbindInputs)
    frame_.finishFrame(stats_, "LidrRenderer::render");
    return stats_;
}

void LidrRenderer::checkLights(const std::vector<PointLight>& lights) const {
    checkLightSpheres(lights, "lidr");
    const PackingConfig& fixed = options_.packing;
    if (!fixed.autoIndexBits() && lights.size() > (1u << fixed.indexBits) - 1u)
        throw Error(std::to_string(lights.size()) + " lights exceed the " + std::to_string((1u << fixed.indexBits) - 1u) +
                    " that " + std::to_string(fixed.indexBits) + "-bit indices hold");
}

bool LidrRenderer::useVolumeShadows(const std::vector<int>& shadowTiles, const ShadingParameters& shading) {
    const bool on = !shadowTiles.empty() && shading.shadows.lidrLookup == ShadowLookup::VolumePass &&
                    options_.volumeTest == VolumeTest::Sphere;
    volumePass_.setShadows(on ? &frame_.shadows : nullptr, shading.shadows);
    return on;
}

void LidrRenderer::depthPrepass(const CameraMatrices& cam, bool tiles) {
    // The pre-pass the volume tests compare against: the MSAA one on the per-sample path.
    if (options_.perSampleIndices)
        frame_.targets.bindColor();
    else
        frame_.targets.bindSingleSample();
    if (!options_.depthPrepass) {
        ClearAction clear;
        clear.depth = true;
        StateCache::current().clear(clear);
        return;
    }
    if (depthSpans_.storesSamples()) {
        // sphere-span with the samples' distances: the MSAA pre-pass first (the forward pass tests against it),
        // then sample 0's point as the single-sample depth: a full-screen pass, not a second geometry pass.
        TimedPass depthSpansTime(frame_.timer, kDepthSpans.name);
        depthSpans_.run(frame_.scene, cam, depthTexture_);
        depthSpansTime.end();
        frame_.targets.bindSingleSample();
        TimedPass depthTime(frame_.timer, kDepthPrepass.name);
        // With tiles, each pixel's depth range in the same pass (cullByTiles reads them back).
        depthSpans_.writeCentreDepth(frame_.targets.depthStencil(), frame_.targets.separateStencil(), tiles);
        frame_.targets.bindSingleSample();
        return;  // no depth copy: the volume shaders read the samples' distances instead
    }
    TimedPass depthTime(frame_.timer, kDepthPrepass.name);
    frame_.depthPrepass.run(frame_.scene, cam);
    copyPrepassDepth(cam);
    depthTime.end();
    if (!depthSpans_) return;
    // sphere-span: the MSAA pre-pass (the forward pass tests against it) writes the samples' spans as it goes.
    TimedPass depthSpansTime(frame_.timer, kDepthSpans.name);
    depthSpans_.run(frame_.scene, cam, depthTexture_);
    frame_.targets.bindSingleSample();
}

void LidrRenderer::copyPrepassDepth(const CameraMatrices& cam) {
    if (!depthTexture_) return;
    // The shader volume tests read the pre-pass depth from a texture that is not attached to the framebuffer
    // they draw into (reading an attached one is a feedback loop).
    if (depthTextureFbo_) {
        depthTextureFbo_.bind();
        frame_.depthPrepass.run(frame_.scene, cam);
        frame_.targets.bindSingleSample();
        checkGl("pre-pass depth texture for the volume tests (OpenGL ES)");
    } else {
        depthTexture_.bind(gl::kUnitDepthCopy);
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, frame_.targets.width(), frame_.targets.height());
        checkGl("depth copy for the volume tests");
    }
}

TileDecision::Choice LidrRenderer::decideTiles(const CameraMatrices& cam, const std::vector<PointLight>& lights) const {
    if (!options_.depthPrepass || !volumeTiles_) return {};  // no depth to cull by: volume meshes
    return tileDecision_.decide(lightRectArea(cam, lights), screenPixels());
}

void LidrRenderer::cullByTiles(const CameraMatrices& cam, const TileDecision::Choice& choice) {
    if (choice.tiles) {
        TimedPass volumeTilesTime(frame_.timer, kVolumeTiles.name);
        if (depthSpans_.storesSamples()) {
            // Under MSAA each pixel's range: the centre's surface and every sample's point.
            depthSpans_.readDepthRanges(tileNearDepth_, tileFarDepth_);
            frame_.targets.bindSingleSample();
            volumeTiles_->buildRanges(tileNearDepth_, tileFarDepth_, volumePass_.tileDepthMargin(), cam);
        } else if (depthSpans_) {
            // The GL 2.1 moments: each pixel's range from the centre's depth (bound) and the resolved spans.
            const std::vector<float>& centre = volumeTiles_->readBoundDepth(frame_.targets.depthBits() == 24);
            depthSpans_.readMomentRanges(centre, tileNearDepth_, tileFarDepth_);
            frame_.targets.bindSingleSample();
            volumeTiles_->buildRanges(tileNearDepth_, tileFarDepth_, volumePass_.tileDepthMargin(), cam);
        } else {
            volumeTiles_->buildFromBoundDepth(volumePass_.tileDepthMargin(), cam, frame_.targets.depthBits() == 24);  // the single-sample pre-pass depth
        }
        volumePass_.setTiles(volumeTiles_.get(), cam);
    } else {
        volumePass_.setTiles(nullptr, cam);
    }
}

FramePlan LidrRenderer::plan(const CameraMatrices& cam, const std::vector<PointLight>& lights, bool tiles,
                             const std::vector<int>* volumeShadowTiles) {
    FramePlanSettings s;
    s.cullLights = options_.cullLights;
    s.tiles = tiles;
    s.transparentLists = drawTransparent_;
    s.autoWidth = options_.packing.autoIndexBits() ? &auto_ : nullptr;
    s.fixedIndexBits = options_.packing.indexBits;
    // Regions need an opaque frame with one list per pixel, read at its own tile (single-sampled, or MSAA's
    // sphere-span lists with the tiles of the samples' depths), and exact small integers in the light table (its
    // tile map).
    s.regionalIndices = options_.regionalIndices && !drawTransparent_ && (frame_.targets.samples() == 0 || depthSpans_) &&
                        !options_.perSampleIndices && frame_.lightTable.format() == LightTableFormat::Float;
    s.maxRegions = kMaxIndexRegions;
    if (volumeTiles_) {
        s.tilesX = volumeTiles_->tilesX();
        s.tilesY = volumeTiles_->tilesY();
        s.tileSize = volumeTiles_->tileSize();
    }
    s.tableCapacity = frame_.lightTable.capacity();
    s.shadowTiles = volumeShadowTiles;
    FramePlanQueries q;
    q.touchesScene = [this](const glm::vec4& sphere) { return frame_.scene.batchesTouchSphere(sphere, DrawFilter::All); };
    q.reachesTransparent = [this](const glm::vec4& sphere) {
        return frame_.scene.batchesTouchSphere(sphere, DrawFilter::Transparent);
    };
    q.reachesTiles = [this](const glm::vec4& sphere) { return volumePass_.sphereReachesTiles(sphere); };
    q.regionsReached = [this](const glm::vec4& sphere, const IndexRegions& regions) {
        return volumePass_.sphereRegions(sphere, regions);
    };
    return planFrame(cam, lights, s, q);
}

void LidrRenderer::loadPlan(const std::vector<PointLight>& lights, const std::vector<int>& shadowTiles) {
    volumePass_.setRegions(plan_.regions);
    if (plan_.regions.on()) {
        // The tile -> row map sits in the light table's rows after the regions' (the forward pass reads it).
        std::vector<float> map(plan_.regions.regionOfTiles.begin(), plan_.regions.regionOfTiles.end());
        frame_.lightTable.setRegionMap(std::move(map), plan_.regions.count, plan_.regions.tileSize, plan_.regions.tilesX);
    } else {
        frame_.lightTable.setRegionMap({}, 0, 1, 1);
    }
    // The table's lights are a selection (automatic width, regions): their tiles follow them (tilesFor).
    if (plan_.compactNumbering)
        frame_.lightTable.update(plan_.tableLights, frame_.shadows.tilesFor(plan_.frameLights));
    else
        frame_.lightTable.update(lights, shadowTiles);
}

void LidrRenderer::selectPacking() {
    const PackingConfig& fixed = options_.packing;
    if (fixed.autoBudget()) {
        // The frame's index width decides the widest budget: 32 (8 targets) holds 4- and 8-bit indices only.
        const int largest = largestAutoBudget_[widthSlot(plan_.indexBits)];
        if (largest > 0) {
            auto_.setMaxBudget(largest);
            autoTransparent_.setMaxBudget(largest);
        }
    }
    selectVariant(fixed.autoBudget() ? auto_.budget() : fixed.budget, plan_.indexBits);
    selectTransparentVariant(fixed.autoBudget() ? autoTransparent_.budget() : fixed.budget, plan_.indexBits);
}

void LidrRenderer::repackWhileOver(const CameraMatrices& cam, const ShadingParameters& shading, int needTransparent) {
    // The main pass's probe is read only after the forward passes are queued, so the GPU is not left idle while
    // the CPU waits for it. The transparent lists have their own budget: a ray in front of a surface meets more
    // lights than the surface does, and only the transparent layers read those lists.
    AutoDecision& decision = stats_.autoDecision;
    for (;;) {
        const int need = measuredNeed();
        decision.measuredBudget = need;
        decision.measuredTransparentBudget = std::max(needTransparent, 0);
        const int repack = auto_.observeNeed(need, narrowingAsked_);
        const int repackTransparent =
            needTransparent >= 0 ? autoTransparent_.observeNeed(needTransparent, narrowingAskedTransparent_) : 0;
        if (repack == 0 && repackTransparent == 0) return;
        ++decision.repacks;  // both passes again: the main pass's stencil counts must be the last ones drawn
        if (repack) selectVariant(repack, plan_.indexBits);
        if (repackTransparent) selectTransparentVariant(repackTransparent, plan_.indexBits);
        needTransparent = drawVolumes(cam, plan_.volumes);
        shade(cam, shading);
    }
}

void LidrRenderer::recordFrame(const TileDecision::Choice& tiles) {
    lightlessFrame_ = plan_.lightless();
    stats_.drawnLights = plan_.drawnLights;
    stats_.volumePassSkipped = lightlessFrame_;
    if (lightlessFrame_) stats_.transparentVolumePassSkipped = true;
    stats_.volumeDrawCalls = volumePass_.drawCalls() + transparentVolumePass_.drawCalls();
    const bool autoBudget = options_.packing.autoBudget();
    AutoDecision& decision = stats_.autoDecision;
    decision.autoBudget = autoBudget;
    decision.autoIndexBits = plan_.compactNumbering;
    decision.visibleLights = plan_.drawnLights;
    decision.indexRegions = plan_.regions.count;
    decision.budget = current_->scheme->config().budget;
    decision.indexBits = current_->scheme->config().indexBits;
    for (size_t i = 0; autoBudget && i < OverlapProbe::kThreshold.size(); ++i)
        if (OverlapProbe::kThreshold[i] == decision.budget) decision.overflowPixels = std::max(0L, pixelsAbove_[i]);
    if (transparentIndexTargets_ && stats_.transparentVolumeLights > 0)
        decision.transparentBudget = currentTransparent_->scheme->config().budget;
    if (requestedAutoBudget_ && !autoBudget) decision.budgetFallback = "fixed (no occlusion queries)";
    if (tiles.tiles) {
        decision.volumeAreaPerPixel = double(volumeQuadPixels_) / screenPixels();
        decision.areaBound = decision.volumeAreaPerPixel > AutoDecision::kAreaBoundPerPixel;
        // Lights the tiles culled would have been drawn by volume meshes too (plan_.meshRectArea).
        tileDecision_.recordTileFrame({tiles.rectArea, plan_.meshRectArea, volumeQuadPixels_, volumeStepLights_,
                                       plan_.volumes.size(), plan_.tilesNarrowed()},
                                      screenPixels());
    } else {
        tileDecision_.recordMeshFrame();
    }
    decision.tileSavingScreens = tileDecision_.lastSavingScreens();
    decision.tilesSkippedForSaving = tiles.skippedForSaving;
}

void LidrRenderer::shade(const CameraMatrices& cam, const ShadingParameters& shading, bool lights) {
    const bool multisampled = frame_.targets.samples() > 0;
    if (multisampled && options_.depthPrepass && !options_.perSampleIndices && !depthSpans_) {
        TimedPass msaaDepthPrepassTime(frame_.timer, kMsaaDepthPrepass.name);
        frame_.targets.bindColor();
        frame_.depthPrepass.run(frame_.scene, cam);
    }

    TimedPass forwardTime(frame_.timer, kForward.name);
    const ShadowMaps* shadows = lights && frame_.shadows.active() ? &frame_.shadows : nullptr;
    frame_.prepareEnvironment(shading, stats_, lights ? indexTargets_->count() : 0);
    VisibleSamples visible;
    stats_.autoDecision.hiddenFragmentSkip = lights && skipHiddenFragments();
    if (stats_.autoDecision.hiddenFragmentSkip) {
        visible.samples = depthSpans_.samples();
        for (int t = 0; t < depthSpans_.packedTextureCount(); ++t) visible.distances[t] = &depthSpans_.packedTexture(t);
    }
    current_->forward->run(frame_.targets, *indexTargets_, frame_.scene, frame_.lightTable, cam, shading, frame_.environment,
                           options_.depthPrepass, lights, shadows, visible);
    forwardTime.end();

    if (drawTransparent_) {
        TimedPass forwardTransparentTime(frame_.timer, kForwardTransparent.name);
        const IndexTargets& transparentTargets = transparentIndexTargets();
        frame_.environment.prepare(shading.environment, lights ? transparentTargets.count() : 0);
        currentTransparent_->forward->runTransparent(frame_.targets, transparentTargets, frame_.scene, frame_.lightTable, cam, shading,
                                                     frame_.environment, lights, shadows);
    }
}

bool LidrRenderer::skipHiddenFragments() const {
    // As ForwardPass::run takes it: after the MSAA pre-pass that stored the distances, at the buffer's own depth.
    if (!depthSpans_.storesSamples() || options_.emulatedDepthBits != 0 ||
        frame_.info.maxTextureUnits < gl::kUnitSampleDistances + depthSpans_.packedTextureCount())
        return false;
    switch (options_.hiddenFragmentSkip) {
        case HiddenFragmentSkip::On: return true;
        case HiddenFragmentSkip::Off: return false;
        default: return shadesRejectedFragments_ && current_->scheme->config().budget >= kHiddenSkipBudget;
    }
}

int LidrRenderer::measuredNeed() {
    auto above = probe_.pixelsAbove();  // waits for the GPU: the forward passes are queued by now
    if (OverlapProbe::smallestBudget(above) < 0) {
        // Over the budget: how far over. The volume pass's counts are still in the stencil (the forward passes
        // after a pre-pass clear colour only), so the probe asks again over the index targets.
        PassDescription pass{indexTargets_->framebuffer().id(),
                             glm::ivec4(0, 0, indexTargets_->width(), indexTargets_->height()), {}, {}};
        StateCache::current().beginPass(pass);
        probe_.issue(OverlapProbe::aboveBudget(current_->scheme->config().budget), probeAreas());
        OverlapProbe::merge(above, probe_.pixelsAbove());
    }
    pixelsAbove_ = above;
    return OverlapProbe::smallestBudget(above);
}

int LidrRenderer::drawVolumes(const CameraMatrices& cam, const std::vector<VolumeLight>& volumes) {
    pixelsAbove_.fill(0);
    // The transparent layers' lists first, so that the main pass's per-pixel light counts stay in the shared
    // stencil: the transparent pass's thresholds are read at once, the main pass's after the forward passes
    // (measuredNeed()).
    const int needTransparent = transparentIndexTargets_ ? drawTransparentVolumes(cam, volumes) : -1;
    TimedPass lightVolumesTime(frame_.timer, kLightVolumes.name);
    volumePass_.begin(*indexTargets_, cam, &depthTexture_);
    current_->scheme->encode(volumePass_, volumes);
    volumeQuadPixels_ += volumePass_.tileQuadPixels();
    volumeStepLights_ += volumePass_.tileStepLights();
    volumePass_.end();
    lightVolumesTime.end();
    if (options_.packing.autoBudget()) {
        TimedPass probeTime(frame_.timer, kOverlapProbe.name);  // apart: full-screen draws, not volume fragments
        probe_.issue(thresholdsToAsk(auto_, current_->scheme->config().budget, narrowingAsked_), probeAreas());
    }
    return needTransparent;
}

int LidrRenderer::drawTransparentVolumes(const CameraMatrices& cam, const std::vector<VolumeLight>& volumes) {
    // Only where transparent geometry can be on screen, and only lights that reach a transparent mesh's bounds:
    // the lists outside stay empty, and no transparent surface reads them.
    glm::ivec4 area(0);
    std::vector<VolumeLight> reaching;
    if (frame_.scene.batchesPixelRect(cam, DrawFilter::Transparent, area))
        for (const VolumeLight& v : volumes)
            if (frame_.scene.batchesTouchSphere(v.posRadius, DrawFilter::Transparent)) reaching.push_back(v);
    stats_.transparentVolumeLights = static_cast<int>(reaching.size());
    stats_.transparentVolumePassSkipped = reaching.empty();
    TimedPass lightVolumesTransparentTime(frame_.timer, kLightVolumesTransparent.name);
    transparentVolumePass_.begin(*transparentIndexTargets_, cam, &depthTexture_);
    if (reaching.empty()) {
        transparentVolumePass_.end();
        return -1;
    }
    const glm::ivec4 box(area.x, area.y, area.z - area.x + 1, area.w - area.y + 1);
    transparentVolumePass_.setScissor(&box);
    currentTransparent_->scheme->encode(transparentVolumePass_, reaching);
    transparentVolumePass_.setScissor(nullptr);
    transparentVolumePass_.end();
    return options_.packing.autoBudget() ? measureTransparentNeed(cam, box) : -1;
}

int LidrRenderer::measureTransparentNeed(const CameraMatrices& cam, const glm::ivec4& box) {
    // Over the transparent meshes' pixels only: there alone are these lists read.
    auto probe = [&](unsigned which) {
        probe_.issueOverMeshes(frame_.scene, DrawFilter::Transparent, cam, which, &box);
        return probe_.pixelsAbove();
    };
    const int budget = currentTransparent_->scheme->config().budget;
    auto above = probe(thresholdsToAsk(autoTransparent_, budget, narrowingAskedTransparent_));
    if (OverlapProbe::smallestBudget(above) < 0) OverlapProbe::merge(above, probe(OverlapProbe::aboveBudget(budget)));
    return OverlapProbe::smallestBudget(above);
}

OverlapProbe::Areas LidrRenderer::probeAreas() const {
    // A pixel's count is at most its tile's candidate bound, so a threshold is drawn only over the tiles whose
    // bound exceeds it (nowhere: answered 0 without a draw); volume meshes give no bound (the whole screen).
    OverlapProbe::Areas areas;
    for (size_t i = 0; i < areas.size(); ++i)
        areas[i] = volumePass_.drawsScreenTiles() ? volumePass_.tileCandidateArea(OverlapProbe::kThreshold[i])
                                                  : glm::ivec4(0, 0, -1, -1);
    return areas;
}

void LidrRenderer::checkObjectMaterial(const Material& material) const {
    // The transparent layers' targets and lists are set up when the renderer is built, for a scene that has
    // transparent meshes; a renderer built without them cannot take one later.
    if (material.opacity < 1.0f && options_.transparency && !drawTransparent_)
        throw Error("lidr: material '" + material.name + "' is transparent (opacity " + std::to_string(material.opacity) +
                    ") but this renderer was built for a scene without transparent meshes; build it from a scene that has "
                    "one (or with transparency off, which draws transparent objects not at all)");
}

}  // namespace lidr
