#include "lidr/modes/light_list_texture.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <string>

#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"

namespace lidr {

LightListTexture::LightListTexture(const GlInfo& info, const LightListNames& names, int indexBits)
    : names_(names), maxTextureSize_(info.maxTextureSize), indexBits_(indexBits) {
    if (kWidth > info.maxTextureSize)
        throw UnsupportedError("this driver's textures are at most " + std::to_string(info.maxTextureSize) +
                               " texels wide; the " + names.mode + " light list needs " + std::to_string(kWidth));
}

void LightListTexture::upload(const std::vector<uint32_t>& entries, int bits) {
    const size_t count = entries.size();
    if (count > (size_t(1) << 24))
        throw Error(std::string(names_.grid) + ": " + std::to_string(count) + " list entries exceed the 2^24 that 24-bit " +
                    names_.cell + " offsets address; use " + names_.advice);
    const int rowsNeeded = int((count + kWidth - 1) / kWidth);
    if (rowsNeeded > rows_ || bits != indexBits_) {  // grow (double until it fits) or change the index width
        int rows = std::max(rows_, 1);
        while (rows < rowsNeeded) rows *= 2;
        rows = std::min(rows, maxTextureSize_);
        if (rows < rowsNeeded)
            throw Error(std::string(names_.grid) + ": " + std::to_string(count) + " list entries exceed the driver's largest " +
                        std::to_string(kWidth) + "x" + std::to_string(maxTextureSize_) + " list texture");
        texture_ = bits == 8 ? gl::Texture::create2D(GL_LUMINANCE8, kWidth, rows, GL_LUMINANCE, GL_UNSIGNED_BYTE)
                             : gl::Texture::create2D(GL_LUMINANCE8_ALPHA8, kWidth, rows, GL_LUMINANCE_ALPHA,
                                                     GL_UNSIGNED_BYTE);
        rows_ = rows;
        indexBits_ = bits;
    }
    const size_t bytesPerEntry = bits == 8 ? 1 : 2;
    staging_.assign(size_t(rowsNeeded) * kWidth * bytesPerEntry, 0);
    if (bits == 8) {
        for (size_t k = 0; k < count; ++k) staging_[k] = uint8_t(entries[k]);
    } else {
        for (size_t k = 0; k < count; ++k) {
            staging_[k * 2] = uint8_t(entries[k] >> 8);
            staging_[k * 2 + 1] = uint8_t(entries[k] & 0xFF);
        }
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    texture_.upload(kWidth, rowsNeeded, bits == 8 ? GL_LUMINANCE : GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE,
                    staging_.data());
}

}  // namespace lidr
