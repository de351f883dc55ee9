#pragma once
// Checks every importer makes on the files it is given, and the number formatting of their messages.
#include <cstddef>
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

namespace lidr {

constexpr int maxTextureSide = 16384;  // the largest texture GL 2.1 contexts commonly offer

// Empty for a regular file (symbolic links followed), else why it cannot be read as one: "not found" only
// when nothing is there; "is a directory", "is not a regular file" (a device, a FIFO), or the system's text
// for any other failure (a symbolic link loop, permissions).
std::string fileProblem(const std::string& path);

// Empty if stb_image can read the image's header and its size fits a texture, else what is wrong with it.
// A PNG's or JPEG's size is read from its header first (stb_image refuses a huge one without telling its size).
std::string imageProblem(const std::string& path);

// The kind and size of a PNG or JPEG read from its first bytes, without decoding: kind "image/png",
// "image/jpeg", or empty for anything else; `sized` false when the header is cut off before the size.
struct ImageHeader {
    std::string kind;
    uint64_t width = 0, height = 0;
    bool sized = false;
};
ImageHeader pngOrJpegHeader(const std::string& firstBytes);
constexpr size_t imageHeaderBytes = size_t(1) << 20;  // bytes to read for it (a JPEG's frame header follows its metadata)

// The whole of a regular file of at most `maxBytes`; throws lidr::Error "<path>: <what> <problem>" where it is
// missing, not a regular file, larger, or unreadable (`what`: "AFF file", "texture").
std::string readWholeFile(const std::string& path, size_t maxBytes, const std::string& what);

// Up to `count` bytes of a file from `offset` (fewer at its end).
std::string readFileBytes(const std::string& path, uint64_t offset, size_t count);

// The name of a model format lidr does not import, by extension ("PLY", "FBX"), or empty (OBJ, glTF, unknown).
std::string unsupportedModelFormat(const std::string& path);

// Lower-case extension with its dot (".obj"), for dispatching on file types.
std::string lowerCaseExtension(const std::string& path);

// Numbers and vectors as messages show them.
std::string str(double value);
std::string str(const glm::vec3& v);
bool isFinite(const glm::vec3& v);

// A key or text from a file as shown in a message: at most `limit` characters.
std::string clipped(const std::string& text, size_t limit = 80);

}  // namespace lidr
