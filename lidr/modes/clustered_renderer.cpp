#include "lidr/modes/clustered_renderer.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <sstream>

#include "lidr/base/error.h"
#include "lidr/base/visualize.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"
#include "lidr/render/shading_pass.h"
#include "lidr/scene/sphere_bounds.h"

namespace lidr {

namespace {
const ClusteredOptions& checkedOptions(const ClusteredOptions& o) {
    if (o.occupiedClusters && !o.preZ)
        throw Error("clustered: occupied clusters come from the pre-Z depth (occupiedClusters without preZ)");
    if (o.initialLoopBound < 1 || o.initialLoopBound > 65535)
        throw Error("clustered: initial loop bound must be 1..65535, got " + std::to_string(o.initialLoopBound));
    if (o.slicing == ClusterSlicing::NearSlice && !(o.lightNear > 0.0f && o.lightNear < 1e30f))
        throw Error("clustered: the near slice's end (lightNear) must be a positive view depth, got " +
                    std::to_string(o.lightNear));
    return o;
}

// Before any GL object: the options (checkedOptions), then the context: the occupied clusters read the depth buffer
// back.
const GlInfo& checkContextFor(const GlInfo& info, const ClusteredOptions& o) {
    checkedOptions(o);
    if (o.occupiedClusters && !info.readDepthStencil)
        throw UnsupportedError("clustered: occupied clusters read the pre-Z depth back, which this context cannot "
                               "(no depth read-back: OpenGL ES 2.0 without NV_read_depth_stencil, WebGL); turn "
                               "occupiedClusters off");
    return info;
}

// Without highp fragment floats (GLSL ES 1.00's mediump: fp16 world positions) a fragment's view depth is off by
// far more than any slice margin can hold: such contexts get one slice, the 2D tile lists.
int slicesFor(const GlInfo& info, int slices) { return info.fragmentHighp ? slices : 1; }
}  // namespace

ClusteredRenderer::ClusteredRenderer(const GlInfo& info, const Scene& scene, const ClusteredOptions& options, int width,
                                     int height)
    : frame_(checkContextFor(info, options), scene, FrameSetup::of(options, scene, width, height)),
      options_(options),
      grid_(width, height, options.tileSize, slicesFor(info, options.slices)),
      gridTextures_(info, grid_.tilesX(), grid_.tilesY(), grid_.sliceCount()),
      slices_(grid_.sliceCount()) {
    buildProgram(options_.initialLoopBound, frame_.lightTable.capacity() <= 255 ? 8 : 16);
}

std::string ClusteredRenderer::programName() const {
    return "clustered-forward-" + std::to_string(frameInfo_.loopBound) + "-" + std::to_string(frameInfo_.indexBits);
}

void ClusteredRenderer::buildProgram(int loopBound, int indexBits) {
    ShaderDefines defines = frame_.lightTable.defines();
    defines.push_back({"LIDR_CLUSTER_TILE_SIZE", std::to_string(grid_.tileSize())});
    defines.push_back({"LIDR_CLUSTER_TILES_X", std::to_string(grid_.tilesX())});
    defines.push_back({"LIDR_CLUSTER_TILES_Y", std::to_string(grid_.tilesY())});
    defines.push_back({"LIDR_CLUSTER_SLICES", std::to_string(grid_.sliceCount())});
    defines.push_back({"LIDR_CLUSTER_SLICES_PER_ROW", std::to_string(gridTextures_.slicesPerRow())});
    defines.push_back({"LIDR_CLUSTER_GRID_SIZE", "vec2(" + std::to_string(gridTextures_.gridWidth()) + ".0, " +
                                                     std::to_string(gridTextures_.gridHeight()) + ".0)"});
    defines.push_back({"LIDR_CLUSTER_INDEX_BITS", std::to_string(indexBits)});
    defines.push_back({"LIDR_LIGHT_LIST_WIDTH", std::to_string(ClusterGridTextures::kListWidth)});
    defines.push_back({"LIDR_MAX_CLUSTER_LIGHTS", std::to_string(loopBound)});
    frameInfo_.loopBound = loopBound;
    frameInfo_.indexBits = indexBits;
    program_ = gl::Program::create(programName(), buildShaderSource("geometry.vert"),
                                   buildShaderSource("clustered_forward.frag", defines), geometryAttributes());
    programDefines_ = defines;
    ++frameInfo_.shaderRebuilds;
}

namespace {
// Clustered forward's own passes, between FrameResources' (passes(), render()).
constexpr FramePass kClusterOccupancy{"cluster-occupancy", "depth (read back)",
                                      "slices fitted to the surfaces, occupied clusters"};
constexpr FramePass kLightGrid{"light-grid", "lights, occupied clusters", "cluster grid (CPU, uploaded)"};
constexpr FramePass kLightGridDense{"light-grid", "lights", "cluster grid (CPU, uploaded)"};
constexpr FramePass kClusteredForward{"clustered-forward",
                                      "scene, depth, cluster grid, light table, [shadow atlas], [environment]", "colour"};
constexpr FramePass kClusteredTransparent{"clustered-transparent",
                                          "transparent meshes, depth, cluster grid, light table, [shadow atlas], "
                                          "[environment]",
                                          "colour", "transparent meshes in the scene"};
}  // namespace

std::vector<FramePass> ClusteredRenderer::passes() const {
    std::vector<FramePass> p{pass::kShadowMaps, pass::kLightTable};
    if (options_.preZ) p.push_back(pass::kDepthPrepass);
    const bool occupancy = usesOccupancy();
    if (occupancy) p.push_back(kClusterOccupancy);
    p.push_back(occupancy ? kLightGrid : kLightGridDense);
    p.push_back(kClusteredForward);
    if (options_.transparency) p.push_back(kClusteredTransparent);
    if (frame_.targets.samples() > 0) p.push_back(pass::kMsaaResolve);
    return p;
}

const FrameStats& ClusteredRenderer::render(const Camera& camera, const std::vector<PointLight>& lights,
                                            const ShadingParameters& shading) {
    const CameraMatrices cam = frame_.checkFrame(camera, lights, shading, "clustered");
    const FrameScope scope(stats_, frame_.timer, lights.size());
    frame_.prepareLights(lights, shading, stats_);  // shadow-maps, light-table
    const bool transparent = options_.transparency && frame_.scene.hasTransparent();
    if (options_.preZ) frame_.drawDepthPrepass(cam);
    ClusterSlices slicing = clusterSlices(cam, slices_, options_.slicing, options_.lightNear);
    const std::vector<uint64_t> occupied = markOccupiedClusters(cam, transparent, slicing);
    buildLightGrid(cam, lights, slicing, occupied);
    const gl::Program& program = shadeOpaque(cam, shading, slicing);
    if (transparent) shadeTransparent(cam, shading, program);
    frame_.resolve();  // msaa-resolve
    StateCache::current().unbindTextures({gl::kUnitClusterGrid, gl::kUnitClusterList});
    frame_.finishFrame(stats_, "ClusteredRenderer::render");
    lastCamera_ = cam;
    frameInfo_.slicing = slicing;
    return stats_;
}

bool ClusteredRenderer::usesOccupancy() const { return options_.occupiedClusters && frame_.targets.samples() == 0; }

std::vector<uint64_t> ClusteredRenderer::markOccupiedClusters(const CameraMatrices& cam, bool transparent,
                                                              ClusterSlices& slicing) {
    frameInfo_.occupancyUsed = usesOccupancy();
    frameInfo_.occupancyMilliseconds = 0.0;
    if (!frameInfo_.occupancyUsed) return {};
    // Olsson's occupied-cluster step, from the pre-Z depth: the slices fitted to the frame's surfaces, then the
    // clusters that hold one.
    TimedPass occupancyTime(frame_.timer, kClusterOccupancy.name);
    const double start = nowMilliseconds();
    readPackedDepth();
    slicing = slicesOverSurfaces(cam, slicing);
    std::vector<uint64_t> occupied = grid_.markOccupiedSlicesPacked(packedDepth_, cam, slicing, transparent);
    frameInfo_.occupancyMilliseconds = nowMilliseconds() - start;
    return occupied;
}

void ClusteredRenderer::readPackedDepth() {
    const int w = frame_.targets.width(), h = frame_.targets.height();
    packedDepth_.resize(size_t(w) * size_t(h));
    frame_.targets.bindColor();
    // The packed depth-stencil as it is stored (GL_UNSIGNED_INT_24_8; what LIDR's volume tiles read): the
    // depth in the top 24 bits, compared in 24-bit steps without a conversion to float.
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, w, h, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packedDepth_.data());
    checkGl("clustered: depth read-back");
}

ClusterSlices ClusteredRenderer::slicesOverSurfaces(const CameraMatrices& cam, const ClusterSlices& camera) const {
    uint32_t nearest = 0xFFFFFFu, farthest = 0u;  // of the surfaces (24-bit depths below the cleared 1.0)
    for (const uint32_t word : packedDepth_) {
        const uint32_t d = word >> 8;
        if (d < 0xFFFFFFu) nearest = std::min(nearest, d), farthest = std::max(farthest, d);
    }
    if (!(nearest <= farthest && slices_ > 1)) return camera;  // no surface, or one slice: the camera's range
    // The slices span the frame's surfaces (widened by a depth step each way): thinner where they are.
    constexpr double kScale = 1.0 / 16777215.0;
    return clusterSlices(cam, slices_, options_.slicing, options_.lightNear,
                         viewDepthFromWindowDepth(cam, float(double(nearest - std::min(nearest, 1u)) * kScale)),
                         viewDepthFromWindowDepth(cam, float(double(std::min(farthest + 1, 0xFFFFFEu)) * kScale)));
}

void ClusteredRenderer::buildLightGrid(const CameraMatrices& cam, const std::vector<PointLight>& lights,
                                       const ClusterSlices& slicing, const std::vector<uint64_t>& occupied) {
    TimedPass lightGridTime(frame_.timer, kLightGrid.name);
    const double assignStart = nowMilliseconds();
    grid_.build(cam, lights, slicing, frameInfo_.occupancyUsed ? &occupied : nullptr, frame_.lightTable.reachError());
    gridTextures_.upload(grid_);
    const ClusterGridStats& gs = grid_.stats();
    if (gs.maxLights > frameInfo_.loopBound || grid_.indexBits() != frameInfo_.indexBits) {
        // A list outgrew the loop (recompile with room for it, the next power of two) or the index width changed.
        int bound = frameInfo_.loopBound;
        while (bound < gs.maxLights) bound *= 2;
        buildProgram(std::min(bound, 65535), grid_.indexBits());
    }
    stats_.drawnLights = gs.assignedLights;
    frameInfo_.grid = gs;
    frameInfo_.assignMilliseconds = nowMilliseconds() - assignStart;
    frameInfo_.listTextureRows = gridTextures_.listRows();
}

const gl::Program& ClusteredRenderer::shadeOpaque(const CameraMatrices& cam, const ShadingParameters& shading,
                                                  const ClusterSlices& slicing) {
    TimedPass forwardTime(frame_.timer, kClusteredForward.name);
    beginOpaqueShading(frame_.targets, shading, options_.preZ);
    // Shadows: the same shading with the lookups compiled in (shadow_lookup.glsl), as the reference does.
    const gl::Program& program =
        frame_.shadows.shadingProgram(program_, "clustered_forward.frag", programDefines_, shading.shadows);
    useShadingProgram(program, cam, shading, frame_.lightTable, frame_.environment);
    frame_.shadows.bind(program, shading.shadows);
    gridTextures_.bind(program);
    if (slices_ > 1) {
        program.set("uClusterDepthAxis", glm::vec4(cam.forward, -glm::dot(cam.forward, cam.eye)));
        program.set("uClusterSlicing", glm::vec2(slicing.scale, slicing.bias));
    }
    frame_.scene.draw(program, DrawFilter::Opaque, true, &cam, shadingVariantKey(program, shading, frame_.environment));
    return program;
}

void ClusteredRenderer::shadeTransparent(const CameraMatrices& cam, const ShadingParameters& shading,
                                         const gl::Program& program) {
    // Each transparent fragment finds its own cluster by its own depth.
    TimedPass transparentTime(frame_.timer, kClusteredTransparent.name);
    beginTransparentShading();  // back to front over the opaque depth, no depth writes
    frame_.scene.drawTransparentSorted(program, cam.eye, shadingVariantKey(program, shading, frame_.environment));
}

std::vector<int> ClusteredRenderer::pixelSlices() const {
    if (frame_.targets.samples() > 0) throw Error("clustered: pixelSlices() reads single-sample depth; this frame had MSAA");
    const int w = frame_.targets.width(), h = frame_.targets.height();
    if (frameInfo_.shaderRebuilds == 0 || lastCamera_.width != w) throw Error("clustered: pixelSlices() before a frame");
    const SavedGlState callerState;
    StateCache& cache = StateCache::current();
    if (!sliceProgram_) {
        ShaderDefines defines = programDefines_;
        defines.push_back({"LIDR_CLUSTER_SLICE_OUTPUT", "1"});
        sliceProgram_ = gl::Program::create("clustered-slices", buildShaderSource("geometry.vert"),
                                            buildShaderSource("clustered_forward.frag", defines), geometryAttributes());
        sliceTexture_ = gl::Texture::create2D(GL_RGBA8, w, h, GL_RGBA, GL_UNSIGNED_BYTE);
        sliceFbo_ = gl::Framebuffer::create();
        sliceFbo_.attachTexture(GL_COLOR_ATTACHMENT0, sliceTexture_);
        sliceFbo_.attachDepthStencil(frame_.targets.depthStencil(), frame_.targets.separateStencil());
        sliceFbo_.checkComplete("clustered slices");
    }
    ClearAction clear;
    clear.color = true;
    clear.colorValue = glm::vec4(1.0f);  // 255: no surface
    cache.beginPass({sliceFbo_.id(), glm::ivec4(0, 0, w, h), {GL_COLOR_ATTACHMENT0}, clear});
    RenderState s;
    s.depthTest = true;
    s.depthFunc = GL_EQUAL;  // the frame's opaque depth: the fragments the shading pass kept
    s.depthWrite = false;
    cache.apply(s);
    const ShadingParameters shading;
    sliceProgram_.use();
    setShadingUniforms(sliceProgram_, lastCamera_, shading, frame_.environment);
    sliceProgram_.set("uViewProj", lastCamera_.viewProjection);
    if (slices_ > 1) {
        sliceProgram_.set("uClusterDepthAxis", glm::vec4(lastCamera_.forward, -glm::dot(lastCamera_.forward, lastCamera_.eye)));
        sliceProgram_.set("uClusterSlicing", glm::vec2(frameInfo_.slicing.scale, frameInfo_.slicing.bias));
    }
    frame_.scene.draw(sliceProgram_, DrawFilter::Opaque, true, &lastCamera_);
    cache.apply(RenderState{});
    const ImageRGBA8 image = readPixelsRGBA8(w, h);
    cache.bindFramebuffer(0);
    checkGl("ClusteredRenderer::pixelSlices");
    std::vector<int> slices(size_t(w) * size_t(h), -1);
    for (size_t p = 0; p < slices.size(); ++p) {
        const int v = image.pixels[p * 4];
        slices[p] = v == 255 ? -1 : v;
    }
    return slices;
}

std::vector<int> ClusteredRenderer::pixelClusters() const {
    const int w = frame_.targets.width(), h = frame_.targets.height();
    std::vector<int> clusters = pixelSlices();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            int& c = clusters[size_t(y) * size_t(w) + size_t(x)];
            if (c >= 0) c = grid_.clusterOf(grid_.tileOf(x, h - 1 - y), c);
        }
    return clusters;
}

ImageRGBA8 ClusteredRenderer::clusterHeatMap(int budget) const {
    const int w = frame_.targets.width(), h = frame_.targets.height();
    std::vector<int> perPixel(size_t(w) * size_t(h), 0);
    std::vector<int> clusters;
    if (frame_.targets.samples() == 0 && frameInfo_.shaderRebuilds > 0) clusters = pixelClusters();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t p = size_t(y) * size_t(w) + size_t(x);
            const int c = clusters.empty() || clusters[p] < 0 ? grid_.clusterOf(grid_.tileOf(x, h - 1 - y), 0) : clusters[p];
            perPixel[p] = grid_.counts()[size_t(c)];
        }
    return overlapHeatMap(w, h, perPixel, budget);
}

ModeStatistics ClusteredRenderer::modeStatistics() const {
    const ClusteredFrameInfo& f = frameInfo_;
    const ClusteredOptions& co = options_;
    ModeStatistics m;
    m.section = "clustered";
    m.values = {modeStatistic("tile_size", co.tileSize), modeStatistic("tiles_x", grid().tilesX()),
                modeStatistic("tiles_y", grid().tilesY()), modeStatistic("slices", f.slicing.count),
                modeStatistic("slicing", std::string(clusterSlicingName(co.slicing))),
                modeStatistic("occupancy", f.occupancyUsed), modeStatistic("msaa_samples", targets().samples()),
                modeStatistic("clusters", grid().clusterCount()),
                modeStatistic("active_clusters", f.grid.activeClusters),
                modeStatistic("listed_clusters", f.grid.listedClusters),
                modeStatistic("max_cluster_lights", f.grid.maxLights), modeStatistic("entries", f.grid.entries),
                modeStatistic("cell_tests", f.grid.cellTests), modeStatistic("index_bits", f.indexBits),
                modeStatistic("loop_bound", f.loopBound), modeStatistic("list_texture_rows", f.listTextureRows),
                modeStatistic("grid_bytes", gridBytes()), modeStatistic("list_bytes", listBytes()),
                modeStatistic("light_table_bytes", frame().lightTable.bytes()),
                modeStatistic("cpu_assign_ms_last_frame", f.assignMilliseconds),
                modeStatistic("cpu_occupancy_ms_last_frame", f.occupancyMilliseconds)};
    std::ostringstream s;
    s << "clustered  " << co.tileSize << " px tiles (" << grid().tilesX() << "x" << grid().tilesY() << ") x "
      << f.slicing.count << " " << clusterSlicingName(co.slicing) << " slices, occupancy "
      << (f.occupancyUsed ? "on" : "off") << ", longest list " << f.grid.maxLights << ", " << f.grid.entries
      << " entries in " << f.grid.listedClusters << " clusters, " << f.indexBits << "-bit indices, CPU assignment "
      << f.assignMilliseconds << " ms"
      << (f.occupancyUsed ? ", occupancy " + std::to_string(f.occupancyMilliseconds) + " ms" : std::string());
    m.line = s.str();
    return m;
}

}  // namespace lidr
