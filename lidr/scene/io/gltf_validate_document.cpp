// The glTF validator's checks of the file as a whole: the GLB container or the JSON text, the asset (version), the
// top-level arrays and the extension lists (gltf_validator_internal.h).
#include <cctype>
#include <cstdio>
#include <set>
#include <string>

#include "lidr/base/error.h"
#include "lidr/scene/io/file_checks.h"
#include "lidr/scene/io/gltf_validator.h"
#include "lidr/scene/io/gltf_validator_internal.h"

namespace lidr::gltf_validation {

namespace {

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

std::string hex(uint32_t value) {
    char text[16];
    std::snprintf(text, sizeof text, "%08X", value);
    return text;
}

bool parseVersion(const std::string& text, int& major, int& minor) {
    const size_t dot = text.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == text.size() || dot > 6 || text.size() - dot > 7) return false;
    for (size_t i = 0; i < text.size(); ++i)
        if (i != dot && !std::isdigit(static_cast<unsigned char>(text[i]))) return false;
    major = std::stoi(text.substr(0, dot));
    minor = std::stoi(text.substr(dot + 1));
    return true;
}

}  // namespace

std::string Validator::readGltfText() {
    if (fileSize_ > maxGltfJsonBytes)
        fail("", "the JSON is " + std::to_string(fileSize_) + " bytes; at most " + std::to_string(maxGltfJsonBytes) +
                     " are read");
    std::string text = readFileBytes(path_, 0, size_t(fileSize_));
    if (text.size() != fileSize_) throw Error(path_ + ": glTF file could not be read");
    if (text.empty()) fail("", "the file is empty");
    return text;
}

void Validator::failGlb(const std::string& rule) const { throw Error(path_ + ": GLB header: " + rule); }

std::string Validator::readGlb() {
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

void Validator::checkAsset() {
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

void Validator::checkTopLevelArrays() {
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

void Validator::checkExtensionLists() {
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

}  // namespace lidr::gltf_validation
