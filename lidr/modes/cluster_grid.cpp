#include "lidr/modes/cluster_grid.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <cmath>

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/modes/light_grid.h"
#include "lidr/scene/sphere_bounds.h"

namespace lidr {

const char* clusterSlicingName(ClusterSlicing slicing) {
    return slicing == ClusterSlicing::Exponential ? "exponential" : "near-slice";
}

ClusterSlicing parseClusterSlicing(const std::string& name) {
    if (name == "exponential") return ClusterSlicing::Exponential;
    if (name == "near-slice") return ClusterSlicing::NearSlice;
    throw Error("unknown cluster slicing '" + name + "' (valid: exponential, near-slice)");
}

double ClusterSlices::boundary(int k) const {
    if (k <= 0) return nearPlane;
    if (k >= count) return farPlane;
    const double z = std::exp2((double(k) - double(bias)) / double(scale));
    return std::clamp(z, double(nearPlane), double(farPlane));
}

int ClusterSlices::sliceOf(double viewDepth) const {
    if (count <= 1 || !(viewDepth > 0.0)) return 0;
    const double k = std::floor(std::log2(viewDepth) * double(scale) + double(bias));
    return int(std::clamp(k, 0.0, double(count - 1)));
}

ClusterSlices clusterSlices(const CameraMatrices& camera, int count, ClusterSlicing slicing, float lightNear,
                            float fitNear, float fitFar) {
    if (count < 1 || count > ClusterGrid::kMaxSlices)
        throw Error("cluster slices must be 1.." + std::to_string(ClusterGrid::kMaxSlices) + ", got " +
                    std::to_string(count));
    ClusterSlices s;
    s.count = count;
    s.nearPlane = camera.nearPlane;
    s.farPlane = camera.farPlane;
    if (count == 1) return s;
    double n = camera.nearPlane, f = camera.farPlane;
    if (fitNear > 0.0f && fitFar > fitNear) {  // the formula spans the depths given; the ends still reach the planes
        n = std::clamp(double(fitNear), n, f);
        f = std::clamp(double(fitFar), n, f);
        if (!(f > n * 1.0001)) f = n * 1.0001;  // one depth: a thin range around it
    }
    if (slicing == ClusterSlicing::NearSlice && lightNear > n && lightNear < f) {
        const double l = lightNear;
        s.scale = float(double(count - 1) / std::log2(f / l));
        s.bias = float(1.0 - std::log2(l) * double(s.scale));
    } else {
        s.scale = float(double(count) / std::log2(f / n));
        s.bias = float(-std::log2(n) * double(s.scale));
    }
    return s;
}

double cellDistanceSquared(const ClusterCell& cell, const glm::vec3& p) {
    const double x = p.x, y = p.y, pd = -double(p.z);
    const double d0 = cell.nearDepth, d1 = cell.farDepth;
    const double sx0 = cell.slopeX0, sx1 = cell.slopeX1, sy0 = cell.slopeY0, sy1 = cell.slopeY1;
    // f(d) / 2's derivative: (d - pd) plus, for each side the point lies beyond at depth d, s (s d - c). f is convex
    // and continuously differentiable, so the derivative rises with d and the minimum is where it crosses 0.
    const auto slopeOf = [&](double d) {
        double v = d - pd;
        if (sx0 * d > x) v += sx0 * (sx0 * d - x);
        else if (x > sx1 * d) v += sx1 * (sx1 * d - x);
        if (sy0 * d > y) v += sy0 * (sy0 * d - y);
        else if (y > sy1 * d) v += sy1 * (sy1 * d - y);
        return v;
    };
    double best;
    if (slopeOf(d0) >= 0.0) {
        best = d0;
    } else if (slopeOf(d1) <= 0.0) {
        best = d1;
    } else {
        // The piece where it crosses: between the breakpoints (x = s d or y = s d) around the crossing.
        double points[4];
        int n = 0;
        for (double bp : {sx0 != 0.0 ? x / sx0 : -1.0, sx1 != 0.0 ? x / sx1 : -1.0, sy0 != 0.0 ? y / sy0 : -1.0,
                          sy1 != 0.0 ? y / sy1 : -1.0})
            if (bp > d0 && bp < d1) points[n++] = bp;
        for (int i = 1; i < n; ++i)  // insertion sort of at most 4
            for (int j = i; j > 0 && points[j] < points[j - 1]; --j) std::swap(points[j], points[j - 1]);
        double lo = d0, hi = d1;
        for (int i = 0; i < n; ++i) {
            if (slopeOf(points[i]) >= 0.0) {
                hi = points[i];
                break;
            }
            lo = points[i];
        }
        // On that piece each side is inactive or (s d - c)^2 throughout: the stationary point of
        // (d - pd)^2 + sum (s d - c)^2 is (pd + sum s c) / (1 + sum s^2).
        const double mid = 0.5 * (lo + hi);
        double num = pd, den = 1.0;
        if (sx0 * mid > x) num += sx0 * x, den += sx0 * sx0;
        else if (x > sx1 * mid) num += sx1 * x, den += sx1 * sx1;
        if (sy0 * mid > y) num += sy0 * y, den += sy0 * sy0;
        else if (y > sy1 * mid) num += sy1 * y, den += sy1 * sy1;
        best = std::clamp(num / den, lo, hi);
    }
    const double gx = std::max(0.0, std::max(sx0 * best - x, x - sx1 * best));
    const double gy = std::max(0.0, std::max(sy0 * best - y, y - sy1 * best));
    return (best - pd) * (best - pd) + gx * gx + gy * gy;
}

namespace {

// The view-space slopes x / d (or y / d) of the screen lines at `pixels` (window coordinates) of a `size`-pixel
// axis: ndc = P00 * x / d - P20 (sphere_bounds.cpp), so x / d = (ndc + P20) / P00.
std::vector<float> boundarySlopes(int tiles, int tileSize, int size, float scale, float offset) {
    std::vector<float> slopes(size_t(tiles) + 1);
    for (int i = 0; i <= tiles; ++i) {
        const double ndc = double(std::min(i * tileSize, size)) / double(size) * 2.0 - 1.0;
        slopes[size_t(i)] = float((ndc + double(offset)) / double(scale));
    }
    return slopes;
}

// Window depth of view depth d for a perspective projection: ndc z = -P22 + P32 / d.
double windowDepthOf(const glm::mat4& projection, double d) {
    return 0.5 * (-double(projection[2][2]) + double(projection[3][2]) / d) + 0.5;
}

// The absolute part of the slice margin for this camera (ClusterGrid::kSliceAbsoluteMargin).
double absoluteSliceMargin(const CameraMatrices& camera) {
    return ClusterGrid::kSliceAbsoluteMargin * (double(glm::length(camera.eye)) + double(camera.farPlane));
}

// The depth range of slice k's cell, widened by the margins.
void widenedSlice(const ClusterSlices& slices, int k, double absolute, double& nearDepth, double& farDepth) {
    nearDepth = std::max(0.0, slices.boundary(k) * (1.0 - ClusterGrid::kSliceRelativeMargin) - absolute);
    farDepth = slices.boundary(k + 1) * (1.0 + ClusterGrid::kSliceRelativeMargin) + absolute;
}

// Whether a spot light's cone may reach into the cell: the cell's bounding sphere (centre the corners' mean, radius
// the farthest corner) against the cone, as the tile grid tests it (light_grid.cpp); a deep cell is also tried as
// 4 slices of equal depth ratio, and one must pass.
bool coneMayReachCell(const ViewCone& cone, const ClusterCell& cell, float radiusMargin) {
    const auto sliceMay = [&](float nearDepth, float farDepth) {
        glm::vec3 corners[8];
        glm::vec3 centre(0.0f);
        for (int k = 0; k < 8; ++k) {
            const float d = (k & 4) ? farDepth : nearDepth;
            corners[k] = glm::vec3(((k & 1) ? cell.slopeX1 : cell.slopeX0) * d, ((k & 2) ? cell.slopeY1 : cell.slopeY0) * d, -d);
            centre += corners[k];
        }
        centre *= 0.125f;
        float radius = 0.0f;
        for (const glm::vec3& c : corners) radius = std::max(radius, glm::length(c - centre));
        return coneMayReachSphere(cone, centre, radius * (1.0f + 1e-5f) + 1e-6f * farDepth + radiusMargin);
    };
    if (!sliceMay(cell.nearDepth, cell.farDepth)) return false;
    if (!(cell.farDepth > cell.nearDepth * 1.25f) || !(cell.nearDepth > 0.0f)) return true;
    const float ratio = std::pow(cell.farDepth / cell.nearDepth, 0.25f);
    float sliceNear = cell.nearDepth;
    for (int k = 0; k < 4; ++k) {
        const float sliceFar = k == 3 ? cell.farDepth : sliceNear * ratio;
        if (sliceMay(sliceNear, sliceFar)) return true;
        sliceNear = sliceFar;
    }
    return false;
}

}  // namespace

ClusterGrid::ClusterGrid(int width, int height, int tileSize, int slices)
    : width_(width), height_(height), tileSize_(tileSize), slices_(slices) {
    if (width <= 0 || height <= 0)
        throw Error("cluster grid: resolution must be positive, got " + std::to_string(width) + "x" +
                    std::to_string(height));
    if (tileSize < kMinTileSize || tileSize > kMaxTileSize)
        throw Error("cluster tile size must be " + std::to_string(kMinTileSize) + ".." + std::to_string(kMaxTileSize) +
                    " pixels, got " + std::to_string(tileSize));
    if (slices < 1 || slices > kMaxSlices)
        throw Error("cluster depth slices must be 1.." + std::to_string(kMaxSlices) + ", got " + std::to_string(slices));
    tilesX_ = (width + tileSize - 1) / tileSize;
    tilesY_ = (height + tileSize - 1) / tileSize;
    offsets_.assign(size_t(clusterCount()), 0u);
    counts_.assign(size_t(clusterCount()), 0);
    entries_.assign(1, 0u);
}

ClusterCell ClusterGrid::cell(const CameraMatrices& camera, const ClusterSlices& slices, int cluster) const {
    const int tile = cluster % tileCount(), k = cluster / tileCount();
    const int tx = tile % tilesX_, ty = tile / tilesX_;
    const std::vector<float> sx = boundarySlopes(tilesX_, tileSize_, width_, camera.projection[0][0], camera.projection[2][0]);
    const std::vector<float> sy = boundarySlopes(tilesY_, tileSize_, height_, camera.projection[1][1], camera.projection[2][1]);
    return {sx[size_t(tx)], sx[size_t(tx) + 1], sy[size_t(ty)], sy[size_t(ty) + 1], float(slices.boundary(k)),
            float(slices.boundary(k + 1))};
}

// A light's sphere in view space as build() tests it against the cells.
struct ClusterGrid::ViewSphere {
    glm::vec3 c{0.0f};         // the centre in view space
    double depth = 0.0;        // its view depth
    double reach = 0.0;        // the radius grown for rounding, squared
    double reachDistance = 0.0;
    bool spot = false;
    ViewCone cone{};
    uint32_t index = 0;        // the light's index (light i: i + 1)
    int tx0 = 0, tx1 = 0;      // the tile columns its pixel rectangle spans
};

void ClusterGrid::build(const CameraMatrices& camera, const std::vector<PointLight>& lights, const ClusterSlices& slices,
                        const std::vector<uint64_t>* occupied, float radiusMargin) {
    if (camera.width != width_ || camera.height != height_)
        throw Error("cluster grid: camera is " + std::to_string(camera.width) + "x" + std::to_string(camera.height) +
                    ", grid was made for " + std::to_string(width_) + "x" + std::to_string(height_));
    if (lights.size() > 65535)
        throw Error("cluster grid: " + std::to_string(lights.size()) + " lights, 16-bit light indices hold 65535");
    if (slices.count != slices_)
        throw Error("cluster grid: " + std::to_string(slices.count) + " slices given, the grid has " +
                    std::to_string(slices_));
    if (occupied && occupied->size() != size_t(tileCount()))
        throw Error("cluster grid: " + std::to_string(occupied->size()) + " occupancy masks for " +
                    std::to_string(tileCount()) + " tiles");
    indexBits_ = lights.size() <= 255 ? 8 : 16;
    prepareCells(camera, slices);
    stats_ = ClusterGridStats{};
    pairCluster_.clear();
    pairLight_.clear();
    for (size_t i = 0; i < lights.size(); ++i)
        assignLight(camera, lights[i], uint32_t(i + 1), slices, occupied, radiusMargin);
    layOutLists(occupied);
}

void ClusterGrid::prepareCells(const CameraMatrices& camera, const ClusterSlices& slices) {
    slopeX_ = boundarySlopes(tilesX_, tileSize_, width_, camera.projection[0][0], camera.projection[2][0]);
    slopeY_ = boundarySlopes(tilesY_, tileSize_, height_, camera.projection[1][1], camera.projection[2][1]);
    // A side plane x + s z = 0 has the unit normal (1, 0, s) / sqrt(1 + s^2).
    planeScaleX_.resize(slopeX_.size());
    planeScaleY_.resize(slopeY_.size());
    for (size_t i = 0; i < slopeX_.size(); ++i) planeScaleX_[i] = 1.0 / std::sqrt(1.0 + double(slopeX_[i]) * slopeX_[i]);
    for (size_t i = 0; i < slopeY_.size(); ++i) planeScaleY_[i] = 1.0 / std::sqrt(1.0 + double(slopeY_[i]) * slopeY_[i]);
    columnOutside_.resize(size_t(tilesX_));
    rowOutside_.resize(size_t(tilesY_));
    const double absolute = absoluteSliceMargin(camera);
    for (int k = 0; k < slices_; ++k) widenedSlice(slices, k, absolute, sliceNear_[k], sliceFar_[k]);
}

void ClusterGrid::assignLight(const CameraMatrices& camera, const PointLight& l, uint32_t index,
                              const ClusterSlices& slices, const std::vector<uint64_t>* occupied, float radiusMargin) {
    const float radius = l.radius + radiusMargin;
    glm::ivec4 rect;
    if (!spherePixelRect(camera, l.position, radius, rect)) return;
    ViewSphere s;
    s.c = glm::vec3(camera.view * glm::vec4(l.position, 1.0f));
    const glm::vec3& c = s.c;
    s.depth = -double(c.z);
    const double dmin = std::max(double(camera.nearPlane), s.depth - radius);
    const double dmax = std::min(double(camera.farPlane), s.depth + radius);
    if (dmin > dmax) return;
    int k0 = slices.sliceOf(dmin), k1 = slices.sliceOf(dmax);
    while (k0 > 0 && sliceFar_[k0 - 1] >= dmin) --k0;
    while (k1 < slices_ - 1 && sliceNear_[k1 + 1] <= dmax) ++k1;
    // The sphere grown for the float rounding of its view-space centre (and the shader's of the distance).
    const double slack = 1e-5 * (std::abs(c.x) + std::abs(c.y) + std::abs(c.z) + radius);
    s.reach = (double(radius) + slack) * (double(radius) + slack);
    s.spot = l.isSpot();
    s.cone = s.spot ? viewCone(camera, l, radius) : ViewCone{};
    s.index = index;
    s.tx0 = rect.x / tileSize_, s.tx1 = rect.z / tileSize_;
    const int ty0 = rect.y / tileSize_, ty1 = rect.w / tileSize_;
    // How far the centre lies outside each tile column's and row's side planes (planes through the eye) and
    // each slice's depth planes: the largest of a cell's is a lower bound of its distance (the cell lies in
    // every half-space), so above the radius the cell is out without the exact test, and at or below 0 the
    // centre is inside it.
    for (int tx = s.tx0; tx <= s.tx1; ++tx)
        columnOutside_[size_t(tx)] = std::max(-(c.x + slopeX_[size_t(tx)] * double(c.z)) * planeScaleX_[size_t(tx)],
                                              (c.x + slopeX_[size_t(tx) + 1] * double(c.z)) * planeScaleX_[size_t(tx) + 1]);
    for (int ty = ty0; ty <= ty1; ++ty)
        rowOutside_[size_t(ty)] = std::max(-(c.y + slopeY_[size_t(ty)] * double(c.z)) * planeScaleY_[size_t(ty)],
                                           (c.y + slopeY_[size_t(ty) + 1] * double(c.z)) * planeScaleY_[size_t(ty) + 1]);
    s.reachDistance = std::sqrt(s.reach);
    const size_t pairsBefore = pairCluster_.size();
    for (int k = k0; k <= k1; ++k) {
        const double sliceOutside = std::max(sliceNear_[k] - s.depth, s.depth - sliceFar_[k]);
        if (sliceOutside > s.reachDistance) continue;
        for (int ty = ty0; ty <= ty1; ++ty) {
            const double rowOutside = std::max(sliceOutside, rowOutside_[size_t(ty)]);
            if (rowOutside > s.reachDistance) continue;
            assignRow(s, k, ty, rowOutside, occupied, radiusMargin);
        }
    }
    if (pairCluster_.size() > pairsBefore) ++stats_.assignedLights;
}

void ClusterGrid::assignRow(const ViewSphere& s, int k, int ty, double rowOutside, const std::vector<uint64_t>* occupied,
                            float radiusMargin) {
    const glm::vec3& c = s.c;
    const auto cellOf = [&](int tx) {
        return ClusterCell{slopeX_[size_t(tx)], slopeX_[size_t(tx) + 1], slopeY_[size_t(ty)],
                           slopeY_[size_t(ty) + 1], float(sliceNear_[k]), float(sliceFar_[k])};
    };
    const auto meets = [&](int tx) {
        const double outside = std::max(rowOutside, columnOutside_[size_t(tx)]);
        if (outside > s.reachDistance) return false;
        if (outside <= 0.0) return true;  // the centre is inside the cell
        // A point of the cell near the centre (its depth clamped to the slice, then x and y to the
        // cross-section there): within reach, the cell is too.
        const double d = std::clamp(s.depth, sliceNear_[k], sliceFar_[k]);
        const double qx = std::clamp(double(c.x), double(slopeX_[size_t(tx)]) * d, double(slopeX_[size_t(tx) + 1]) * d);
        const double qy = std::clamp(double(c.y), double(slopeY_[size_t(ty)]) * d, double(slopeY_[size_t(ty) + 1]) * d);
        if ((qx - c.x) * (qx - c.x) + (qy - c.y) * (qy - c.y) + (d - s.depth) * (d - s.depth) <= s.reach) return true;
        ++stats_.cellTests;
        return cellDistanceSquared(cellOf(tx), c) <= s.reach;
    };
    // The sphere's part within a slice and a tile row is convex, and x / d is continuous on it, so the columns
    // whose cells it meets are one run: found from both ends, the cells between need no test.
    int first = s.tx0;
    while (first <= s.tx1 && !meets(first)) ++first;
    if (first > s.tx1) return;
    int last = s.tx1;
    while (last > first && !meets(last)) --last;
    const int tiles = tileCount();
    for (int tx = first; tx <= last; ++tx) {
        const int tile = ty * tilesX_ + tx;
        if (occupied && !(((*occupied)[size_t(tile)] >> k) & 1u)) continue;
        if (s.spot && !coneMayReachCell(s.cone, cellOf(tx), radiusMargin)) continue;
        pairCluster_.push_back(uint32_t(k * tiles + tile));
        pairLight_.push_back(s.index);
    }
}

void ClusterGrid::layOutLists(const std::vector<uint64_t>* occupied) {
    // Lists by counting sort: lights were visited in ascending order, so every list comes out ascending.
    const size_t clusters = size_t(clusterCount());
    counts_.assign(clusters, 0);
    for (uint32_t cl : pairCluster_) ++counts_[cl];
    offsets_.assign(clusters, 0u);
    size_t next = 1;  // entry 0: the shared empty list
    for (size_t cl = 0; cl < clusters; ++cl) {
        if (counts_[cl] == 0) continue;
        offsets_[cl] = uint32_t(next);
        next += size_t(counts_[cl]) + 1;
        stats_.maxLights = std::max(stats_.maxLights, counts_[cl]);
        ++stats_.listedClusters;
    }
    entries_.assign(next, 0u);
    std::vector<uint32_t> cursor = offsets_;
    for (size_t p = 0; p < pairCluster_.size(); ++p) entries_[cursor[pairCluster_[p]]++] = pairLight_[p];
    stats_.entries = long(pairCluster_.size());
    if (occupied) {
        for (uint64_t mask : *occupied) stats_.activeClusters += __builtin_popcountll(mask);
    } else {
        stats_.activeClusters = long(clusters);
    }
}

namespace {

// The per-pixel marking of markOccupiedSlices, for float window depths (Depth float, Threshold float) and for
// packed DEPTH24_STENCIL8 words read back as they are stored (Depth uint32_t, the depth in the top 24 bits;
// Threshold int64_t in 24-bit steps): slice k holds the depths [lo[k], hi[k]], both rising with k, so a depth's
// slices are a run.
template <typename Depth, typename Threshold, typename Value>
void markSlices(const Depth* depth, int width, int height, int tileSize, int tilesX, int slices, const Threshold* lo,
                const Threshold* hi, Threshold background, Value value, std::vector<uint64_t>& masks,
                std::vector<uint8_t>* emptyTiles) {
    // The run of slices of the last depth looked up, and the depths that have the very same run (a depth w has
    // slices first..last: hi[first - 1] < w <= hi[first], lo[last] <= w < lo[last + 1]); neighbouring pixels
    // mostly share it.
    Threshold aboveLo = 1, upToHi = 0, fromLo = 1, belowLo = 0;
    uint64_t runBits = 0;
    for (int y = 0; y < height; ++y) {
        const Depth* row = depth + size_t(y) * size_t(width);
        const int rowTile = (y / tileSize) * tilesX;
        for (int tx = 0; tx < tilesX; ++tx) {
            uint64_t bits = 0;
            bool empty = false;
            const int xEnd = std::min(width, (tx + 1) * tileSize);
            for (int x = tx * tileSize; x < xEnd; ++x) {
                const Threshold w = value(row[x]);
                if (w >= background) {
                    empty = true;
                    continue;
                }
                if (!(w > aboveLo && w <= upToHi && w >= fromLo && w < belowLo)) {
                    int first = 0;
                    while (hi[first] < w) ++first;  // the last slice's hi is past every depth: always found
                    int last = first;
                    while (last + 1 < slices && lo[last + 1] <= w) ++last;
                    aboveLo = first > 0 ? hi[first - 1] : lo[0] - 1;
                    upToHi = hi[first];
                    fromLo = lo[last];
                    belowLo = last + 1 < slices ? lo[last + 1] : hi[slices - 1] + 1;
                    runBits = 0;
                    for (int s = first; s <= last; ++s) runBits |= uint64_t(1) << s;
                }
                bits |= runBits;
            }
            masks[size_t(rowTile + tx)] |= bits;
            if (empty && emptyTiles) (*emptyTiles)[size_t(rowTile + tx)] = 1;
        }
    }
}

}  // namespace

std::vector<uint64_t> ClusterGrid::markOccupiedSlices(const std::vector<float>& windowDepth, const CameraMatrices& camera,
                                                      const ClusterSlices& slices, bool transparentReach,
                                                      float depthMargin) const {
    if (windowDepth.size() != size_t(width_) * size_t(height_))
        throw Error("cluster grid: " + std::to_string(windowDepth.size()) + " depths for a " + std::to_string(width_) +
                    "x" + std::to_string(height_) + " grid");
    return markOccupied(windowDepth.data(), nullptr, camera, slices, transparentReach, depthMargin);
}

std::vector<uint64_t> ClusterGrid::markOccupiedSlicesPacked(const std::vector<uint32_t>& packedDepthStencil,
                                                            const CameraMatrices& camera, const ClusterSlices& slices,
                                                            bool transparentReach, float depthMargin) const {
    if (packedDepthStencil.size() != size_t(width_) * size_t(height_))
        throw Error("cluster grid: " + std::to_string(packedDepthStencil.size()) + " depths for a " +
                    std::to_string(width_) + "x" + std::to_string(height_) + " grid");
    return markOccupied(nullptr, packedDepthStencil.data(), camera, slices, transparentReach, depthMargin);
}

std::vector<uint64_t> ClusterGrid::markOccupied(const float* windowDepth, const uint32_t* packed,
                                                const CameraMatrices& camera, const ClusterSlices& slices,
                                                bool transparentReach, float depthMargin) const {
    if (slices.count != slices_)
        throw Error("cluster grid: " + std::to_string(slices.count) + " slices given, the grid has " +
                    std::to_string(slices_));
    // Slice k holds the window depths [lo[k], hi[k]]: its widened cell's, widened again by depthMargin (the depth
    // buffer's rounding against the fragment's own depth); the first reaches below 0, the last above 1.
    const double absolute = absoluteSliceMargin(camera);
    double lo[kMaxSlices], hi[kMaxSlices];
    for (int k = 0; k < slices_; ++k) {
        double n, f;
        widenedSlice(slices, k, absolute, n, f);
        lo[k] = k == 0 ? -1.0 : windowDepthOf(camera.projection, std::max(n, 1e-30)) - depthMargin;
        hi[k] = k == slices_ - 1 ? 2.0 : windowDepthOf(camera.projection, f) + depthMargin;
    }
    std::vector<uint64_t> masks(size_t(tileCount()), 0u);
    std::vector<uint8_t> background(transparentReach ? size_t(tileCount()) : 0, 0);
    std::vector<uint8_t>* empty = transparentReach ? &background : nullptr;
    if (windowDepth) {
        float loF[kMaxSlices], hiF[kMaxSlices];
        for (int k = 0; k < slices_; ++k) loF[k] = float(lo[k]), hiF[k] = float(hi[k]);
        markSlices(windowDepth, width_, height_, tileSize_, tilesX_, slices_, loF, hiF, 1.0f,
                   [](float w) { return w; }, masks, empty);
    } else {
        // In 24-bit steps (w = d / (2^24 - 1)), rounded outwards.
        constexpr double kSteps = 16777215.0;
        int64_t loI[kMaxSlices], hiI[kMaxSlices];
        for (int k = 0; k < slices_; ++k)
            loI[k] = int64_t(std::floor(lo[k] * kSteps)), hiI[k] = int64_t(std::ceil(hi[k] * kSteps));
        markSlices(packed, width_, height_, tileSize_, tilesX_, slices_, loI, hiI, int64_t(16777215),
                   [](uint32_t d) { return int64_t(d >> 8); }, masks, empty);
    }
    if (transparentReach) {
        const uint64_t all = slices_ == 64 ? ~uint64_t(0) : (uint64_t(1) << slices_) - 1;
        for (size_t t = 0; t < masks.size(); ++t) {
            if (background[t] || masks[t] == 0) {
                masks[t] = all;
                continue;
            }
            const int top = 63 - __builtin_clzll(masks[t]);
            masks[t] = top == 63 ? ~uint64_t(0) : (uint64_t(1) << (top + 1)) - 1;
        }
    }
    return masks;
}

std::vector<uint32_t> ClusterGrid::list(int cluster) const {
    const auto first = entries_.begin() + offsets_.at(size_t(cluster));
    return std::vector<uint32_t>(first, first + counts_.at(size_t(cluster)));
}

// --- GPU side ---------------------------------------------------------------------------------------

ClusterGridTextures::ClusterGridTextures(const GlInfo& info, int tilesX, int tilesY, int slices)
    : tilesX_(tilesX),
      tilesY_(tilesY),
      slices_(slices),
      list_(info, {"cluster grid", "clustered", "cluster", "larger tiles, fewer slices or fewer lights"}, 0) {
    slicesPerRow_ = std::clamp(info.maxTextureSize / std::max(tilesX, 1), 1, slices);
    sliceRows_ = (slices + slicesPerRow_ - 1) / slicesPerRow_;
    if (tilesX > info.maxTextureSize || long(tilesY) * sliceRows_ > info.maxTextureSize)
        throw Error("cluster grid of " + std::to_string(tilesX) + "x" + std::to_string(tilesY) + " tiles x " +
                    std::to_string(slices) + " slices does not fit the driver's " +
                    std::to_string(info.maxTextureSize) + "-texel textures; use larger tiles or fewer slices");
    grid_ = gl::Texture::create2D(GL_RGBA8, gridWidth(), gridHeight(), GL_RGBA, GL_UNSIGNED_BYTE);
    gridBytes_.assign(size_t(gridWidth()) * size_t(gridHeight()) * 4, 0);
}

void ClusterGridTextures::upload(const ClusterGrid& grid) {
    if (grid.tilesX() != tilesX_ || grid.tilesY() != tilesY_ || grid.sliceCount() != slices_)
        throw Error("cluster grid textures: grid size changed");
    list_.upload(grid.entries(), grid.indexBits());
    // The grid: cluster (tile, slice k) at texel (tx + tilesX (k mod P), ty + tilesY floor(k / P)).
    const std::vector<uint32_t>& offsets = grid.offsets();
    const int tiles = tilesX_ * tilesY_, width = gridWidth();
    for (int k = 0; k < slices_; ++k) {
        const int x0 = tilesX_ * (k % slicesPerRow_), y0 = tilesY_ * (k / slicesPerRow_);
        for (int ty = 0; ty < tilesY_; ++ty)
            for (int tx = 0; tx < tilesX_; ++tx)
                putListOffset(gridBytes_.data() + (size_t(y0 + ty) * size_t(width) + size_t(x0 + tx)) * 4,
                              offsets[size_t(k) * size_t(tiles) + size_t(ty * tilesX_ + tx)]);
    }
    grid_.upload(gridWidth(), gridHeight(), GL_RGBA, GL_UNSIGNED_BYTE, gridBytes_.data());
    StateCache::current().bindTexture(GL_TEXTURE_2D, 0);
    checkGl("ClusterGridTextures::upload");
}

void ClusterGridTextures::bind(const gl::Program& program) const {
    grid_.bind(gl::kUnitClusterGrid);
    list_.texture().bind(gl::kUnitClusterList);
    glActiveTexture(GL_TEXTURE0);
    program.set("uClusterGrid", gl::kUnitClusterGrid);
    program.set("uClusterLights", gl::kUnitClusterList);
    program.set("uClusterListRows", float(list_.rows()));
}

size_t ClusterGridTextures::gridBytes() const { return size_t(gridWidth()) * size_t(gridHeight()) * 4; }

}  // namespace lidr
