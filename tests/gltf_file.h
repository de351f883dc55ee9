#pragma once
// A glTF 2.0 file written by a test: JSON with a base64 buffer, a separate .bin or a .glb (test_gltf_import.cpp,
// test_material_textures.cpp): the tests make their own models, nothing is downloaded.
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "lidr/base/image.h"
#include "temp_dir.h"

namespace lidr::test {

using Json = nlohmann::json;

inline std::string base64(const std::vector<unsigned char>& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t v = uint32_t(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= uint32_t(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) v |= bytes[i + 2];
        out += digits[(v >> 18) & 63];
        out += digits[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[v & 63] : '=';
    }
    return out;
}

// A glTF document under construction: one binary buffer, accessors appended to it.
struct GltfFile {
    Json doc = Json{{"asset", {{"version", "2.0"}}}, {"buffers", Json::array()}, {"bufferViews", Json::array()},
                    {"accessors", Json::array()}, {"meshes", Json::array()}, {"nodes", Json::array()},
                    {"scenes", Json::array({Json{{"nodes", Json::array()}}})}, {"scene", 0}};
    std::vector<unsigned char> bin;

    int accessor(const void* data, size_t bytes, int componentType, const char* type, size_t count) {
        while (bin.size() % 4) bin.push_back(0);
        const size_t offset = bin.size();
        bin.insert(bin.end(), static_cast<const unsigned char*>(data), static_cast<const unsigned char*>(data) + bytes);
        doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
        doc["accessors"].push_back({{"bufferView", doc["bufferViews"].size() - 1}, {"componentType", componentType},
                                    {"type", type}, {"count", count}});
        return int(doc["accessors"].size() - 1);
    }
    int positions(const std::vector<glm::vec3>& p) { return accessor(p.data(), p.size() * 12, 5126, "VEC3", p.size()); }
    int indices(const std::vector<uint16_t>& i) { return accessor(i.data(), i.size() * 2, 5123, "SCALAR", i.size()); }

    // A mesh of one primitive; returns its index.
    int mesh(Json primitive) {
        doc["meshes"].push_back({{"primitives", Json::array({primitive})}});
        return int(doc["meshes"].size() - 1);
    }
    int node(Json node, bool root) {
        doc["nodes"].push_back(node);
        const int index = int(doc["nodes"].size() - 1);
        if (root) doc["scenes"][0]["nodes"].push_back(index);
        return index;
    }

    std::string writeGltf(const TempDir& dir, const std::string& name) {
        doc["buffers"] = Json::array({{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}});
        return dir.write(name, doc.dump());
    }
    // An image as an embedded PNG data URI; returns its index in "images".
    int pngImage(const TempDir& dir, const ImageRGBA8& image) {
        const std::string file = dir.file("image" + std::to_string(doc["images"].is_array() ? doc["images"].size() : 0) + ".png");
        writePng(file, image);
        std::ifstream in(file, std::ios::binary);
        const std::vector<unsigned char> png((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (!doc.contains("images")) doc["images"] = Json::array();
        doc["images"].push_back({{"uri", "data:image/png;base64," + base64(png)}});
        return int(doc["images"].size() - 1);
    }
    std::string writeGlb(const TempDir& dir, const std::string& name) {
        doc["buffers"] = Json::array({{{"byteLength", bin.size()}}});
        std::string json = doc.dump();
        while (json.size() % 4) json += ' ';
        std::vector<unsigned char> binary = bin;
        while (binary.size() % 4) binary.push_back(0);
        std::string out;
        const auto u32 = [&](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
        out += "glTF";
        u32(2);
        u32(uint32_t(12 + 8 + json.size() + 8 + binary.size()));
        u32(uint32_t(json.size()));
        out += "JSON";
        out += json;
        u32(uint32_t(binary.size()));
        out.append("BIN\0", 4);
        out.append(reinterpret_cast<const char*>(binary.data()), binary.size());
        return dir.write(name, out);
    }
};


}  // namespace lidr::test
