#include "lidr/render/light_table.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <cmath>

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"

namespace lidr {

LightTable::LightTable(const GlInfo& info, int capacity, bool forceFixed16)
    : format_(info.textureFloat && !forceFixed16 ? LightTableFormat::Float : LightTableFormat::Fixed16),
      capacity_(capacity),
      rows_((capacity + 1 + kWidth - 1) / kWidth) {
    if (capacity < 0 || capacity > 65535) throw Error("light table capacity must be 0..65535");
    for (TextureSet& set : sets_) {
        if (format_ == LightTableFormat::Float) {
            set.posRadius = gl::Texture::create2D(GL_RGBA32F_ARB, kWidth, 2 * rows_, GL_RGBA, GL_FLOAT);
            set.color = gl::Texture::create2D(GL_RGBA32F_ARB, kWidth, 2 * rows_, GL_RGBA, GL_FLOAT);
        } else {
            set.posRadius = gl::Texture::create2D(GL_RGBA8, kWidth, 2 * rows_, GL_RGBA, GL_UNSIGNED_BYTE);
            set.posRadiusLow = gl::Texture::create2D(GL_RGBA8, kWidth, 2 * rows_, GL_RGBA, GL_UNSIGNED_BYTE);
            set.color = gl::Texture::create2D(GL_RGBA8, kWidth, 2 * rows_, GL_RGBA, GL_UNSIGNED_BYTE);
        }
    }
}

FixedColor fixedInverseSquareColor(const glm::vec3& color, bool spot) {
    // The exponent puts the brightest channel in [0.5, 1) of 2^e, so it keeps at least 7 of its 8 bits.
    const float brightest = std::max({color.r, color.g, color.b});
    int exponent = -63;
    if (brightest > 0.0f) std::frexp(brightest, &exponent);
    exponent = std::clamp(exponent, -63, 63);
    FixedColor out;
    for (int c = 0; c < 3; ++c)
        out.bytes[c] =
            static_cast<uint8_t>(std::lround(std::clamp(std::ldexp(color[c], -exponent), 0.0f, 1.0f) * 255.0f));
    out.bytes[3] = static_cast<uint8_t>(1 + (spot ? 127 : 0) + exponent + 63);
    out.decoded = glm::vec3(out.bytes[0], out.bytes[1], out.bytes[2]) / 255.0f * std::ldexp(1.0f, exponent);
    return out;
}

size_t LightTable::bytes() const {
    const size_t texels = size_t(kWidth) * rows_;
    // Two row blocks (the light, its spot cone) of two RGBA32F or three RGBA8 textures, in each of the two sets.
    return 2 * 2 * (format_ == LightTableFormat::Float ? texels * 32 : texels * 12);
}

float LightTable::reachError() const {
    if (format_ == LightTableFormat::Float) return 0.0f;
    return (0.5f * glm::length(boundsExtent_) + radiusScale_) / 65535.0f * 1.01f;  // 1 %: float rounding here
}

ShaderDefines LightTable::defines() const {
    if (format_ == LightTableFormat::Fixed16) return {{"LIDR_LIGHT_TABLE_FIXED16", "1"}};
    return {};
}

void LightTable::setRegionMap(std::vector<float> tileRows, int firstRow, int tileSize, int tilesX) {
    if (!tileRows.empty() &&
        (format_ != LightTableFormat::Float ||
         size_t(firstRow) * kWidth + tileRows.size() > size_t(kWidth) * size_t(rows_) || firstRow < 0))
        throw Error("light table: no room for the region map (" + std::to_string(tileRows.size()) + " tiles from row " +
                    std::to_string(firstRow) + " of " + std::to_string(rows_) + ")");
    regionMap_ = std::move(tileRows);
    regionMapFirstRow_ = firstRow;
    regionMapUniform_ = regionMap_.empty() ? glm::vec4(0.0f)
                                           : glm::vec4(1.0f / float(tileSize), float(tilesX), float(firstRow), 1.0f);
}

namespace {
// Light i's shadow tile + 1 as the table stores it (lidrFetchShadowTile; 0: none).
int shadowTileCode(const std::vector<int>& shadowTiles, size_t i) {
    return shadowTiles.empty() ? 0 : std::clamp(shadowTiles[i] + 1, 0, 65535);
}
}  // namespace

void LightTable::update(const std::vector<PointLight>& lights, const std::vector<int>& shadowTiles) {
    if (static_cast<int>(lights.size()) > capacity_)
        throw Error("light table holds " + std::to_string(capacity_) + " lights, scene has " +
                    std::to_string(lights.size()));
    if (!shadowTiles.empty() && shadowTiles.size() != lights.size())
        throw Error("light table: " + std::to_string(shadowTiles.size()) + " shadow tiles for " +
                    std::to_string(lights.size()) + " lights");
    count_ = static_cast<int>(lights.size());
    current_ ^= 1;
    if (format_ == LightTableFormat::Float)
        uploadFloat(lights, shadowTiles);
    else
        uploadFixed(lights, shadowTiles);
    StateCache::current().bindTexture(GL_TEXTURE_2D, 0);
    checkGl("LightTable::update");
}

void LightTable::uploadFloat(const std::vector<PointLight>& lights, const std::vector<int>& shadowTiles) {
    const TextureSet& set = sets_[current_];
    const size_t texels = size_t(kWidth) * rows_;
    // The null light (index 0) and unused entries: black, radius 1, so they add exactly nothing. Rows
    // [rows, 2 rows) of the position texture hold the spot cone (spotCone(): (0, 0, 0, 1) for a point light);
    // every texture has both blocks, so one texture coordinate addresses all (the colour's second is unused).
    std::vector<float> pos(texels * 8, 0.0f), col(texels * 8, 0.0f);
    for (size_t i = 0; i < 2 * texels; ++i) pos[i * 4 + 3] = 1.0f;
    for (size_t i = 0; i < lights.size(); ++i) {
        const PointLight& l = lights[i];
        float* p = &pos[(i + 1) * 4];
        p[0] = l.position.x, p[1] = l.position.y, p[2] = l.position.z;
        p[3] = l.falloff == LightFalloff::InverseSquare ? -l.radius : l.radius;  // the sign lidrShadeLight reads
        const glm::vec4 cone = spotCone(l);
        float* q = &pos[(texels + i + 1) * 4];
        q[0] = cone.x, q[1] = cone.y, q[2] = cone.z, q[3] = cone.w;
        float* c = &col[(i + 1) * 4];
        c[0] = l.color.r, c[1] = l.color.g, c[2] = l.color.b, c[3] = l.isSpot() ? 0.0f : 1.0f;  // 0: read the cone
        col[(texels + i + 1) * 4 + 2] = float(shadowTileCode(shadowTiles, i));
    }
    if (!regionMap_.empty() && size_t(regionMapFirstRow_) * kWidth < lights.size() + 1)
        throw Error("light table: the region map would overwrite lights");
    for (size_t t = 0; t < regionMap_.size(); ++t) pos[(size_t(regionMapFirstRow_) * kWidth + t) * 4] = regionMap_[t];
    set.posRadius.upload(kWidth, 2 * rows_, GL_RGBA, GL_FLOAT, pos.data());
    set.color.upload(kWidth, 2 * rows_, GL_RGBA, GL_FLOAT, col.data());
}

void LightTable::setFixedScales(const std::vector<PointLight>& lights) {
    glm::vec3 lo(0.0f), hi(1.0f);
    float maxRadius = 1.0f, maxColor = 1.0f;
    if (!lights.empty()) {
        lo = hi = lights[0].position;
        maxRadius = maxColor = 0.0f;
        for (const PointLight& l : lights) {
            lo = glm::min(lo, l.position);
            hi = glm::max(hi, l.position);
            maxRadius = std::max(maxRadius, l.radius);
            if (l.falloff == LightFalloff::Smooth) maxColor = std::max({maxColor, l.color.r, l.color.g, l.color.b});
        }
    }
    boundsMin_ = lo;
    boundsExtent_ = glm::max(hi - lo, glm::vec3(1e-6f));
    radiusScale_ = std::max(maxRadius, 1e-6f);
    colorScale_ = std::max(maxColor, 1e-6f);
}

void LightTable::uploadFixed(const std::vector<PointLight>& lights, const std::vector<int>& shadowTiles) {
    setFixedScales(lights);
    const TextureSet& set = sets_[current_];
    const size_t texels = size_t(kWidth) * rows_;
    // Rows [rows, 2 rows): the spot cone, 16-bit fractions: high/low bytes of the axis as (d + 1) / 2 and
    // cos(outer cone angle) in the position textures, cos(inner) in the colour texture's red and green; the
    // colour's alpha is 0 for a spot light (255: a point light, whose cone is not read: its term is 1).
    std::vector<uint8_t> high(texels * 8, 0), low(texels * 8, 0), col(texels * 8, 0);
    auto put16 = [&](size_t at, float unit) {
        const int v = static_cast<int>(std::lround(std::clamp(unit, 0.0f, 1.0f) * 65535.0f));
        high[at] = static_cast<uint8_t>(v >> 8);
        low[at] = static_cast<uint8_t>(v & 0xFF);
    };
    put16(3, 1.0f);  // null light: radius = the scale, black, a point light
    col[3] = 255;
    for (size_t i = 0; i < lights.size(); ++i) {
        const PointLight& l = lights[i];
        const glm::vec3 unit = (l.position - boundsMin_) / boundsExtent_;
        const size_t t = (i + 1) * 4;
        put16(t + 0, unit.x);
        put16(t + 1, unit.y);
        put16(t + 2, unit.z);
        // Round the radius up so the fixed-point light never reaches less far than the real one.
        const int r = static_cast<int>(std::ceil(l.radius / radiusScale_ * 65535.0f));
        high[t + 3] = static_cast<uint8_t>(std::min(r, 65535) >> 8);
        low[t + 3] = static_cast<uint8_t>(std::min(r, 65535) & 0xFF);
        if (l.falloff == LightFalloff::InverseSquare) {
            const FixedColor fixed = fixedInverseSquareColor(l.color, l.isSpot());
            for (int c = 0; c < 4; ++c) col[t + size_t(c)] = fixed.bytes[c];
        } else {
            for (int c = 0; c < 3; ++c)
                col[t + c] =
                    static_cast<uint8_t>(std::lround(std::clamp(l.color[c] / colorScale_, 0.0f, 1.0f) * 255.0f));
            col[t + 3] = l.isSpot() ? 0 : 255;  // 0: read the cone
        }
        const size_t cone = (texels + i + 1) * 4;
        const int tile = shadowTileCode(shadowTiles, i);
        col[cone + 2] = static_cast<uint8_t>(tile & 0xFF);
        col[cone + 3] = static_cast<uint8_t>(tile >> 8);
        if (!l.isSpot()) continue;
        const glm::vec3 axis = glm::normalize(l.direction);
        for (int c = 0; c < 3; ++c) put16(cone + size_t(c), (axis[c] + 1.0f) * 0.5f);
        put16(cone + 3, std::cos(l.outerConeAngle));
        const int inner = static_cast<int>(std::lround(std::clamp(std::cos(l.innerConeAngle), 0.0f, 1.0f) * 65535.0f));
        col[cone + 0] = static_cast<uint8_t>(inner >> 8);
        col[cone + 1] = static_cast<uint8_t>(inner & 0xFF);
    }
    set.posRadius.upload(kWidth, 2 * rows_, GL_RGBA, GL_UNSIGNED_BYTE, high.data());
    set.posRadiusLow.upload(kWidth, 2 * rows_, GL_RGBA, GL_UNSIGNED_BYTE, low.data());
    set.color.upload(kWidth, 2 * rows_, GL_RGBA, GL_UNSIGNED_BYTE, col.data());
}

void LightTable::bind(const gl::Program& program) const {
    const TextureSet& set = sets_[current_];
    set.posRadius.bind(gl::kUnitLightPosRadius);
    set.color.bind(gl::kUnitLightColor);
    program.set("uLightPosRadius", gl::kUnitLightPosRadius);
    program.set("uLightColor", gl::kUnitLightColor);
    program.set("uLightTableRows", float(2 * rows_));  // the textures' rows: the lights' and their cones'
    if (format_ == LightTableFormat::Fixed16) {
        set.posRadiusLow.bind(gl::kUnitLightPosRadiusLow);
        program.set("uLightPosRadiusLow", gl::kUnitLightPosRadiusLow);
        program.set("uLightBoundsMin", boundsMin_);
        program.set("uLightBoundsExtent", boundsExtent_);
        program.set("uLightRadiusScale", radiusScale_);
        program.set("uLightColorScale", colorScale_);
    }
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace lidr
