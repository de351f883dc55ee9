#include "lidr/scene/io/ppm_image.h"

#include <cctype>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <sstream>

#include "lidr/base/error.h"
#include "lidr/scene/io/file_checks.h"

namespace lidr {

namespace {

// The header's fields: whitespace-separated decimal numbers with `#` comments running to the end of the line.
class HeaderReader {
public:
    HeaderReader(const std::string& bytes, const std::string& name) : bytes_(bytes), name_(name) {}
    uint64_t number(const char* what) {
        skipSpaceAndComments();
        if (pos_ >= bytes_.size()) fail(std::string("the header ends before its ") + what);
        if (!std::isdigit(static_cast<unsigned char>(bytes_[pos_])))
            fail(std::string("the header's ") + what + " is not a number (at byte " + std::to_string(pos_) + ")");
        uint64_t value = 0;
        while (pos_ < bytes_.size() && std::isdigit(static_cast<unsigned char>(bytes_[pos_]))) {
            value = value * 10 + uint64_t(bytes_[pos_++] - '0');
            if (value > 1000000000ull) fail(std::string("the header's ") + what + " is out of range");
        }
        return value;
    }
    void skipSpaceAndComments() {
        while (pos_ < bytes_.size()) {
            const char c = bytes_[pos_];
            if (c == '#') {
                while (pos_ < bytes_.size() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r') ++pos_;
            } else if (std::isspace(static_cast<unsigned char>(c))) {
                ++pos_;
            } else {
                return;
            }
        }
    }
    // Binary formats: exactly one whitespace byte ends the header.
    size_t binaryStart() {
        if (pos_ >= bytes_.size() || !std::isspace(static_cast<unsigned char>(bytes_[pos_])))
            fail("the header's maxval is not followed by a whitespace byte");
        return pos_ + 1;
    }
    [[noreturn]] void fail(const std::string& problem) const { throw Error(name_ + ": " + problem); }

private:
    const std::string& bytes_;
    const std::string& name_;
    size_t pos_ = 2;
};

}  // namespace

ImageRGBA8 decodePpm(const std::string& bytes, const std::string& name) {
    const auto fail = [&](const std::string& problem) { throw Error(name + ": " + problem); };
    if (bytes.size() < 2 || bytes[0] != 'P') fail("not a Netpbm image (no 'P' magic number)");
    const char kind = bytes[1];
    if (kind == '1' || kind == '4') fail("a PBM bitmap (P" + std::string(1, kind) + "); textures must be PPM (P6, P3) or PGM (P5, P2)");
    if (kind == '7') fail("a PAM image (P7); textures must be PPM (P6, P3) or PGM (P5, P2)");
    if (kind != '2' && kind != '3' && kind != '5' && kind != '6') fail("not a PPM or PGM image (magic 'P" + clipped(std::string(1, kind)) + "')");
    const bool colour = kind == '3' || kind == '6', binary = kind == '5' || kind == '6';
    HeaderReader header(bytes, name);
    const uint64_t width = header.number("width"), height = header.number("height"), maxval = header.number("maxval");
    if (width == 0 || height == 0) fail("size " + std::to_string(width) + "x" + std::to_string(height) + " is empty");
    if (width > uint64_t(maxTextureSide) || height > uint64_t(maxTextureSide))
        fail("size " + std::to_string(width) + "x" + std::to_string(height) + " exceeds the largest texture, " +
             std::to_string(maxTextureSide) + " per side");
    if (maxval == 0 || maxval > 65535) fail("maxval " + std::to_string(maxval) + " must be 1..65535");
    const int channels = colour ? 3 : 1;
    const uint64_t samples = width * height * uint64_t(channels);
    const int sampleBytes = maxval > 255 ? 2 : 1;
    ImageRGBA8 image;
    const auto store = [&](uint64_t index, uint64_t sample) {
        if (sample > maxval) fail("sample " + std::to_string(index) + " is " + std::to_string(sample) + ", above maxval " + std::to_string(maxval));
        const uint8_t value = uint8_t((sample * 255 + maxval / 2) / maxval);
        const uint64_t pixel = index / uint64_t(channels);
        uint8_t* p = &image.pixels[size_t(pixel) * 4];
        if (colour) p[index % 3] = value;
        else p[0] = p[1] = p[2] = value;
    };
    if (binary) {
        const size_t start = header.binaryStart();
        const uint64_t needed = samples * uint64_t(sampleBytes);
        if (bytes.size() - start < needed)
            fail("the header says " + std::to_string(width) + "x" + std::to_string(height) + " (" + std::to_string(needed) +
                 " bytes of samples) but the file holds " + std::to_string(bytes.size() - start));
        image = ImageRGBA8(int(width), int(height));
        for (size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 255;
        const auto* b = reinterpret_cast<const unsigned char*>(bytes.data()) + start;
        for (uint64_t i = 0; i < samples; ++i)
            store(i, sampleBytes == 2 ? uint64_t(b[2 * i]) << 8 | b[2 * i + 1] : b[i]);
        return image;
    }
    // Plain: each sample a decimal number; at least two bytes a sample, so a header asking for more than the file
    // can hold is refused before the image is allocated.
    if ((bytes.size() + 1) / 2 < samples)
        fail("the header says " + std::to_string(width) + "x" + std::to_string(height) + " (" + std::to_string(samples) +
             " samples) but the file is too short to hold them");
    image = ImageRGBA8(int(width), int(height));
    for (size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 255;
    for (uint64_t i = 0; i < samples; ++i) store(i, header.number(("sample " + std::to_string(i)).c_str()));
    return image;
}

ImageRGBA8 readPpm(const std::string& path) { return decodePpm(readWholeFile(path, maxPpmFileBytes, "texture"), path); }

}  // namespace lidr
