#pragma once
// The light lists of tiled and clustered forward as one texture, and the 24-bit list offsets their grids hold.
// List: kWidth entries a row, one light index a texel, 8-bit (LUMINANCE8: at most 255 lights) or 16-bit
// (LUMINANCE8_ALPHA8, L high byte, A low), the lists end to end. The texture grows (its rows doubled until they hold
// the frame's entries, up to the driver's texture size) when a frame needs more, so nothing is ever cut off; past
// what the driver or 24-bit offsets can address, upload() throws lidr::Error.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"

namespace lidr {

// What a grid's errors call it and its cells: {"light grid", "tiled", "tile", "larger tiles or fewer lights"}.
struct LightListNames {
    const char* grid;    // "light grid"
    const char* mode;    // "tiled": the texture-width refusal names "the tiled light list"
    const char* cell;    // "tile": "24-bit tile offsets"
    const char* advice;  // what to change where the offsets run out
};

class LightListTexture {
public:
    static constexpr int kWidth = 1024;

    LightListTexture() = default;
    // Throws UnsupportedError where the driver's textures are narrower than kWidth. `indexBits`: the width the
    // texture is made at (0: at the first upload's).
    LightListTexture(const GlInfo& info, const LightListNames& names, int indexBits);
    // The frame's entries at `indexBits` (8 or 16) into the texture, grown or remade at another width first.
    void upload(const std::vector<uint32_t>& entries, int indexBits);
    const gl::Texture& texture() const { return texture_; }
    int rows() const { return rows_; }
    int indexBits() const { return indexBits_; }  // as allocated (0: nothing yet)
    size_t bytes() const { return size_t(kWidth) * size_t(rows_) * size_t(indexBits_ == 8 ? 1 : 2); }

private:
    LightListNames names_{};
    int maxTextureSize_ = 0, rows_ = 0, indexBits_ = 0;
    gl::Texture texture_;
    std::vector<uint8_t> staging_;  // kept between frames
};

// A list offset into texel bytes R, G, B (high to low; A left as it is): what the grids' shaders read back.
inline void putListOffset(uint8_t* texel, uint32_t offset) {
    texel[0] = uint8_t(offset >> 16);
    texel[1] = uint8_t(offset >> 8);
    texel[2] = uint8_t(offset);
}

}  // namespace lidr
