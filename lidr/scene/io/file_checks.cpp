#include "lidr/scene/io/file_checks.h"

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

std::string imageProblem(const std::string& path) {
    const std::string problem = fileProblem(path);
    if (!problem.empty()) return "texture '" + path + "' " + problem;
    int width = 0, height = 0, channels = 0;
    // stb_image refuses a huge PNG as "too large" before it tells its size: read the size from the IHDR chunk.
    {
        std::ifstream in(path, std::ios::binary);
        unsigned char h[24] = {};
        if (in.read(reinterpret_cast<char*>(h), sizeof h) &&
            std::memcmp(h, "\x89PNG\r\n\x1a\n", 8) == 0 && std::memcmp(h + 12, "IHDR", 4) == 0) {
            const auto be32 = [&](int at) {
                return (uint32_t(h[at]) << 24) | (uint32_t(h[at + 1]) << 16) | (uint32_t(h[at + 2]) << 8) | h[at + 3];
            };
            const uint32_t w = be32(16), hgt = be32(20);
            if (w > uint32_t(maxTextureSide) || hgt > uint32_t(maxTextureSide))
                return "texture '" + path + "' is " + std::to_string(w) + "x" + std::to_string(hgt) +
                       ", over the texture limit of " + std::to_string(maxTextureSide) + " per side";
        }
    }
    if (!stbi_info(path.c_str(), &width, &height, &channels)) {
        const char* reason = stbi_failure_reason();
        return "texture '" + path + "' cannot be read (" + (reason ? reason : "unknown format") + ")";
    }
    if (width > maxTextureSide || height > maxTextureSide)
        return "texture '" + path + "' is " + std::to_string(width) + "x" + std::to_string(height) +
               ", over the texture limit of " + std::to_string(maxTextureSide) + " per side";
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
