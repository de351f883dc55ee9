#include "lidr/scene/io/scene_loader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cerrno>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <map>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <stb_image.h>
#include <tiny_obj_loader.h>

#include <sys/stat.h>

#include "lidr/scene/default_scene.h"
#include "lidr/base/error.h"
#include "lidr/scene/primitives.h"
#include "lidr/modes/render_mode.h"

namespace lidr {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

constexpr int maxResolution = 16384;
constexpr int maxLights = int(maxSceneLights);
constexpr int maxSegments = maxPrimitiveSegments;
constexpr int maxSubdivisions = maxPrimitiveSubdivisions;
constexpr int maxTextureSide = 16384;  // the largest texture GL 2.1 contexts commonly offer

std::string str(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string str(const glm::vec3& v) { return "(" + str(v.x) + ", " + str(v.y) + ", " + str(v.z) + ")"; }

// JSON nesting allowed in a scene file (the format itself needs 6 levels); deeper input is refused while
// parsing, so an error's path stays short.
constexpr int maxJsonDepth = 64;
// Longest error message a scene file gives; longer ones (a huge key or string echoed back) keep their start
// and end.
constexpr size_t maxMessageLength = 2000;

// A key or text from the file as shown in a message: at most 80 characters.
std::string clipped(const std::string& text, size_t limit = 80) {
    if (text.size() <= limit) return text;
    return text.substr(0, limit) + "...(" + std::to_string(text.size()) + " characters)";
}

// Empty for a regular file (symbolic links followed), else why it cannot be read as one: "not found" only
// when nothing is there; "is a directory", "is not a regular file" (a device, a FIFO), or the system's text
// for any other failure (a symbolic link loop, permissions).
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

// Empty if stb_image can read the image's header and its size fits a texture, else what is wrong with it.
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

// Model formats other than OBJ, by extension, so they are named instead of failing as "no triangles".
std::string unsupportedModelFormat(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    static const std::map<std::string, std::string> known = {
        {".ply", "PLY"}, {".gltf", "glTF"}, {".glb", "glTF"}, {".fbx", "FBX"}, {".stl", "STL"},
        {".dae", "COLLADA"}, {".3ds", "3DS"}, {".blend", "Blender"}, {".usd", "USD"}, {".usdz", "USD"},
        {".abc", "Alembic"}, {".x3d", "X3D"}, {".off", "OFF"}};
    const auto it = known.find(ext);
    return it == known.end() ? std::string() : it->second;
}

// tinyobjloader reads a number it cannot parse ("nan", "inf", "1e999" overflows to inf) as 0 or inf without a
// word; scan the v / vn / vt lines first and name the first coordinate that is not a finite float.
void checkObjNumbers(const std::string& objPath, const std::function<void(const std::string&)>& fail) {
    std::ifstream in(objPath, std::ios::binary);
    std::string line;
    size_t lineNumber = 0, counts[3] = {0, 0, 0};
    static const char* const keywords[3] = {"v", "vn", "vt"};
    static const char* const names[3] = {"vertex", "normal", "texcoord"};
    static const int needed[3] = {3, 3, 2};
    while (std::getline(in, line)) {
        ++lineNumber;
        std::istringstream tokens(line);
        std::string keyword;
        if (!(tokens >> keyword)) continue;
        int kind = -1;
        for (int k = 0; k < 3; ++k)
            if (keyword == keywords[k]) kind = k;
        if (kind < 0) continue;
        const size_t item = ++counts[kind];
        std::string token;
        for (int c = 0; c < needed[kind] && tokens >> token; ++c) {
            char* end = nullptr;
            const double value = std::strtod(token.c_str(), &end);
            const bool parsed = end == token.c_str() + token.size();
            if (!parsed || !std::isfinite(value) || std::abs(value) > double(std::numeric_limits<float>::max()))
                fail("line " + std::to_string(lineNumber) + ": " + names[kind] + " " + std::to_string(item) +
                     " coordinate '" + token + "' is " +
                     (!parsed ? "not a number" : std::isfinite(value) ? "not finite as a float" : "not finite"));
        }
    }
}

// ---------------------------------------------------------------------------------------------------------
// OBJ files

// A vertex of the output mesh: OBJ position, normal and texcoord indices, plus the bits of the face normal
// for corners with a flat normal (so the two triangles of a flat quad still share their vertices).
using CornerKey = std::array<uint32_t, 6>;

CornerKey cornerKey(const tinyobj::index_t& corner, const glm::vec3* flatNormal) {
    CornerKey key{uint32_t(corner.vertex_index), uint32_t(corner.normal_index), uint32_t(corner.texcoord_index),
                  ~0u, ~0u, ~0u};
    if (flatNormal) {
        const glm::vec3 withoutNegativeZero = *flatNormal + glm::vec3(0.0f);  // -0 + 0 is +0
        std::memcpy(&key[3], &withoutNegativeZero, sizeof(glm::vec3));
    }
    return key;
}

struct MeshBuilder {
    Mesh mesh;
    std::map<CornerKey, uint32_t> vertexOf;
    bool hasTexCoords = false;
};

// Loading the same OBJ twice reuses its materials instead of adding copies.
int findOrAddMaterial(Scene& scene, const Material& material) {
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& existing = scene.materials[i];
        if (existing.name == material.name && existing.diffuse == material.diffuse &&
            existing.diffuseTexture == material.diffuseTexture && existing.specular == material.specular &&
            existing.shininess == material.shininess && existing.opacity == material.opacity)
            return int(i);
    }
    scene.materials.push_back(material);
    return int(scene.materials.size() - 1);
}

// Geometry without a material gets the scene's "default" material, which a scene file may define itself.
int findOrAddDefaultMaterial(Scene& scene) {
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].name == "default") return int(i);
    Material material;
    material.name = "default";
    scene.materials.push_back(material);
    return int(scene.materials.size() - 1);
}

glm::vec3 normalizedOr(const glm::vec3& v, const glm::vec3& fallback) {
    const float length = glm::length(v);
    return std::isfinite(length) && length > 1e-20f ? v / length : fallback;
}

}  // namespace

void appendObj(Scene& scene, const std::string& objPath, const glm::mat4& transform, int overrideMaterial) {
    const auto fail = [&](const std::string& problem) { throw Error(objPath + ": " + problem); };
    const std::string format = unsupportedModelFormat(objPath);
    if (!format.empty()) fail("format not supported (" + format + "); only OBJ models can be loaded");
    const std::string problem = fileProblem(objPath);
    if (!problem.empty()) fail("OBJ file " + problem);
    if (overrideMaterial >= int(scene.materials.size())) fail("override material out of range");
    checkObjNumbers(objPath, fail);

    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    // Warnings (a missing .mtl, say) are not fatal; the geometry is checked below.
    if (!reader.ParseFromFile(objPath, config)) {
        std::string message = reader.Error();
        message.erase(message.find_last_not_of(" \n") + 1);  // tinyobjloader ends its messages with newlines
        fail("malformed OBJ: " + message);
    }
    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    const int positionCount = int(attrib.vertices.size() / 3);
    const int normalCount = int(attrib.normals.size() / 3);
    const int texCoordCount = int(attrib.texcoords.size() / 2);

    std::vector<int> sceneMaterialOf;
    if (overrideMaterial < 0) {
        const fs::path folder = fs::path(objPath).parent_path();
        for (const tinyobj::material_t& source : reader.GetMaterials()) {
            Material material;
            material.name = source.name;
            material.diffuse = {source.diffuse[0], source.diffuse[1], source.diffuse[2]};
            material.specular = {source.specular[0], source.specular[1], source.specular[2]};
            material.shininess = std::max(source.shininess, 1.0f);  // exporters often write Ns 0
            material.opacity = source.dissolve;
            // MTL values the renderer cannot use are the file's error, named with its keyword (the fuzzer found
            // "Kd 0 0 -0.5" passing import and failing only later, in scene validation).
            const auto color = [&](const char* keyword, const glm::vec3& c) {
                if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && c.x >= 0.0f && c.y >= 0.0f &&
                      c.z >= 0.0f))
                    fail("material '" + source.name + "': " + keyword + " must be finite and >= 0, got (" +
                         std::to_string(c.x) + ", " + std::to_string(c.y) + ", " + std::to_string(c.z) + ")");
            };
            color("Kd", material.diffuse);
            color("Ks", material.specular);
            if (!std::isfinite(material.shininess))
                fail("material '" + source.name + "': Ns must be finite, got " + std::to_string(source.shininess));
            if (!(material.opacity >= 0.0f && material.opacity <= 1.0f))
                fail("material '" + source.name + "': d (dissolve) must be in [0, 1], got " + std::to_string(source.dissolve));
            if (!source.diffuse_texname.empty()) {
                material.diffuseTexture = (folder / source.diffuse_texname).lexically_normal().string();
                const std::string problem = imageProblem(material.diffuseTexture);
                if (!problem.empty()) fail("material '" + source.name + "': " + problem);
            }
            sceneMaterialOf.push_back(findOrAddMaterial(scene, material));
        }
    }

    const glm::mat3 linear(transform);
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));
    const bool mirrored = glm::determinant(linear) < 0.0f;  // keep triangles counter-clockwise from outside
    const auto worldPosition = [&](int index) {
        const float* p = &attrib.vertices[3 * size_t(index)];
        return glm::vec3(transform * glm::vec4(p[0], p[1], p[2], 1.0f));
    };
    for (int i = 0; i < positionCount; ++i)
        if (!std::isfinite(attrib.vertices[3 * i]) || !std::isfinite(attrib.vertices[3 * i + 1]) ||
            !std::isfinite(attrib.vertices[3 * i + 2]))
            fail("vertex " + std::to_string(i + 1) + " is not finite");

    struct Triangle {
        std::array<tinyobj::index_t, 3> corners;
        glm::vec3 faceNormal;
        bool smooth;
        int sceneMaterial;
    };
    std::vector<Triangle> triangles;
    // Corners without a normal in smoothing groups share the normal of their position, averaged over its
    // faces weighted by the corner angle (so how a polygon was triangulated does not matter).
    std::vector<glm::vec3> smoothNormals(size_t(positionCount), glm::vec3(0.0f));
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const tinyobj::mesh_t& source = shape.mesh;
        for (size_t face = 0; face < source.num_face_vertices.size(); ++face) {
            const std::string faceName = "face " + std::to_string(face + 1) + " of '" + shape.name + "'";
            if (source.num_face_vertices[face] != 3)
                fail(faceName + " has " + std::to_string(source.num_face_vertices[face]) + " vertices after triangulation");
            Triangle triangle;
            for (int k = 0; k < 3; ++k) triangle.corners[size_t(k)] = source.indices[3 * face + size_t(k)];
            if (mirrored) std::swap(triangle.corners[1], triangle.corners[2]);
            for (const tinyobj::index_t& corner : triangle.corners) {
                if (corner.vertex_index < 0 || corner.vertex_index >= positionCount)
                    fail(faceName + ": vertex index " + std::to_string(corner.vertex_index + 1) + " out of range (" +
                         std::to_string(positionCount) + " vertices)");
                if (corner.normal_index >= normalCount)
                    fail(faceName + ": normal index " + std::to_string(corner.normal_index + 1) + " out of range (" +
                         std::to_string(normalCount) + " normals)");
                if (corner.texcoord_index >= texCoordCount)
                    fail(faceName + ": texcoord index " + std::to_string(corner.texcoord_index + 1) +
                         " out of range (" + std::to_string(texCoordCount) + " texcoords)");
            }
            std::array<glm::vec3, 3> points;
            for (size_t k = 0; k < 3; ++k) points[k] = worldPosition(triangle.corners[k].vertex_index);
            const glm::vec3 areaNormal = glm::cross(points[1] - points[0], points[2] - points[0]);
            triangle.faceNormal = normalizedOr(areaNormal, glm::vec3(0.0f, 1.0f, 0.0f));
            triangle.smooth = face < source.smoothing_group_ids.size() && source.smoothing_group_ids[face] != 0;
            const int objMaterial = face < source.material_ids.size() ? source.material_ids[face] : -1;
            if (overrideMaterial >= 0)
                triangle.sceneMaterial = overrideMaterial;
            else if (objMaterial >= 0 && size_t(objMaterial) < sceneMaterialOf.size())
                triangle.sceneMaterial = sceneMaterialOf[size_t(objMaterial)];
            else
                triangle.sceneMaterial = findOrAddDefaultMaterial(scene);
            if (triangle.smooth && glm::length(areaNormal) > 0.0f)
                for (size_t k = 0; k < 3; ++k) {
                    if (triangle.corners[k].normal_index >= 0) continue;
                    const glm::vec3 toNext = glm::normalize(points[(k + 1) % 3] - points[k]);
                    const glm::vec3 toPrevious = glm::normalize(points[(k + 2) % 3] - points[k]);
                    const float angle = std::acos(glm::clamp(glm::dot(toNext, toPrevious), -1.0f, 1.0f));
                    smoothNormals[size_t(triangle.corners[k].vertex_index)] += angle * triangle.faceNormal;
                }
            triangles.push_back(triangle);
        }
    }
    if (triangles.empty()) fail("no triangles");

    const std::string stem = fs::path(objPath).stem().string();
    std::map<int, MeshBuilder> builders;  // by scene material: ascending, so the mesh order is deterministic
    for (const Triangle& triangle : triangles) {
        MeshBuilder& builder = builders[triangle.sceneMaterial];
        for (const tinyobj::index_t& corner : triangle.corners) {
            const bool flat = corner.normal_index < 0 && !triangle.smooth;
            const CornerKey key = cornerKey(corner, flat ? &triangle.faceNormal : nullptr);
            const auto found = builder.vertexOf.find(key);
            if (found != builder.vertexOf.end()) {
                builder.mesh.indices.push_back(found->second);
                continue;
            }
            glm::vec3 normal = triangle.faceNormal;
            if (corner.normal_index >= 0) {
                const float* n = &attrib.normals[3 * size_t(corner.normal_index)];
                normal = normalizedOr(normalMatrix * glm::vec3(n[0], n[1], n[2]), triangle.faceNormal);
            } else if (triangle.smooth) {
                normal = normalizedOr(smoothNormals[size_t(corner.vertex_index)], triangle.faceNormal);
            }
            glm::vec2 texCoord(0.0f);
            if (corner.texcoord_index >= 0) {
                texCoord = {attrib.texcoords[2 * size_t(corner.texcoord_index)],
                            attrib.texcoords[2 * size_t(corner.texcoord_index) + 1]};
                builder.hasTexCoords = true;
            }
            const uint32_t index = uint32_t(builder.mesh.positions.size());
            builder.mesh.positions.push_back(worldPosition(corner.vertex_index));
            builder.mesh.normals.push_back(normal);
            builder.mesh.texCoords.push_back(texCoord);
            builder.mesh.indices.push_back(index);
            builder.vertexOf.emplace(key, index);
        }
    }
    for (auto& [material, builder] : builders) {
        builder.mesh.material = material;
        builder.mesh.name = stem + "/" + scene.materials[size_t(material)].name;
        if (!builder.hasTexCoords) builder.mesh.texCoords.clear();
        scene.meshes.push_back(std::move(builder.mesh));
    }
}

namespace {

// ---------------------------------------------------------------------------------------------------------
// JSON documents

// Builds the document like nlohmann::json::parse, but a syntax error or an out-of-range number (1e999) is
// reported with the path of the value being read (lights[3].radius), and duplicate keys are errors.
class PathTrackingParser : public nlohmann::json_sax<Json> {
public:
    explicit PathTrackingParser(const std::string& file) : file_(file) {}

    Json document;

    bool null() override { return add(nullptr); }
    bool boolean(bool value) override { return add(value); }
    bool number_integer(number_integer_t value) override { return add(value); }
    bool number_unsigned(number_unsigned_t value) override { return add(value); }
    bool number_float(number_float_t value, const string_t&) override { return add(value); }
    bool string(string_t& value) override { return add(value); }
    bool binary(binary_t& value) override { return add(Json::binary(value)); }
    bool start_object(std::size_t) override { return open(Json::object()); }
    bool start_array(std::size_t) override { return open(Json::array()); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    bool key(string_t& name) override {
        Frame& top = open_.back();
        top.key = name;
        if (top.node->contains(name)) fail("duplicate key");
        return true;
    }

    bool parse_error(std::size_t, const std::string&, const Json::exception& error) override {
        // Drop nlohmann's "[json.exception.parse_error.101] " prefix.
        const std::string what = error.what();
        const size_t prefixEnd = what.find("] ");
        fail("malformed JSON: " + (prefixEnd == std::string::npos ? what : what.substr(prefixEnd + 2)));
    }

private:
    struct Frame {
        Json* node;
        std::string key;  // objects: the member being read
    };

    [[noreturn]] void fail(const std::string& problem) const {
        const std::string path = currentPath();
        throw Error(file_ + ": " + (path.empty() ? "" : path + ": ") + problem);
    }

    std::string currentPath() const {
        std::string path;
        for (size_t k = 0; k < open_.size(); ++k) {
            const Frame& frame = open_[k];
            if (frame.node->is_array()) {
                // An element still open is already in the array; the value being read is not yet.
                const size_t index = frame.node->size() - (k + 1 < open_.size() ? 1 : 0);
                path += "[" + std::to_string(index) + "]";
            } else if (!frame.key.empty()) {
                path += (path.empty() ? "" : ".") + clipped(frame.key);
            }
        }
        return path;
    }

    Json* insert(Json value) {
        if (open_.empty()) {
            document = std::move(value);
            return &document;
        }
        Frame& top = open_.back();
        if (top.node->is_array()) {
            top.node->push_back(std::move(value));
            return &top.node->back();
        }
        return &((*top.node)[top.key] = std::move(value));
    }

    bool add(Json value) {
        insert(std::move(value));
        return true;
    }

    bool open(Json container) {
        if (open_.size() >= size_t(maxJsonDepth))
            fail("nested deeper than " + std::to_string(maxJsonDepth) + " arrays and objects (scene files need at most 6)");
        Json* node = insert(std::move(container));
        open_.push_back({node, {}});
        return true;
    }

    bool close() {
        open_.pop_back();
        return true;
    }

    const std::string& file_;
    std::vector<Frame> open_;
};

// A value of the document with its path, so every problem reads "<file>: <path>: <problem>".
class Field {
public:
    Field(const Json& value, std::string path, const std::string& file)
        : value_(value), path_(std::move(path)), file_(file) {}

    const std::string& path() const { return path_; }

    [[noreturn]] void fail(const std::string& problem) const {
        throw Error(file_ + ": " + (path_.empty() ? "" : path_ + ": ") + problem);
    }

    bool has(const char* key) const { return value_.is_object() && value_.contains(key); }
    bool isArray() const { return value_.is_array(); }

    // A member that must be there.
    Field operator[](const char* key) const {
        if (!value_.is_object()) fail("expected an object, got " + typeName());
        const std::string childPath = path_.empty() ? clipped(key) : path_ + "." + clipped(key);
        if (!has(key)) Field(value_, childPath, file_).fail("missing required field");
        return Field(value_.at(key), childPath, file_);
    }

    // An object whose keys are all in `known`: a typo is an error, not a silently ignored setting.
    void expectObject(std::initializer_list<const char*> known) const {
        if (!value_.is_object()) fail("expected an object, got " + typeName());
        for (const auto& member : value_.items()) {
            bool isKnown = false;
            for (const char* name : known) isKnown = isKnown || member.key() == name;
            if (!isKnown) (*this)[member.key().c_str()].fail("unknown key");
        }
    }

    std::vector<Field> items(size_t requiredSize = 0) const {
        if (!value_.is_array()) fail("expected an array, got " + typeName());
        if (requiredSize && value_.size() != requiredSize)
            fail("expected " + std::to_string(requiredSize) + " elements, got " + std::to_string(value_.size()));
        std::vector<Field> result;
        for (size_t i = 0; i < value_.size(); ++i)
            result.emplace_back(value_[i], path_ + "[" + std::to_string(i) + "]", file_);
        return result;
    }

    // A finite number that fits a float.
    float number() const {
        if (!value_.is_number()) fail("expected a number, got " + typeName());
        const double value = value_.get<double>();
        if (!std::isfinite(value) || std::abs(value) > double(std::numeric_limits<float>::max()))
            fail("number " + str(value) + " is out of range");
        return float(value);
    }

    int64_t integer(int64_t min, int64_t max) const {
        if (!value_.is_number()) fail("expected an integer, got " + typeName());
        const double value = value_.get<double>();
        if (value != std::floor(value)) fail("expected an integer, got " + str(value));
        if (value < double(min) || value > double(max))
            fail("must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " + str(value));
        return int64_t(value);
    }

    bool boolean() const {
        if (!value_.is_boolean()) fail("expected true or false, got " + typeName());
        return value_.get<bool>();
    }

    std::string text() const {
        if (!value_.is_string()) fail("expected a string, got " + typeName());
        return value_.get<std::string>();
    }

    glm::vec3 vec3() const {
        const std::vector<Field> elements = items(3);
        return {elements[0].number(), elements[1].number(), elements[2].number()};
    }

    // [x, y, z], or one number for all three.
    glm::vec3 vec3OrScalar() const { return value_.is_number() ? glm::vec3(number()) : vec3(); }

private:
    std::string typeName() const { return value_.type_name(); }

    const Json& value_;
    std::string path_;
    const std::string& file_;
};

float positive(const Field& field) {
    const float value = field.number();
    if (!(value > 0.0f)) field.fail("must be > 0, got " + str(value));
    return value;
}

float nonNegative(const Field& field) {
    const float value = field.number();
    if (!(value >= 0.0f)) field.fail("must be >= 0, got " + str(value));
    return value;
}

glm::vec3 color(const Field& field) {
    const glm::vec3 value = field.vec3OrScalar();
    if (value.x < 0.0f || value.y < 0.0f || value.z < 0.0f)
        field.fail("colour components must be >= 0, got " + str(value));
    return value;
}

glm::vec3 positiveVec3(const Field& field) {
    const glm::vec3 value = field.vec3OrScalar();
    if (!(value.x > 0.0f && value.y > 0.0f && value.z > 0.0f))
        field.fail("components must be > 0, got " + str(value));
    return value;
}

// Reads one scene document into a Scene; the sections are applied in a fixed order (base, materials,
// models, primitives, lights, generate), whatever their order in the file.
class SceneReader {
public:
    SceneReader(const std::string& file, const std::string& baseDir) : file_(file), baseDir_(baseDir) {}

    Scene read(const Json& document) {
        const Field root(document, "", file_);
        root.expectObject({"name", "description", "base", "seed", "base_lights", "resolution", "time", "camera",
                           "ambient", "background", "materials", "models", "primitives", "lights", "generate",
                           "msaa", "transparency", "mode"});
        readBase(root);
        if (root.has("name")) scene_.name = root["name"].text();
        if (root.has("description")) root["description"].text();  // free text for people; only its type is checked
        if (root.has("resolution")) readResolution(root["resolution"]);
        if (root.has("time")) scene_.time = root["time"].number();
        if (root.has("mode")) {
            scene_.renderMode = root["mode"].text();
            if (!isRenderModeName(scene_.renderMode))
                root["mode"].fail("unknown render mode '" + scene_.renderMode + "' (valid: " + renderModeList() + ")");
        }
        if (root.has("camera")) readCamera(root["camera"]);
        if (root.has("ambient")) scene_.ambient = color(root["ambient"]);
        if (root.has("background")) scene_.backgroundColor = color(root["background"]);
        if (root.has("msaa")) {
            scene_.msaaSamples = int(root["msaa"].integer(0, 64));
            if (scene_.msaaSamples != 0 && (scene_.msaaSamples < 2 || (scene_.msaaSamples & (scene_.msaaSamples - 1)) != 0))
                root["msaa"].fail("must be 0 (off) or a power of two 2, 4, 8, ... 64, got " +
                                  std::to_string(scene_.msaaSamples));
        }
        if (root.has("transparency")) scene_.transparency = root["transparency"].boolean();
        if (root.has("materials"))
            for (const Field& material : root["materials"].items()) readMaterial(material);
        if (root.has("models"))
            for (const Field& model : root["models"].items()) readModel(model);
        if (root.has("primitives"))
            for (const Field& primitive : root["primitives"].items()) readPrimitive(primitive);
        // Paths stay one per light while reading; all-static scenes drop them at the end.
        scene_.lightPaths.resize(scene_.lights.size());
        if (root.has("lights"))
            for (const Field& light : root["lights"].items()) readLight(light);
        if (root.has("generate")) readGenerators(root["generate"]);
        bool anyMoves = false;
        for (const LightPath& path : scene_.lightPaths) anyMoves = anyMoves || path.kind != LightPath::Kind::Static;
        if (!anyMoves) scene_.lightPaths.clear();

        try {
            scene_.validate(maxResolution);
        } catch (const Error& error) {
            throw Error(file_ + ": " + error.what());
        }
        return std::move(scene_);
    }

private:
    void readBase(const Field& root) {
        if (!root.has("base")) {
            if (root.has("seed")) root["seed"].fail("only used with \"base\"");
            if (root.has("base_lights")) root["base_lights"].fail("only used with \"base\"");
            return;
        }
        const std::string base = root["base"].text();
        if (base != "default-room") root["base"].fail("unknown base scene '" + base + "' (known: default-room)");
        DefaultSceneOptions options;
        if (root.has("seed")) options.seed = uint32_t(root["seed"].integer(0, std::numeric_limits<uint32_t>::max()));
        scene_ = makeDefaultScene(options);
        if (!(root.has("base_lights") && root["base_lights"].boolean())) {
            scene_.lights.clear();
            scene_.lightPaths.clear();
        }
    }

    void readResolution(const Field& field) {
        const std::vector<Field> size = field.items(2);
        scene_.width = int(size[0].integer(1, maxResolution));
        scene_.height = int(size[1].integer(1, maxResolution));
    }

    void readCamera(const Field& field) {
        field.expectObject({"position", "target", "up", "fov", "near", "far"});
        Camera& camera = scene_.camera;
        if (field.has("position")) camera.position = field["position"].vec3();
        if (field.has("target")) camera.target = field["target"].vec3();
        if (field.has("up")) camera.up = field["up"].vec3();
        if (field.has("fov")) camera.fovYDegrees = field["fov"].number();
        if (field.has("near")) camera.nearPlane = field["near"].number();
        if (field.has("far")) camera.farPlane = field["far"].number();
        // Ranges and consistency are checked with the whole scene (Scene::validate names "camera").
    }

    void readMaterial(const Field& field) {
        field.expectObject({"name", "diffuse", "texture", "specular", "shininess", "opacity"});
        Material material;
        material.name = field["name"].text();
        if (material.name.empty()) field["name"].fail("must not be empty");
        if (findMaterial(material.name) >= 0) field["name"].fail("material '" + material.name + "' already exists");
        if (field.has("diffuse")) material.diffuse = color(field["diffuse"]);
        if (field.has("texture")) {
            material.diffuseTexture = resolve(field["texture"].text());
            const std::string problem = imageProblem(material.diffuseTexture);
            if (!problem.empty()) field["texture"].fail(problem);
        }
        if (field.has("specular")) material.specular = color(field["specular"]);
        if (field.has("shininess")) material.shininess = positive(field["shininess"]);
        if (field.has("opacity")) {
            material.opacity = field["opacity"].number();
            if (!(material.opacity >= 0.0f && material.opacity <= 1.0f))
                field["opacity"].fail("must be in [0, 1], got " + str(material.opacity));
        }
        scene_.materials.push_back(material);
    }

    void readModel(const Field& field) {
        field.expectObject({"file", "translate", "rotate", "rotate_y", "scale", "material"});
        glm::mat4 transform(1.0f);
        if (field.has("translate")) transform = glm::translate(transform, field["translate"].vec3());
        if (field.has("rotate") && field.has("rotate_y")) field.fail("give either \"rotate\" or \"rotate_y\", not both");
        if (field.has("rotate")) {
            const std::vector<Field> values = field["rotate"].items(4);
            const float angle = values[0].number();
            const glm::vec3 axis(values[1].number(), values[2].number(), values[3].number());
            if (glm::length(axis) == 0.0f) field["rotate"].fail("the axis must not be zero");
            transform = glm::rotate(transform, glm::radians(angle), glm::normalize(axis));
        }
        if (field.has("rotate_y"))
            transform = glm::rotate(transform, glm::radians(field["rotate_y"].number()), glm::vec3(0, 1, 0));
        if (field.has("scale")) transform = glm::scale(transform, positiveVec3(field["scale"]));
        const int material = field.has("material") ? materialIndex(field["material"]) : -1;
        const Field file = field["file"];
        try {
            appendObj(scene_, resolve(file.text()), transform, material);
        } catch (const Error& error) {
            file.fail(error.what());
        }
        checkTriangleCount(field);
    }

    void readPrimitive(const Field& field) {
        const std::string shape = field["shape"].text();
        const int material = field.has("material") ? materialIndex(field["material"]) : findOrAddDefaultMaterial(scene_);
        const auto segments = [&](const char* key, int fallback) {
            return field.has(key) ? int(field[key].integer(3, maxSegments)) : fallback;
        };
        const auto subdivisions = [&] {
            return field.has("subdivisions") ? int(field["subdivisions"].integer(1, maxSubdivisions)) : 1;
        };
        if (shape == "box") {
            field.expectObject({"shape", "material", "min", "max", "subdivisions"});
            const glm::vec3 min = field["min"].vec3(), max = field["max"].vec3();
            if (!(min.x < max.x && min.y < max.y && min.z < max.z))
                field["max"].fail("must be greater than min " + str(min) + " on every axis, got " + str(max));
            addBox(scene_, min, max, material, subdivisions());
        } else if (shape == "plane") {
            field.expectObject({"shape", "material", "center", "size", "subdivisions"});
            const std::vector<Field> size = field["size"].items(2);
            addPlane(scene_, field["center"].vec3(), {positive(size[0]), positive(size[1])}, material, subdivisions());
        } else if (shape == "sphere") {
            field.expectObject({"shape", "material", "center", "radius", "segments"});
            addSphere(scene_, field["center"].vec3(), positive(field["radius"]), material, segments("segments", 16));
        } else if (shape == "cylinder") {
            field.expectObject({"shape", "material", "base", "radius", "height", "segments"});
            addCylinder(scene_, field["base"].vec3(), positive(field["radius"]), positive(field["height"]), material,
                        segments("segments", 16));
        } else if (shape == "torus") {
            field.expectObject(
                {"shape", "material", "center", "major_radius", "minor_radius", "major_segments", "minor_segments"});
            addTorus(scene_, field["center"].vec3(), positive(field["major_radius"]), positive(field["minor_radius"]),
                     material, segments("major_segments", 24), segments("minor_segments", 12));
        } else {
            field["shape"].fail("unknown shape '" + shape + "' (known: box, plane, sphere, cylinder, torus)");
        }
        checkTriangleCount(field);
    }

    // After each primitive or model (each adds at most a few million triangles, see the limits), so a scene
    // that asks for too many stops before the rest is built.
    void checkTriangleCount(const Field& field) const {
        const size_t count = scene_.triangleCount();
        if (count > maxSceneTriangles)
            field.fail("the scene now has " + std::to_string(count) + " triangles; at most " +
                       std::to_string(maxSceneTriangles) + " are supported");
    }

    void readLight(const Field& field) {
        field.expectObject({"position", "radius", "color", "priority", "path"});
        PointLight light;
        LightPath path;
        if (field.has("path")) path = readPath(field["path"]);
        if (path.kind == LightPath::Kind::Orbit) {
            if (field.has("position"))
                field["position"].fail("not used by orbit lights: they start on their orbit (see path)");
            light.position = evaluatePath(path, glm::vec3(0.0f), 0.0f);
        } else {
            light.position = field["position"].vec3();
        }
        light.radius = positive(field["radius"]);
        if (light.radius > maxLightRadius)
            field["radius"].fail("radius " + str(light.radius) + " is too large (limit " + str(maxLightRadius) + ")");
        if (field.has("color")) light.color = color(field["color"]);
        if (field.has("priority")) light.priority = field["priority"].number();
        scene_.lights.push_back(light);
        scene_.lightPaths.push_back(path);
    }

    LightPath readPath(const Field& field) {
        LightPath path;
        const std::string kind = field["kind"].text();
        if (kind == "static") {
            field.expectObject({"kind"});
        } else if (kind == "orbit") {
            field.expectObject({"kind", "center", "radius", "angular_speed", "phase", "bob"});
            path.kind = LightPath::Kind::Orbit;
            path.center = field["center"].vec3();
            path.orbitRadius = nonNegative(field["radius"]);
            path.angularSpeed = field["angular_speed"].number();
            if (field.has("phase")) path.phase = field["phase"].number();
            if (field.has("bob")) path.bobAmplitude = field["bob"].number();
        } else if (kind == "bounce") {
            field.expectObject({"kind", "velocity", "box_min", "box_max"});
            path.kind = LightPath::Kind::Bounce;
            path.velocity = field["velocity"].vec3();
            path.boxMin = field["box_min"].vec3();
            path.boxMax = field["box_max"].vec3();
            if (!glm::all(glm::lessThanEqual(path.boxMin, path.boxMax)))
                field["box_max"].fail("must be >= box_min " + str(path.boxMin) + " on every axis, got " + str(path.boxMax));
        } else {
            field["kind"].fail("unknown path kind '" + kind + "' (known: static, orbit, bounce)");
        }
        return path;
    }

    // "generate" is one generator object or an array of them.
    void readGenerators(const Field& field) {
        if (field.isArray())
            for (const Field& generator : field.items()) readGenerator(generator);
        else
            readGenerator(field);
    }

    void readGenerator(const Field& field) {
        field.expectObject({"seed", "count", "bounds_min", "bounds_max", "radius_min", "radius_max", "intensity", "speed"});
        LightGeneratorOptions options;
        if (field.has("seed")) options.seed = uint32_t(field["seed"].integer(0, std::numeric_limits<uint32_t>::max()));
        const Field count = field["count"];
        options.count = int(count.integer(0, maxLights));
        if (scene_.lights.size() + size_t(options.count) > size_t(maxLights))
            count.fail(std::to_string(options.count) + " more lights would make " +
                       std::to_string(scene_.lights.size() + size_t(options.count)) + "; at most " +
                       std::to_string(maxLights) + " are supported");
        options.boundsMin = field["bounds_min"].vec3();
        options.boundsMax = field["bounds_max"].vec3();
        if (!glm::all(glm::lessThanEqual(options.boundsMin, options.boundsMax)))
            field["bounds_max"].fail("must be >= bounds_min " + str(options.boundsMin) + " on every axis, got " +
                                     str(options.boundsMax));
        if (field.has("radius_min")) options.radiusMin = positive(field["radius_min"]);
        if (field.has("radius_max")) options.radiusMax = positive(field["radius_max"]);
        if (options.radiusMax > maxLightRadius)
            field["radius_max"].fail("radius " + str(options.radiusMax) + " is too large (limit " + str(maxLightRadius) + ")");
        if (!isFinite(options.boundsMax - options.boundsMin) || !isFinite(options.boundsMin - glm::vec3(options.radiusMax)) ||
            !isFinite(options.boundsMax + glm::vec3(options.radiusMax)))
            field.fail("light generator bounds " + str(options.boundsMin) + " .. " + str(options.boundsMax) +
                       " overflow float (their extent, or the bounds +- radius_max, is not finite)");
        if (options.radiusMin > options.radiusMax)
            field.fail("radius_min (" + str(options.radiusMin) + ") must be <= radius_max (" + str(options.radiusMax) + ")");
        if (field.has("intensity")) options.intensity = nonNegative(field["intensity"]);
        if (field.has("speed")) options.speed = nonNegative(field["speed"]);
        generateLights(scene_, options);
    }

    int findMaterial(const std::string& name) const {
        for (size_t i = 0; i < scene_.materials.size(); ++i)
            if (scene_.materials[i].name == name) return int(i);
        return -1;
    }

    int materialIndex(const Field& field) const {
        const std::string name = field.text();
        const int index = findMaterial(name);
        if (index < 0) field.fail("unknown material '" + name + "'");
        return index;
    }

    std::string resolve(const std::string& path) const {
        if (path.empty() || fs::path(path).is_absolute() || baseDir_.empty()) return path;
        return (fs::path(baseDir_) / path).lexically_normal().string();
    }

    const std::string& file_;
    const std::string baseDir_;
    Scene scene_;
};

}  // namespace

Scene parseSceneJson(const std::string& jsonText, const std::string& baseDir, const std::string& nameForErrors) {
    try {
        PathTrackingParser parser(nameForErrors);
        Json::sax_parse(jsonText, &parser);
        return SceneReader(nameForErrors, baseDir).read(parser.document);
    } catch (const Error& error) {
        const std::string message = error.what();
        if (message.size() <= maxMessageLength) throw;
        const size_t keep = maxMessageLength / 2;
        throw Error(message.substr(0, keep) + " ...(" + std::to_string(message.size() - 2 * keep) +
                    " characters left out)... " + message.substr(message.size() - keep));
    }
}

Scene loadSceneFile(const std::string& path) {
    std::error_code error;
    if (!fs::exists(path, error) && !error) throw Error(path + ": scene file not found");
    const std::string problem = fileProblem(path);
    if (!problem.empty()) throw Error(path + ": scene file " + problem);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open the scene file");
    std::ostringstream text;
    text << in.rdbuf();  // an empty file sets failbit on `text`; the parser then reports it
    if (in.bad()) throw Error(path + ": cannot read the scene file");
    return parseSceneJson(text.str(), fs::path(path).parent_path().string(), path);
}

}  // namespace lidr
