#include "lidr/modes/tiled_renderer.h"
#include "lidr/base/gl.h"
#include "lidr/gl/saved_gl_state.h"

#include <algorithm>
#include <sstream>

#include "lidr/base/error.h"
#include "lidr/render/shading_pass.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"
#include "lidr/scene/sphere_bounds.h"
#include "lidr/base/visualize.h"

namespace lidr {

namespace {
void checkOptions(const TiledOptions& o) {
    if (o.depthBounds && !o.preZ)
        throw Error("tiled: per-tile depth bounds need the pre-Z pass (depthBounds without preZ)");
    if (o.halfZ && !o.depthBounds)
        throw Error("tiled: half-Z splits the per-tile depth bounds (halfZ without depthBounds)");
    if (o.initialLoopBound < 1 || o.initialLoopBound > 65535)
        throw Error("tiled: initial loop bound must be 1..65535, got " + std::to_string(o.initialLoopBound));
}

// Before any GL object: the options (checkOptions), then the context: per-tile depth bounds write
// gl_FragCoord.z into colour, and GLSL ES 1.00 declares gl_FragCoord mediump (Mesa's ES 2.0 then gives depth to
// about 11 bits: bounds that miss the surface).
const GlInfo& checkedContext(const GlInfo& info, const TiledOptions& o) {
    checkOptions(o);
    if (info.gles && o.depthBounds && o.msaaSamples == 0)
        throw UnsupportedError("tiled depth bounds read gl_FragCoord.z, which OpenGL ES 2.0 (GLSL ES 1.00) gives only "
                               "at mediump: use --no-depth-bounds on ES");
    return info;
}

}  // namespace

TiledRenderer::TiledRenderer(const GlInfo& info, const Scene& scene, const TiledOptions& options, int width,
                             int height)
    : frame_(checkedContext(info, options), scene, FrameSetup::of(options, scene, width, height)),
      options_(options),
      grid_(width, height, options.tileSize),
      gridTextures_(info, grid_.tilesX(), grid_.tilesY()) {
    if (options_.depthBounds) {
        try {
            depthBounds_ = std::make_unique<TileDepthBounds>(info, width, height, options_.tileSize,
                                                             frame_.targets.depthStencil(), options_.forcePackedDepth,
                                                             options_.halfZ,
                                                             options_.msaaSamples > 0 ? &frame_.targets : nullptr);
        } catch (const UnsupportedError&) {
            if (options_.msaaSamples == 0) throw;  // MSAA without float targets: 2D lists (depthBoundsUsed false)
        }
    }
    buildProgram(options_.initialLoopBound);
    frameInfo_.shaderRebuilds = 0;
}

DepthReductionFormat TiledRenderer::depthFormat() const {
    return depthBounds_ ? depthBounds_->format() : DepthReductionFormat::Float32;
}

size_t TiledRenderer::lightDataBytes() const {
    return gridTextures_.bytes() + depthReductionBytes();
}

void TiledRenderer::buildProgram(int loopBound) {
    ShaderDefines defines = frame_.lightTable.defines();
    defines.push_back({"LIDR_TILE_SIZE", std::to_string(options_.tileSize)});
    defines.push_back({"LIDR_LIGHT_LIST_WIDTH", std::to_string(LightGridTextures::kListWidth)});
    defines.push_back({"LIDR_MAX_TILE_LIGHTS", std::to_string(loopBound)});
    program_ = gl::Program::create("tiled-forward-" + std::to_string(loopBound), buildShaderSource("geometry.vert"),
                                   buildShaderSource("tiled_forward.frag", defines), geometryAttributes());
    programDefines_ = defines;
    frameInfo_.loopBound = loopBound;
    ++frameInfo_.shaderRebuilds;
}

namespace {
// Tiled forward's own passes, between FrameResources' (passes(), render()).
constexpr FramePass kDepthPrepassWithCopy{"depth-prepass", "scene", "depth, packed depth copy"};
constexpr FramePass kNoDepthPrepass{"depth-prepass", "-", "nothing (TiledOptions::preZ false)"};
constexpr FramePass kTileDepthReduce{"tile-depth-reduce", "packed depth copy", "tile depth ranges (read back)"};
constexpr FramePass kLightGrid{"light-grid", "lights, tile depth ranges", "light grid (CPU, uploaded)"};
constexpr FramePass kLightGrid2D{"light-grid", "lights", "light grid (CPU, uploaded)"};
constexpr FramePass kTiledForward{"tiled-forward",
                                  "scene, depth, light grid, light table, [shadow atlas], [environment]", "colour"};
constexpr FramePass kTiledTransparent{"tiled-transparent",
                                      "transparent meshes, depth, transparent lists, light table, [shadow atlas], "
                                      "[environment]",
                                      "colour", "transparent meshes in the scene"};

}  // namespace

std::vector<FramePass> TiledRenderer::passes() const {
    std::vector<FramePass> p{pass::kShadowMaps, pass::kLightTable};
    p.push_back(depthBounds_ ? kDepthPrepassWithCopy : options_.preZ ? pass::kDepthPrepass : kNoDepthPrepass);
    if (depthBounds_) p.push_back(kTileDepthReduce);
    p.push_back(depthBounds_ ? kLightGrid : kLightGrid2D);
    p.push_back(kTiledForward);
    if (options_.transparency) p.push_back(kTiledTransparent);
    if (frame_.targets.samples() > 0) p.push_back(pass::kMsaaResolve);
    return p;
}

const FrameStats& TiledRenderer::render(const Camera& camera, const std::vector<PointLight>& lights,
                                        const ShadingParameters& shading) {
    const CameraMatrices cam = frame_.checkFrame(camera, lights, shading, "tiled");
    const FrameScope scope(stats_, frame_.timer, lights.size());
    frame_.prepareLights(lights, shading, stats_);  // shadow-maps, light-table
    const bool transparent = options_.transparency && frame_.scene.hasTransparent();
    drawDepthPrepass(cam);
    reduceTileDepth();
    buildLightGrid(cam, lights, transparent);
    const gl::Program& program = shadeOpaque(cam, shading);
    if (transparent) shadeTransparent(cam, shading, program);
    frame_.resolve();  // msaa-resolve
    StateCache::current().unbindTextures({gl::kUnitTileGrid, gl::kUnitTileList});
    frame_.finishFrame(stats_, "TiledRenderer::render");
    return stats_;
}

void TiledRenderer::drawDepthPrepass(const CameraMatrices& cam) {
    // With depth bounds the pre-pass also writes the packed depth copy the reduction reads.
    TimedPass depthPrepassTime(frame_.timer, pass::kDepthPrepass.name);
    if (depthBounds_) {
        depthBounds_->prepass(frame_.scene, cam);
        if (!depthBounds_->coversSamples()) return;
        depthBounds_->samples(frame_.scene, cam);  // MSAA: the samples' depth, with the depths they shade
    } else if (options_.preZ) {
        frame_.targets.bindColor();
        frame_.depthPrepass.run(frame_.scene, cam);
    }
}

void TiledRenderer::reduceTileDepth() {
    tileDepth_.clear();
    if (!depthBounds_) return;
    TimedPass tileDepthReduceTime(frame_.timer, kTileDepthReduce.name);
    tileDepth_ = depthBounds_->reduce();
}

void TiledRenderer::buildLightGrid(const CameraMatrices& cam, const std::vector<PointLight>& lights, bool transparent) {
    TimedPass lightGridTime(frame_.timer, kLightGrid.name);
    const double assignStart = nowMilliseconds();
    const float reach = frame_.lightTable.reachError();
    grid_.build(cam, lights, depthBounds_ ? &tileDepth_ : nullptr, transparent, reach);
    gridTextures_.upload(grid_);
    const LightGridStats& gs = grid_.stats();
    const int longest = std::max(gs.maxOpaqueLights, transparent ? gs.maxTransparentLights : 0);
    if (longest > frameInfo_.loopBound) {  // a list outgrew the loop: recompile with room for it
        int bound = frameInfo_.loopBound;
        while (bound < longest) bound *= 2;
        buildProgram(std::min(bound, 65535));
    }
    stats_.drawnLights = gs.assignedLights;
    frameInfo_.grid = gs;
    frameInfo_.assignMilliseconds = nowMilliseconds() - assignStart;
    frameInfo_.listTextureRows = gridTextures_.listRows();
    frameInfo_.depthBoundsUsed = depthBounds_ != nullptr;
}

const gl::Program& TiledRenderer::shadeOpaque(const CameraMatrices& cam, const ShadingParameters& shading) {
    TimedPass tiledForwardTime(frame_.timer, kTiledForward.name);
    beginOpaqueShading(frame_.targets, shading, options_.preZ);
    // Shadows: the same shading with the lookups compiled in (shadow_lookup.glsl), as the reference does.
    const gl::Program& program =
        frame_.shadows.shadingProgram(program_, "tiled_forward.frag", programDefines_, shading.shadows);
    useShadingProgram(program, cam, shading, frame_.lightTable, frame_.environment);
    frame_.shadows.bind(program, shading.shadows);
    gridTextures_.bind(program, false);
    frame_.scene.draw(program, DrawFilter::Opaque, true, &cam, shadingVariantKey(program, shading, frame_.environment));
    return program;
}

void TiledRenderer::shadeTransparent(const CameraMatrices& cam, const ShadingParameters& shading,
                                     const gl::Program& program) {
    TimedPass tiledTransparentTime(frame_.timer, kTiledTransparent.name);
    beginTransparentShading();  // back to front over the opaque depth, no depth writes
    gridTextures_.bind(program, true);
    frame_.scene.drawTransparentSorted(program, cam.eye, shadingVariantKey(program, shading, frame_.environment));
}

ImageRGBA8 TiledRenderer::tileHeatMap(int budget, bool transparent) const {
    const int w = frame_.targets.width(), h = frame_.targets.height();
    const std::vector<int>& counts = transparent ? grid_.transparentCounts() : grid_.opaqueCounts();
    std::vector<int> perPixel(size_t(w) * h, 0);
    if (!counts.empty())
        for (int y = 0; y < h; ++y)  // image rows top to bottom, tiles counted from the bottom
            for (int x = 0; x < w; ++x) perPixel[size_t(y) * w + x] = counts[grid_.tileOf(x, h - 1 - y)];
    return overlapHeatMap(w, h, perPixel, budget);
}

ModeStatistics TiledRenderer::modeStatistics() const {
    const LightGridStats& g = frameInfo_.grid;
    ModeStatistics m;
    m.section = "tiled";
    m.values = {modeStatistic("tile_size", options_.tileSize), modeStatistic("tiles_x", grid().tilesX()),
                modeStatistic("tiles_y", grid().tilesY()), modeStatistic("depth_bounds", frameInfo_.depthBoundsUsed),
                modeStatistic("half_z", options_.halfZ), modeStatistic("msaa_samples", targets().samples()),
                modeStatistic("depth_format", std::string(depthReductionFormatName(depthFormat()))),
                modeStatistic("max_opaque_lights", g.maxOpaqueLights),
                modeStatistic("max_transparent_lights", g.maxTransparentLights),
                modeStatistic("opaque_entries", g.opaqueEntries),
                modeStatistic("transparent_entries", g.transparentEntries),
                modeStatistic("loop_bound", frameInfo_.loopBound),
                modeStatistic("list_texture_rows", frameInfo_.listTextureRows), modeStatistic("grid_bytes", gridBytes()),
                modeStatistic("list_bytes", listBytes()), modeStatistic("depth_reduction_bytes", depthReductionBytes()),
                modeStatistic("light_table_bytes", frame().lightTable.bytes()),
                modeStatistic("cpu_assign_ms_last_frame", frameInfo_.assignMilliseconds)};
    std::ostringstream s;
    s << "tiled      " << options_.tileSize << " px tiles (" << grid().tilesX() << "x" << grid().tilesY()
      << "), depth bounds " << (frameInfo_.depthBoundsUsed ? (options_.halfZ ? "half-Z" : "min/max") : "off")
      << ", longest list " << g.maxOpaqueLights << " (transparent " << g.maxTransparentLights << "), "
      << g.opaqueEntries << " entries, CPU assignment " << frameInfo_.assignMilliseconds << " ms";
    m.line = s.str();
    return m;
}

}  // namespace lidr
