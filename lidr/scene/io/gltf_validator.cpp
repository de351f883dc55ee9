#include "lidr/scene/io/gltf_validator.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "lidr/base/error.h"
#include "lidr/scene/io/file_checks.h"

namespace lidr {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// Extensions lidr reads; a file that requires any other is refused (the specification's rule for
// extensionsRequired), one that only uses it gets a warning.
const std::set<std::string> extensionsRead = {"KHR_lights_punctual", "KHR_materials_emissive_strength",
                                              "KHR_texture_transform"};

// What some well-known extensions do, so a refusal says what the file needs.
std::string extensionPurpose(const std::string& name) {
    if (name == "KHR_draco_mesh_compression") return " (Draco-compressed meshes)";
    if (name == "EXT_meshopt_compression") return " (meshoptimizer-compressed buffers)";
    if (name == "KHR_mesh_quantization") return " (quantized vertex attributes)";
    if (name == "KHR_texture_basisu") return " (KTX2 / Basis Universal textures)";
    if (name == "EXT_texture_webp") return " (WebP textures)";
    return "";
}

constexpr uint32_t glbMagic = 0x46546C67;      // "glTF"
constexpr uint32_t glbChunkJson = 0x4E4F534A;  // "JSON"
constexpr uint32_t glbChunkBin = 0x004E4942;   // "BIN\0"

uint32_t le32(const unsigned char* p) { return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24; }

// A JSON pointer segment (RFC 6901): "~" and "/" escaped.
std::string pointerSegment(const std::string& key) {
    std::string out;
    for (char c : clipped(key)) {
        if (c == '~') out += "~0";
        else if (c == '/') out += "~1";
        else out += c;
    }
    return out;
}

// The shape of JSON text, scanned without recursion (strings skipped) before any parser runs: a 100,000-deep
// document is refused before a parser recurses into it, a huge number of values before two parsers (this one's
// and tinygltf's) build trees of them.
struct JsonShape {
    size_t offsetPastDepth = std::string::npos;  // where the nesting first passes the limit
    uint64_t values = 0;                          // about: arrays and objects, plus one per ',' (an upper bound)
};

JsonShape jsonShape(const std::string& text, int depthLimit) {
    JsonShape shape;
    int depth = 0;
    bool inString = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\') ++i;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            ++shape.values;
            if (++depth > depthLimit && shape.offsetPastDepth == std::string::npos) shape.offsetPastDepth = i;
        } else if (c == ']' || c == '}') {
            --depth;
        } else if (c == ',') {
            ++shape.values;
        }
    }
    return shape;
}

int base64Value(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
}

// Decodes base64 text from character `from` (a multiple of 4), at most `maxBytes` bytes.
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

class Validator {
public:
    Validator(const std::string& path, std::vector<std::string>& warnings) : path_(path), warnings_(warnings) {}

    void run() {
        const std::string problem = fileProblem(path_);
        if (problem.empty() == false) throw Error(path_ + ": glTF file " + problem);
        std::error_code error;
        fileSize_ = fs::file_size(path_, error);
        if (error) throw Error(path_ + ": glTF file: " + error.message());
        const bool binary = lowerCaseExtension(path_) == ".glb";
        const std::string text = binary ? readGlb() : readGltfText();
        const JsonShape shape = jsonShape(text, maxGltfJsonDepth);
        if (shape.offsetPastDepth != std::string::npos)
            fail("", "JSON nested deeper than " + std::to_string(maxGltfJsonDepth) + " arrays and objects (at byte " +
                         std::to_string(shape.offsetPastDepth) + " of the JSON)");
        if (shape.values > maxGltfJsonValues)
            fail("", "JSON of about " + std::to_string(shape.values) + " values; lidr reads at most " +
                         std::to_string(maxGltfJsonValues));
        try {
            root_ = Json::parse(text);
        } catch (const Json::exception& error) {
            const std::string what = error.what();
            const size_t prefixEnd = what.find("] ");
            fail("", "malformed JSON: " + (prefixEnd == std::string::npos ? what : what.substr(prefixEnd + 2)));
        }
        if (!root_.is_object()) fail("", "the document must be a JSON object, got " + std::string(root_.type_name()));
        checkAsset();
        checkTopLevelArrays();
        checkExtensionLists();
        checkBuffers();
        checkBufferViews();
        checkAccessors();
        checkImages();
        checkSamplersAndTextures();
        checkMaterials();
        checkCameras();
        checkLights();
        checkMeshes();
        checkSkins();
        checkNodes();
        checkScenes();
        checkAnimations();
    }

private:
    // ---- messages and typed access ---------------------------------------------------------------------------

    [[noreturn]] void fail(const std::string& pointer, const std::string& rule) const {
        throw Error(path_ + ": " + (pointer.empty() ? "/" : pointer) + ": " + rule);
    }

    void warn(const std::string& text) { warnings_.push_back(path_ + ": " + text); }

    enum class Kind { Object, Array, String, Number, Integer, Boolean };

    static const char* kindName(Kind kind) {
        switch (kind) {
        case Kind::Object: return "an object";
        case Kind::Array: return "an array";
        case Kind::String: return "a string";
        case Kind::Number: return "a number";
        case Kind::Integer: return "an integer";
        case Kind::Boolean: return "true or false";
        }
        return "";
    }

    static bool isKind(const Json& value, Kind kind) {
        switch (kind) {
        case Kind::Object: return value.is_object();
        case Kind::Array: return value.is_array();
        case Kind::String: return value.is_string();
        case Kind::Number: return value.is_number();
        case Kind::Integer: return value.is_number_integer();  // 1.0 too is refused: tinygltf would not read it
        case Kind::Boolean: return value.is_boolean();
        }
        return false;
    }

    void expect(const Json& value, const std::string& at, Kind kind) const {
        if (!isKind(value, kind)) fail(at, "must be " + std::string(kindName(kind)) + ", got " + value.type_name() +
                                               (value.is_number() ? " " + str(value.get<double>()) : ""));
    }

    // The member `key` of `object` (at `at`) checked to be of `kind`, or null where it is absent.
    const Json* member(const Json& object, const std::string& at, const char* key, Kind kind, bool required = false) const {
        const auto it = object.find(key);
        if (it == object.end()) {
            if (required) fail(at + "/" + key, "required property missing");
            return nullptr;
        }
        expect(*it, at + "/" + key, kind);
        return &*it;
    }

    double number(const Json& object, const std::string& at, const char* key, double fallback) const {
        const Json* value = member(object, at, key, Kind::Number);
        return value ? value->get<double>() : fallback;
    }

    int64_t integer(const Json& object, const std::string& at, const char* key, int64_t fallback, bool required = false) const {
        const Json* value = member(object, at, key, Kind::Integer, required);
        if (!value) return fallback;
        if (value->is_number_unsigned() && value->get<uint64_t>() > uint64_t(INT64_MAX))
            fail(at + "/" + key, "integer " + std::to_string(value->get<uint64_t>()) + " is out of range");
        return value->get<int64_t>();
    }

    size_t count(const char* array) const {
        const auto it = root_.find(array);
        return it != root_.end() && it->is_array() ? it->size() : 0;
    }

    // An index into the top-level array `target` (or `size` entries named `what`); -1 where absent.
    int64_t indexAt(const Json& value, const std::string& at, size_t size, const char* what) const {
        expect(value, at, Kind::Integer);
        const double d = value.get<double>();
        if (d < 0) fail(at, "index " + str(d) + " is negative");
        if (d >= double(size))
            fail(at, "index " + str(d) + " is out of range (" + std::to_string(size) + " " + what + ")");
        return int64_t(d);
    }

    int64_t index(const Json& object, const std::string& at, const char* key, const char* target, bool required = false) const {
        const auto it = object.find(key);
        if (it == object.end()) {
            if (required) fail(at + "/" + key, "required property missing");
            return -1;
        }
        return indexAt(*it, at + "/" + key, count(target), target);
    }

    // The numbers of a fixed-size array property; empty where absent.
    std::vector<double> numbers(const Json& object, const std::string& at, const char* key, size_t size) const {
        const Json* array = member(object, at, key, Kind::Array);
        if (!array) return {};
        if (array->size() != size)
            fail(at + "/" + key, "must have " + std::to_string(size) + " numbers, got " + std::to_string(array->size()));
        std::vector<double> out;
        for (size_t i = 0; i < size; ++i) {
            expect((*array)[i], at + "/" + key + "/" + std::to_string(i), Kind::Number);
            out.push_back((*array)[i].get<double>());
        }
        return out;
    }

    void inRange(const std::vector<double>& values, const std::string& at, double low, double high) const {
        for (size_t i = 0; i < values.size(); ++i)
            if (!(values[i] >= low && values[i] <= high))
                fail(at + "/" + std::to_string(i), "must be in [" + str(low) + ", " + str(high) + "], got " + str(values[i]));
    }

    // Each entry of a top-level array (checked to be an object) with its pointer.
    template <typename F>
    void forEach(const char* array, F&& body) {
        const auto it = root_.find(array);
        if (it == root_.end()) return;
        for (size_t i = 0; i < it->size(); ++i) body((*it)[i], "/" + std::string(array) + "/" + std::to_string(i), i);
    }

    // An optional array of objects inside an entry.
    template <typename F>
    void forEachIn(const Json& object, const std::string& at, const char* key, F&& body, bool required = false) {
        const Json* array = member(object, at, key, Kind::Array, required);
        if (!array) return;
        for (size_t i = 0; i < array->size(); ++i) {
            const std::string where = at + "/" + key + "/" + std::to_string(i);
            expect((*array)[i], where, Kind::Object);
            body((*array)[i], where, i);
        }
    }

    // ---- the container ---------------------------------------------------------------------------------------

    std::string readGltfText() {
        if (fileSize_ > maxGltfJsonBytes)
            fail("", "the JSON is " + std::to_string(fileSize_) + " bytes; at most " + std::to_string(maxGltfJsonBytes) +
                         " are read");
        std::string text = readFileBytes(path_, 0, size_t(fileSize_));
        if (text.size() != fileSize_) throw Error(path_ + ": glTF file could not be read");
        if (text.empty()) fail("", "the file is empty");
        return text;
    }

    [[noreturn]] void failGlb(const std::string& rule) const { throw Error(path_ + ": GLB header: " + rule); }

    std::string readGlb() {
        const std::string header = readFileBytes(path_, 0, 20);
        if (header.size() < 12) failGlb("the file has " + std::to_string(header.size()) + " bytes; a GLB header has 12");
        const auto* h = reinterpret_cast<const unsigned char*>(header.data());
        if (le32(h) != glbMagic) failGlb("magic is not 'glTF' (not a binary glTF file)");
        if (le32(h + 4) != 2) failGlb("version " + std::to_string(le32(h + 4)) + " is not 2 (lidr reads GLB version 2)");
        const uint64_t length = le32(h + 8);
        if (length != fileSize_)
            failGlb("length " + std::to_string(length) + " differs from the file size " + std::to_string(fileSize_));
        if (header.size() < 20) failGlb("no JSON chunk (the first chunk must be JSON)");
        const uint64_t jsonLength = le32(h + 12);
        if (le32(h + 16) != glbChunkJson) failGlb("the first chunk is not JSON (chunk type 0x" + hex(le32(h + 16)) + ")");
        if (20 + jsonLength > fileSize_)
            failGlb("JSON chunk length " + std::to_string(jsonLength) + " runs past the end of the file (" +
                    std::to_string(fileSize_) + " bytes)");
        if (jsonLength % 4 != 0) failGlb("JSON chunk length " + std::to_string(jsonLength) + " is not a multiple of 4");
        if (jsonLength > maxGltfJsonBytes)
            failGlb("JSON chunk of " + std::to_string(jsonLength) + " bytes; at most " + std::to_string(maxGltfJsonBytes) +
                    " are read");
        uint64_t at = 20 + jsonLength;
        for (int chunk = 1; at < fileSize_; ++chunk) {
            const std::string chunkHeader = readFileBytes(path_, at, 8);
            if (chunkHeader.size() < 8) failGlb("chunk " + std::to_string(chunk) + " header is cut off at the end of the file");
            const auto* c = reinterpret_cast<const unsigned char*>(chunkHeader.data());
            const uint64_t chunkLength = le32(c);
            const uint32_t type = le32(c + 4);
            if (at + 8 + chunkLength > fileSize_)
                failGlb("chunk " + std::to_string(chunk) + " length " + std::to_string(chunkLength) +
                        " runs past the end of the file (" + std::to_string(fileSize_) + " bytes)");
            if (chunkLength % 4 != 0)
                failGlb("chunk " + std::to_string(chunk) + " length " + std::to_string(chunkLength) + " is not a multiple of 4");
            if (type == glbChunkJson) failGlb("chunk " + std::to_string(chunk) + " is a second JSON chunk");
            if (type == glbChunkBin) {
                if (chunk != 1) failGlb("the BIN chunk is chunk " + std::to_string(chunk) + "; it must directly follow the JSON chunk");
                binOffset_ = at + 8;
                binLength_ = chunkLength;
                hasBin_ = true;
            }
            at += 8 + chunkLength;
        }
        std::string text = readFileBytes(path_, 20, size_t(jsonLength));
        // Trailing spaces pad the chunk to 4 bytes; NUL padding is tolerated too (written by some exporters).
        while (!text.empty() && text.back() == '\0') text.pop_back();
        return text;
    }

    static std::string hex(uint32_t value) {
        char text[16];
        std::snprintf(text, sizeof text, "%08X", value);
        return text;
    }

    // ---- asset and extensions --------------------------------------------------------------------------------

    static bool parseVersion(const std::string& text, int& major, int& minor) {
        const size_t dot = text.find('.');
        if (dot == std::string::npos || dot == 0 || dot + 1 == text.size() || dot > 6 || text.size() - dot > 7) return false;
        for (size_t i = 0; i < text.size(); ++i)
            if (i != dot && !std::isdigit(static_cast<unsigned char>(text[i]))) return false;
        major = std::stoi(text.substr(0, dot));
        minor = std::stoi(text.substr(dot + 1));
        return true;
    }

    void checkAsset() {
        const Json* asset = member(root_, "", "asset", Kind::Object, true);
        const Json* version = member(*asset, "/asset", "version", Kind::String, true);
        int major = 0, minor = 0;
        if (!parseVersion(version->get<std::string>(), major, minor))
            fail("/asset/version", "'" + clipped(version->get<std::string>()) + "' is not a version MAJOR.MINOR");
        if (major != 2) fail("/asset/version", "glTF " + version->get<std::string>() + " is not 2.x (lidr reads glTF 2.0)");
        if (const Json* minVersion = member(*asset, "/asset", "minVersion", Kind::String)) {
            int minMajor = 0, minMinor = 0;
            if (!parseVersion(minVersion->get<std::string>(), minMajor, minMinor))
                fail("/asset/minVersion", "'" + clipped(minVersion->get<std::string>()) + "' is not a version MAJOR.MINOR");
            if (minMajor > major || (minMajor == major && minMinor > minor))
                fail("/asset/minVersion", "minVersion " + minVersion->get<std::string>() + " is above version " +
                                              version->get<std::string>());
            if (minMajor != 2 || minMinor > 0)
                fail("/asset/minVersion", "the file needs glTF " + minVersion->get<std::string>() + "; lidr reads 2.0");
        }
        for (const char* key : {"generator", "copyright"}) member(*asset, "/asset", key, Kind::String);
    }

    void checkTopLevelArrays() {
        for (const char* name : {"accessors", "animations", "buffers", "bufferViews", "cameras", "images", "materials",
                                 "meshes", "nodes", "samplers", "scenes", "skins", "textures"}) {
            const Json* array = member(root_, "", name, Kind::Array);
            if (!array) continue;
            if (array->size() > maxGltfArrayEntries)
                fail("/" + std::string(name), std::to_string(array->size()) + " entries; lidr reads at most " +
                                                  std::to_string(maxGltfArrayEntries));
            for (size_t i = 0; i < array->size(); ++i) {
                const std::string at = "/" + std::string(name) + "/" + std::to_string(i);
                expect((*array)[i], at, Kind::Object);
                member((*array)[i], at, "name", Kind::String);  // every glTFChildOfRootProperty
                member((*array)[i], at, "extensions", Kind::Object);
            }
        }
        if (root_.contains("scene")) index(root_, "", "scene", "scenes");
        member(root_, "", "extensions", Kind::Object);
    }

    void checkExtensionLists() {
        std::set<std::string> used;
        if (const Json* list = member(root_, "", "extensionsUsed", Kind::Array))
            for (size_t i = 0; i < list->size(); ++i) {
                const std::string at = "/extensionsUsed/" + std::to_string(i);
                expect((*list)[i], at, Kind::String);
                if (!used.insert((*list)[i].get<std::string>()).second) fail(at, "extension listed twice");
            }
        std::set<std::string> required;
        if (const Json* list = member(root_, "", "extensionsRequired", Kind::Array))
            for (size_t i = 0; i < list->size(); ++i) {
                const std::string at = "/extensionsRequired/" + std::to_string(i);
                expect((*list)[i], at, Kind::String);
                const std::string name = (*list)[i].get<std::string>();
                if (!used.count(name)) fail(at, "required extension " + clipped(name) + " is not in extensionsUsed");
                if (!extensionsRead.count(name))
                    fail(at, "required extension " + clipped(name) + extensionPurpose(name) + " is not implemented by lidr");
                required.insert(name);
            }
        for (const std::string& name : used)
            if (!extensionsRead.count(name))
                warn("extension " + clipped(name) + extensionPurpose(name) + " is used but not read by lidr; its content is left out");
    }

    // ---- buffers, views, accessors ---------------------------------------------------------------------------

    struct BufferInfo {
        uint64_t byteLength = 0;
        std::string dataUri;  // the base64 text of a data: URI
        std::string file;     // an external file
        bool glbBin = false;
    };

    // A URI's data: "data:<mime>;base64,<text>", checked; returns the MIME type and sets `base64` (a copy).
    std::string dataUri(const std::string& uri, const std::string& at, std::string& base64) const {
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

    static uint64_t base64Bytes(const std::string& base64) {
        size_t length = base64.size();
        while (length && base64[length - 1] == '=') --length;
        return uint64_t(length) * 6 / 8;
    }

    // An external URI resolved against the file's folder, its file kind checked.
    std::string externalFile(const std::string& uri, const std::string& at, const char* what) const {
        if (uri.find("://") != std::string::npos || uri.rfind("file:", 0) == 0)
            fail(at, "URI '" + clipped(uri) + "' is not a relative path; lidr reads only files next to the glTF file");
        if (uri.empty()) fail(at, "empty URI");
        const std::string file = (fs::path(path_).parent_path() / percentDecoded(uri)).lexically_normal().string();
        const std::string problem = fileProblem(file);
        if (!problem.empty()) fail(at, std::string(what) + " file '" + file + "' " + problem);
        return file;
    }

    void checkBuffers() {
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

    struct ViewInfo {
        int64_t buffer = 0;
        uint64_t byteOffset = 0, byteLength = 0, byteStride = 0;
    };

    void checkBufferViews() {
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

    static int componentSize(int64_t componentType) {
        switch (componentType) {
        case 5120: case 5121: return 1;
        case 5122: case 5123: return 2;
        case 5125: case 5126: return 4;
        default: return 0;
        }
    }

    static int componentsOf(const std::string& type) {
        static const std::pair<const char*, int> types[] = {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4},
                                                           {"MAT2", 4},   {"MAT3", 9}, {"MAT4", 16}};
        for (const auto& t : types)
            if (type == t.first) return t.second;
        return 0;
    }

    // Bytes one element takes, with the column padding the specification asks of small matrices.
    static uint64_t elementSize(const std::string& type, int size) {
        if (type == "MAT2" && size == 1) return 8;
        if (type == "MAT3" && size == 1) return 12;
        if (type == "MAT3" && size == 2) return 24;
        return uint64_t(componentsOf(type)) * uint64_t(size);
    }

    struct AccessorInfo {
        int64_t componentType = 0;
        std::string type;
        uint64_t count = 0;
        int64_t bufferView = -1;
        int64_t byteOffset = 0;
    };

    // Elements of `count` x `element` bytes from `offset` with `stride` fit `length` bytes, without overflow.
    static bool fits(uint64_t offset, uint64_t element, uint64_t stride, uint64_t count, uint64_t length) {
        if (count == 0) return true;
        if (offset > length || element > length - offset) return false;
        return count - 1 <= (length - offset - element) / stride;
    }

    void checkAccessors() {
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

    // ---- images, samplers, textures, materials ---------------------------------------------------------------

    // The first bytes of a buffer range (for image headers).
    std::string bufferBytes(int64_t bufferIndex, uint64_t offset, uint64_t length) const {
        const BufferInfo& buffer = buffers_[size_t(bufferIndex)];
        const size_t wanted = size_t(std::min<uint64_t>(length, imageHeaderBytes));
        if (buffer.glbBin) return readFileBytes(path_, binOffset_ + offset, wanted);
        if (!buffer.file.empty()) return readFileBytes(buffer.file, offset, wanted);
        std::string bytes = base64Decode(buffer.dataUri, size_t(offset / 3 * 4), wanted + 3);
        return bytes.substr(size_t(offset % 3), wanted);
    }

    void checkImageBytes(const std::string& bytes, const std::string& at, const std::string& declaredType,
                         const std::string& name) const {
        const ImageHeader header = pngOrJpegHeader(bytes);
        if (header.kind.empty()) fail(at, name + " is neither PNG nor JPEG (the image formats of glTF 2.0)");
        if (!declaredType.empty() && declaredType != header.kind)
            fail(at, name + " is " + header.kind + " but declared " + clipped(declaredType));
        if (!header.sized) fail(at, name + ": the " + header.kind + " header gives no size (cut off?)");
        if (header.width == 0 || header.height == 0 || header.width > uint64_t(maxTextureSide) ||
            header.height > uint64_t(maxTextureSide))
            fail(at, name + " is " + std::to_string(header.width) + "x" + std::to_string(header.height) +
                         "; textures must be 1.." + std::to_string(maxTextureSide) + " pixels per side");
    }

    void checkImages() {
        forEach("images", [&](const Json& image, const std::string& at, size_t i) {
            const std::string name = "image " + std::to_string(i);
            const Json* mime = member(image, at, "mimeType", Kind::String);
            const std::string mimeType = mime ? mime->get<std::string>() : "";
            if (mime && mimeType != "image/png" && mimeType != "image/jpeg")
                fail(at + "/mimeType", "'" + clipped(mimeType) + "' is not image/png or image/jpeg");
            const Json* uri = member(image, at, "uri", Kind::String);
            const int64_t view = index(image, at, "bufferView", "bufferViews");
            if (uri && view >= 0) fail(at, "has both uri and bufferView; give one");
            if (!uri && view < 0) fail(at, "has neither uri nor bufferView");
            if (view >= 0) {
                if (!mime) fail(at + "/mimeType", "required with bufferView");
                const ViewInfo& v = views_[size_t(view)];
                checkImageBytes(bufferBytes(v.buffer, v.byteOffset, v.byteLength), at + "/bufferView", mimeType, name);
                return;
            }
            const std::string text = uri->get<std::string>();
            if (text.rfind("data:", 0) == 0) {
                std::string base64;
                const std::string type = dataUri(text, at + "/uri", base64);
                if (type != "image/png" && type != "image/jpeg")
                    fail(at + "/uri", "data: URI type '" + clipped(type) + "' is not image/png or image/jpeg");
                checkImageBytes(base64Decode(base64, 0, imageHeaderBytes), at + "/uri", type, name + " (data: URI)");
            } else {
                const std::string file = externalFile(text, at + "/uri", "image");
                checkImageBytes(readFileBytes(file, 0, imageHeaderBytes), at + "/uri", mimeType, name + " '" + file + "'");
            }
        });
    }

    void checkSamplersAndTextures() {
        forEach("samplers", [&](const Json& sampler, const std::string& at, size_t) {
            const auto oneOf = [&](const char* key, std::initializer_list<int64_t> allowed) {
                if (!sampler.contains(key)) return;
                const int64_t value = integer(sampler, at, key, 0);
                if (std::find(allowed.begin(), allowed.end(), value) == allowed.end())
                    fail(at + "/" + key, std::to_string(value) + " is not a GL filter or wrap mode glTF allows");
            };
            oneOf("magFilter", {9728, 9729});
            oneOf("minFilter", {9728, 9729, 9984, 9985, 9986, 9987});
            oneOf("wrapS", {33071, 33648, 10497});
            oneOf("wrapT", {33071, 33648, 10497});
        });
        forEach("textures", [&](const Json& texture, const std::string& at, size_t) {
            index(texture, at, "sampler", "samplers");
            index(texture, at, "source", "images");
        });
    }

    void textureInfo(const Json& object, const std::string& at, const char* key) const {
        const Json* info = member(object, at, key, Kind::Object);
        if (!info) return;
        const std::string where = at + "/" + key;
        index(*info, where, "index", "textures", true);
        if (integer(*info, where, "texCoord", 0) < 0) fail(where + "/texCoord", "must be >= 0");
    }

    void checkMaterials() {
        forEach("materials", [&](const Json& material, const std::string& at, size_t) {
            if (const Json* pbr = member(material, at, "pbrMetallicRoughness", Kind::Object)) {
                const std::string where = at + "/pbrMetallicRoughness";
                inRange(numbers(*pbr, where, "baseColorFactor", 4), where + "/baseColorFactor", 0, 1);
                for (const char* key : {"metallicFactor", "roughnessFactor"}) {
                    const double value = number(*pbr, where, key, 1);
                    if (!(value >= 0 && value <= 1)) fail(where + "/" + key, "must be in [0, 1], got " + str(value));
                }
                textureInfo(*pbr, where, "baseColorTexture");
                textureInfo(*pbr, where, "metallicRoughnessTexture");
            }
            textureInfo(material, at, "normalTexture");
            textureInfo(material, at, "occlusionTexture");
            textureInfo(material, at, "emissiveTexture");
            inRange(numbers(material, at, "emissiveFactor", 3), at + "/emissiveFactor", 0, 1);
            if (const Json* mode = member(material, at, "alphaMode", Kind::String)) {
                const std::string value = mode->get<std::string>();
                if (value != "OPAQUE" && value != "MASK" && value != "BLEND")
                    fail(at + "/alphaMode", "'" + clipped(value) + "' is not OPAQUE, MASK or BLEND");
            }
            if (number(material, at, "alphaCutoff", 0.5) < 0) fail(at + "/alphaCutoff", "must be >= 0");
            member(material, at, "doubleSided", Kind::Boolean);
        });
    }

    // ---- cameras and lights ----------------------------------------------------------------------------------

    void checkCameras() {
        forEach("cameras", [&](const Json& camera, const std::string& at, size_t) {
            const std::string type = member(camera, at, "type", Kind::String, true)->get<std::string>();
            if (type == "perspective") {
                const Json* p = member(camera, at, "perspective", Kind::Object, true);
                const std::string where = at + "/perspective";
                member(*p, where, "yfov", Kind::Number, true);
                member(*p, where, "znear", Kind::Number, true);
                const double yfov = number(*p, where, "yfov", 0);
                if (!(yfov > 0 && yfov < 3.14159265358979))
                    fail(where + "/yfov", "must be in (0, pi) radians, got " + str(yfov));
                const double znear = number(*p, where, "znear", 0);
                if (!(znear > 0)) fail(where + "/znear", "must be > 0, got " + str(znear));
                if (p->contains("zfar") && !(number(*p, where, "zfar", 0) > znear))
                    fail(where + "/zfar", "must be > znear (" + str(znear) + ")");
                if (p->contains("aspectRatio") && !(number(*p, where, "aspectRatio", 1) > 0))
                    fail(where + "/aspectRatio", "must be > 0");
            } else if (type == "orthographic") {
                const Json* o = member(camera, at, "orthographic", Kind::Object, true);
                const std::string where = at + "/orthographic";
                for (const char* key : {"xmag", "ymag", "znear", "zfar"}) member(*o, where, key, Kind::Number, true);
                if (number(*o, where, "xmag", 0) == 0 || number(*o, where, "ymag", 0) == 0)
                    fail(where, "xmag and ymag must not be 0");
                if (!(number(*o, where, "znear", 0) >= 0)) fail(where + "/znear", "must be >= 0");
                if (!(number(*o, where, "zfar", 0) > number(*o, where, "znear", 0))) fail(where + "/zfar", "must be > znear");
            } else {
                fail(at + "/type", "'" + clipped(type) + "' is not perspective or orthographic");
            }
        });
    }

    void checkLights() {
        const Json* extensions = member(root_, "", "extensions", Kind::Object);
        if (!extensions) return;
        const Json* punctual = member(*extensions, "/extensions", "KHR_lights_punctual", Kind::Object);
        if (!punctual) return;
        const std::string at = "/extensions/KHR_lights_punctual";
        const Json* lights = member(*punctual, at, "lights", Kind::Array, true);
        if (lights->size() > maxSceneLights)
            fail(at + "/lights", std::to_string(lights->size()) + " lights; lidr draws at most " +
                                     std::to_string(maxSceneLights) + " (16-bit light indices)");
        lightCount_ = lights->size();
        forEachIn(*punctual, at, "lights", [&](const Json& light, const std::string& where, size_t) {
            const std::string type = member(light, where, "type", Kind::String, true)->get<std::string>();
            if (type != "point" && type != "spot" && type != "directional")
                fail(where + "/type", "'" + clipped(type) + "' is not point, spot or directional");
            inRange(numbers(light, where, "color", 3), where + "/color", 0, 1);
            const double intensity = number(light, where, "intensity", 1);
            if (!(intensity >= 0 && std::isfinite(intensity))) fail(where + "/intensity", "must be >= 0, got " + str(intensity));
            if (light.contains("range") && !(number(light, where, "range", 0) > 0))
                fail(where + "/range", "must be > 0, got " + str(number(light, where, "range", 0)));
            if (type == "spot") {
                const Json* spot = member(light, where, "spot", Kind::Object, true);
                const double inner = number(*spot, where + "/spot", "innerConeAngle", 0);
                const double outer = number(*spot, where + "/spot", "outerConeAngle", 3.14159265358979 / 4);
                if (!(inner >= 0 && inner < outer && outer <= 3.14159265358979 / 2))
                    fail(where + "/spot", "cone angles must satisfy 0 <= inner < outer <= pi/2");
            }
            checkLidrExtras(light, where);
        });
    }

    // lidr's own settings on a light or on the node that places it (doc/scene-format.md, "glTF"): extras.lidr,
    // an object whose only key is "shadow" (true or false). Other extras belong to other applications: any type.
    // Returns extras.lidr, or null where there is none.
    const Json* checkLidrExtras(const Json& owner, const std::string& at) const {
        const auto extras = owner.find("extras");
        if (extras == owner.end() || !extras->is_object()) return nullptr;
        const Json* lidr = member(*extras, at + "/extras", "lidr", Kind::Object);
        if (!lidr) return nullptr;
        for (const auto& item : lidr->items())
            if (item.key() != "shadow")
                fail(at + "/extras/lidr/" + pointerSegment(item.key()),
                     "unknown lidr setting (lidr reads \"shadow\": true or false, whether the light casts shadows)");
        member(*lidr, at + "/extras/lidr", "shadow", Kind::Boolean);
        return lidr;
    }

    // ---- meshes, skins, nodes, scenes, animations ------------------------------------------------------------

    void checkMeshes() {
        forEach("meshes", [&](const Json& mesh, const std::string& at, size_t) {
            const Json* primitives = member(mesh, at, "primitives", Kind::Array, true);
            if (primitives->empty()) fail(at + "/primitives", "must have at least one primitive");
            bool morphed = false;
            forEachIn(mesh, at, "primitives", [&](const Json& primitive, const std::string& where, size_t) {
                const Json* attributes = member(primitive, where, "attributes", Kind::Object, true);
                int64_t vertexCount = -1;
                for (const auto& attribute : attributes->items()) {
                    const std::string key = where + "/attributes/" + pointerSegment(attribute.key());
                    const int64_t accessor = indexAt(attribute.value(), key, accessors_.size(), "accessors");
                    const AccessorInfo& info = accessors_[size_t(accessor)];
                    // The specification's alignment of vertex attributes, stricter than the component size.
                    if (info.bufferView >= 0 && (info.byteOffset % 4 != 0 || views_[size_t(info.bufferView)].byteOffset % 4 != 0))
                        fail(key, "accessor " + std::to_string(accessor) + " starts at byte " +
                                      std::to_string(views_[size_t(info.bufferView)].byteOffset) + " + " +
                                      std::to_string(info.byteOffset) + "; vertex attributes must be 4-byte aligned");
                    const int64_t elements = int64_t(info.count);
                    if (vertexCount >= 0 && elements != vertexCount)
                        fail(key, "accessor " + std::to_string(accessor) + " has " + std::to_string(elements) +
                                      " elements; the primitive's other attributes have " + std::to_string(vertexCount));
                    vertexCount = elements;
                }
                const int64_t indices = index(primitive, where, "indices", "accessors");
                if (indices >= 0) {
                    const AccessorInfo& info = accessors_[size_t(indices)];
                    if (info.type != "SCALAR" ||
                        (info.componentType != 5121 && info.componentType != 5123 && info.componentType != 5125))
                        fail(where + "/indices", "accessor " + std::to_string(indices) +
                                                     " must be SCALAR of unsigned byte, short or int");
                    if (info.bufferView >= 0 && views_[size_t(info.bufferView)].byteStride)
                        fail(where + "/indices", "accessor " + std::to_string(indices) + "'s bufferView " +
                                                     std::to_string(info.bufferView) + " has a byteStride; indices must be tightly packed");
                }
                index(primitive, where, "material", "materials");
                if (primitive.contains("mode")) {
                    const int64_t mode = integer(primitive, where, "mode", 4);
                    if (mode < 0 || mode > 6) fail(where + "/mode", "must be 0..6, got " + std::to_string(mode));
                }
                forEachIn(primitive, where, "targets", [&](const Json& target, const std::string& t, size_t) {
                    morphed = true;
                    for (const auto& attribute : target.items())
                        indexAt(attribute.value(), t + "/" + pointerSegment(attribute.key()), accessors_.size(), "accessors");
                });
            });
            if (morphed) warn(at.substr(1) + ": morph targets are not applied (the base shape is drawn)");
        });
    }

    void checkSkins() {
        forEach("skins", [&](const Json& skin, const std::string& at, size_t) {
            index(skin, at, "inverseBindMatrices", "accessors");
            index(skin, at, "skeleton", "nodes");
            const Json* joints = member(skin, at, "joints", Kind::Array, true);
            for (size_t j = 0; j < joints->size(); ++j)
                indexAt((*joints)[j], at + "/joints/" + std::to_string(j), count("nodes"), "nodes");
        });
        if (count("skins")) warn("skins are not applied (the bind pose is drawn)");
    }

    void checkNodes() {
        const size_t nodes = count("nodes");
        std::vector<int64_t> parent(nodes, -1);
        forEach("nodes", [&](const Json& node, const std::string& at, size_t i) {
            index(node, at, "camera", "cameras");
            index(node, at, "mesh", "meshes");
            if (index(node, at, "skin", "skins") >= 0 && !node.contains("mesh"))
                fail(at + "/skin", "a node with a skin must have a mesh");
            const std::vector<double> matrix = numbers(node, at, "matrix", 16);
            const std::vector<double> rotation = numbers(node, at, "rotation", 4);
            const std::vector<double> scale = numbers(node, at, "scale", 3);
            const std::vector<double> translation = numbers(node, at, "translation", 3);
            for (const auto* values : {&matrix, &rotation, &scale, &translation})
                for (double v : *values)
                    if (!std::isfinite(v)) fail(at, "transform is not finite");
            if (!matrix.empty()) {
                if (!rotation.empty() || !scale.empty() || !translation.empty())
                    fail(at + "/matrix", "a node has matrix or translation/rotation/scale, not both");
                // Column-major: the last row is elements 3, 7, 11, 15.
                if (matrix[3] != 0 || matrix[7] != 0 || matrix[11] != 0 || matrix[15] != 1)
                    fail(at + "/matrix", "the last row must be 0 0 0 1 (an affine transform), got " + str(matrix[3]) + " " +
                                             str(matrix[7]) + " " + str(matrix[11]) + " " + str(matrix[15]));
            }
            if (!rotation.empty()) {
                const double length = std::sqrt(rotation[0] * rotation[0] + rotation[1] * rotation[1] +
                                                 rotation[2] * rotation[2] + rotation[3] * rotation[3]);
                if (std::abs(length - 1.0) > 0.005)
                    fail(at + "/rotation", "must be a unit quaternion, its length is " + str(length));
            }
            if (const Json* children = member(node, at, "children", Kind::Array)) {
                for (size_t c = 0; c < children->size(); ++c) {
                    const std::string where = at + "/children/" + std::to_string(c);
                    const int64_t child = indexAt((*children)[c], where, nodes, "nodes");
                    if (size_t(child) == i) fail(where, "node " + std::to_string(i) + " is its own child");
                    if (parent[size_t(child)] == int64_t(i)) fail(where, "node " + std::to_string(child) + " is listed twice");
                    if (parent[size_t(child)] >= 0)
                        fail(where, "node " + std::to_string(child) + " already has parent node " +
                                        std::to_string(parent[size_t(child)]) + " (a node has at most one parent)");
                    parent[size_t(child)] = int64_t(i);
                }
            }
            bool placesLight = false;
            if (const Json* extensions = member(node, at, "extensions", Kind::Object))
                if (const Json* punctual = member(*extensions, at + "/extensions", "KHR_lights_punctual", Kind::Object)) {
                    indexAt(*member(*punctual, at + "/extensions/KHR_lights_punctual", "light", Kind::Integer, true),
                            at + "/extensions/KHR_lights_punctual/light", lightCount_, "lights");
                    placesLight = true;
                }
            if (checkLidrExtras(node, at) && !placesLight)
                fail(at + "/extras/lidr", "only for a node with a KHR_lights_punctual light (it says whether that "
                                          "light casts shadows)");
        });
        // One parent each, so a cycle is a walk up the parents that comes back to a node on the same walk.
        std::vector<char> state(nodes, 0);  // 0 unseen, 1 on the current walk, 2 done
        for (size_t start = 0; start < nodes; ++start) {
            std::vector<size_t> walk;
            int64_t at = int64_t(start);
            while (at >= 0 && state[size_t(at)] == 0) {
                state[size_t(at)] = 1;
                walk.push_back(size_t(at));
                at = parent[size_t(at)];
            }
            if (at >= 0 && state[size_t(at)] == 1)
                fail("/nodes/" + std::to_string(at), "node " + std::to_string(at) + " is its own ancestor (a cycle)");
            for (size_t n : walk) state[n] = 2;
        }
        parent_ = std::move(parent);
    }

    void checkScenes() {
        forEach("scenes", [&](const Json& scene, const std::string& at, size_t) {
            const Json* nodes = member(scene, at, "nodes", Kind::Array);
            if (!nodes) return;
            std::set<int64_t> seen;
            for (size_t n = 0; n < nodes->size(); ++n) {
                const std::string where = at + "/nodes/" + std::to_string(n);
                const int64_t node = indexAt((*nodes)[n], where, parent_.size(), "nodes");
                if (!seen.insert(node).second) fail(where, "node " + std::to_string(node) + " is listed twice");
                if (parent_[size_t(node)] >= 0)
                    fail(where, "node " + std::to_string(node) + " is a child of node " +
                                    std::to_string(parent_[size_t(node)]) + "; a scene's nodes must be roots");
            }
        });
    }

    void checkAnimations() {
        forEach("animations", [&](const Json& animation, const std::string& at, size_t) {
            const Json* samplers = member(animation, at, "samplers", Kind::Array, true);
            forEachIn(animation, at, "samplers", [&](const Json& sampler, const std::string& where, size_t) {
                index(sampler, where, "input", "accessors", true);
                index(sampler, where, "output", "accessors", true);
            });
            forEachIn(animation, at, "channels", [&](const Json& channel, const std::string& where, size_t) {
                indexAt(*member(channel, where, "sampler", Kind::Integer, true), where + "/sampler", samplers->size(), "samplers");
                index(*member(channel, where, "target", Kind::Object, true), where + "/target", "node", "nodes");
            }, true);
        });
        if (count("animations")) warn("animations are not played (the file's static pose is drawn)");
    }

    const std::string& path_;
    std::vector<std::string>& warnings_;
    uint64_t fileSize_ = 0;
    bool hasBin_ = false;
    uint64_t binOffset_ = 0, binLength_ = 0;
    Json root_;
    std::vector<BufferInfo> buffers_;
    std::vector<ViewInfo> views_;
    std::vector<AccessorInfo> accessors_;
    std::vector<int64_t> parent_;
    size_t lightCount_ = 0;
};

}  // namespace

void validateGltfFile(const std::string& path, std::vector<std::string>& warnings) {
    Validator(path, warnings).run();
}

}  // namespace lidr
