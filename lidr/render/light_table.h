#pragma once
// The light table the forward shaders read: light i (1-based; 0 is the null light) at texel
// (i mod 256, i / 256) of 256-wide textures. Float textures where ARB_texture_float exists; otherwise a
// documented fixed-point path (16-bit position and radius in two RGBA8 textures, colour in RGBA8).
// Two sets of textures alternate frame by frame, so an update never waits for the GPU to finish reading
// the previous frame's table (Trebilco's advice for dynamic light data).
#include <cstdint>
#include <vector>

#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/scene/scene.h"
#include "lidr/gl/shader_source.h"

namespace lidr {

enum class LightTableFormat { Float, Fixed16 };

// A glTF light's (LightFalloff::InverseSquare) colour in the fixed-point table: three bytes times its own 2^e,
// e in [-63, 63] chosen so the brightest channel fills [0.5, 1) of it, and the alpha byte (light_table.glsl).
// Each channel is within 2^e / 510 <= brightest / 255 of the real one (relative to the light itself, whatever
// the other lights' intensities). `decoded` is what the shader reads back.
struct FixedColor {
    uint8_t bytes[4];
    glm::vec3 decoded;
};
FixedColor fixedInverseSquareColor(const glm::vec3& color, bool spot);

class LightTable {
public:
    static constexpr int kWidth = 256;

    LightTable() = default;
    // Room for `capacity` lights (plus the null light). Fixed16 is chosen when the context has no float
    // textures or when `forceFixed16`.
    LightTable(const GlInfo& info, int capacity, bool forceFixed16 = false);
    // Throws if more lights than capacity. shadowTiles: empty, or per light the first shadow-atlas tile of its
    // maps (-1: it casts no shadow; ShadowAtlas::firstTiles), read by LIDR_SHADOWS shaders (lidrFetchShadowTile).
    void update(const std::vector<PointLight>& lights, const std::vector<int>& shadowTiles = {});
    void bind(const gl::Program& program) const;          // textures to their units and the uniforms
    LightTableFormat format() const { return format_; }
    ShaderDefines defines() const;                         // LIDR_LIGHT_TABLE_FIXED16 when fixed
    int rows() const { return rows_; }
    int lightCount() const { return count_; }
    int capacity() const { return capacity_; }
    size_t bytes() const;  // both sets
    // How much farther than the real sphere a light of the last update() may reach in the shader: 0 for the
    // float table; for fixed16, half a 1/65535 step of the lights' box (positions round to nearest) plus a
    // 1/65535 step of the largest radius (radii round up). Light assignment widens spheres by it.
    float reachError() const;
    // Region-local indices (lidr/technique/volume_tiles.h, IndexRegions; float table only): `tileRows` holds a
    // table row per screen tile (row-major, rows bottom to top), written by the next update() into the
    // position texture's x from row `firstRow` on, after the regions' rows. Empty: off. The forward pass reads
    // it through regionMapUniform() = (1 / tile size, tiles per row, first row, 1 when on).
    void setRegionMap(std::vector<float> tileRows, int firstRow, int tileSize, int tilesX);
    glm::vec4 regionMapUniform() const { return regionMapUniform_; }

private:
    // update()'s two formats: the float textures, or the fixed-point ones (their scales first, from the lights).
    void uploadFloat(const std::vector<PointLight>& lights, const std::vector<int>& shadowTiles);
    void uploadFixed(const std::vector<PointLight>& lights, const std::vector<int>& shadowTiles);
    void setFixedScales(const std::vector<PointLight>& lights);

    std::vector<float> regionMap_;
    int regionMapFirstRow_ = 0;
    glm::vec4 regionMapUniform_{0.0f};
    LightTableFormat format_ = LightTableFormat::Float;
    int capacity_ = 0, rows_ = 1, count_ = 0;
    struct TextureSet {
        gl::Texture posRadius, posRadiusLow, color;
    };
    TextureSet sets_[2];
    int current_ = 0;
    glm::vec3 boundsMin_{0.0f}, boundsExtent_{1.0f};
    float radiusScale_ = 1.0f, colorScale_ = 1.0f;
};

}  // namespace lidr
