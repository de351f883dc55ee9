#include "lidr/modes/tiled_deferred_renderer.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <sstream>

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"
#include "lidr/render/shading_pass.h"
#include "lidr/render/shading_variants.h"

namespace lidr {

namespace {
const GlInfo& checkedContext(const GlInfo& info, const TiledDeferredOptions& o) {
    const std::string msaaRefusal = deferredMsaaRefusal(info, o.msaaSamples, "tiled-deferred");
    if (!msaaRefusal.empty()) throw UnsupportedError(msaaRefusal);
    if (o.initialLoopBound < 1 || o.initialLoopBound > 65535)
        throw Error("tiled-deferred: initial loop bound must be 1..65535, got " + std::to_string(o.initialLoopBound));
    return info;
}

// Tiled deferred's own passes, between FrameResources' (passes(), render()).
constexpr FramePass kDepthPrepassWithCopy{"depth-prepass", "scene", "depth, packed depth copy"};
constexpr FramePass kTileDepthReduce{"tile-depth-reduce", "packed depth copy", "tile depth ranges (read back)"};
constexpr FramePass kLightGrid{"light-grid", "lights, [tile depth ranges]", "light grid (CPU, uploaded)"};
constexpr FramePass kGBuffer{"g-buffer", "scene, depth", "G-buffer (4 targets; RGBA8: 5)"};
constexpr FramePass kTiledDeferred{"tiled-deferred",
                                   "G-buffer, light grid, light table, [shadow atlas], [environment]", "colour"};
constexpr FramePass kTransparent{"tiled-transparent",
                                 "transparent meshes, depth, transparent lists, light table, [shadow atlas], "
                                 "[environment]",
                                 "colour", "transparent meshes in the scene"};
}  // namespace

TiledDeferredRenderer::TiledDeferredRenderer(const GlInfo& info, const Scene& scene,
                                             const TiledDeferredOptions& options, int width, int height)
    : frame_(checkedContext(info, options), scene, FrameSetup::of(options, scene, width, height)),
      options_(options),
      gBuffer_(makeDeferredGBuffer(info, frame_.targets, options.format, false)),
      tiledShader_(frame_.targets.samples() > 0 ? "tiled_deferred_multisample.frag" : "tiled_deferred.frag"),
      grid_(width, height, options.tileSize),
      gridTextures_(info, grid_.tilesX(), grid_.tilesY()) {
    if (options_.depthBounds && !info.gles)
        depthBounds_ = std::make_unique<TileDepthBounds>(  // MSAA: the ranges cover every sample's surface
            info, width, height, options_.tileSize, frame_.targets.depthStencil(), options_.forcePackedDepth, false,
            frame_.targets.samples() > 0 ? &frame_.targets : nullptr);
    buildPrograms(options_.initialLoopBound);
}

void TiledDeferredRenderer::buildPrograms(int loopBound) {
    defines_ = frame_.lightTable.defines();
    defines_.push_back({"LIDR_TILE_SIZE", std::to_string(options_.tileSize)});
    defines_.push_back({"LIDR_LIGHT_LIST_WIDTH", std::to_string(LightGridTextures::kListWidth)});
    defines_.push_back({"LIDR_MAX_TILE_LIGHTS", std::to_string(loopBound)});
    for (const auto& d : gBuffer_->shaderDefines()) defines_.push_back(d);  // the RGBA8 layout's decoding
    ShaderDefines tiledDefines = defines_;
    tiledDefines.push_back({"LIDR_DIELECTRIC_SPECULAR", "1"});  // F90 comes from the G-buffer
    tiled_ = gl::Program::create("tiled-deferred-" + std::to_string(loopBound),
                                 buildShaderSource("deferred_fullscreen.vert"),
                                 buildShaderSource(tiledShader_, tiledDefines), geometryAttributes());
    transparent_ = gl::Program::create("tiled-deferred-transparent-" + std::to_string(loopBound),
                                       buildShaderSource("geometry.vert"),
                                       buildShaderSource("tiled_forward.frag", defines_), geometryAttributes());
    loopBound_ = loopBound;
}

size_t TiledDeferredRenderer::lightDataBytes() const {
    return gBuffer_->bytes() + gridTextures_.bytes() + (depthBounds_ ? depthBounds_->bytes() : 0);
}

std::vector<FramePass> TiledDeferredRenderer::passes() const {
    std::vector<FramePass> p{pass::kShadowMaps, pass::kLightTable};
    p.push_back(depthBounds_ ? kDepthPrepassWithCopy : pass::kDepthPrepass);
    if (depthBounds_) p.push_back(kTileDepthReduce);
    p.insert(p.end(), {kLightGrid, kGBuffer, kTiledDeferred});
    if (options_.transparency) p.push_back(kTransparent);
    if (frame_.targets.samples() > 0) p.push_back(pass::kMsaaResolve);
    return p;
}

const FrameStats& TiledDeferredRenderer::render(const Camera& camera, const std::vector<PointLight>& lights,
                                                const ShadingParameters& shading) {
    const CameraMatrices cam = frame_.checkFrame(camera, lights, shading, "tiled-deferred");
    const FrameScope scope(stats_, frame_.timer, lights.size());
    frame_.prepareLights(lights, shading, stats_);  // shadow-maps, light-table
    const bool transparent = options_.transparency && frame_.scene.hasTransparent();
    drawDepthPrepass(cam);
    buildLightGrid(cam, lights, transparent);
    {
        TimedPass gBufferTime(frame_.timer, kGBuffer.name);
        gBuffer_->draw(frame_.scene, cam);
    }
    shadeTiles(cam, shading);
    if (transparent) shadeTransparent(cam, shading);
    frame_.resolve();
    gBuffer_->unbind();
    StateCache::current().unbindTextures({gl::kUnitTileGrid, gl::kUnitTileList});
    frame_.finishFrame(stats_, "TiledDeferredRenderer::render");
    return stats_;
}

void TiledDeferredRenderer::drawDepthPrepass(const CameraMatrices& cam) {
    tileDepth_.clear();
    if (!depthBounds_) {
        frame_.drawDepthPrepass(cam);
        return;
    }
    {
        TimedPass depthPrepassTime(frame_.timer, pass::kDepthPrepass.name);
        depthBounds_->prepass(frame_.scene, cam);
        if (depthBounds_->coversSamples()) depthBounds_->samples(frame_.scene, cam);  // MSAA: the samples' depth
    }
    TimedPass reduceTime(frame_.timer, kTileDepthReduce.name);
    tileDepth_ = depthBounds_->reduce();
}

void TiledDeferredRenderer::buildLightGrid(const CameraMatrices& cam, const std::vector<PointLight>& lights,
                                           bool transparent) {
    TimedPass lightGridTime(frame_.timer, kLightGrid.name);
    grid_.build(cam, lights, depthBounds_ ? &tileDepth_ : nullptr, transparent, frame_.lightTable.reachError());
    gridTextures_.upload(grid_);
    const LightGridStats& gs = grid_.stats();
    const int longest = std::max(gs.maxOpaqueLights, transparent ? gs.maxTransparentLights : 0);
    if (longest > loopBound_) {  // a list outgrew the loop: recompile with room for it
        int bound = loopBound_;
        while (bound < longest) bound *= 2;
        buildPrograms(std::min(bound, 65535));
    }
    stats_.drawnLights = gs.assignedLights;
}

void TiledDeferredRenderer::shadeTiles(const CameraMatrices& cam, const ShadingParameters& shading) {
    TimedPass tiledTime(frame_.timer, kTiledDeferred.name);
    beginOpaqueShading(frame_.targets, shading, true);  // cleared to the background
    RenderState fullScreen;  // no depth test; MSAA: once a sample
    fullScreen.sampleShading = frame_.targets.samples() > 0;
    StateCache::current().apply(fullScreen);
    const gl::Program& shadowed =
        frame_.shadows.active() ? frame_.shadows.program(tiled_.name(), "deferred_fullscreen.vert",
                                                         tiledShader_, [&] {
                                                             ShaderDefines d = defines_;
                                                             d.push_back({"LIDR_DIELECTRIC_SPECULAR", "1"});
                                                             return d;
                                                         }(),
                                                         shading.shadows)
                                : tiled_;
    const uint32_t key = shadingVariantKey(shadowed, shading, frame_.environment);
    const gl::Program& program = shadowed.variant(key, [&] { return shadingVariantDefines(key); });
    useShadingProgram(program, cam, shading, frame_.lightTable, frame_.environment);
    frame_.shadows.bind(program, shading.shadows);
    gridTextures_.bind(program, false);
    gBuffer_->bind(program, cam);
    gBuffer_->drawFullScreen();
}

void TiledDeferredRenderer::shadeTransparent(const CameraMatrices& cam, const ShadingParameters& shading) {
    TimedPass transparentTime(frame_.timer, kTransparent.name);
    frame_.targets.bindColor();
    beginTransparentShading();  // back to front over the opaque depth, no depth writes
    const gl::Program& program =
        frame_.shadows.shadingProgram(transparent_, "tiled_forward.frag", defines_, shading.shadows);
    useShadingProgram(program, cam, shading, frame_.lightTable, frame_.environment);
    frame_.shadows.bind(program, shading.shadows);
    gridTextures_.bind(program, true);
    frame_.scene.drawTransparentSorted(program, cam.eye, shadingVariantKey(program, shading, frame_.environment));
}

ModeStatistics TiledDeferredRenderer::modeStatistics() const {
    ModeStatistics m;
    m.section = "deferred";
    const std::string format = gBufferFormatName(gBuffer_->format());
    m.values = {modeStatistic("g_buffer_format", format), modeStatistic("g_buffer_samples", gBuffer_->samples()),
                modeStatistic("g_buffer_bytes_per_pixel", gBuffer_->bytesPerPixel()),
                modeStatistic("geometry_passes", gBuffer_->geometryPasses()),
                modeStatistic("tile_size", options_.tileSize), modeStatistic("depth_bounds", depthBoundsUsed()),
                modeStatistic("loop_bound", loopBound_)};
    std::ostringstream s;
    s << "g-buffer   " << gBufferDescription(*gBuffer_) << "; " << options_.tileSize << " px tiles, depth bounds "
      << (depthBoundsUsed() ? "min/max" : "off") << ", loop bound " << loopBound_;
    m.line = s.str();
    return m;
}

}  // namespace lidr
