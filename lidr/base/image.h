#pragma once
// CPU images: what lidr reads back from GL and writes to disk. Rows are stored top to bottom (GL reads bottom
// to top; readback flips), so pixel (x, y) with y = 0 at the top is what a PNG viewer shows.
#include <cstdint>
#include <string>
#include <vector>

namespace lidr {

struct ImageRGBA8 {
    int width = 0, height = 0;
    std::vector<uint8_t> pixels;  // RGBA, width * height * 4
    ImageRGBA8() = default;
    ImageRGBA8(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(w) * h * 4, 0) {}
    uint8_t* at(int x, int y) { return &pixels[(static_cast<size_t>(y) * width + x) * 4]; }
    const uint8_t* at(int x, int y) const { return &pixels[(static_cast<size_t>(y) * width + x) * 4]; }
};

struct ImageFloat {
    int width = 0, height = 0;
    std::vector<float> pixels;  // one channel
    ImageFloat() = default;
    ImageFloat(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(w) * h, 0.0f) {}
    float& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
    float at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
};

// Lossless PNG (RGBA8, every channel kept, alpha included). Throws lidr::Error if the file cannot be written.
void writePng(const std::string& path, const ImageRGBA8& image);
ImageRGBA8 readPng(const std::string& path);
// Portable float map, one channel ("Pf"), little-endian, rows bottom to top as the format says.
void writePfm(const std::string& path, const ImageFloat& image);
ImageFloat readPfm(const std::string& path);

// GL readback of the bound read framebuffer into a top-to-bottom image.
ImageRGBA8 readPixelsRGBA8(int width, int height);
ImageFloat readDepth(int width, int height);     // window-space depth in [0, 1]
std::vector<uint8_t> readStencil(int width, int height);  // top to bottom

}  // namespace lidr
