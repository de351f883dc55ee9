#pragma once
// Light Indexed Deferred Rendering, end to end: depth pre-pass, light volumes into RGBA8 index targets
// (packed by a PackingScheme), forward pass that unpacks and shades. Each pass is its own class and file, and
// so is each CPU decision of a frame (the tile decision, tile_decision.h; the frame plan, frame_plan.h); this
// class runs the frame: the stages in order (render(), doc/architecture.md "One frame of LIDR"), with the
// FrameResources every mode holds (scene, targets, light table, pre-pass, shadows, environment, timer) and its own
// index targets, packing variants and read-back.
#include <array>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "lidr/technique/auto_configuration.h"
#include "lidr/technique/depth_span_pass.h"
#include "lidr/technique/overlap_probe.h"
#include "lidr/technique/forward_pass.h"
#include "lidr/technique/frame_plan.h"
#include "lidr/technique/light_volume_pass.h"
#include "lidr/technique/packing_scheme.h"
#include "lidr/render/frame_resources.h"
#include "lidr/technique/tile_decision.h"
#include "lidr/technique/volume_tiles.h"

namespace lidr {

struct LidrOptions {
    // Default: automatic (bit-shift; budget measured per frame, the narrowest index width for the visible lights,
    // renumbered compactly). A named scheme takes a fixed budget and width, either of which may stay kAuto.
    PackingConfig packing;
    // Automatic choices widen at once and narrow after this many frames in a row that fit the narrower one.
    int autoHoldFrames = AutoConfiguration::kDefaultHoldFrames;
    // ... and ask whether a smaller budget would do only every this many frames (the overlap probe's second
    // full-screen test; every frame still asks whether it overflows, so nothing is dropped for it).
    int autoNarrowingInterval = AutoConfiguration::kDefaultNarrowingInterval;
    VolumeTest volumeTest = VolumeTest::Sphere;  // exact, batched (LightVolumePass)
    bool depthPrepass = true;   // may be false only with the front-face test (vertex-bound scenes)
    int msaaSamples = 0;        // 0, or 2..GL_MAX_SAMPLES: MSAA colour, single-sample index texture
    // sphere-span: how the volume pass learns the surfaces of a pixel's samples (DepthSpanStorage): Auto is
    // Samples (each sample's distance, read per sample) where the context has multisample textures, else Moments.
    DepthSpanStorage msaaSpans = DepthSpanStorage::Auto;
    // With the samples' distances (msaaSpans Samples): the opaque forward pass skips the light list of every
    // fragment that keeps no sample (hidden at all of them; ForwardPass, VisibleSamples). The image is the same.
    // Auto: where the context shades fragments its depth test rejected (counted once, early_depth_probe.h:
    // llvmpipe) and the frame's budget is 8 or more (shorter lists save less than the test costs; measured in
    // doc/msaa-transparency.md). On: whenever the distances exist. Off: never.
    HiddenFragmentSkip hiddenFragmentSkip = HiddenFragmentSkip::Auto;
    // Transparent geometry (Material.opacity < 1) is drawn after the opaque, back to front. It is lit from
    // a front-face index texture: the main one in front-face mode, else one more volume pass for it alone.
    bool transparency = true;
    // Trebilco's MSAA technique 1, optional (GL 3.2 multisample textures + ARB_sample_shading): pre-pass,
    // light volumes and index targets are all multisampled and every sample reads its own index list, so
    // any volume test works with MSAA. Needs msaaSamples >= 2.
    bool perSampleIndices = false;
    bool cullLights = true;           // skip lights whose volume is wholly outside the view frustum
    // Coarser volumes (20 or 80 faces) for lights small on screen, where they reach at most a pixel past the
    // 320-face one (LightVolumePass); false: the 320-face volume for every light.
    bool volumeDetail = false;
    // Tile-culled volumes (the sphere test, desktop GL): the pre-pass depth is read back and kept per
    // volumeTileSize^2 tile as a depth range and a mask of depth slices holding surfaces (volume_tiles.h), and
    // each light is drawn as screen quads over the tiles where its sphere may reach a surface instead of its
    // volume mesh: lights hidden behind nearer surfaces and empty tiles cost no fragment, and the second stencil
    // rank window (budget 16) touches only tiles with more than 8 candidate lights. The lists are the same (the
    // shader's test is); false: volume meshes.
    bool tileCulledVolumes = true;
    int volumeTileSize = 16;
    // With tile-culled volumes and more than 255 lights reaching the view (automatic index width, opaque
    // frame, single-sampled or MSAA's sphere-span with the samples' distances): the screen is split into the fewest regions (a grid of tiles, at most
    // kMaxIndexRegions) in which at most 255 lights each reach a tile, and each region numbers its own lights in its
    // own row of the light table, so indices stay 8-bit: half the index targets, written and read, of 16-bit
    // global numbering. The lists hold the same lights (frameLightIndices, frameIndexRegions). false: global.
    bool regionalIndices = true;
    // Used in a frame only where the lights' pixel rectangles add up to at least kTileCullingMinArea screens:
    // below, the volume meshes cost less than the depth read-back (doc/benchmarks.md, "Deep, occluded scenes").
    bool forceFixedLightTable = false;  // test the no-float-texture light table path
    // Depth buffer precision: 24 (DEPTH24_STENCIL8) or 16 (a DEPTH_COMPONENT16 renderbuffer with a separate
    // STENCIL_INDEX8, where the driver accepts the pair: checkDepthBits in lidr/gl/render_targets.h; Mesa's
    // Gallium drivers refuse it). doc/stability.md says what 16 bits cost.
    int depthBits = 24;
    // 16: measure what 16-bit depth does where the driver cannot hold it. The buffer stays DEPTH24_STENCIL8 and
    // every LIDR pass that writes or tests depth rounds its fragment depth to the 16-bit levels (gl_FragDepth,
    // lidr_depth_emulated.glsl), so each depth test and the sphere tests' depth copy see what a 16-bit buffer
    // holds (round to nearest). A measurement aid, slower (no early depth test): needs depthBits 24, no MSAA,
    // lidr's own forward shader and desktop GL. 0: off. doc/stability.md.
    int emulatedDepthBits = 0;
    bool timing = false;  // per-pass times in FrameStats (Renderer::setTiming); off: no timer queries at all
    TimingMethod timingMethod = TimingMethod::Auto;
    // The program's own material: a GLSL 1.20 fragment shader for the forward pass (and transparent layers)
    // that iterates this pixel's lights with lidr_lights.glsl (doc/embedding.md). Empty: lidr's own shading (shading.glsl).
    std::string materialShader;
};

class LidrRenderer final : public Renderer {
public:
    // An automatic budget where the context has no occlusion queries to measure it (OpenGL ES 2.0): this fixed
    // budget instead, the paper's main case (one RGBA8 target at 8-bit indices); options() holds it and
    // FrameStats::autoDecision.budgetFallback says so.
    static constexpr int kBudgetWithoutOcclusionQueries = 4;
    // LidrOptions::tileCulledVolumes: the tile decision's rules (TileDecision, tile_decision.h): tiles from this many
    // screens of the lights' summed pixel rectangles; once a tile frame has measured it, only where they save
    // kTileCullingMinSaving screens of volume pixels, re-measured after kTileCullingRecheckFrames frames without;
    // where they narrow the index width (or number by region) they stay.
    static constexpr double kTileCullingMinArea = TileDecision::kMinArea;
    static constexpr double kTileCullingMinSaving = TileDecision::kMinSaving;
    static constexpr int kTileCullingRecheckFrames = TileDecision::kRecheckFrames;

    // Checks everything before any drawing: FBO support, resolution, scheme x budget x width, the volume test's
    // needs; throws UnsupportedError / lidr::Error with the reason.
    LidrRenderer(const GlInfo& info, const Scene& scene, const LidrOptions& options, int width, int height);

    // Renders one frame. `lights` (light i has index i + 1) must fit the index width.
    std::string modeName() const override { return "lidr"; }
    const FrameStats& render(const Camera& camera, const std::vector<PointLight>& lights,
                             const ShadingParameters& shading) override;

    // The scheme, index targets and light numbering of the last frame (with automatic choices they change).
    const PackingScheme& scheme() const { return *current_->scheme; }
    // The scheme of the transparent layers' own front-face lists (their budget is measured apart: a ray in front
    // of a surface meets more lights than the surface does); scheme() where they read the main lists.
    const PackingScheme& transparentScheme() const { return *currentTransparent_->scheme; }
    const LidrOptions& options() const { return options_; }
    // Whether the last frame's opaque pass skipped the light lists of fragments that keep no sample (MSAA,
    // samples spans; LidrOptions::hiddenFragmentSkip; also the frame's AutoDecision::hiddenFragmentSkip).
    bool skippedHiddenFragments() const { return stats_.autoDecision.hiddenFragmentSkip; }
    // Auto's smallest budget for the skip: at budget 4 (the room) it saved nothing, at 2 (city-255) it cost the
    // forward pass 13 %, at 8 (hall-255) it saved 19 %, at 32 (hall-1024) 40 % (doc/auto.md).
    static constexpr int kHiddenSkipBudget = 8;
    const FrameResources& frame() const override { return frame_; }
    std::vector<FramePass> passes() const override;
    const IndexTargets& indexTargets() const { return *indexTargets_; }
    // With an automatic index width, visible lights are numbered 1..n in draw order: entry k - 1 is the scene
    // index (1-based) of index k. Empty: indices are the scene's own.
    // With region-local indices (frameIndexRegions().on()): entry row * 256 + k - 1 is the scene index of index k
    // in region `row` (0: an unused entry); IndexRegions::regionOfPixel gives a pixel's row.
    const std::vector<uint32_t>& frameLightIndices() const { return plan_.frameLights; }
    const IndexRegions& frameIndexRegions() const { return plan_.regions; }
    static constexpr int kMaxIndexRegions = 32;
    // The index targets transparent layers read: the main ones in front-face mode.
    const IndexTargets& transparentIndexTargets() const;
    bool drawsTransparency() const { return drawTransparent_; }
    float volumeMeshOutsideRadius() const { return volumePass_.meshOutsideRadius(); }
    // Per light of the last frame (light i has index i + 1): the relative vertex distance of the volume it
    // was drawn with (LidrOptions::volumeDetail picks coarser volumes for lights small on screen).
    std::vector<float> volumeOutsideRadii(const std::vector<PointLight>& lights) const;
    std::vector<ImageRGBA8> readIndexTargets() const;
    // sphere-span (MSAA): per pixel, top to bottom, the window depths the samples shade (DepthSpanPass::Span);
    // empty for the other tests.
    // Empty too where the spans are stored per sample: readSampleDepths() then (per sample an image of window
    // depths, top to bottom, 1 where the sample has no surface); empty otherwise.
    std::vector<DepthSpanPass::Span> readDepthSpans() const;
    std::vector<ImageFloat> readSampleDepths() const;
    // Per-pixel count of lights whose volume test passed (from stencil), top to bottom; empty if the
    // stencil did not keep a count.
    std::vector<uint8_t> readLightCounts() const;
    size_t lightDataBytes() const override;

    // Lights in the order the volume pass draws them: priority high to low, then index low to high (lidr::drawOrder).
    static std::vector<uint32_t> drawOrder(const std::vector<PointLight>& lights) { return lidr::drawOrder(lights); }

    void checkObjectMaterial(const Material& material) const override;

private:
    // The stages of a frame, in the order render() runs them (doc/architecture.md, "One frame of LIDR").
    // Finite spheres of positive radius (checkLightSpheres, as every mode), and a fixed width must hold them all.
    void checkLights(const std::vector<PointLight>& lights) const;
    // 0. After the shadow maps: whether the main sphere test discards what they shadow (the paper's first way,
    // ShadowLookup::VolumePass); sets the volume pass's shadows.
    bool useVolumeShadows(const std::vector<int>& shadowTiles, const ShadingParameters& shading);
    // 1a. The tile decision (TileDecision): whether this frame's volumes are culled by the pre-pass depth per tile.
    TileDecision::Choice decideTiles(const CameraMatrices& cam, const std::vector<PointLight>& lights) const;
    // 1. The depth pre-pass (and the depth copy the shader volume tests read), or a depth clear without one; with
    // sphere-span, the MSAA pre-pass too (with the samples' distances first, the single-sample depth from it, and
    // with `tiles` each pixel's depth range in the same full-screen pass).
    void depthPrepass(const CameraMatrices& cam, bool tiles);
    void copyPrepassDepth(const CameraMatrices& cam);  // the depth copy (OpenGL ES: the pre-pass drawn again into it)
    // 1b. Where the decision takes tiles, the pre-pass depth read back per tile and given to the volume pass.
    void cullByTiles(const CameraMatrices& cam, const TileDecision::Choice& choice);
    // 2. The frame plan (frame_plan.h) from this renderer's options, meshes and tiles; then its regions to the volume
    // pass and its lights into the light table, and the packing variants for its index width.
    FramePlan plan(const CameraMatrices& cam, const std::vector<PointLight>& lights, bool tiles,
                   const std::vector<int>* volumeShadowTiles);
    void loadPlan(const std::vector<PointLight>& lights, const std::vector<int>& shadowTiles);
    void selectPacking();
    // 3. The volume passes (the transparent layers' own lists first, then the main ones) with the current variants;
    // with an automatic budget the transparent pass's need is measured (returned; -1 where the transparent lists
    // were not drawn or not measured) and the main pass's probe issued (read by measuredNeed()).
    int drawVolumes(const CameraMatrices& cam, const std::vector<VolumeLight>& volumes);
    int drawTransparentVolumes(const CameraMatrices& cam, const std::vector<VolumeLight>& volumes);
    int measureTransparentNeed(const CameraMatrices& cam, const glm::ivec4& box);
    // 4. The forward passes (opaque, transparent layers) from the current index lists (with the frame's shadows:
    // each listed light looked up by index where it casts); lights false: no light is listed anywhere.
    void shade(const CameraMatrices& cam, const ShadingParameters& shading, bool lights = true);
    // 5. The automatic re-pack: a frame measured over the budget it was packed with is packed again with the
    // smallest budget that holds it, and shaded again, until it holds (doc/auto.md).
    void repackWhileOver(const CameraMatrices& cam, const ShadingParameters& shading, int needTransparent);
    // 6. The frame's record: what the tiles saved (for the next tile decision) and the frame's statistics.
    void recordFrame(const TileDecision::Choice& tiles);

    double screenPixels() const { return double(frame_.targets.width()) * frame_.targets.height(); }
    // One packing of the frame: the scheme and its forward shader, built on first use and kept.
    struct Variant {
        std::unique_ptr<PackingScheme> scheme;
        std::unique_ptr<ForwardPass> forward;
    };
    Variant& variant(int budget, int indexBits);
    void selectVariant(int budget, int indexBits);  // current_ and the index targets for its target count
    void selectTransparentVariant(int budget, int indexBits);  // the same for the transparent lists
    IndexTargets& indexTargetsFor(std::map<int, IndexTargets>& cache, int count);
    // The main volume pass's smallest budget that drops nothing, from its probe (asking how far over if over).
    int measuredNeed();
    // This frame's opaque pass skips hidden fragments' lists (LidrOptions::hiddenFragmentSkip).
    bool skipHiddenFragments() const;
    // Where the main pass's probe draws each threshold (OverlapProbe::Areas), from the tiles' candidate bounds.
    OverlapProbe::Areas probeAreas() const;

    LidrOptions options_;  // as asked, with the context's fallbacks (withContextFallbacks)
    bool requestedAutoBudget_ = false;
    PackingConfig firstPacking_;  // checked options, resolved for the first frame: before any GL object exists
    // The scene on the GPU, the targets (LidrOptions::depthBits), the light table (sized for the index width: it never
    // grows), the pre-pass (LidrOptions::emulatedDepthBits), the shadow maps, the environment maps and the timer.
    // Shadows (ShadingParameters::shadows): the maps, drawn first each frame. ShadowLookup::VolumePass: the main
    // sphere test discards what they shadow (its lights carry their tiles); every forward pass looks the listed
    // lights up by index.
    FrameResources frame_;
    DepthSpanPass depthSpans_;  // sphere-span: what the volume pass reads beside the depth copy
    bool shadesRejectedFragments_ = false;  // with the samples' distances: counted once (early_depth_probe.h)
    std::vector<float> tileNearDepth_, tileFarDepth_;  // sphere-span with tiles: each pixel's range (readDepthRanges)
    std::map<std::pair<int, int>, Variant> variants_;  // by (budget, index bits)
    Variant* current_ = nullptr;
    Variant* currentTransparent_ = nullptr;
    AutoConfiguration auto_, autoTransparent_;
    std::array<int, 3> largestAutoBudget_{};  // the automatic budget's largest at 4-, 8- and 16-bit indices (0: unused)
    static size_t widthSlot(int indexBits) { return indexBits == 4 ? 0 : indexBits == 8 ? 1 : 2; }
    OverlapProbe probe_;
    std::array<long, OverlapProbe::kThresholds> pixelsAbove_{};  // the last measurement, both passes
    bool narrowingAsked_ = true, narrowingAskedTransparent_ = true;  // the last measurement asked below the budget
    FramePlan plan_;  // the last frame's
    // The last frame had no light to index: no volume pass was drawn and its lists are empty (the index targets
    // still hold an earlier frame's; the read-backs answer with the empty lists).
    bool lightlessFrame_ = false;
    long volumeQuadPixels_ = 0;  // this frame's tile quads, every draw of the main volume pass
    long volumeStepLights_ = 0;  // lights asked for by those draws, once per draw
    TileDecision tileDecision_;
    std::map<int, IndexTargets> indexTargetCache_, transparentTargetCache_;  // by target count
    IndexTargets* indexTargets_ = nullptr;
    IndexTargets* transparentIndexTargets_ = nullptr;  // when transparent layers need their own front-face lists
    gl::Texture depthTexture_;              // copy of the pre-pass depth, for the shader volume tests
    gl::Framebuffer depthTextureFbo_;       // OpenGL ES: the pre-pass drawn again into depthTexture_
    std::unique_ptr<VolumeTiles> volumeTiles_;  // LidrOptions::tileCulledVolumes: the frame's depth per tile
    LightVolumePass volumePass_;
    LightVolumePass transparentVolumePass_;
    bool drawTransparent_ = false;
};

}  // namespace lidr
