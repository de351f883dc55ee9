#include "lidr/scene/io/file_checks.h"

#include "lidr/base/error.h"

#include <algorithm>
#include <cerrno>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <stb_image.h>

#include <sys/stat.h>

namespace lidr {

std::string readWholeFile(const std::string& path, size_t maxBytes, const std::string& what) {
    const std::string problem = fileProblem(path);
    if (!problem.empty()) throw Error(path + ": " + what + " " + problem);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open the " + what);
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0 || uint64_t(size) > uint64_t(maxBytes))
        throw Error(path + ": " + what + " of " + std::to_string(size) + " bytes; lidr reads up to " +
                    std::to_string(maxBytes >> 20) + " MiB");
    in.seekg(0);
    std::string bytes(static_cast<size_t>(size), '\0');
    in.read(bytes.data(), size);
    if (!in) throw Error(path + ": cannot read the " + what);
    return bytes;
}

std::string str(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string str(const glm::vec3& v) { return "(" + str(v.x) + ", " + str(v.y) + ", " + str(v.z) + ")"; }

std::string clipped(const std::string& text, size_t limit) {
    if (text.size() <= limit) return text;
    return text.substr(0, limit) + "...(" + std::to_string(text.size()) + " characters)";
}

std::string fileProblem(const std::string& path) {
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) {
        const int error = errno;
        if (error == ENOENT) return "not found";
        return std::strerror(error);
    }
    if (S_ISDIR(info.st_mode)) return "is a directory";
    if (!S_ISREG(info.st_mode)) return "is not a regular file";
    return {};
}

namespace {

uint32_t bigEndian32(const unsigned char* p) {
    return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

}  // namespace

ImageHeader pngOrJpegHeader(const std::string& firstBytes) {
    ImageHeader header;
    const auto* b = reinterpret_cast<const unsigned char*>(firstBytes.data());
    const size_t size = firstBytes.size();
    if (size >= 8 && std::memcmp(b, "\x89PNG\r\n\x1a\n", 8) == 0) {
        header.kind = "image/png";
        if (size >= 24 && std::memcmp(b + 12, "IHDR", 4) == 0) {
            header.width = bigEndian32(b + 16);
            header.height = bigEndian32(b + 20);
            header.sized = true;
        }
    } else if (size >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) {
        header.kind = "image/jpeg";
        // Walk the marker segments to the first start of frame (SOF0..SOF15 but DHT C4, JPG C8, DAC CC).
        size_t at = 2;
        while (at + 4 <= size && b[at] == 0xFF) {
            const unsigned char marker = b[at + 1];
            if (marker == 0xFF) {  // fill byte
                ++at;
                continue;
            }
            if (marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC) {
                if (at + 9 <= size) {
                    header.height = uint64_t(b[at + 5]) << 8 | b[at + 6];
                    header.width = uint64_t(b[at + 7]) << 8 | b[at + 8];
                    header.sized = true;
                }
                break;
            }
            const size_t length = size_t(b[at + 2]) << 8 | b[at + 3];
            if (length < 2) break;
            at += 2 + length;
        }
    }
    return header;
}

std::string readFileBytes(const std::string& path, uint64_t offset, size_t count) {
    std::ifstream in(path, std::ios::binary);
    std::string bytes(count, '\0');
    in.seekg(std::streamoff(offset));
    in.read(bytes.data(), std::streamsize(count));
    bytes.resize(size_t(std::max<std::streamsize>(in.gcount(), 0)));
    return bytes;
}

std::string imageProblem(const std::string& path) {
    const std::string problem = fileProblem(path);
    if (!problem.empty()) return "texture '" + path + "' " + problem;
    const auto overLimit = [&](uint64_t width, uint64_t height) {
        return "texture '" + path + "' is " + std::to_string(width) + "x" + std::to_string(height) +
               ", over the texture limit of " + std::to_string(maxTextureSide) + " per side";
    };
    // stb_image refuses a huge PNG as "too large" before it tells its size: read the size from the header.
    const ImageHeader header = pngOrJpegHeader(readFileBytes(path, 0, imageHeaderBytes));
    if (header.sized && (header.width > uint64_t(maxTextureSide) || header.height > uint64_t(maxTextureSide)))
        return overLimit(header.width, header.height);
    int width = 0, height = 0, channels = 0;
    if (!stbi_info(path.c_str(), &width, &height, &channels)) {
        const char* reason = stbi_failure_reason();
        return "texture '" + path + "' cannot be read (" + (reason ? reason : "unknown format") + ")";
    }
    if (width > maxTextureSide || height > maxTextureSide) return overLimit(uint64_t(width), uint64_t(height));
    return {};
}

std::string lowerCaseExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

// Model formats other than OBJ and glTF, by extension, so they are named instead of failing as "no triangles".
std::string unsupportedModelFormat(const std::string& path) {
    const std::string ext = lowerCaseExtension(path);
    static const std::map<std::string, std::string> known = {
        {".ply", "PLY"}, {".fbx", "FBX"}, {".stl", "STL"},
        {".dae", "COLLADA"}, {".3ds", "3DS"}, {".blend", "Blender"}, {".usd", "USD"}, {".usdz", "USD"},
        {".abc", "Alembic"}, {".x3d", "X3D"}, {".off", "OFF"}};
    const auto it = known.find(ext);
    return it == known.end() ? std::string() : it->second;
}

}  // namespace lidr
