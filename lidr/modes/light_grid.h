#pragma once
// The tiled-forward light grid (Olsson & Assarsson 2011, section 6.2; Billeter et al. 2013, section 4.4):
// the screen in fixed T x T pixel tiles, each with a list of the lights whose sphere may touch a pixel of it.
// LightGrid builds the lists on the CPU; LightGridTextures holds them in GL 2.1-class textures for the
// fragment shader (shaders/modes/tiled_grid.glsl reads them; doc/tiled.md has the layout).
//
// Layout: one flat index list, entry 0 is the null light 0 (the shared empty list). Every non-empty tile
// list is its light indices (ascending) followed by a 0 terminator, so the shader needs only the list's
// offset per tile. Opaque lists come first, then the transparent ones.
#include <cstdint>
#include <vector>

#include "lidr/modes/light_list_texture.h"
#include "lidr/scene/camera.h"
#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/scene/scene.h"

namespace lidr {

// A tile's depth range from the pre-Z pass: window depths in [0, 1]. A tile without geometry has
// minDepth = maxDepth = 1 (the cleared depth).
struct TileDepthRange {
    float minDepth = 0.0f;
    float maxDepth = 1.0f;
    // Half-Z: with `split`, the tile's depths all lie in [minDepth, nearMaxDepth] or [farMinDepth, maxDepth]
    // (the range split at its middle, each half shrunk to its depths), and opaque lists keep only lights that
    // reach one of the two.
    bool split = false;
    float nearMaxDepth = 1.0f;
    float farMinDepth = 0.0f;
};

// A spot light's cone in view space, for the tile and cluster tests: apex, unit axis, range, and the cone's half
// angle widened to spotBoundingConeAngle (sphere_bounds.h: covers the fixed-point light table's 16-bit cosines).
struct ViewCone {
    glm::vec3 apex, axis;
    float range, cosAngle, sinAngle;
};
ViewCone viewCone(const CameraMatrices& camera, const PointLight& light, float range);
// Whether the cone may reach into the sphere (centre, radius): false only where the sphere lies wholly outside
// the cone's side, beyond its range or behind its apex (the cone-sphere test of Wronski, "Cull that cone", 2016).
bool coneMayReachSphere(const ViewCone& cone, const glm::vec3& centre, float radius);

struct LightGridStats {
    int maxOpaqueLights = 0;       // longest opaque tile list
    int maxTransparentLights = 0;  // longest transparent tile list
    long opaqueEntries = 0;        // sum of opaque list lengths
    long transparentEntries = 0;
    int assignedLights = 0;        // lights in at least one list
};

class LightGrid {
public:
    // Throws lidr::Error for a tile size below 1 or larger than the screen (in either direction).
    LightGrid(int width, int height, int tileSize);

    // Assigns `lights` (light i has index i + 1) to tiles from their clipped, projected sphere bounds
    // (lidr/scene/sphere_bounds.h). With `depth` (one range per tile, tile (x, y) at y * tilesX() + x, rows from
    // the bottom as GL windows count them) lights are pruned in depth: a transparent list keeps lights that
    // reach in front of the tile's opaque maximum depth (the near plane to the opaque max), an opaque list
    // also drops lights wholly in front of the tile's minimum. `radiusMargin` widens every sphere (world
    // units; covers a light table that quantises positions and radii). Without `depth`, or without
    // `transparentLists`, the transparent lists are the opaque ones.
    void build(const CameraMatrices& camera, const std::vector<PointLight>& lights,
               const std::vector<TileDepthRange>* depth, bool transparentLists, float radiusMargin = 0.0f);

    int tileSize() const { return tileSize_; }
    int tilesX() const { return tilesX_; }
    int tilesY() const { return tilesY_; }
    int tileCount() const { return tilesX_ * tilesY_; }
    // The tile of a pixel, GL window coordinates (y up).
    int tileOf(int x, int yFromBottom) const { return (yFromBottom / tileSize_) * tilesX_ + x / tileSize_; }

    const std::vector<uint32_t>& entries() const { return entries_; }
    const std::vector<uint32_t>& opaqueOffsets() const { return opaqueOffset_; }
    const std::vector<uint32_t>& transparentOffsets() const { return transparentOffset_; }
    const std::vector<int>& opaqueCounts() const { return opaqueCount_; }
    const std::vector<int>& transparentCounts() const { return transparentCount_; }
    std::vector<uint32_t> opaqueList(int tile) const;
    std::vector<uint32_t> transparentList(int tile) const;
    const LightGridStats& stats() const { return stats_; }

private:
    // The per-tile lists laid end to end in entries_ (each ended by 0), offsets and counts per tile; without
    // `transparent` the transparent lists are the opaque ones.
    void layOut(const std::vector<std::vector<uint32_t>>& opaque, const std::vector<std::vector<uint32_t>>* transparent);

    int width_, height_, tileSize_, tilesX_, tilesY_;
    std::vector<uint32_t> entries_, opaqueOffset_, transparentOffset_;
    std::vector<int> opaqueCount_, transparentCount_;
    LightGridStats stats_;
};

// The grid on the GPU. Tile grids: one RGBA8 texel per tile holding its list offset as a 24-bit integer
// (R high byte, B low byte: putListOffset), one texture for opaque and one for transparent lists. Index list: a
// LightListTexture of 16-bit light indices (LUMINANCE8_ALPHA8, L high, A low), grown as the lists grow; past what
// the driver or 24-bit offsets can address, upload() throws lidr::Error.
class LightGridTextures {
public:
    static constexpr int kListWidth = LightListTexture::kWidth;

    LightGridTextures() = default;
    LightGridTextures(const GlInfo& info, int tilesX, int tilesY);
    void upload(const LightGrid& grid);
    // Binds the grid textures and sets tiled_grid.glsl's uniforms; `transparent` picks that grid.
    void bind(const gl::Program& program, bool transparent) const;
    int listRows() const { return list_.rows(); }
    size_t bytes() const { return gridBytes() + listBytes(); }
    size_t gridBytes() const;  // the two tile grids
    size_t listBytes() const { return list_.bytes(); }  // the whole list texture, as allocated

private:
    int tilesX_ = 0, tilesY_ = 0;
    gl::Texture opaqueGrid_, transparentGrid_;
    LightListTexture list_;
};

}  // namespace lidr
