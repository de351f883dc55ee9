#pragma once
// Tiled forward shading ("tiled"; Olsson & Assarsson 2011, Billeter, Olsson & Assarsson 2013) on the same
// GL 2.1-class footing as LIDR: the same scene, camera, light table and shading function.
//
// Frame: light table -> pre-Z (depth plus a colour copy of depth) -> per-tile min/max depth reduced on the
// GPU and read back -> lights assigned to tiles on the CPU (clipped projected sphere bounds, pruned in depth;
// separate lists for transparent geometry, from the near plane to the opaque max) -> opaque geometry shaded
// with its tile's lights (depth EQUAL) -> transparent geometry back to front, alpha blended, lit from the
// transparent lists; passes() lists them by name (lidr-demo --list-passes tiled). doc/tiled.md describes the data
// layout and its memory.
#include <memory>
#include <string>
#include <vector>

#include "lidr/base/image.h"
#include "lidr/modes/light_grid.h"
#include "lidr/modes/tile_depth_bounds.h"
#include "lidr/render/frame_resources.h"

namespace lidr {

struct TiledOptions {
    int tileSize = 32;                 // tile edge in pixels; 1..min(width, height)
    bool preZ = true;                  // depth pre-pass, then shading with depth EQUAL (no overdraw shading)
    bool depthBounds = true;           // per-tile min/max depth from the pre-Z pass prunes lights (needs preZ)
    bool halfZ = false;                // also split each tile's depth range in two (needs depthBounds)
    bool transparency = true;          // draw transparent meshes (opacity < 1) after the opaque ones
    // MSAA samples: 0, or 2..GL_MAX_SAMPLES. Shading goes to the multisampled targets and is resolved. The
    // depth bounds then cover every sample's surface (one depth per pixel would miss samples of triangles that
    // cover no pixel centre): the MSAA depth spans of LIDR's sphere-span test (DepthSpanPass), reduced per tile;
    // without float colour buffers 2D lists only, and no half-Z. frameInfo().depthBoundsUsed says which.
    int msaaSamples = 0;
    bool forceFixedLightTable = false; // the RGBA8 fixed-point light table even with float textures
    bool forcePackedDepth = false;     // the RGBA8 packed depth reduction even with float render targets
    int initialLoopBound = 16;         // first LIDR_MAX_TILE_LIGHTS; grows (power of two) with the lists
    bool timing = false;  // as LidrOptions::timing
    TimingMethod timingMethod = TimingMethod::Auto;
};

struct TiledFrameInfo {
    LightGridStats grid;
    int loopBound = 0;          // LIDR_MAX_TILE_LIGHTS the frame's shader ran with (>= every list's length)
    int shaderRebuilds = 0;     // times the loop bound grew, since construction
    int listTextureRows = 0;    // rows of the index list texture (it grows too)
    bool depthBoundsUsed = false;   // false without depthBounds, and under MSAA without float colour buffers
    double assignMilliseconds = 0.0;  // CPU time of the light assignment and grid upload (GPU timer queries
                                      // do not see CPU work)
};

class TiledRenderer final : public Renderer {
public:
    // Checks everything before any drawing: FBOs, resolution, tile size (lidr::Error for < 1 or larger than
    // the screen), depthBounds without preZ (lidr::Error).
    TiledRenderer(const GlInfo& info, const Scene& scene, const TiledOptions& options, int width, int height);

    std::string modeName() const override { return "tiled"; }
    // Light i has index i + 1; at most 65535 lights (the light table grows to hold them).
    const FrameStats& render(const Camera& camera, const std::vector<PointLight>& lights,
                             const ShadingParameters& shading) override;
    size_t lightDataBytes() const override;
    ModeStatistics modeStatistics() const override;  // "tiled": the grid and its lists
    const FrameResources& frame() const override { return frame_; }

    const TiledOptions& options() const { return options_; }
    const LightGrid& grid() const { return grid_; }               // the last frame's tile lists
    const TiledFrameInfo& frameInfo() const { return frameInfo_; }
    const std::vector<TileDepthRange>& tileDepth() const { return tileDepth_; }  // empty without depth bounds
    DepthReductionFormat depthFormat() const;  // of the reduction (meaningful with depthBounds)
    size_t depthReductionBytes() const { return depthBounds_ ? depthBounds_->bytes() : 0; }
    size_t gridBytes() const { return gridTextures_.gridBytes(); }
    size_t listBytes() const { return gridTextures_.listBytes(); }

    // Lights per tile as an image (width x height, rows top to bottom), coloured like overlapHeatMap:
    // blue -> yellow up to `budget`, red past it; `transparent` shows the transparent lists.
    ImageRGBA8 tileHeatMap(int budget = 16, bool transparent = false) const;

    std::vector<FramePass> passes() const override;

private:
    void buildProgram(int loopBound);
    // The passes of render(), in its order (passes() says what each reads and writes).
    void drawDepthPrepass(const CameraMatrices& cam);
    void reduceTileDepth();
    void buildLightGrid(const CameraMatrices& cam, const std::vector<PointLight>& lights, bool transparent);
    const gl::Program& shadeOpaque(const CameraMatrices& cam, const ShadingParameters& shading);
    void shadeTransparent(const CameraMatrices& cam, const ShadingParameters& shading, const gl::Program& program);

    FrameResources frame_;  // first: the options and the context are checked before any GL object
    TiledOptions options_;
    LightGrid grid_;
    LightGridTextures gridTextures_;
    std::unique_ptr<TileDepthBounds> depthBounds_;
    gl::Program program_;
    ShaderDefines programDefines_;  // program_'s, for its shadowed twin (ShadowMaps::program)
    std::vector<TileDepthRange> tileDepth_;
    TiledFrameInfo frameInfo_;
};

}  // namespace lidr
