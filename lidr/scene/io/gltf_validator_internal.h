#pragma once
// What the files of the glTF validator share (not installed; the API is gltf_validator.h): the Validator, its
// typed access to the JSON with the pointer of every value, and what each section's checks leave for the next.
// The checks are defined by glTF section, one file each:
//   gltf_validator.cpp            the entry point, the order of the checks, messages and typed access
//   gltf_validate_document.cpp    the file: GLB container or JSON text, asset, top-level arrays, extension lists
//   gltf_validate_buffers.cpp     buffers (data: URIs, external files, the GLB BIN chunk), buffer views, accessors
//   gltf_validate_materials.cpp   images (their headers), samplers, textures, materials
//   gltf_validate_nodes.cpp       cameras, lights, meshes, skins, nodes (a forest), scenes, animations
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace lidr::gltf_validation {

using Json = nlohmann::json;

// A JSON pointer segment (RFC 6901): "~" and "/" escaped.
std::string pointerSegment(const std::string& key);

// Decodes base64 text from character `from` (a multiple of 4), at most `maxBytes` bytes.
std::string base64Decode(const std::string& text, size_t from, size_t maxBytes);

// The JSON types a property is checked against (Validator::expect).
enum class Kind { Object, Array, String, Number, Integer, Boolean };

class Validator {
public:
    Validator(const std::string& path, std::vector<std::string>& warnings) : path_(path), warnings_(warnings) {}

    void run();

private:
    // ---- messages and typed access (gltf_validator.cpp) -----------------------------------------------------

    [[noreturn]] void fail(const std::string& pointer, const std::string& rule) const;
    void warn(const std::string& text);
    void expect(const Json& value, const std::string& at, Kind kind) const;
    // The member `key` of `object` (at `at`) checked to be of `kind`, or null where it is absent.
    const Json* member(const Json& object, const std::string& at, const char* key, Kind kind, bool required = false) const;
    double number(const Json& object, const std::string& at, const char* key, double fallback) const;
    int64_t integer(const Json& object, const std::string& at, const char* key, int64_t fallback, bool required = false) const;
    size_t count(const char* array) const;
    // An index into the top-level array `target` (or `size` entries named `what`); -1 where absent.
    int64_t indexAt(const Json& value, const std::string& at, size_t size, const char* what) const;
    int64_t index(const Json& object, const std::string& at, const char* key, const char* target, bool required = false) const;
    // The numbers of a fixed-size array property; empty where absent.
    std::vector<double> numbers(const Json& object, const std::string& at, const char* key, size_t size) const;
    void inRange(const std::vector<double>& values, const std::string& at, double low, double high) const;

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

    // ---- the file (gltf_validate_document.cpp) --------------------------------------------------------------

    std::string readGltfText();
    [[noreturn]] void failGlb(const std::string& rule) const;
    std::string readGlb();
    void checkAsset();
    void checkTopLevelArrays();
    void checkExtensionLists();

    // ---- buffers, views, accessors (gltf_validate_buffers.cpp) ----------------------------------------------

    struct BufferInfo {
        uint64_t byteLength = 0;
        std::string dataUri;  // the base64 text of a data: URI
        std::string file;     // an external file
        bool glbBin = false;
    };

    struct ViewInfo {
        int64_t buffer = 0;
        uint64_t byteOffset = 0, byteLength = 0, byteStride = 0;
    };

    struct AccessorInfo {
        int64_t componentType = 0;
        std::string type;
        uint64_t count = 0;
        int64_t bufferView = -1;
        int64_t byteOffset = 0;
    };

    // A URI's data: "data:<mime>;base64,<text>", checked; returns the MIME type and sets `base64` (a copy).
    std::string dataUri(const std::string& uri, const std::string& at, std::string& base64) const;
    // An external URI resolved against the file's folder, its file kind checked.
    std::string externalFile(const std::string& uri, const std::string& at, const char* what) const;
    // The first bytes of a buffer range (for image headers).
    std::string bufferBytes(int64_t bufferIndex, uint64_t offset, uint64_t length) const;
    void checkBuffers();
    void checkBufferViews();
    void checkAccessors();

    // ---- images, samplers, textures, materials (gltf_validate_materials.cpp) --------------------------------

    void checkImageBytes(const std::string& bytes, const std::string& at, const std::string& declaredType,
                         const std::string& name) const;
    void checkImages();
    void checkSamplersAndTextures();
    void textureInfo(const Json& object, const std::string& at, const char* key) const;
    void checkMaterials();

    // ---- cameras, lights, meshes, skins, nodes, scenes, animations (gltf_validate_nodes.cpp) ----------------

    void checkCameras();
    void checkLights();
    // lidr's own settings on a light or on the node that places it; returns extras.lidr, or null.
    const Json* checkLidrExtras(const Json& owner, const std::string& at) const;
    void checkMeshes();
    void checkSkins();
    void checkNodes();
    void checkScenes();
    void checkAnimations();

    const std::string& path_;
    std::vector<std::string>& warnings_;
    uint64_t fileSize_ = 0;
    bool hasBin_ = false;                // a .glb file with a BIN chunk (readGlb)
    uint64_t binOffset_ = 0, binLength_ = 0;
    Json root_;
    std::vector<BufferInfo> buffers_;    // checkBuffers
    std::vector<ViewInfo> views_;        // checkBufferViews
    std::vector<AccessorInfo> accessors_;  // checkAccessors
    std::vector<int64_t> parent_;        // checkNodes: each node's parent, -1 for a root
    size_t lightCount_ = 0;              // checkLights
};

}  // namespace lidr::gltf_validation
