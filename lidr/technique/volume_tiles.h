#pragma once
// Where on screen a light volume can mark anything: the pre-pass depth read back once per frame and kept per
// T x T tile as the window-depth range of its surfaces and a 32-bit mask of which of 32 equal slices of that
// range hold a surface (the "2.5D" depth mask of Harada et al., 2012, here on the CPU). Each occupied slice is
// a cell of the view frustum (the tile's pixels between two depths); a light can reach a surface of the tile
// only if its sphere meets one of those cells, so lights hidden behind nearer surfaces, lights floating
// between a near pillar and a far wall, lights beside the tile in depth and empty tiles are rejected before
// any fragment (LightVolumeGeometry draws the rest as screen quads; doc/architecture.md). Conservative: each
// pixel marks the slices of its depth widened by the sphere test's margin, and a cell is the box around the
// tile's corner rays between its slice's depths.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "lidr/scene/camera.h"

namespace lidr {

// Screen regions for region-local light indices (doc/architecture.md, "Region-local indices"): a partition of
// the tiles into at most 32 rectangles. With more than 255 lights reaching the view, each region numbers only
// the lights that reach its tiles, 1..n, and keeps them in its own row of the light table, so the index targets
// hold 8-bit indices where global numbering would need 16 bits; the forward pass finds the row from the pixel's
// tile (a map kept in the light table). count == 0: off (global numbering).
struct IndexRegions {
    int count = 0;
    int tilesX = 0, tileSize = 16;
    std::vector<uint8_t> regionOfTiles;  // per tile (row-major, rows bottom to top as VolumeTiles numbers them)
    bool on() const { return count > 0; }
    int regionOfTile(int tile) const { return regionOfTiles[size_t(tile)]; }
    int regionOfPixel(int x, int y) const {  // window pixel, y up
        return regionOfTiles[size_t((y / tileSize) * tilesX + x / tileSize)];
    }
};

class VolumeTiles {
public:
    VolumeTiles() = default;
    // Throws lidr::Error for a tile size outside [4, 256] or a size below 1 pixel.
    VolumeTiles(int width, int height, int tileSize);

    // From window depths, rows bottom to top (as glReadPixels gives them), width x height, seen by `camera` (a
    // perspective projection). `margin`: each pixel's surface lies within this much window depth of its stored
    // depth (the sphere test's uDepthMargin).
    void build(const std::vector<float>& depth, float margin, const CameraMatrices& camera);
    // The same from a depth range per pixel (MSAA: the nearest and farthest of the points its samples shade,
    // DepthSpanPass::readDepthRanges; 1 in nearDepth where it has none): each pixel marks every slice of its range.
    void buildRanges(const std::vector<float>& nearDepth, const std::vector<float>& farDepth, float margin,
                     const CameraMatrices& camera);
    // Reads the bound framebuffer's depth (glReadPixels) and builds from it; packedDepthStencil: the depth is a
    // DEPTH24_STENCIL8 buffer, read as GL_UNSIGNED_INT_24_8 (every desktop context lidr runs on has packed
    // depth-stencil: its FBOs need it).
    void buildFromBoundDepth(float margin, const CameraMatrices& camera, bool packedDepthStencil);
    // The read-back alone: the bound framebuffer's window depths, rows bottom to top (valid until the next read or
    // build from the bound depth).
    const std::vector<float>& readBoundDepth(bool packedDepthStencil);

    // The occupied depth slices of `tile` (bit s: slice s) whose cell the sphere (centre in view space, radius)
    // meets, its window-depth span being [nearDepth, farDepth] (sphereDepthSpan); 0: no surface of the tile can
    // lie inside it.
    uint32_t slicesReached(int tile, const glm::vec3& viewCentre, float radius, float nearDepth, float farDepth) const;
    // The most consecutive slices one pixel's widened depth overlaps in `tile`, minus one (0: every pixel's lies in
    // one slice). The sphere test keeps a light that meets any point of that span, so the lights marking a pixel
    // are those reaching any slice of a run of sliceSpan + 1: candidateWindows turns a light's slicesReached into
    // the runs it reaches (bit s: slices s .. s + span), and the most lights reaching one run bounds every pixel's
    // count in the tile (the rank windows skip tiles by it, lidr/technique/light_volume_geometry.h).
    int sliceSpan(int tile) const { return sliceSpan_[size_t(tile)]; }
    static uint32_t candidateWindows(uint32_t reached, int span) {
        uint32_t windows = reached;
        for (int i = 1; i <= span && i < 32; ++i) windows |= reached >> i;
        return windows;
    }
    // The window-depth span of a light's sphere on this camera (clamped to [0, 1]), widened for rounding; false
    // when it lies wholly in front of the near plane.
    static bool sphereDepthSpan(const CameraMatrices& camera, const glm::vec3& centre, float radius, float& nearDepth,
                                float& farDepth);

    int tileSize() const { return tileSize_; }
    int tilesX() const { return tilesX_; }
    int tilesY() const { return tilesY_; }
    int tileCount() const { return tilesX_ * tilesY_; }
    bool empty() const { return tileSize_ == 0; }
    // A tile's surface depth range widened by the margin (min > max: no surface) and its occupied slices.
    float tileMinDepth(int tile) const { return minDepth_[size_t(tile)]; }
    float tileMaxDepth(int tile) const { return maxDepth_[size_t(tile)]; }
    uint32_t tileSlices(int tile) const { return slices_[size_t(tile)]; }

private:
    // build()'s three passes over the depth (`margin` with kDepthSlack), for the tile rows [firstRow, endRow): each
    // tile's widened depth range, the slices each pixel overlaps, each occupied slice's distances. Bands of tile
    // rows share nothing, so build() runs two of them at once.
    void buildRows(const std::vector<float>& nearDepth, const std::vector<float>& farDepth, float margin, int firstRow,
                   int endRow);
    void rangeTiles(const std::vector<float>& nearDepth, const std::vector<float>& farDepth, float margin, int firstRow,
                    int endRow);
    void markSlices(const std::vector<float>& nearDepth, const std::vector<float>& farDepth, float margin, int firstRow,
                    int endRow);
    void measureSlices(int firstRow, int endRow);

    int width_ = 0, height_ = 0, tileSize_ = 0, tilesX_ = 0, tilesY_ = 0;
    std::vector<float> minDepth_, maxDepth_;  // per tile; min > max: no surface
    std::vector<uint32_t> slices_;
    std::vector<int> sliceSpan_;  // per tile: sliceSpan()
    // Per tile and occupied slice, the slice's distance span [near, far] in front of the eye (widened as
    // slicesReached needs it): 2 x 32 floats a tile, filled once per build instead of per light and tile.
    std::vector<glm::vec2> sliceDistances_;
    // Tile boundaries as view-space slopes x / -z (columns) and y / -z (rows); window depth d -> distance in
    // front of the eye: depthToDistance.x / (d + depthToDistance.y).
    std::vector<float> slopeX_, slopeY_;
    glm::vec2 depthToDistance_{0.0f};
    std::vector<float> readback_;
    std::vector<uint32_t> packed_;
};

}  // namespace lidr
