#pragma once
// Tiled forward's pre-Z pass with per-tile min/max depth, reduced on the GPU in fragment shaders and read
// back for the CPU light assignment (Billeter et al. 2013, section 4.4; Olsson & Assarsson 2011, 6.3).
//
// The pre-Z pass fills the frame's depth-stencil buffer as usual and also writes each fragment's window depth
// into a colour texture (GL 2.1 cannot sample a packed depth-stencil renderbuffer). Two fragment-shader
// passes reduce it: W x H -> tilesX x H (min/max over T texels along x), then -> tilesX x tilesY (along y).
// The tilesX x tilesY result is read back: one TileDepthRange per tile, rows from the bottom. Half-Z (optional)
// adds two passes that split each tile's range at its middle and shrink both halves to their depths.
//
// Formats: the full-size depth copy is always RGBA8 with depth packed as a 24-bit integer in RGB (4 bytes a
// pixel, exact). The reduced textures are RGBA32F (R = min, G = max) where ARB_texture_float exists and the
// driver renders to it; otherwise packed RGBA8 too, with the min and the max reduced in two chains (no float
// render targets and no multiple render targets needed). shaders/modes/depth_pack.glsl has the encoding.
#include <vector>

#include "lidr/scene/camera.h"
#include "lidr/gl/gl_info.h"
#include "lidr/gl/full_screen_triangle.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/render/gpu_scene.h"
#include "lidr/modes/light_grid.h"
#include "lidr/technique/depth_span_pass.h"

#include <memory>

namespace lidr {

enum class DepthReductionFormat { Float32, PackedRGBA8 };
const char* depthReductionFormatName(DepthReductionFormat f);

class TileDepthBounds {
public:
    // `depthStencil` is the frame's depth-stencil buffer (width x height), filled by prepass().
    // `halfZ`: also split each tile's range at its middle (two more passes, tile_depth_split.frag), so the
    // ranges come back with `split` set.
    // `msaa` (MSAA targets, else nullptr): each tile's range also covers the surfaces its pixels' samples shade
    // (DepthSpanPass, drawn by samples()); float reduction only (UnsupportedError where the context has none or no
    // half-float colour buffers), without half-Z.
    TileDepthBounds(const GlInfo& info, int width, int height, int tileSize, const gl::Renderbuffer& depthStencil,
                    bool forcePacked = false, bool halfZ = false, const RenderTargets* msaa = nullptr);
    // Clears depth, stencil and the depth copy, then draws the scene's opaque geometry.
    void prepass(const GpuScene& scene, const CameraMatrices& camera) const;
    // MSAA, after prepass(): the MSAA pre-pass into the targets' multisampled depth, with the samples' depth spans.
    void samples(const GpuScene& scene, const CameraMatrices& camera) const;
    bool coversSamples() const { return spans_ != nullptr; }
    // Reduces the depth copy to one (min, max) per tile on the GPU and reads the result back.
    std::vector<TileDepthRange> reduce() const;
    DepthReductionFormat format() const { return format_; }
    int tilesX() const { return tilesX_; }
    int tilesY() const { return tilesY_; }
    size_t bytes() const;

private:
    struct Chain {  // one reduction: the intermediate and the final texture, each with its FBO
        gl::Texture columns, tiles;
        gl::Framebuffer columnsFbo, tilesFbo;
    };
    void createTargets(const gl::Renderbuffer& depthStencil);
    Chain makeChain() const;
    void runPass(const gl::Program& program, const gl::Texture& input, const gl::Framebuffer& output, int outW,
                 int outH) const;
    std::vector<float> readChain(const Chain& chain, int component) const;  // one value per tile, [0, 1]

    DepthReductionFormat format_;
    int width_, height_, tilesX_, tilesY_;
    gl::Texture depthCopy_;
    gl::Framebuffer prepassFbo_;
    std::vector<Chain> chains_;  // float: one (min and max together); packed: min, then max
    std::vector<Chain> splitChains_;  // half-Z. float: one (far min, near max); packed: far min, then near max
    gl::Program prepassProgram_;
    std::vector<gl::Program> horizontal_, vertical_;  // per chain
    std::vector<gl::Program> splitHorizontal_, splitVertical_;  // per split chain
    bool halfZ_ = false;
    std::unique_ptr<DepthSpanPass> spans_;  // MSAA
    FullScreenTriangle triangle_;
};

}  // namespace lidr
