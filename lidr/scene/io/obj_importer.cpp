#include "lidr/scene/io/obj_importer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include <tiny_obj_loader.h>

#include "lidr/base/colour.h"
#include "lidr/base/error.h"
#include "lidr/scene/io/file_checks.h"
#include "lidr/scene/io/mesh_split.h"

namespace lidr {

namespace {

namespace fs = std::filesystem;

// One pass over the lines before tinyobjloader reads (and allocates) anything:
// - tinyobjloader reads a number it cannot parse ("nan", "inf", "1e999" overflows to inf) as 0 or inf without a
//   word: the first v / vn / vt coordinate that is not a finite float is named;
// - the triangles the faces make (a face of n corners: n - 2) and the vertices are counted against the scene
//   limit, so a huge file is refused before its arrays are built;
// - every mtllib file that is there but is not a regular file (a directory, a device such as /dev/zero, a FIFO
//   that would block, a symbolic link loop) is named; a missing one stays tinyobjloader's warning.
void checkObjLines(const std::string& objPath, const std::function<void(const std::string&)>& fail) {
    std::ifstream in(objPath, std::ios::binary);
    std::string line;
    size_t lineNumber = 0, counts[3] = {0, 0, 0}, triangles = 0;
    static const char* const keywords[3] = {"v", "vn", "vt"};
    static const char* const names[3] = {"vertex", "normal", "texcoord"};
    static const int needed[3] = {3, 3, 2};
    while (std::getline(in, line)) {
        ++lineNumber;
        std::istringstream tokens(line);
        std::string keyword;
        if (!(tokens >> keyword)) continue;
        const std::string where = "line " + std::to_string(lineNumber) + ": ";
        if (keyword == "f") {
            size_t corners = 0;
            for (std::string corner; tokens >> corner;) ++corners;
            triangles += corners >= 3 ? corners - 2 : 0;
            if (triangles > maxSceneTriangles)
                fail(where + "the faces so far make " + std::to_string(triangles) + " triangles; at most " +
                     std::to_string(maxSceneTriangles) + " are supported");
            continue;
        }
        if (keyword == "mtllib") {
            for (std::string file; tokens >> file;) {
                const std::string mtl = (fs::path(objPath).parent_path() / file).lexically_normal().string();
                const std::string problem = fileProblem(mtl);
                if (!problem.empty() && problem != "not found") fail(where + "MTL file '" + mtl + "' " + problem);
            }
            continue;
        }
        int kind = -1;
        for (int k = 0; k < 3; ++k)
            if (keyword == keywords[k]) kind = k;
        if (kind < 0) continue;
        const size_t item = ++counts[kind];
        if (item > 3 * maxSceneTriangles)
            fail(where + "more than " + std::to_string(3 * maxSceneTriangles) + " " + names[kind] +
                 " lines (3 x the scene's triangle limit)");
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


// The materials whose MTL files (named by the OBJ's mtllib lines) give an `illum` line: tinyobjloader reads a
// missing illum as 0 (unlit), which would turn every material without one black-and-flat.
std::set<std::string> materialsWithIllum(const std::string& objPath) {
    std::set<std::string> result;
    std::ifstream obj(objPath, std::ios::binary);
    std::string line;
    while (std::getline(obj, line)) {
        std::istringstream tokens(line);
        std::string keyword, file;
        if (!(tokens >> keyword) || keyword != "mtllib") continue;
        while (tokens >> file) {
            std::ifstream mtl(fs::path(objPath).parent_path() / file, std::ios::binary);
            std::string mtlLine, current;
            while (std::getline(mtl, mtlLine)) {
                std::istringstream words(mtlLine);
                std::string word;
                if (!(words >> word)) continue;
                if (word == "newmtl") {
                    std::getline(words >> std::ws, current);
                    current.erase(current.find_last_not_of(" \t\r") + 1);
                } else if (word == "illum") {
                    result.insert(current);
                }
            }
        }
    }
    return result;
}

// MTL illumination models (illum 0..10) as far as Blinn-Phong with opacity and an emissive term can draw them.
// 0: colour without lighting (Kd shown as is: drawn as emission); 1: no highlights (Ks off); 2: Blinn-Phong;
// 3..10 add reflection, refraction, Fresnel or shadow effects lidr does not draw: shaded as 2, with a warning;
// the glass models (4, 6, 7, 9) are drawn transparent when the file gives no d below 1: opacity from Tf
// (1 - its mean, at least 0.2). Last, an opacity of 0 (d 0, or Tr 1, whose direction exporters disagree on) would
// hide the material: drawn opaque, with a warning.
void applyIllum(Material& material, const tinyobj::material_t& source, bool illumGiven,
                const std::function<void(const std::string&)>& warn) {
    const std::string name = "material '" + source.name + "'";
    const int illum = illumGiven ? source.illum : 2;
    if (illum == 0) {
        material.emissive += material.diffuse;
        material.diffuse = glm::vec3(0.0f);
        material.specular = glm::vec3(0.0f);
    } else if (illum == 1) {
        material.specular = glm::vec3(0.0f);
    } else if (illum >= 3 && illum <= 10) {
        const bool glass = illum == 4 || illum == 6 || illum == 7 || illum == 9;
        const glm::vec3 filter(source.transmittance[0], source.transmittance[1], source.transmittance[2]);
        const float transmitted = (filter.x + filter.y + filter.z) / 3.0f;
        if (glass && material.opacity >= 1.0f && std::isfinite(transmitted) && transmitted > 0.0f) {
            material.opacity = std::clamp(1.0f - transmitted, 0.2f, 1.0f);
            warn(name + ": illum " + std::to_string(illum) + " (glass) drawn as a transparent surface with opacity " +
                 str(material.opacity) + " from Tf; reflection and refraction are not drawn");
        } else {
            warn(name + ": illum " + std::to_string(illum) + " asks for reflection/refraction lidr does not draw; shaded as illum 2");
        }
    } else if (illum != 2) {
        warn(name + ": unknown illum " + std::to_string(illum) + "; shaded as illum 2");
    }
    if (material.opacity <= 0.0f) {
        material.opacity = 1.0f;
        warn(name + ": d 0 (or Tr 1) would make it invisible; drawn opaque (exporters disagree on which way Tr runs)");
    }
}

glm::vec3 normalizedOr(const glm::vec3& v, const glm::vec3& fallback) {
    const float length = glm::length(v);
    return std::isfinite(length) && length > 1e-20f ? v / length : fallback;
}

using Report = std::function<void(const std::string&)>;  // appendObj's fail (throws) and warn

// The file checked before tinyobjloader reads it: its format, that it can be read, the override material, its lines.
void checkObjFile(const Scene& scene, const std::string& objPath, int overrideMaterial, const Report& fail) {
    const std::string format = unsupportedModelFormat(objPath);
    if (!format.empty()) fail("format not supported (" + format + "); OBJ and glTF models can be loaded");
    const std::string extension = lowerCaseExtension(objPath);
    if (extension == ".gltf" || extension == ".glb") fail("a glTF file, not OBJ (appendGltf reads it)");
    const std::string problem = fileProblem(objPath);
    if (!problem.empty()) fail("OBJ file " + problem);
    if (overrideMaterial >= int(scene.materials.size())) fail("override material out of range");
    checkObjLines(objPath, fail);
}

// tinyobjloader's parse (triangulated); its warnings (a missing .mtl, an unknown usemtl: those faces get the
// "default" material) are the scene's, one line each, and not fatal: the geometry is checked after.
void readObj(tinyobj::ObjReader& reader, const std::string& objPath, const Report& fail, const Report& warn) {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    if (!reader.ParseFromFile(objPath, config)) {
        std::string message = reader.Error();
        message.erase(message.find_last_not_of(" \n") + 1);  // tinyobjloader ends its messages with newlines
        fail("malformed OBJ: " + message);
    }
    std::istringstream lines(reader.Warning());
    std::string line;
    while (std::getline(lines, line)) {
        line.erase(line.find_last_not_of(" \r\n.") + 1);
        if (!line.empty()) warn(line);
    }
}

// An MTL material as lidr's, its values checked (a value the renderer cannot use is the file's error, named with
// its keyword: the fuzzer found "Kd 0 0 -0.5" passing import and failing only later, in scene validation).
Material objMaterial(const tinyobj::material_t& source, const fs::path& folder, bool illumGiven, const Report& fail,
                     const Report& warn) {
    Material material;
    material.name = source.name;
    material.diffuse = {source.diffuse[0], source.diffuse[1], source.diffuse[2]};
    material.specular = {source.specular[0], source.specular[1], source.specular[2]};
    material.shininess = std::max(source.shininess, 1.0f);  // exporters often write Ns 0
    material.opacity = source.dissolve;
    material.emissive = {source.emission[0], source.emission[1], source.emission[2]};
    const auto color = [&](const char* keyword, const glm::vec3& c) {
        if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && c.x >= 0.0f && c.y >= 0.0f &&
              c.z >= 0.0f))
            fail("material '" + source.name + "': " + keyword + " must be finite and >= 0, got (" +
                 std::to_string(c.x) + ", " + std::to_string(c.y) + ", " + std::to_string(c.z) + ")");
    };
    color("Kd", material.diffuse);
    color("Ks", material.specular);
    color("Ke", material.emissive);
    // MTL colours are display values (sRGB-encoded, as colour pickers give them); lidr shades in linear light.
    material.diffuse = displayColourToLinear(material.diffuse);
    material.specular = displayColourToLinear(material.specular);
    material.emissive = displayColourToLinear(material.emissive);
    if (!std::isfinite(material.shininess))
        fail("material '" + source.name + "': Ns must be finite, got " + std::to_string(source.shininess));
    if (!(material.opacity >= 0.0f && material.opacity <= 1.0f))
        fail("material '" + source.name + "': d (dissolve) must be in [0, 1], got " + std::to_string(source.dissolve));
    applyIllum(material, source, illumGiven, warn);
    if (!source.diffuse_texname.empty()) {
        material.diffuseTexture = (folder / source.diffuse_texname).lexically_normal().string();
        const std::string problem = imageProblem(material.diffuseTexture);
        if (!problem.empty()) fail("material '" + source.name + "': " + problem);
    }
    return material;
}

// The file's triangles in world space, with what the meshes are built from.
struct Triangle {
    std::array<tinyobj::index_t, 3> corners;
    glm::vec3 faceNormal;
    bool smooth;
    int sceneMaterial;
    size_t shape;
};

struct ObjTriangles {
    std::vector<Triangle> triangles;
    // Corners without a normal in smoothing groups share the normal of their position, averaged over its faces
    // weighted by the corner angle (so how a polygon was triangulated does not matter).
    std::vector<glm::vec3> smoothNormals;
};

// How appendObj places the file's vertices and picks each face's scene material.
struct ObjPlacement {
    const tinyobj::attrib_t& attrib;
    glm::mat4 transform;
    bool mirrored;  // keep triangles counter-clockwise from outside
    int overrideMaterial;
    std::vector<int> sceneMaterialOf;  // per MTL material
    glm::vec3 worldPosition(int index) const {
        const float* p = &attrib.vertices[3 * size_t(index)];
        return glm::vec3(transform * glm::vec4(p[0], p[1], p[2], 1.0f));
    }
};

// A face's corners checked against the file's vertices, normals and texture coordinates.
void checkCorners(const Triangle& triangle, const tinyobj::attrib_t& attrib, const std::string& faceName,
                  const Report& fail) {
    const int positionCount = int(attrib.vertices.size() / 3);
    const int normalCount = int(attrib.normals.size() / 3);
    const int texCoordCount = int(attrib.texcoords.size() / 2);
    for (const tinyobj::index_t& corner : triangle.corners) {
        if (corner.vertex_index < 0 || corner.vertex_index >= positionCount)
            fail(faceName + ": vertex index " + std::to_string(corner.vertex_index + 1) + " out of range (" +
                 std::to_string(positionCount) + " vertices)");
        if (corner.normal_index >= normalCount)
            fail(faceName + ": normal index " + std::to_string(corner.normal_index + 1) + " out of range (" +
                 std::to_string(normalCount) + " normals)");
        if (corner.texcoord_index >= texCoordCount)
            fail(faceName + ": texcoord index " + std::to_string(corner.texcoord_index + 1) + " out of range (" +
                 std::to_string(texCoordCount) + " texcoords)");
    }
}

ObjTriangles collectTriangles(Scene& scene, const std::vector<tinyobj::shape_t>& shapes, const ObjPlacement& place,
                              const ObjImportOptions& options, const Report& fail) {
    ObjTriangles out;
    out.smoothNormals.assign(place.attrib.vertices.size() / 3, glm::vec3(0.0f));
    for (size_t shapeIndex = 0; shapeIndex < shapes.size(); ++shapeIndex) {
        const tinyobj::shape_t& shape = shapes[shapeIndex];
        const tinyobj::mesh_t& source = shape.mesh;
        for (size_t face = 0; face < source.num_face_vertices.size(); ++face) {
            const std::string faceName = "face " + std::to_string(face + 1) + " of '" + shape.name + "'";
            if (source.num_face_vertices[face] != 3)
                fail(faceName + " has " + std::to_string(source.num_face_vertices[face]) + " vertices after triangulation");
            Triangle triangle;
            for (int k = 0; k < 3; ++k) triangle.corners[size_t(k)] = source.indices[3 * face + size_t(k)];
            if (place.mirrored) std::swap(triangle.corners[1], triangle.corners[2]);
            checkCorners(triangle, place.attrib, faceName, fail);
            std::array<glm::vec3, 3> points;
            for (size_t k = 0; k < 3; ++k) points[k] = place.worldPosition(triangle.corners[k].vertex_index);
            const glm::vec3 areaNormal = glm::cross(points[1] - points[0], points[2] - points[0]);
            triangle.faceNormal = normalizedOr(areaNormal, glm::vec3(0.0f, 1.0f, 0.0f));
            triangle.smooth = options.smoothNormals ||
                              (face < source.smoothing_group_ids.size() && source.smoothing_group_ids[face] != 0);
            triangle.shape = shapeIndex;
            const int objMaterial = face < source.material_ids.size() ? source.material_ids[face] : -1;
            if (place.overrideMaterial >= 0)
                triangle.sceneMaterial = place.overrideMaterial;
            else if (objMaterial >= 0 && size_t(objMaterial) < place.sceneMaterialOf.size())
                triangle.sceneMaterial = place.sceneMaterialOf[size_t(objMaterial)];
            else
                triangle.sceneMaterial = findOrAddDefaultMaterial(scene);
            if (triangle.smooth && glm::length(areaNormal) > 0.0f)
                for (size_t k = 0; k < 3; ++k) {
                    if (triangle.corners[k].normal_index >= 0) continue;
                    const glm::vec3 toNext = glm::normalize(points[(k + 1) % 3] - points[k]);
                    const glm::vec3 toPrevious = glm::normalize(points[(k + 2) % 3] - points[k]);
                    const float angle = std::acos(glm::clamp(glm::dot(toNext, toPrevious), -1.0f, 1.0f));
                    out.smoothNormals[size_t(triangle.corners[k].vertex_index)] += angle * triangle.faceNormal;
                }
            out.triangles.push_back(triangle);
        }
    }
    return out;
}

// The triangles as meshes, by group or object (tinyobjloader's shapes, in file order), then scene material: the
// mesh order is deterministic. Each is split spatially for culling (mesh_split.h).
void addMeshes(Scene& scene, const std::string& objPath, const std::vector<tinyobj::shape_t>& shapes,
               const ObjTriangles& obj, const ObjPlacement& place) {
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(place.transform)));
    std::map<std::pair<size_t, int>, MeshBuilder> builders;
    for (const Triangle& triangle : obj.triangles) {
        MeshBuilder& builder = builders[{triangle.shape, triangle.sceneMaterial}];
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
                const float* n = &place.attrib.normals[3 * size_t(corner.normal_index)];
                normal = normalizedOr(normalMatrix * glm::vec3(n[0], n[1], n[2]), triangle.faceNormal);
            } else if (triangle.smooth) {
                normal = normalizedOr(obj.smoothNormals[size_t(corner.vertex_index)], triangle.faceNormal);
            }
            glm::vec2 texCoord(0.0f);
            if (corner.texcoord_index >= 0) {
                texCoord = {place.attrib.texcoords[2 * size_t(corner.texcoord_index)],
                            place.attrib.texcoords[2 * size_t(corner.texcoord_index) + 1]};
                builder.hasTexCoords = true;
            }
            const uint32_t index = uint32_t(builder.mesh.positions.size());
            builder.mesh.positions.push_back(place.worldPosition(corner.vertex_index));
            builder.mesh.normals.push_back(normal);
            builder.mesh.texCoords.push_back(texCoord);
            builder.mesh.indices.push_back(index);
            builder.vertexOf.emplace(key, index);
        }
    }
    const std::string stem = fs::path(objPath).stem().string();
    for (auto& [key, builder] : builders) {
        const auto& [shape, material] = key;
        builder.mesh.material = material;
        const std::string& group = shapes[shape].name;
        builder.mesh.name = stem + "/" + (group.empty() ? "" : group + "/") + scene.materials[size_t(material)].name;
        if (!builder.hasTexCoords) builder.mesh.texCoords.clear();
        for (Mesh& part : splitMeshSpatially(std::move(builder.mesh))) scene.meshes.push_back(std::move(part));
    }
}

}  // namespace

void appendObj(Scene& scene, const std::string& objPath, const glm::mat4& transform, int overrideMaterial,
               const ObjImportOptions& options) {
    const Report fail = [&](const std::string& problem) { throw Error(objPath + ": " + problem); };
    const Report warn = [&](const std::string& warning) { scene.warnings.push_back(objPath + ": " + warning); };
    checkObjFile(scene, objPath, overrideMaterial, fail);
    tinyobj::ObjReader reader;
    readObj(reader, objPath, fail, warn);
    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    const glm::mat3 linear(transform);
    ObjPlacement place{attrib, transform, glm::determinant(linear) < 0.0f, overrideMaterial, {}};
    if (overrideMaterial < 0) {
        const fs::path folder = fs::path(objPath).parent_path();
        const std::set<std::string> withIllum = materialsWithIllum(objPath);
        for (const tinyobj::material_t& source : reader.GetMaterials())
            place.sceneMaterialOf.push_back(
                findOrAddMaterial(scene, objMaterial(source, folder, withIllum.count(source.name) > 0, fail, warn)));
    }
    const int positionCount = int(attrib.vertices.size() / 3);
    for (int i = 0; i < positionCount; ++i)
        if (!std::isfinite(attrib.vertices[3 * i]) || !std::isfinite(attrib.vertices[3 * i + 1]) ||
            !std::isfinite(attrib.vertices[3 * i + 2]))
            fail("vertex " + std::to_string(i + 1) + " is not finite");
    const ObjTriangles obj = collectTriangles(scene, reader.GetShapes(), place, options, fail);
    if (obj.triangles.empty()) fail("no triangles");
    addMeshes(scene, objPath, reader.GetShapes(), obj, place);
}

}  // namespace lidr
