#pragma once
// Tiled deferred shading ("tiled-deferred"; Olsson & Assarsson 2011's TiledDeferred): the G-buffer of deferred
// shading (lidr/modes/g_buffer.h) lit in one full-screen pass that loops over each tile's light list, the grid
// tiled forward builds (lidr/modes/light_grid.h, with per-tile depth bounds from the depth pre-pass:
// lidr/modes/tile_depth_bounds.h). Same scene, camera, light table and shading function as every mode.
//
// Frame: shadow maps, light table -> depth pre-pass with the packed depth copy -> tile depth ranges -> light grid
// (CPU) -> G-buffer (depth EQUAL) -> tiled-deferred, full screen: each pixel's surface from the G-buffer lit by its
// tile's list, with the ambient, environment, emission and directional terms -> transparent meshes by tiled
// forward shading from the same grid's transparent lists (Olsson's "simple" way); passes() lists them
// (lidr-demo --list-passes tiled-deferred). MSAA: the multisampled G-buffer (lidr/modes/g_buffer_multisample.h),
// the tile ranges covering every sample's surface, the full-screen pass once a sample into the MSAA target, then
// resolved; refused without multisample textures and per-sample shading (GL 2.1, ES 2.0, WebGL 1).
// On OpenGL ES 2.0 the depth bounds are left out (gl_FragCoord.z is mediump there: TiledRenderer's reason).
#include <memory>
#include <string>
#include <vector>

#include "lidr/modes/g_buffer.h"
#include "lidr/modes/g_buffer_multisample.h"
#include "lidr/modes/light_grid.h"
#include "lidr/modes/tile_depth_bounds.h"
#include "lidr/render/frame_resources.h"

namespace lidr {

struct TiledDeferredOptions {
    int tileSize = 32;         // tile edge in pixels; 1..min(width, height)
    bool depthBounds = true;   // per-tile min/max depth prunes the lists (left out on OpenGL ES 2.0)
    GBufferFormat format = GBufferFormat::Auto;  // rgba16f where the context renders to it, else rgba8
    bool transparency = true;  // transparent meshes by tiled forward shading after the opaque ones
    int msaaSamples = 0;       // 0, or 2..: the multisampled G-buffer (refused without deferredMsaaRefusal's features)
    bool forceFixedLightTable = false;
    bool forcePackedDepth = false;  // the RGBA8 packed depth reduction even with float render targets
    int initialLoopBound = 16;      // first LIDR_MAX_TILE_LIGHTS; grows (power of two) with the lists
    bool timing = false;
    TimingMethod timingMethod = TimingMethod::Auto;
};

class TiledDeferredRenderer final : public Renderer {
public:
    TiledDeferredRenderer(const GlInfo& info, const Scene& scene, const TiledDeferredOptions& options, int width,
                          int height);
    std::string modeName() const override { return "tiled-deferred"; }
    const FrameStats& render(const Camera& camera, const std::vector<PointLight>& lights,
                             const ShadingParameters& shading) override;
    const FrameResources& frame() const override { return frame_; }
    std::vector<FramePass> passes() const override;
    // The G-buffer, the grid and list textures and the depth reduction.
    size_t lightDataBytes() const override;
    // "deferred": the G-buffer's format, samples and bytes a pixel (all samples), the tile grid and its longest list.
    ModeStatistics modeStatistics() const override;
    const DeferredGBuffer& gBuffer() const { return *gBuffer_; }
    const LightGrid& grid() const { return grid_; }
    const TiledDeferredOptions& options() const { return options_; }
    bool depthBoundsUsed() const { return depthBounds_ != nullptr; }
    int loopBound() const { return loopBound_; }

private:
    void buildPrograms(int loopBound);
    void drawDepthPrepass(const CameraMatrices& cam);
    void buildLightGrid(const CameraMatrices& cam, const std::vector<PointLight>& lights, bool transparent);
    void shadeTiles(const CameraMatrices& cam, const ShadingParameters& shading);
    void shadeTransparent(const CameraMatrices& cam, const ShadingParameters& shading);

    FrameResources frame_;
    TiledDeferredOptions options_;
    std::unique_ptr<DeferredGBuffer> gBuffer_;
    std::string tiledShader_;  // the full-screen pass's fragment shader file (the multisample one under MSAA)
    LightGrid grid_;
    LightGridTextures gridTextures_;
    std::unique_ptr<TileDepthBounds> depthBounds_;
    std::vector<TileDepthRange> tileDepth_;
    gl::Program tiled_, transparent_;
    ShaderDefines defines_;
    int loopBound_ = 0;
};

}  // namespace lidr
