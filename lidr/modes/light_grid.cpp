#include "lidr/modes/light_grid.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/scene/sphere_bounds.h"

namespace lidr {

namespace {
// Window-depth slack around a tile's reduced range: the colour copy of depth that is reduced is the
// unrounded fragment depth, the depth buffer keeps 24 bits, and the RGBA8 fallback rounds once more; a few
// 2^-24 steps cover all of it, 1e-6 is about 17.
constexpr float kWindowDepthSlack = 1e-6f;
constexpr double kRelativeViewDepthSlack = 1e-5;
}  // namespace

ViewCone viewCone(const CameraMatrices& camera, const PointLight& l, float range) {
    ViewCone c;
    c.apex = glm::vec3(camera.view * glm::vec4(l.position, 1.0f));
    c.axis = glm::normalize(glm::vec3(camera.view * glm::vec4(glm::normalize(l.direction), 0.0f)));
    c.range = range;
    const double angle = spotBoundingConeAngle(l.outerConeAngle);
    c.cosAngle = float(std::cos(angle));
    c.sinAngle = float(std::sin(angle));
    return c;
}

bool coneMayReachSphere(const ViewCone& c, const glm::vec3& centre, float radius) {
    const glm::vec3 v = centre - c.apex;
    const float along = glm::dot(v, c.axis);
    const float across = std::sqrt(std::max(0.0f, glm::dot(v, v) - along * along));
    if (c.cosAngle * across - along * c.sinAngle > radius) return false;  // outside the side
    if (along > c.range + radius) return false;
    return along >= -radius;
}

LightGrid::LightGrid(int width, int height, int tileSize) : width_(width), height_(height), tileSize_(tileSize) {
    if (width <= 0 || height <= 0)
        throw Error("light grid: resolution must be positive, got " + std::to_string(width) + "x" +
                    std::to_string(height));
    if (tileSize < 1) throw Error("tile size must be at least 1 pixel, got " + std::to_string(tileSize));
    if (tileSize > width || tileSize > height)
        throw Error("tile size " + std::to_string(tileSize) + " is larger than the " + std::to_string(width) + "x" +
                    std::to_string(height) + " screen");
    tilesX_ = (width + tileSize - 1) / tileSize;
    tilesY_ = (height + tileSize - 1) / tileSize;
}

namespace {
// Per tile, the view-space depth interval its geometry can have (opaque: [min, max], transparent: [near, max]);
// widened by the slack so that pruning never drops a light that touches a pixel. With half-Z, the gap
// (gapStart, gapEnd) between the two halves holds no geometry. Without depth ranges: the camera's.
struct TileDepthIntervals {
    std::vector<float> near, far, gapStart, gapEnd;
    TileDepthIntervals(const CameraMatrices& camera, const std::vector<TileDepthRange>* depth, int tiles)
        : near(size_t(tiles), camera.nearPlane), far(size_t(tiles), camera.farPlane), gapStart(size_t(tiles), 0.0f),
          gapEnd(size_t(tiles), 0.0f) {
        if (!depth) return;
        auto nearer = [&](float d) {  // view distance of window depth d, moved towards the eye by the slack
            return float(viewDepthFromWindowDepth(camera, std::clamp(d - kWindowDepthSlack, 0.0f, 1.0f)) *
                         (1.0 - kRelativeViewDepthSlack));
        };
        auto farther = [&](float d) {
            return float(viewDepthFromWindowDepth(camera, std::clamp(d + kWindowDepthSlack, 0.0f, 1.0f)) *
                         (1.0 + kRelativeViewDepthSlack));
        };
        for (int t = 0; t < tiles; ++t) {
            const TileDepthRange& r = (*depth)[size_t(t)];
            near[size_t(t)] = nearer(r.minDepth);
            far[size_t(t)] = farther(r.maxDepth);
            if (r.split) {
                gapStart[size_t(t)] = farther(std::max(r.nearMaxDepth, r.minDepth));
                gapEnd[size_t(t)] = nearer(std::min(r.farMinDepth, r.maxDepth));
            }
        }
    }
};

// Spot lights: a tile's cell (its pixels' rays between two view depths) is bounded by a sphere, and the cone
// tested against it. The tile's corner rays in view space, as the points where they cross view depth 1 and 2
// (a point at view depth d is then lerp(at1, at2, d - 1): exact for perspective and orthographic alike).
class TileCells {
public:
    TileCells(const CameraMatrices& camera, int tilesX, int tilesY, int tileSize, float radiusMargin)
        : radiusMargin_(radiusMargin) {
        const glm::mat4 inverseProjection = glm::inverse(camera.projection);
        const auto viewPointAtDepth = [&](float ndcX, float ndcY, float depth) {
            const glm::vec4 a = inverseProjection * glm::vec4(ndcX, ndcY, -1.0f, 1.0f), b = inverseProjection * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);
            const glm::vec3 pa = glm::vec3(a) / a.w, pb = glm::vec3(b) / b.w;
            return pa + (pb - pa) * ((depth + pa.z) / (pa.z - pb.z));
        };
        cornerAt1_.resize(size_t(tilesX * tilesY) * 4);
        cornerAt2_.resize(size_t(tilesX * tilesY) * 4);
        for (int ty = 0; ty < tilesY; ++ty)
            for (int tx = 0; tx < tilesX; ++tx)
                for (int k = 0; k < 4; ++k) {
                    const float px = float(std::min((tx + (k & 1)) * tileSize, camera.width));
                    const float py = float(std::min((ty + (k >> 1)) * tileSize, camera.height));
                    const float ndcX = px / float(camera.width) * 2.0f - 1.0f, ndcY = py / float(camera.height) * 2.0f - 1.0f;
                    const size_t at = size_t(ty * tilesX + tx) * 4 + size_t(k);
                    cornerAt1_[at] = viewPointAtDepth(ndcX, ndcY, 1.0f);
                    cornerAt2_[at] = viewPointAtDepth(ndcX, ndcY, 2.0f);
                }
    }

    // A deep cell's sphere is far wider than the cell: where the whole cell's passes, its 4 slices (equal depth
    // ratios) are tried, and the cone must reach one of them.
    bool cellMayHoldCone(const ViewCone& cone, int t, float nearDepth, float farDepth) const {
        if (!sliceMayHoldCone(cone, t, nearDepth, farDepth)) return false;
        if (!(farDepth > nearDepth * 1.25f) || !(nearDepth > 0.0f)) return true;
        const float ratio = std::pow(farDepth / nearDepth, 0.25f);
        float sliceNear = nearDepth;
        for (int k = 0; k < 4; ++k) {
            const float sliceFar = k == 3 ? farDepth : sliceNear * ratio;
            if (sliceMayHoldCone(cone, t, sliceNear, sliceFar)) return true;
            sliceNear = sliceFar;
        }
        return false;
    }

private:
    // The bounding sphere of tile t's cell between view depths near and far (centre: the corners' mean).
    bool sliceMayHoldCone(const ViewCone& cone, int t, float nearDepth, float farDepth) const {
        glm::vec3 corners[8];
        glm::vec3 centre(0.0f);
        for (int k = 0; k < 4; ++k) {
            const glm::vec3 a = cornerAt1_[size_t(t) * 4 + size_t(k)], step = cornerAt2_[size_t(t) * 4 + size_t(k)] - a;
            corners[k] = a + step * (nearDepth - 1.0f);
            corners[k + 4] = a + step * (farDepth - 1.0f);
            centre += corners[k] + corners[k + 4];
        }
        centre *= 0.125f;
        float radius = 0.0f;
        for (const glm::vec3& corner : corners) radius = std::max(radius, glm::length(corner - centre));
        // Grown by the margin that covers a quantised light table (a moved apex) and a hair of rounding.
        return coneMayReachSphere(cone, centre, radius * (1.0f + 1e-5f) + 1e-6f * farDepth + radiusMargin_);
    }

    float radiusMargin_;
    std::vector<glm::vec3> cornerAt1_, cornerAt2_;
};
}  // namespace

void LightGrid::build(const CameraMatrices& camera, const std::vector<PointLight>& lights,
                      const std::vector<TileDepthRange>* depth, bool transparentLists, float radiusMargin) {
    if (camera.width != width_ || camera.height != height_)
        throw Error("light grid: camera is " + std::to_string(camera.width) + "x" + std::to_string(camera.height) +
                    ", grid was made for " + std::to_string(width_) + "x" + std::to_string(height_));
    if (lights.size() > 65535)
        throw Error("light grid: " + std::to_string(lights.size()) + " lights, 16-bit light indices hold 65535");
    if (depth && depth->size() != size_t(tileCount()))
        throw Error("light grid: " + std::to_string(depth->size()) + " depth ranges for " +
                    std::to_string(tileCount()) + " tiles");
    const int tiles = tileCount();
    const bool separate = depth && transparentLists;
    const TileDepthIntervals interval(camera, depth, tiles);
    bool anySpot = false;
    for (const PointLight& l : lights) anySpot = anySpot || l.isSpot();
    const std::unique_ptr<TileCells> cells =
        anySpot ? std::make_unique<TileCells>(camera, tilesX_, tilesY_, tileSize_, radiusMargin) : nullptr;

    std::vector<std::vector<uint32_t>> opaque(static_cast<size_t>(tiles)), transparent(separate ? size_t(tiles) : 0);
    stats_ = LightGridStats{};
    for (size_t i = 0; i < lights.size(); ++i) {
        const PointLight& l = lights[i];
        const float radius = l.radius + radiusMargin;
        const SphereBounds b = projectSphereBounds(camera, l.position, radius);
        glm::ivec4 rect;
        if (!b.visible || !spherePixelRect(camera, l.position, radius, rect)) continue;
        const bool spot = l.isSpot();
        const ViewCone cone = spot ? viewCone(camera, l, radius) : ViewCone{};
        bool used = false;
        for (int ty = rect.y / tileSize_; ty <= rect.w / tileSize_; ++ty)
            for (int tx = rect.x / tileSize_; tx <= rect.z / tileSize_; ++tx) {
                const int t = ty * tilesX_ + tx;
                const size_t u = size_t(t);
                if (depth && b.viewDepthMin > interval.far[u]) continue;  // hidden behind the tile's opaque max
                // A spot light whose cone misses the tile's cell (from the near plane: the transparent lists').
                if (spot && !cells->cellMayHoldCone(cone, t, camera.nearPlane, interval.far[u])) continue;
                if (separate) transparent[u].push_back(uint32_t(i + 1)), used = true;
                if (depth && b.viewDepthMax < interval.near[u]) continue;  // wholly in front of the opaque min
                if (b.viewDepthMin > interval.gapStart[u] && b.viewDepthMax < interval.gapEnd[u]) continue;  // half-Z gap
                if (spot && depth && !cells->cellMayHoldCone(cone, t, interval.near[u], interval.far[u])) continue;
                opaque[u].push_back(uint32_t(i + 1));
                used = true;
            }
        if (used) ++stats_.assignedLights;
    }
    layOut(opaque, separate ? &transparent : nullptr);
}

void LightGrid::layOut(const std::vector<std::vector<uint32_t>>& opaque,
                       const std::vector<std::vector<uint32_t>>* transparent) {
    const int tiles = tileCount();
    entries_.assign(1, 0u);  // entry 0: the shared empty list
    auto lay = [&](const std::vector<std::vector<uint32_t>>& lists, std::vector<uint32_t>& offsets,
                   std::vector<int>& counts, int& maxCount, long& total) {
        offsets.assign(size_t(tiles), 0u);
        counts.assign(size_t(tiles), 0);
        for (int t = 0; t < tiles; ++t) {
            const std::vector<uint32_t>& list = lists[size_t(t)];
            counts[size_t(t)] = int(list.size());
            maxCount = std::max(maxCount, counts[size_t(t)]);
            total += long(list.size());
            if (list.empty()) continue;
            offsets[size_t(t)] = uint32_t(entries_.size());
            entries_.insert(entries_.end(), list.begin(), list.end());  // ascending: lights were visited in order
            entries_.push_back(0u);
        }
    };
    lay(opaque, opaqueOffset_, opaqueCount_, stats_.maxOpaqueLights, stats_.opaqueEntries);
    if (transparent) {
        lay(*transparent, transparentOffset_, transparentCount_, stats_.maxTransparentLights, stats_.transparentEntries);
    } else {
        transparentOffset_ = opaqueOffset_;
        transparentCount_ = opaqueCount_;
        stats_.maxTransparentLights = stats_.maxOpaqueLights;
        stats_.transparentEntries = stats_.opaqueEntries;
    }
}

std::vector<uint32_t> LightGrid::opaqueList(int tile) const {
    const auto first = entries_.begin() + opaqueOffset_.at(tile);
    return std::vector<uint32_t>(first, first + opaqueCount_.at(tile));
}

std::vector<uint32_t> LightGrid::transparentList(int tile) const {
    const auto first = entries_.begin() + transparentOffset_.at(tile);
    return std::vector<uint32_t>(first, first + transparentCount_.at(tile));
}

// --- GPU side ---------------------------------------------------------------------------------------

LightGridTextures::LightGridTextures(const GlInfo& info, int tilesX, int tilesY) : tilesX_(tilesX), tilesY_(tilesY) {
    if (tilesX > info.maxTextureSize || tilesY > info.maxTextureSize)
        throw Error("light grid of " + std::to_string(tilesX) + "x" + std::to_string(tilesY) +
                    " tiles exceeds the driver's texture size " + std::to_string(info.maxTextureSize));
    list_ = LightListTexture(info, {"light grid", "tiled", "tile", "larger tiles or fewer lights"}, 16);
    opaqueGrid_ = gl::Texture::create2D(GL_RGBA8, tilesX, tilesY, GL_RGBA, GL_UNSIGNED_BYTE);
    transparentGrid_ = gl::Texture::create2D(GL_RGBA8, tilesX, tilesY, GL_RGBA, GL_UNSIGNED_BYTE);
}

void LightGridTextures::upload(const LightGrid& grid) {
    if (grid.tilesX() != tilesX_ || grid.tilesY() != tilesY_) throw Error("light grid textures: grid size changed");
    list_.upload(grid.entries(), 16);
    auto gridBytes = [&](const std::vector<uint32_t>& offsets) {
        std::vector<uint8_t> b(offsets.size() * 4, 0);
        for (size_t t = 0; t < offsets.size(); ++t) putListOffset(&b[t * 4], offsets[t]);
        return b;
    };
    opaqueGrid_.upload(tilesX_, tilesY_, GL_RGBA, GL_UNSIGNED_BYTE, gridBytes(grid.opaqueOffsets()).data());
    transparentGrid_.upload(tilesX_, tilesY_, GL_RGBA, GL_UNSIGNED_BYTE, gridBytes(grid.transparentOffsets()).data());
    StateCache::current().bindTexture(GL_TEXTURE_2D, 0);
    checkGl("LightGridTextures::upload");
}

void LightGridTextures::bind(const gl::Program& program, bool transparent) const {
    (transparent ? transparentGrid_ : opaqueGrid_).bind(gl::kUnitTileGrid);
    list_.texture().bind(gl::kUnitTileList);
    glActiveTexture(GL_TEXTURE0);
    program.set("uTileGrid", gl::kUnitTileGrid);
    program.set("uLightList", gl::kUnitTileList);
    program.set("uTileGridSize", glm::vec2(float(tilesX_), float(tilesY_)));
    program.set("uLightListRows", float(list_.rows()));
}

size_t LightGridTextures::gridBytes() const { return size_t(tilesX_) * tilesY_ * 4 * 2; }

}  // namespace lidr
