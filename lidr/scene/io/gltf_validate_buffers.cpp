// The glTF validator's checks of the binary data: buffers (data: URIs, external files, the GLB BIN chunk), buffer
// views and accessors, their bounds and alignment (gltf_validator_internal.h).
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

#include "lidr/scene/io/file_checks.h"
#include "lidr/scene/io/gltf_validator.h"
#include "lidr/scene/io/gltf_validator_internal.h"

namespace lidr::gltf_validation {

namespace {

namespace fs = std::filesystem;

int base64Value(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
}

std::string percentDecoded(const std::string& uri) {
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            out += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

uint64_t base64Bytes(const std::string& base64) {
    size_t length = base64.size();
    while (length && base64[length - 1] == '=') --length;
    return uint64_t(length) * 6 / 8;
}

int componentSize(int64_t componentType) {
    switch (componentType) {
    case 5120: case 5121: return 1;
    case 5122: case 5123: return 2;
    case 5125: case 5126: return 4;
    default: return 0;
    }
}

int componentsOf(const std::string& type) {
    static const std::pair<const char*, int> types[] = {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4},
                                                       {"MAT2", 4},   {"MAT3", 9}, {"MAT4", 16}};
    for (const auto& t : types)
        if (type == t.first) return t.second;
    return 0;
}

// Bytes one element takes, with the column padding the specification asks of small matrices.
uint64_t elementSize(const std::string& type, int size) {
    if (type == "MAT2" && size == 1) return 8;
    if (type == "MAT3" && size == 1) return 12;
    if (type == "MAT3" && size == 2) return 24;
    return uint64_t(componentsOf(type)) * uint64_t(size);
}

// Elements of `count` x `element` bytes from `offset` with `stride` fit `length` bytes, without overflow.
bool fits(uint64_t offset, uint64_t element, uint64_t stride, uint64_t count, uint64_t length) {
    if (count == 0) return true;
    if (offset > length || element > length - offset) return false;
    return count - 1 <= (length - offset - element) / stride;
}

}  // namespace

std::string base64Decode(const std::string& text, size_t from, size_t maxBytes) {
    std::string out;
    uint32_t bits = 0;
    int held = 0;
    for (size_t i = from; i < text.size() && out.size() < maxBytes; ++i) {
        const int v = base64Value(text[i]);
        if (v < 0) break;
        bits = bits << 6 | uint32_t(v);
        held += 6;
        if (held >= 8) {
            held -= 8;
            out += char((bits >> held) & 0xFF);
        }
    }
    return out;
}

std::string Validator::dataUri(const std::string& uri, const std::string& at, std::string& base64) const {
    const size_t comma = uri.find(',');
    if (comma == std::string::npos) fail(at, "data: URI without ',' before its data");
    const std::string head = uri.substr(5, comma - 5);
    const size_t semicolon = head.rfind(";base64");
    if (semicolon == std::string::npos || semicolon + 7 != head.size())
        fail(at, "data: URI is not base64 (\"data:<type>;base64,...\" is what glTF allows)");
    base64 = uri.substr(comma + 1);
    size_t padding = 0;
    for (size_t i = 0; i < base64.size(); ++i) {
        const char c = base64[i];
        if (c == '=') {
            ++padding;
        } else if (base64Value(c) < 0 || padding) {
            fail(at, "data: URI has a character that is not base64 at position " + std::to_string(comma + 1 + i));
        }
    }
    if (padding > 2 || base64.size() % 4 == 1 || (padding && base64.size() % 4 != 0))
        fail(at, "data: URI base64 text of " + std::to_string(base64.size()) + " characters is cut off or badly padded");
    return head.substr(0, semicolon);
}

std::string Validator::externalFile(const std::string& uri, const std::string& at, const char* what) const {
    if (uri.find("://") != std::string::npos || uri.rfind("file:", 0) == 0)
        fail(at, "URI '" + clipped(uri) + "' is not a relative path; lidr reads only files next to the glTF file");
    if (uri.empty()) fail(at, "empty URI");
    const std::string file = (fs::path(path_).parent_path() / percentDecoded(uri)).lexically_normal().string();
    const std::string problem = fileProblem(file);
    if (!problem.empty()) fail(at, std::string(what) + " file '" + file + "' " + problem);
    return file;
}

std::string Validator::bufferBytes(int64_t bufferIndex, uint64_t offset, uint64_t length) const {
    const BufferInfo& buffer = buffers_[size_t(bufferIndex)];
    const size_t wanted = size_t(std::min<uint64_t>(length, imageHeaderBytes));
    if (buffer.glbBin) return readFileBytes(path_, binOffset_ + offset, wanted);
    if (!buffer.file.empty()) return readFileBytes(buffer.file, offset, wanted);
    std::string bytes = base64Decode(buffer.dataUri, size_t(offset / 3 * 4), wanted + 3);
    return bytes.substr(size_t(offset % 3), wanted);
}

void Validator::checkBuffers() {
    // The sizes first, so no file is opened for a document that asks for too much.
    uint64_t total = 0;
    forEach("buffers", [&](const Json& buffer, const std::string& at, size_t) {
        const int64_t byteLength = integer(buffer, at, "byteLength", 0, true);
        if (byteLength < 1) fail(at + "/byteLength", "must be >= 1, got " + std::to_string(byteLength));
        if (uint64_t(byteLength) > maxGltfBufferBytes)
            fail(at + "/byteLength", std::to_string(byteLength) + " bytes is over lidr's limit of " +
                                         std::to_string(maxGltfBufferBytes) + " per buffer");
        total += uint64_t(byteLength);
        if (total > maxGltfTotalBufferBytes)
            fail(at + "/byteLength", "the buffers so far need " + std::to_string(total) + " bytes; lidr's limit is " +
                                         std::to_string(maxGltfTotalBufferBytes) + " for all buffers of a file");
    });
    forEach("buffers", [&](const Json& buffer, const std::string& at, size_t i) {
        BufferInfo info;
        info.byteLength = uint64_t(buffer["byteLength"].get<int64_t>());
        if (const Json* uri = member(buffer, at, "uri", Kind::String)) {
            const std::string text = uri->get<std::string>();
            if (text.rfind("data:", 0) == 0) {
                const std::string mime = dataUri(text, at + "/uri", info.dataUri);
                if (mime != "application/octet-stream" && mime != "application/gltf-buffer")
                    fail(at + "/uri", "data: URI type '" + clipped(mime) +
                                          "' is not application/octet-stream or application/gltf-buffer");
                if (base64Bytes(info.dataUri) < info.byteLength)
                    fail(at + "/byteLength", std::to_string(info.byteLength) + " bytes, but the data: URI holds " +
                                                 std::to_string(base64Bytes(info.dataUri)));
            } else {
                info.file = externalFile(text, at + "/uri", "buffer");
                std::error_code error;
                const uint64_t size = fs::file_size(info.file, error);
                if (error) fail(at + "/uri", "buffer file '" + info.file + "': " + error.message());
                if (size < info.byteLength)
                    fail(at + "/byteLength", std::to_string(info.byteLength) + " bytes, but '" + info.file + "' has " +
                                                 std::to_string(size));
                if (size > maxGltfBufferBytes)
                    fail(at + "/uri", "'" + info.file + "' has " + std::to_string(size) + " bytes; lidr's limit is " +
                                          std::to_string(maxGltfBufferBytes) + " per buffer");
            }
        } else {
            if (i != 0 || !hasBin_)
                fail(at, "buffer without uri; only buffer 0 of a .glb file with a BIN chunk may leave it out");
            if (binLength_ < info.byteLength)
                fail(at + "/byteLength", std::to_string(info.byteLength) + " bytes, but the GLB BIN chunk has " +
                                             std::to_string(binLength_));
            if (binLength_ > info.byteLength + 3)
                fail(at + "/byteLength", std::to_string(info.byteLength) + " bytes, but the GLB BIN chunk has " +
                                             std::to_string(binLength_) + " (more than 3 bytes of padding)");
            info.glbBin = true;
        }
        buffers_.push_back(std::move(info));
    });
}

void Validator::checkBufferViews() {
    forEach("bufferViews", [&](const Json& view, const std::string& at, size_t) {
        ViewInfo info;
        info.buffer = index(view, at, "buffer", "buffers", true);
        const int64_t offset = integer(view, at, "byteOffset", 0);
        if (offset < 0) fail(at + "/byteOffset", "must be >= 0, got " + std::to_string(offset));
        const int64_t length = integer(view, at, "byteLength", 0, true);
        if (length < 1) fail(at + "/byteLength", "must be >= 1, got " + std::to_string(length));
        info.byteOffset = uint64_t(offset);
        info.byteLength = uint64_t(length);
        const uint64_t bufferLength = buffers_[size_t(info.buffer)].byteLength;
        if (info.byteOffset > bufferLength || info.byteLength > bufferLength - info.byteOffset)
            fail(at + "/byteLength", "bytes " + std::to_string(offset) + " + " + std::to_string(length) +
                                         " lie outside buffer " + std::to_string(info.buffer) + " (" +
                                         std::to_string(bufferLength) + " bytes)");
        if (view.contains("byteStride")) {
            const int64_t stride = integer(view, at, "byteStride", 0);
            if (stride < 4 || stride > 252 || stride % 4 != 0)
                fail(at + "/byteStride", "must be a multiple of 4 in [4, 252], got " + std::to_string(stride));
            info.byteStride = uint64_t(stride);
        }
        if (view.contains("target")) {
            const int64_t target = integer(view, at, "target", 0);
            if (target != 34962 && target != 34963)
                fail(at + "/target", "must be 34962 (ARRAY_BUFFER) or 34963 (ELEMENT_ARRAY_BUFFER), got " + std::to_string(target));
        }
        views_.push_back(info);
    });
}

void Validator::checkAccessors() {
    forEach("accessors", [&](const Json& accessor, const std::string& at, size_t) {
        AccessorInfo info;
        info.componentType = integer(accessor, at, "componentType", 0, true);
        const int size = componentSize(info.componentType);
        if (!size)
            fail(at + "/componentType", "must be 5120, 5121, 5122, 5123, 5125 or 5126, got " + std::to_string(info.componentType));
        info.type = member(accessor, at, "type", Kind::String, true)->get<std::string>();
        if (!componentsOf(info.type))
            fail(at + "/type", "'" + clipped(info.type) + "' is not SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3 or MAT4");
        const int64_t count = integer(accessor, at, "count", 0, true);
        if (count < 1) fail(at + "/count", "must be >= 1, got " + std::to_string(count));
        if (uint64_t(count) > maxGltfAccessorCount)
            fail(at + "/count", std::to_string(count) + " elements is over lidr's limit of " +
                                    std::to_string(maxGltfAccessorCount) + " (3 x " +
                                    std::to_string(maxSceneTriangles) + " triangles)");
        info.count = uint64_t(count);
        member(accessor, at, "normalized", Kind::Boolean);
        if (accessor.value("normalized", false) && (info.componentType == 5125 || info.componentType == 5126))
            fail(at + "/normalized", "only byte and short components can be normalized");
        const uint64_t element = elementSize(info.type, size);
        for (const char* key : {"min", "max"}) numbers(accessor, at, key, size_t(componentsOf(info.type)));
        const int64_t offset = integer(accessor, at, "byteOffset", 0);
        if (offset < 0) fail(at + "/byteOffset", "must be >= 0, got " + std::to_string(offset));
        info.bufferView = index(accessor, at, "bufferView", "bufferViews");
        info.byteOffset = offset;
        if (info.bufferView < 0) {
            if (accessor.contains("byteOffset")) fail(at + "/byteOffset", "must not be given without a bufferView");
        } else {
            const ViewInfo& view = views_[size_t(info.bufferView)];
            if (offset % size != 0)
                fail(at + "/byteOffset", std::to_string(offset) + " is not a multiple of the component size " +
                                             std::to_string(size));
            if ((view.byteOffset + uint64_t(offset)) % uint64_t(size) != 0)
                fail(at + "/byteOffset", "bufferView " + std::to_string(info.bufferView) + " offset " +
                                             std::to_string(view.byteOffset) + " + " + std::to_string(offset) +
                                             " is not a multiple of the component size " + std::to_string(size));
            if (view.byteStride && view.byteStride < element)
                fail("/bufferViews/" + std::to_string(info.bufferView) + "/byteStride",
                     "stride " + std::to_string(view.byteStride) + " is smaller than the " + std::to_string(element) +
                         "-byte elements of accessor " + at.substr(11));
            const uint64_t stride = view.byteStride ? view.byteStride : element;
            if (!fits(uint64_t(offset), element, stride, info.count, view.byteLength))
                fail(at + "/count", std::to_string(count) + " elements of " + std::to_string(element) + " bytes (stride " +
                                        std::to_string(stride) + ") from byte " + std::to_string(offset) +
                                        " do not fit bufferView " + std::to_string(info.bufferView) + " (" +
                                        std::to_string(view.byteLength) + " bytes)");
        }
        if (const Json* sparse = member(accessor, at, "sparse", Kind::Object)) {
            const std::string where = at + "/sparse";
            const int64_t sparseCount = integer(*sparse, where, "count", 0, true);
            if (sparseCount < 1 || sparseCount > count)
                fail(where + "/count", "must be in [1, " + std::to_string(count) + "], got " + std::to_string(sparseCount));
            index(*member(*sparse, where, "indices", Kind::Object, true), where + "/indices", "bufferView", "bufferViews", true);
            index(*member(*sparse, where, "values", Kind::Object, true), where + "/values", "bufferView", "bufferViews", true);
        }
        accessors_.push_back(info);
    });
}

}  // namespace lidr::gltf_validation
