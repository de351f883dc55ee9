#include "lidr/modes/light_grid.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <cmath>

#include "lidr/base/error.h"
#include "lidr/scene/sphere_bounds.h"

namespace lidr {

namespace {
// Window-depth slack around a tile's reduced range: the colour copy of depth that is reduced is the
// unrounded fragment depth, the depth buffer keeps 24 bits, and the RGBA8 fallback rounds once more; a few
// 2^-24 steps cover all of it, 1e-6 is about 17.
constexpr float kWindowDepthSlack = 1e-6f;
constexpr double kRelativeViewDepthSlack = 1e-5;
}  // namespace

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

    // Per tile, the view-space depth interval its geometry can have (opaque: [min, max], transparent:
    // [near, max]); widened by the slack so that pruning never drops a light that touches a pixel.
    // With half-Z, the gap (gapStart, gapEnd) between the two halves holds no geometry.
    std::vector<float> tileNear(tiles, camera.nearPlane), tileFar(tiles, camera.farPlane);
    std::vector<float> gapStart(tiles, 0.0f), gapEnd(tiles, 0.0f);
    auto nearer = [&](float d) {  // view distance of window depth d, moved towards the eye by the slack
        return float(viewDepthFromWindowDepth(camera, std::clamp(d - kWindowDepthSlack, 0.0f, 1.0f)) *
                     (1.0 - kRelativeViewDepthSlack));
    };
    auto farther = [&](float d) {
        return float(viewDepthFromWindowDepth(camera, std::clamp(d + kWindowDepthSlack, 0.0f, 1.0f)) *
                     (1.0 + kRelativeViewDepthSlack));
    };
    if (depth) {
        for (int t = 0; t < tiles; ++t) {
            const TileDepthRange& r = (*depth)[t];
            tileNear[t] = nearer(r.minDepth);
            tileFar[t] = farther(r.maxDepth);
            if (r.split) {
                gapStart[t] = farther(std::max(r.nearMaxDepth, r.minDepth));
                gapEnd[t] = nearer(std::min(r.farMinDepth, r.maxDepth));
            }
        }
    }

    std::vector<std::vector<uint32_t>> opaque(tiles), transparent(separate ? tiles : 0);
    stats_ = LightGridStats{};
    for (size_t i = 0; i < lights.size(); ++i) {
        const PointLight& l = lights[i];
        const float radius = l.radius + radiusMargin;
        const SphereBounds b = projectSphereBounds(camera, l.position, radius);
        glm::ivec4 rect;
        if (!b.visible || !spherePixelRect(camera, l.position, radius, rect)) continue;
        bool used = false;
        for (int ty = rect.y / tileSize_; ty <= rect.w / tileSize_; ++ty)
            for (int tx = rect.x / tileSize_; tx <= rect.z / tileSize_; ++tx) {
                const int t = ty * tilesX_ + tx;
                if (depth && b.viewDepthMin > tileFar[t]) continue;  // hidden behind the tile's opaque max
                if (separate) transparent[t].push_back(uint32_t(i + 1)), used = true;
                if (depth && b.viewDepthMax < tileNear[t]) continue;  // wholly in front of the opaque min
                if (b.viewDepthMin > gapStart[t] && b.viewDepthMax < gapEnd[t]) continue;  // in the half-Z gap
                opaque[t].push_back(uint32_t(i + 1));
                used = true;
            }
        if (used) ++stats_.assignedLights;
    }

    entries_.assign(1, 0u);  // entry 0: the shared empty list
    auto lay = [&](std::vector<std::vector<uint32_t>>& lists, std::vector<uint32_t>& offsets, std::vector<int>& counts,
                   int& maxCount, long& total) {
        offsets.assign(tiles, 0u);
        counts.assign(tiles, 0);
        for (int t = 0; t < tiles; ++t) {
            const std::vector<uint32_t>& list = lists[t];
            counts[t] = int(list.size());
            maxCount = std::max(maxCount, counts[t]);
            total += long(list.size());
            if (list.empty()) continue;
            offsets[t] = uint32_t(entries_.size());
            entries_.insert(entries_.end(), list.begin(), list.end());  // ascending: lights were visited in order
            entries_.push_back(0u);
        }
    };
    lay(opaque, opaqueOffset_, opaqueCount_, stats_.maxOpaqueLights, stats_.opaqueEntries);
    if (separate) {
        lay(transparent, transparentOffset_, transparentCount_, stats_.maxTransparentLights, stats_.transparentEntries);
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

LightGridTextures::LightGridTextures(const GlInfo& info, int tilesX, int tilesY)
    : maxTextureSize_(info.maxTextureSize), tilesX_(tilesX), tilesY_(tilesY) {
    if (tilesX > info.maxTextureSize || tilesY > info.maxTextureSize)
        throw Error("light grid of " + std::to_string(tilesX) + "x" + std::to_string(tilesY) +
                    " tiles exceeds the driver's texture size " + std::to_string(info.maxTextureSize));
    if (kListWidth > info.maxTextureSize)
        throw UnsupportedError("this driver's textures are at most " + std::to_string(info.maxTextureSize) +
                               " texels wide; the tiled light list needs " + std::to_string(kListWidth));
    opaqueGrid_ = gl::Texture::create2D(GL_RGBA8, tilesX, tilesY, GL_RGBA, GL_UNSIGNED_BYTE);
    transparentGrid_ = gl::Texture::create2D(GL_RGBA8, tilesX, tilesY, GL_RGBA, GL_UNSIGNED_BYTE);
}

void LightGridTextures::upload(const LightGrid& grid) {
    if (grid.tilesX() != tilesX_ || grid.tilesY() != tilesY_) throw Error("light grid textures: grid size changed");
    const size_t entries = grid.entries().size();
    if (entries > (size_t(1) << 24))
        throw Error("light grid: " + std::to_string(entries) +
                    " list entries exceed the 2^24 that 24-bit tile offsets address; use larger tiles or fewer lights");
    const int rowsNeeded = int((entries + kListWidth - 1) / kListWidth);
    if (rowsNeeded > listRows_) {  // grow: double until it fits, so growth is rare
        int rows = std::max(listRows_, 1);
        while (rows < rowsNeeded) rows *= 2;
        rows = std::min(rows, maxTextureSize_);
        if (rows < rowsNeeded)
            throw Error("light grid: " + std::to_string(entries) + " list entries exceed the driver's largest " +
                        std::to_string(kListWidth) + "x" + std::to_string(maxTextureSize_) + " list texture");
        list_ = gl::Texture::create2D(GL_LUMINANCE8_ALPHA8, kListWidth, rows, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE);
        listRows_ = rows;
    }
    std::vector<uint8_t> listBytes(size_t(rowsNeeded) * kListWidth * 2, 0);
    for (size_t k = 0; k < entries; ++k) {
        const uint32_t v = grid.entries()[k];
        listBytes[k * 2] = uint8_t(v >> 8);
        listBytes[k * 2 + 1] = uint8_t(v & 0xFF);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBindTexture(GL_TEXTURE_2D, list_.id());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kListWidth, rowsNeeded, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE,
                    listBytes.data());
    auto gridBytes = [&](const std::vector<uint32_t>& offsets) {
        std::vector<uint8_t> b(offsets.size() * 4, 0);
        for (size_t t = 0; t < offsets.size(); ++t) {
            b[t * 4] = uint8_t(offsets[t] >> 16);
            b[t * 4 + 1] = uint8_t(offsets[t] >> 8);
            b[t * 4 + 2] = uint8_t(offsets[t]);
        }
        return b;
    };
    const std::vector<uint8_t> opaque = gridBytes(grid.opaqueOffsets());
    glBindTexture(GL_TEXTURE_2D, opaqueGrid_.id());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, tilesX_, tilesY_, GL_RGBA, GL_UNSIGNED_BYTE, opaque.data());
    const std::vector<uint8_t> transparent = gridBytes(grid.transparentOffsets());
    glBindTexture(GL_TEXTURE_2D, transparentGrid_.id());
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, tilesX_, tilesY_, GL_RGBA, GL_UNSIGNED_BYTE, transparent.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    checkGl("LightGridTextures::upload");
}

void LightGridTextures::bind(const gl::Program& program, bool transparent) const {
    (transparent ? transparentGrid_ : opaqueGrid_).bind(gl::kUnitTileGrid);
    list_.bind(gl::kUnitTileList);
    glActiveTexture(GL_TEXTURE0);
    program.set("uTileGrid", gl::kUnitTileGrid);
    program.set("uLightList", gl::kUnitTileList);
    program.set("uTileGridSize", glm::vec2(float(tilesX_), float(tilesY_)));
    program.set("uLightListRows", float(listRows_));
}

size_t LightGridTextures::gridBytes() const { return size_t(tilesX_) * tilesY_ * 4 * 2; }
size_t LightGridTextures::listBytes() const { return size_t(kListWidth) * listRows_ * 2; }

}  // namespace lidr
