#pragma once
// Netpbm colour and grey images (.ppm, .pgm): BART's textures. Read whole into an ImageRGBA8 (rows top to bottom,
// as the file stores them; alpha 255), checked before anything is allocated: the header's size against
// maxTextureSide and against the bytes the file holds. Every problem is an lidr::Error naming the file.
#include <cstddef>
#include <string>

#include "lidr/base/image.h"

namespace lidr {

// The largest PPM file read: 256 MiB (a binary 8-bit image of about 9,000 x 9,000), so a texture never takes
// gigabytes.
constexpr size_t maxPpmFileBytes = size_t(256) << 20;

// P6 (binary RGB) and P3 (plain RGB), P5 and P2 (grey, copied to R, G and B); maxval 1..65535 (two-byte samples
// big-endian, as the format says), scaled to 0..255; `#` comments in the header. P1 / P4 (bitmaps), P7 (PAM) and
// anything else are refused by name.
ImageRGBA8 readPpm(const std::string& path);
// The same from bytes in memory (`name` names them in messages).
ImageRGBA8 decodePpm(const std::string& bytes, const std::string& name);

}  // namespace lidr
