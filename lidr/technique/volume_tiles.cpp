#include "lidr/technique/volume_tiles.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <thread>
#include <cmath>
#include <string>

#include "lidr/base/error.h"

namespace lidr {

namespace {
constexpr int kSlices = 32;
// Float rounding of a depth computed two ways (the shader's and this file's): a few steps of a 24-bit buffer.
constexpr float kDepthSlack = 4.0f / 16777215.0f;

uint32_t sliceMask(int first, int last) {  // bits first..last, 0 <= first <= last < 32
    const uint32_t upTo = last >= 31 ? 0xFFFFFFFFu : (1u << (last + 1)) - 1u;
    return upTo & ~((1u << first) - 1u);
}
}  // namespace

VolumeTiles::VolumeTiles(int width, int height, int tileSize)
    : width_(width), height_(height), tileSize_(tileSize) {
    if (tileSize < 4 || tileSize > 256)
        throw Error("light-volume tiles: the tile size must be in [4, 256], got " + std::to_string(tileSize));
    if (width < 1 || height < 1) throw Error("light-volume tiles: the target must be at least 1 x 1");
    tilesX_ = (width + tileSize - 1) / tileSize;
    tilesY_ = (height + tileSize - 1) / tileSize;
}

void VolumeTiles::build(const std::vector<float>& depth, float margin, const CameraMatrices& camera) {
    buildRanges(depth, depth, margin, camera);
}

void VolumeTiles::buildRanges(const std::vector<float>& nearDepth, const std::vector<float>& farDepth, float margin,
                              const CameraMatrices& camera) {
    for (const std::vector<float>* depth : {&nearDepth, &farDepth})
        if (depth->size() != size_t(width_) * size_t(height_))
            throw Error("light-volume tiles: " + std::to_string(depth->size()) + " depths for a " +
                        std::to_string(width_) + " x " + std::to_string(height_) + " target");
    const glm::mat4& P = camera.projection;
    if (P[2][3] != -1.0f || P[3][3] != 0.0f) throw Error("light-volume tiles need a perspective projection");
    depthToDistance_ = {0.5f * P[3][2], 0.5f * (P[2][2] - 1.0f)};
    // NDC x = P00 (x / -z) - P20, so x / -z = (ndc + P20) / P00; the same for y.
    slopeX_.resize(size_t(tilesX_) + 1);
    slopeY_.resize(size_t(tilesY_) + 1);
    for (int i = 0; i <= tilesX_; ++i)
        slopeX_[size_t(i)] = (2.0f * float(std::min(i * tileSize_, width_)) / float(width_) - 1.0f + P[2][0]) / P[0][0];
    for (int i = 0; i <= tilesY_; ++i)
        slopeY_[size_t(i)] = (2.0f * float(std::min(i * tileSize_, height_)) / float(height_) - 1.0f + P[2][1]) / P[1][1];
    const size_t tiles = size_t(tileCount());
    minDepth_.assign(tiles, 2.0f);
    maxDepth_.assign(tiles, -1.0f);
    slices_.assign(tiles, 0u);
    sliceSpan_.assign(tiles, 0);
    margin += kDepthSlack;
    sliceDistances_.resize(tiles * size_t(kSlices));
    // The CPU side of every tile-culled frame, run while the GPU waits for its result: the lower half of the tile
    // rows on a second thread.
    const int half = tilesY_ / 2;
    if (half < 2) {
        buildRows(nearDepth, farDepth, margin, 0, tilesY_);
        return;
    }
    std::thread lower([&] { buildRows(nearDepth, farDepth, margin, 0, half); });
    buildRows(nearDepth, farDepth, margin, half, tilesY_);
    lower.join();
}

void VolumeTiles::buildRows(const std::vector<float>& nearDepth, const std::vector<float>& farDepth, float margin,
                            int firstRow, int endRow) {
    rangeTiles(nearDepth, farDepth, margin, firstRow, endRow);
    markSlices(nearDepth, farDepth, margin, firstRow, endRow);
    measureSlices(firstRow, endRow);
}

void VolumeTiles::rangeTiles(const std::vector<float>& nearDepth, const std::vector<float>& farDepth, float margin,
                             int firstRow, int endRow) {
    // Both passes walk each row a tile's span at a time (no division per pixel) with branch-free inner loops
    // the compiler can vectorise: this is the CPU side of every tile-culled frame (doc/benchmarks.md).
    // Pass 1: each tile's range of surface depths, widened by the margin. Rounding is monotonic, so
    // min(d) - margin is min(d - margin), bit for bit.
    for (int y = firstRow * tileSize_, yEnd = std::min(endRow * tileSize_, height_); y < yEnd; ++y) {
        const float* nearRow = nearDepth.data() + size_t(y) * size_t(width_);
        const float* farRow = farDepth.data() + size_t(y) * size_t(width_);
        const size_t tileRow = size_t(y / tileSize_) * size_t(tilesX_);
        for (int tx = 0; tx < tilesX_; ++tx) {
            const int x0 = tx * tileSize_, x1 = std::min(x0 + tileSize_, width_);
            float lo = 2.0f, hi = -1.0f;
            for (int x = x0; x < x1; ++x) {
                const float n = nearRow[x], f = farRow[x];
                const bool surface = n < 1.0f;  // background (1, or NaN): the sphere test discards it
                lo = std::min(lo, surface ? n : 2.0f);
                hi = std::max(hi, surface ? f : -1.0f);
            }
            if (hi < lo) continue;
            const size_t t = tileRow + size_t(tx);
            minDepth_[t] = std::min(minDepth_[t], lo - margin);
            maxDepth_[t] = std::max(maxDepth_[t], hi + margin);
        }
    }
}

void VolumeTiles::markSlices(const std::vector<float>& nearDepth, const std::vector<float>& farDepth, float margin,
                             int firstRow, int endRow) {
    // Pass 2: the slices each pixel's widened depth overlaps. d - margin >= the tile's minimum, so both slice
    // coordinates are >= 0 and truncation is the floor.
    const size_t firstTile = size_t(firstRow) * size_t(tilesX_), endTile = size_t(endRow) * size_t(tilesX_);
    std::vector<float> scale(size_t(tileCount()), 0.0f);
    for (size_t t = firstTile; t < endTile; ++t)
        if (maxDepth_[t] > minDepth_[t]) scale[t] = float(kSlices) / (maxDepth_[t] - minDepth_[t]);
    for (int y = firstRow * tileSize_, yEnd = std::min(endRow * tileSize_, height_); y < yEnd; ++y) {
        const float* nearRow = nearDepth.data() + size_t(y) * size_t(width_);
        const float* farRow = farDepth.data() + size_t(y) * size_t(width_);
        const size_t tileRow = size_t(y / tileSize_) * size_t(tilesX_);
        for (int tx = 0; tx < tilesX_; ++tx) {
            const size_t t = tileRow + size_t(tx);
            if (!(maxDepth_[t] > minDepth_[t])) continue;  // no surface in this tile
            const int x0 = tx * tileSize_, x1 = std::min(x0 + tileSize_, width_);
            const float base = minDepth_[t], s = scale[t];
            uint32_t bits = slices_[t];
            int span = sliceSpan_[t];
            for (int x = x0; x < x1; ++x) {
                const float n = nearRow[x], f = farRow[x];
                if (!(n < 1.0f)) continue;
                const int first = std::min(int((n - margin - base) * s), kSlices - 1);
                const int last = std::min(int((f + margin - base) * s), kSlices - 1);
                bits |= sliceMask(first, last);
                span = std::max(span, last - first);
            }
            slices_[t] = bits;
            sliceSpan_[t] = span;
        }
    }
}

void VolumeTiles::measureSlices(int firstRow, int endRow) {
    // Pass 3: each occupied slice's distances, widened by a tenth of a slice (rounding in the floors above) and
    // by relative slack, computed once here rather than for every light that reaches the tile.
    auto distance = [&](float d) { return depthToDistance_.x / (d + depthToDistance_.y); };
    for (size_t t = size_t(firstRow) * size_t(tilesX_), end = size_t(endRow) * size_t(tilesX_); t < end; ++t) {
        const float lo = minDepth_[t], width = (maxDepth_[t] - lo) / float(kSlices);
        for (uint32_t bits = slices_[t]; bits != 0; bits &= bits - 1) {
            const int s = __builtin_ctz(bits);
            const float d0 = std::max(lo + (float(s) - 0.1f) * width, 0.0f), d1 = std::min(lo + (float(s) + 1.1f) * width, 1.0f);
            const float D0 = distance(d0), D1 = distance(d1);
            sliceDistances_[t * size_t(kSlices) + size_t(s)] = {D0 - 1e-5f * D0, D1 + 1e-5f * D1};
        }
    }
}

void VolumeTiles::buildFromBoundDepth(float margin, const CameraMatrices& camera, bool packedDepthStencil) {
    build(readBoundDepth(packedDepthStencil), margin, camera);
}

const std::vector<float>& VolumeTiles::readBoundDepth(bool packedDepthStencil) {
    const size_t pixels = size_t(width_) * size_t(height_);
    readback_.resize(pixels);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    if (packedDepthStencil) {
        // A packed depth-stencil buffer read as it is stored: Mesa copies the rows (its float read converts each
        // pixel, the larger part of this pass's read-back), and the conversion here vectorises. The same value
        // as the float read: the 24-bit depth times 1 / (2^24 - 1) in double, rounded to float.
        packed_.resize(pixels);
        glReadPixels(0, 0, width_, height_, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, packed_.data());
        checkGl("light-volume tiles: depth read-back");
        constexpr double kScale = 1.0 / 16777215.0;
        for (size_t i = 0; i < pixels; ++i) readback_[i] = float(double(packed_[i] >> 8) * kScale);
    } else {
        glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, readback_.data());
        checkGl("light-volume tiles: depth read-back");
    }
    return readback_;
}

uint32_t VolumeTiles::slicesReached(int tile, const glm::vec3& c, float radius, float nearDepth, float farDepth) const {
    const float lo = minDepth_[size_t(tile)], hi = maxDepth_[size_t(tile)];
    if (!(hi > lo) || farDepth < lo || nearDepth > hi) return 0;
    const float scale = float(kSlices) / (hi - lo);
    // Slices are widened by one on each side: the pixels' slices were found with the same float formula, so a
    // depth on a slice boundary may have landed on either side of it.
    const int first = std::clamp(int(std::floor((nearDepth - lo) * scale)) - 1, 0, kSlices - 1);
    const int last = std::clamp(int(std::floor((farDepth - lo) * scale)) + 1, 0, kSlices - 1);
    const uint32_t occupied = slices_[size_t(tile)] & sliceMask(first, last);
    if (occupied == 0) return 0;
    // The tile's corner slopes; a cell between distances D0 < D1 spans x in [min(sx0 D0, sx0 D1), max(sx1 D0,
    // sx1 D1)] (x = slope * distance), the same in y, and z in [-D1, -D0].
    const int tx = tile % tilesX_, ty = tile / tilesX_;
    const float sx0 = slopeX_[size_t(tx)], sx1 = slopeX_[size_t(tx) + 1];
    const float sy0 = slopeY_[size_t(ty)], sy1 = slopeY_[size_t(ty) + 1];
    const float r2 = radius * radius * (1.0f + 1e-4f) + 1e-12f;
    const float slack = 1e-5f * (std::abs(c.x) + std::abs(c.y) + std::abs(c.z) + radius);
    const float reach2 = r2 + 2.0f * radius * slack + slack * slack;
    const glm::vec2* distances = sliceDistances_.data() + size_t(tile) * size_t(kSlices);
    uint32_t reached = 0;
    for (uint32_t bits = occupied; bits != 0; bits &= bits - 1) {
        const int s = __builtin_ctz(bits);
        const float D0 = distances[s].x, D1 = distances[s].y;
        const glm::vec3 boxMin(std::min(sx0 * D0, sx0 * D1), std::min(sy0 * D0, sy0 * D1), -D1);
        const glm::vec3 boxMax(std::max(sx1 * D0, sx1 * D1), std::max(sy1 * D0, sy1 * D1), -D0);
        const glm::vec3 e = c - glm::clamp(c, boxMin, boxMax);
        if (glm::dot(e, e) <= reach2) reached |= 1u << s;
    }
    return reached;
}

bool VolumeTiles::sphereDepthSpan(const CameraMatrices& camera, const glm::vec3& centre, float radius,
                                  float& nearDepth, float& farDepth) {
    // Distance along the view direction -> window depth, for lidr's perspective projections:
    // d = (P22 - 1) / 2 * -1 ... written as d = x / distance - y with (x, y) the sphere shader's uDepthToDistance.
    const glm::mat4& P = camera.projection;
    const double x = 0.5 * double(P[3][2]), y = 0.5 * (double(P[2][2]) - 1.0);
    const double along = double(glm::dot(centre - camera.eye, camera.forward));
    const double slack = 1e-5 * (std::abs(along) + double(radius)) + 1e-6;
    const double nearest = along - double(radius) - slack, farthest = along + double(radius) + slack;
    if (farthest <= 0.0) return false;
    auto windowDepth = [&](double distance) { return distance <= 0.0 ? -1.0 : x / distance - y; };
    nearDepth = float(std::max(0.0, windowDepth(nearest)) - kDepthSlack);
    farDepth = float(std::min(1.0, windowDepth(farthest)) + kDepthSlack);
    return true;
}

}  // namespace lidr
