#pragma once
// Clustered forward's light grid (Olsson, Billeter & Assarsson 2012, "Clustered Deferred and Forward Shading";
// the dense CPU-built grid of Doom 2016 and Filament's froxels): the view frustum cut into clusters, T x T pixel
// screen tiles times S slices of view depth, exponentially spaced, each cluster with the list of the lights whose
// sphere (and, for a spot light, cone) may reach into its cell. ClusterGrid builds the lists on the CPU;
// ClusterGridTextures holds them in GL 2.1 / ES 2.0 / WebGL 1-class textures for the fragment shader
// (shaders/modes/cluster_grid.glsl reads them; doc/clustered.md has the layout and its memory).
//
// Layout: as the tiled grid's (light_grid.h): one flat index list whose entry 0 is the null light 0 (the shared
// empty list), every non-empty cluster list its light indices (ascending) and a 0 terminator; one 24-bit offset
// per cluster. Cluster (tile t, slice k) is number k * tileCount() + t.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "lidr/modes/light_list_texture.h"
#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/scene/camera.h"
#include "lidr/scene/scene.h"

namespace lidr {

// How view depth is cut into slices. Both are exponential (each slice's far depth a fixed multiple of its near
// one, so a slice is about as deep as its tiles are wide at every distance); they differ at the ends.
//   Exponential: Doom 2016's (Sousa & Geffroy), z_k = near * (far / near)^(k / S), from the camera's near to its
//                far plane.
//   NearSlice:   Filament's froxels: slice 0 from the near plane to `lightNear` (where a first-person camera has
//                little but its own floor), then S - 1 exponential slices from lightNear to the far plane.
enum class ClusterSlicing { Exponential, NearSlice };
const char* clusterSlicingName(ClusterSlicing slicing);  // "exponential", "near-slice"
// Throws lidr::Error naming the valid names.
ClusterSlicing parseClusterSlicing(const std::string& name);

// One frame's slicing: the shader's slice of a view depth z (distance in front of the eye) is
// clamp(floor(log2(z) * scale + bias), 0, count - 1) (cluster_grid.glsl; no integers, GLSL ES 1.00-safe). Slice 0
// starts at the near plane and slice count - 1 ends at the far plane whatever the formula says, so every depth a
// fragment can have is in a slice.
struct ClusterSlices {
    int count = 1;
    float scale = 0.0f, bias = 0.0f;
    float nearPlane = 0.1f, farPlane = 100.0f;
    // The view depth where slice k starts (k = 0: the near plane; k = count: the far plane), exact.
    double boundary(int k) const;
    // The slice of view depth z by the shader's formula in double precision (the GPU's may differ next to a
    // boundary: ClusterGrid widens every cell by kSliceRelativeMargin for that).
    int sliceOf(double viewDepth) const;
};
// The slicing of `camera` with `count` slices (1..kMaxSlices). NearSlice: with `lightNear` (view depth, scene
// units) outside the view range the first slice would hold nothing or everything, so there it falls back to
// Exponential. fitNear < fitFar (view depths, e.g. the nearest and farthest surface of the frame): the formula
// spans them instead of the near and far planes (slice 0 still starts at the near plane and the last ends at the
// far plane), so the slices are as thin as the frame's depth range allows.
ClusterSlices clusterSlices(const CameraMatrices& camera, int count, ClusterSlicing slicing, float lightNear,
                            float fitNear = 0.0f, float fitFar = 0.0f);

struct ClusterGridStats {
    int maxLights = 0;         // longest cluster list
    long entries = 0;          // light-cluster pairs: the sum of the list lengths
    long listedClusters = 0;   // clusters with a non-empty list
    long activeClusters = 0;   // clusters that can be shaded: all, or with occupancy the occupied (and transparent) ones
    int assignedLights = 0;    // lights in at least one list
    long cellTests = 0;        // exact sphere-cell distances computed (cells the plane tests could not decide)
};

// A cluster's cell in view space: the rays through its tile's pixels (x / d in [slopeX0, slopeX1], y / d in
// [slopeY0, slopeY1], d the distance in front of the eye, -z) between the view depths nearDepth and farDepth: a
// convex frustum with 4 side planes through the eye and 2 depth planes.
struct ClusterCell {
    float slopeX0, slopeX1, slopeY0, slopeY1;
    float nearDepth, farDepth;
};
// The exact squared distance from a view-space point to the cell (0 inside). The squared distance to the
// cell's cross-section at depth d (a rectangle) plus (d - depth of the point)^2 is a convex piecewise quadratic in
// d (and continuously differentiable): its minimum over [nearDepth, farDepth] is at an end, or where the derivative
// crosses 0, found between the breakpoints (where the point's x or y meets a side's slope) as the stationary point
// of that piece's quadratic.
double cellDistanceSquared(const ClusterCell& cell, const glm::vec3& viewPoint);

class ClusterGrid {
public:
    static constexpr int kMinTileSize = 4, kMaxTileSize = 256;
    static constexpr int kMaxSlices = 64;  // a tile's occupied slices fit one 64-bit mask
    // Relative and absolute widening of every cell's depth range: the shader finds a fragment's slice from its
    // interpolated world position in fp32 (a dot product, log2, a multiply-add), so next to a boundary it may pick
    // the neighbouring slice; the margins hold every such fragment in the cell it picked. The absolute part scales
    // with the eye's and the far plane's distance from the origin (the dot product's rounding). Measured in
    // doc/clustered.md ("Slice boundaries").
    static constexpr double kSliceRelativeMargin = 1e-5, kSliceAbsoluteMargin = 1e-6;

    // Throws lidr::Error for a size below 1 pixel, a tile size outside [kMinTileSize, kMaxTileSize], a slice count
    // outside [1, kMaxSlices]. A tile wider or taller than the screen is one tile across or up.
    ClusterGrid(int width, int height, int tileSize, int slices);

    // Assigns `lights` (light i has index i + 1) to the clusters whose cell they may reach: the light's clipped,
    // projected sphere rectangle (sphere_bounds.h) and its slice range pre-filter; then the exact sphere-cell
    // distance test (cells widened by the margins above, the sphere by `radiusMargin`: the fixed-point light
    // table's reach); a spot light also by its cone against the cell's bounding sphere (light_grid.h).
    // `occupied`: per tile, bit k set where slice k may hold a surface that is shaded (markOccupiedSlices); only
    // those clusters get lists. Null: every cluster does (the dense grid).
    void build(const CameraMatrices& camera, const std::vector<PointLight>& lights, const ClusterSlices& slices,
               const std::vector<uint64_t>* occupied = nullptr, float radiusMargin = 0.0f);

    // Per tile, the slices holding a pixel of `windowDepth` (width x height, rows bottom to top as glReadPixels
    // gives them; 1: no surface). Every slice the GPU may find for the pixel is marked: its depth widened by
    // `depthMargin` (window depth) and the slice margins. `transparentReach`: also every slice in front of the
    // tile's farthest surface (transparent layers are drawn over it), and every slice of a tile without one.
    std::vector<uint64_t> markOccupiedSlices(const std::vector<float>& windowDepth, const CameraMatrices& camera,
                                             const ClusterSlices& slices, bool transparentReach,
                                             float depthMargin = 1e-6f) const;
    // The same from DEPTH24_STENCIL8 words as glReadPixels gives them with GL_UNSIGNED_INT_24_8 (the depth in the
    // top 24 bits, 2^24 - 1 no surface): no conversion to float.
    std::vector<uint64_t> markOccupiedSlicesPacked(const std::vector<uint32_t>& packedDepthStencil,
                                                   const CameraMatrices& camera, const ClusterSlices& slices,
                                                   bool transparentReach, float depthMargin = 1e-6f) const;

    int width() const { return width_; }
    int height() const { return height_; }
    int tileSize() const { return tileSize_; }
    int tilesX() const { return tilesX_; }
    int tilesY() const { return tilesY_; }
    int tileCount() const { return tilesX_ * tilesY_; }
    int sliceCount() const { return slices_; }
    int clusterCount() const { return tileCount() * slices_; }
    // The tile of a pixel, GL window coordinates (y up); the cluster of a tile and slice.
    int tileOf(int x, int yFromBottom) const { return (yFromBottom / tileSize_) * tilesX_ + x / tileSize_; }
    int clusterOf(int tile, int slice) const { return slice * tileCount() + tile; }
    // The cell of a cluster for `slices`, without margins.
    ClusterCell cell(const CameraMatrices& camera, const ClusterSlices& slices, int cluster) const;

    const std::vector<uint32_t>& entries() const { return entries_; }
    const std::vector<uint32_t>& offsets() const { return offsets_; }  // per cluster, into entries()
    const std::vector<int>& counts() const { return counts_; }         // per cluster
    std::vector<uint32_t> list(int cluster) const;
    const ClusterGridStats& stats() const { return stats_; }
    // Lights the lists may name: 8-bit indices where at most 255 (the list texture's format follows it).
    int indexBits() const { return indexBits_; }

private:
    std::vector<uint64_t> markOccupied(const float* windowDepth, const uint32_t* packed, const CameraMatrices& camera,
                                       const ClusterSlices& slices, bool transparentReach, float depthMargin) const;
    // build()'s steps: the frame's tile side planes and widened slices; each light's cells (a row of a slice at a
    // time) as light-cluster pairs; the pairs into lists.
    struct ViewSphere;
    void prepareCells(const CameraMatrices& camera, const ClusterSlices& slices);
    void assignLight(const CameraMatrices& camera, const PointLight& light, uint32_t index, const ClusterSlices& slices,
                     const std::vector<uint64_t>* occupied, float radiusMargin);
    void assignRow(const ViewSphere& sphere, int slice, int tileRow, double rowOutside,
                   const std::vector<uint64_t>* occupied, float radiusMargin);
    void layOutLists(const std::vector<uint64_t>* occupied);

    int width_, height_, tileSize_, tilesX_, tilesY_, slices_;
    int indexBits_ = 8;
    std::vector<float> slopeX_, slopeY_;  // tile boundaries: tilesX + 1 and tilesY + 1 view-space slopes
    std::vector<double> planeScaleX_, planeScaleY_;     // 1 / |normal| of each boundary's side plane
    std::vector<double> columnOutside_, rowOutside_;    // per light: its centre's distance outside a column, a row
    double sliceNear_[kMaxSlices] = {}, sliceFar_[kMaxSlices] = {};  // the frame's slices, widened (widenedSlice)
    std::vector<uint32_t> entries_, offsets_;
    std::vector<int> counts_;
    std::vector<uint32_t> pairCluster_, pairLight_;  // the frame's light-cluster pairs, lights in ascending order
    ClusterGridStats stats_;
};

// The grid on the GPU (all GL 2.1 / ES 2.0 / WebGL 1 formats). Grid: one RGBA8 texel per cluster holding its
// list's offset as a 24-bit integer (R high byte, B low: putListOffset), tile (tx, ty) of slice k at texel
// (tx + tilesX * (k mod P), ty + tilesY * floor(k / P)), P = slicesPerRow() slices side by side, as many as fit
// the driver's texture size. Index list: a LightListTexture of 8-bit (LUMINANCE8) or 16-bit (LUMINANCE8_ALPHA8,
// L high) indices, grown as the lists grow; past what the driver or 24-bit offsets can address, upload() throws
// lidr::Error.
class ClusterGridTextures {
public:
    static constexpr int kListWidth = LightListTexture::kWidth;

    ClusterGridTextures() = default;
    // Throws lidr::Error where the grid cannot be laid out within the driver's texture size.
    ClusterGridTextures(const GlInfo& info, int tilesX, int tilesY, int slices);
    void upload(const ClusterGrid& grid);
    // Binds the textures and sets cluster_grid.glsl's texture uniforms.
    void bind(const gl::Program& program) const;
    int slicesPerRow() const { return slicesPerRow_; }
    int gridWidth() const { return tilesX_ * slicesPerRow_; }
    int gridHeight() const { return tilesY_ * sliceRows_; }
    int listRows() const { return list_.rows(); }
    int indexBits() const { return list_.indexBits(); }  // of the list texture as allocated (0: none yet)
    size_t bytes() const { return gridBytes() + listBytes(); }
    size_t gridBytes() const;  // the grid texture
    size_t listBytes() const { return list_.bytes(); }  // the whole list texture, as allocated

private:
    int tilesX_ = 0, tilesY_ = 0, slices_ = 0, slicesPerRow_ = 1, sliceRows_ = 1;
    gl::Texture grid_;
    LightListTexture list_;
    std::vector<uint8_t> gridBytes_;  // upload staging, kept between frames
};

}  // namespace lidr
