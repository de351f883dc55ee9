#include "lidr/base/image.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>

#include <stb_image.h>
#include <stb_image_write.h>

#include <cerrno>
#include <cstring>

#include "lidr/base/error.h"
#include "lidr/base/gl.h"

namespace lidr {

void writePng(const std::string& path, const ImageRGBA8& image) {
    if (image.width <= 0 || image.height <= 0) throw Error("writePng: empty image for " + path);
    errno = 0;
    if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.pixels.data(), image.width * 4))
        throw Error("could not write PNG '" + path + "': " + (errno ? std::strerror(errno) : "write failed"));
}

ImageRGBA8 readPng(const std::string& path) {
    int w = 0, h = 0, n = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> data(stbi_load(path.c_str(), &w, &h, &n, 4), stbi_image_free);
    if (!data) throw Error("could not read image '" + path + "': " + stbi_failure_reason());
    ImageRGBA8 img(w, h);
    std::memcpy(img.pixels.data(), data.get(), img.pixels.size());
    return img;
}

void writePfm(const std::string& path, const ImageFloat& image) {
    errno = 0;
    std::ofstream f(path, std::ios::binary);
    if (!f) throw Error("could not write PFM '" + path + "': " + (errno ? std::strerror(errno) : "open failed"));
    f << "Pf\n" << image.width << " " << image.height << "\n-1.0\n";  // negative scale: little-endian
    for (int y = image.height - 1; y >= 0; --y)
        f.write(reinterpret_cast<const char*>(&image.pixels[static_cast<size_t>(y) * image.width]),
                static_cast<std::streamsize>(sizeof(float)) * image.width);
    if (!f) throw Error("could not write PFM '" + path + "'");
}

ImageFloat readPfm(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::string magic;
    int w = 0, h = 0;
    float scale = 0;
    if (!(f >> magic >> w >> h >> scale) || magic != "Pf" || w <= 0 || h <= 0 || scale >= 0)
        throw Error("'" + path + "' is not a little-endian one-channel PFM");
    f.get();
    ImageFloat img(w, h);
    for (int y = h - 1; y >= 0; --y)
        f.read(reinterpret_cast<char*>(&img.pixels[static_cast<size_t>(y) * w]),
               static_cast<std::streamsize>(sizeof(float)) * w);
    if (!f) throw Error("'" + path + "' is truncated");
    return img;
}

namespace {
// glReadPixels into a tightly packed buffer whatever pack state (and pixel-pack buffer) the program set; both come
// back.
void readTight(int width, int height, GLenum format, GLenum type, GLint alignment, void* out, const char* where) {
    GLint oldAlignment = 4, oldRowLength = 0, oldSkipRows = 0, oldSkipPixels = 0;
    if (currentContextIsGles()) {  // OpenGL ES 2.0 packs by alignment alone (no row length or skips)
        glGetIntegerv(GL_PACK_ALIGNMENT, &oldAlignment);
        glPixelStorei(GL_PACK_ALIGNMENT, alignment);
        glReadPixels(0, 0, width, height, format, type, out);
        glPixelStorei(GL_PACK_ALIGNMENT, oldAlignment);
        checkGl(where);
        return;
    }
    // A pixel-pack buffer the program left bound (GL 2.1 core) would take the pixels instead of `out`.
    GLint oldPackBuffer = 0;
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &oldPackBuffer);
    if (oldPackBuffer != 0) glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glGetIntegerv(GL_PACK_ALIGNMENT, &oldAlignment);
    glGetIntegerv(GL_PACK_ROW_LENGTH, &oldRowLength);
    glGetIntegerv(GL_PACK_SKIP_ROWS, &oldSkipRows);
    glGetIntegerv(GL_PACK_SKIP_PIXELS, &oldSkipPixels);
    glPixelStorei(GL_PACK_ALIGNMENT, alignment);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    glReadPixels(0, 0, width, height, format, type, out);
    glPixelStorei(GL_PACK_ALIGNMENT, oldAlignment);
    glPixelStorei(GL_PACK_ROW_LENGTH, oldRowLength);
    glPixelStorei(GL_PACK_SKIP_ROWS, oldSkipRows);
    glPixelStorei(GL_PACK_SKIP_PIXELS, oldSkipPixels);
    if (oldPackBuffer != 0) glBindBuffer(GL_PIXEL_PACK_BUFFER, GLuint(oldPackBuffer));
    checkGl(where);
}
}  // namespace

ImageRGBA8 readPixelsRGBA8(int width, int height) {
    ImageRGBA8 img(width, height);
    std::vector<uint8_t> raw(img.pixels.size());
    readTight(width, height, GL_RGBA, GL_UNSIGNED_BYTE, 1, raw.data(), "readPixelsRGBA8");
    const size_t row = static_cast<size_t>(width) * 4;
    for (int y = 0; y < height; ++y)
        std::memcpy(&img.pixels[static_cast<size_t>(y) * row], &raw[static_cast<size_t>(height - 1 - y) * row], row);
    return img;
}

namespace {
// OpenGL ES reads depth and stencil together or not at all: NV_read_depth_stencil's DEPTH_STENCIL with
// UNSIGNED_INT_24_8 (Mesa's ES 2.0 refuses depth as FLOAT and stencil alone), depth in the top 24 bits.
std::vector<GLuint> readDepthStencilEs(int width, int height, const char* where) {
    std::vector<GLuint> raw(static_cast<size_t>(width) * height);
    readTight(width, height, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, 4, raw.data(), where);
    return raw;
}
}  // namespace

ImageFloat readDepth(int width, int height) {
    ImageFloat img(width, height);
    if (currentContextIsGles()) {
        const std::vector<GLuint> raw = readDepthStencilEs(width, height, "readDepth (DEPTH_STENCIL)");
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)  // what a FLOAT read of the 24-bit depth gives on desktop GL
                img.pixels[static_cast<size_t>(y) * width + x] =
                    float(double(raw[static_cast<size_t>(height - 1 - y) * width + x] >> 8) / 16777215.0);
        return img;
    }
    std::vector<float> raw(img.pixels.size());
    readTight(width, height, GL_DEPTH_COMPONENT, GL_FLOAT, 4, raw.data(), "readDepth");
    for (int y = 0; y < height; ++y)
        std::memcpy(&img.pixels[static_cast<size_t>(y) * width], &raw[static_cast<size_t>(height - 1 - y) * width],
                    sizeof(float) * width);
    return img;
}

std::vector<uint8_t> readStencil(int width, int height) {
    std::vector<uint8_t> raw(static_cast<size_t>(width) * height), out(raw.size());
    if (currentContextIsGles()) {
        const std::vector<GLuint> packed = readDepthStencilEs(width, height, "readStencil (DEPTH_STENCIL)");
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                out[static_cast<size_t>(y) * width + x] =
                    uint8_t(packed[static_cast<size_t>(height - 1 - y) * width + x] & 0xFFu);
        return out;
    }
    readTight(width, height, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, 1, raw.data(), "readStencil");
    for (int y = 0; y < height; ++y)
        std::memcpy(&out[static_cast<size_t>(y) * width], &raw[static_cast<size_t>(height - 1 - y) * width], width);
    return out;
}

}  // namespace lidr
