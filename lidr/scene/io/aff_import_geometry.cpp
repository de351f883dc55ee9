// The AFF importer's geometry commands: m (meshes, optionally textured), p / pp (polygons), tt / ttp (textured
// triangles), each a Piece under the current node; the textures they name, found and read once.
#include "lidr/scene/io/aff_importer_internal.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "lidr/base/error.h"
#include "lidr/scene/io/file_checks.h"
#include "lidr/scene/io/ppm_image.h"

namespace lidr::aff_import {

namespace fs = std::filesystem;

namespace {

// The unit normal of triangle a, b, c (counter-clockwise seen from its front); +y where it has no area.
glm::vec3 faceNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length = glm::length(n);
    return length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0.0f, 1.0f, 0.0f);
}

}  // namespace

size_t AffReader::look(const std::string& texture) {
    for (size_t i = 0; i < looks_.size(); ++i)
        if (looks_[i].material == material_ && looks_[i].texture == texture) return i;
    looks_.push_back({material_, texture});
    return looks_.size() - 1;
}

// A texture named by a mesh: beside the file naming it, in a TextureFiles folder beside that file's folder
// (BART's layout: aff/ and TextureFiles/), or in a TextureFiles folder inside it.
std::string AffReader::texturePath(AffTokens& in, const std::string& name) {
    const fs::path folder = fs::path(in.path()).parent_path();
    const fs::path candidates[] = {folder / name, folder.parent_path() / "TextureFiles" / name,
                                   folder / "TextureFiles" / name};
    std::string looked;
    for (const fs::path& candidate : candidates) {
        const std::string path = candidate.lexically_normal().string();
        if (fileProblem(path).empty()) {
            loadTexture(in, path);
            return path;
        }
        looked += (looked.empty() ? "" : ", ") + path;
    }
    in.fail("texture '" + clipped(name, 80) + "' not found (looked for " + looked + ")");
}

void AffReader::loadTexture(AffTokens& in, const std::string& path) {
    auto& image = textures_[path];
    if (image) return;
    const std::string extension = lowerCaseExtension(path);
    if (extension != ".ppm" && extension != ".pgm" && extension != ".pnm")
        in.fail("texture '" + path + "': lidr reads BART's PPM textures (.ppm, .pgm), not " + extension + " files");
    try {
        image = std::make_shared<const ImageRGBA8>(readPpm(path));
    } catch (const Error& e) {
        in.fail(std::string("texture: ") + e.what());
    }
}

void AffReader::addTriangles(AffTokens& in, size_t count) {
    triangles_ += count;
    if (triangles_ > maxSceneTriangles)
        in.fail("the scene so far has " + std::to_string(triangles_) + " triangles; at most " +
                std::to_string(maxSceneTriangles) + " are supported");
}

std::vector<glm::vec3> AffReader::vectors(AffTokens& in, const std::string& what, long count) {
    std::vector<glm::vec3> result;
    result.reserve(size_t(std::min<long>(count, 65536)));  // grows with what the file really holds
    for (long i = 0; i < count; ++i) result.push_back(vector3(in, what + " " + std::to_string(i)));
    return result;
}

void AffReader::mesh(AffTokens& in) {
    const long limit = long(3 * maxSceneTriangles);
    in.expect("vertices", "a mesh (m) starts with its vertices");
    const std::vector<glm::vec3> vertices = vectors(in, "vertex", in.integer("vertex count", 0, limit));
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> texCoords;
    std::string texture;
    if (in.peek() == "normals") {
        in.word("normals");
        normals = vectors(in, "normal", in.integer("normal count", 0, limit));
    }
    if (in.peek() == "texturecoords") {
        in.word("texturecoords");
        const long count = in.integer("texture coordinate count", 0, limit);
        texture = texturePath(in, in.word("the texture's file name (texturecoords N FILE)"));
        texCoords.reserve(size_t(std::min<long>(count, 65536)));
        for (long i = 0; i < count; ++i) {
            const float u = in.number("texture coordinate u"), v = in.number("texture coordinate v");
            texCoords.emplace_back(u, 1.0f - v);  // BART's v runs down the image from its first row; lidr's up
        }
    }
    in.expect("triangles", "a mesh (m) ends with its triangles");
    const long count = in.integer("triangle count", 0, long(maxSceneTriangles));
    addTriangles(in, size_t(count));
    Piece piece;
    piece.node = currentNode();
    piece.look = look(texture);
    piece.mesh.name = fs::path(in.path()).stem().string() + ":" + std::to_string(in.line());
    std::map<std::array<long, 4>, uint32_t> vertexOf;  // (position, normal, texcoord, flat triangle) -> vertex
    for (long t = 0; t < count; ++t) {
        long v[3], n[3] = {-1, -1, -1}, c[3] = {-1, -1, -1};
        for (long& i : v) i = index(in, "vertex", vertices.size());
        if (!normals.empty()) for (long& i : n) i = index(in, "normal", normals.size());
        if (!texCoords.empty()) for (long& i : c) i = index(in, "texture coordinate", texCoords.size());
        const glm::vec3 flat = faceNormal(vertices[size_t(v[0])], vertices[size_t(v[1])], vertices[size_t(v[2])]);
        for (int k = 0; k < 3; ++k) {
            const std::array<long, 4> key{v[k], n[k], c[k], normals.empty() ? t : -1};
            const auto [found, added] = vertexOf.emplace(key, uint32_t(piece.mesh.positions.size()));
            if (added) {
                piece.mesh.positions.push_back(vertices[size_t(v[k])]);
                glm::vec3 normal = n[k] >= 0 ? normals[size_t(n[k])] : flat;
                const float length = glm::length(normal);
                normal = length > 0.0f ? normal / length : flat;
                piece.mesh.normals.push_back(normal);
                if (!texCoords.empty()) piece.mesh.texCoords.push_back(texCoords[size_t(c[k])]);
            }
            piece.mesh.indices.push_back(found->second);
        }
    }
    if (count > 0) pieces_.push_back(std::move(piece));
}

long AffReader::index(AffTokens& in, const char* what, size_t count) {
    const long i = in.integer(std::string("triangle ") + what + " index", 0, long(maxSceneTriangles) * 3);
    if (size_t(i) >= count)
        in.fail(std::string("triangle ") + what + " index " + std::to_string(i) + " out of range (the mesh has " +
                std::to_string(count) + ")");
    return i;
}

// p / pp: a convex polygon, fanned into triangles; pp gives a normal per vertex.
void AffReader::polygon(AffTokens& in, bool patch) {
    const long count = in.integer("polygon vertex count", 3, long(maxSceneTriangles));
    addTriangles(in, size_t(count - 2));
    Piece piece;
    piece.node = currentNode();
    piece.look = look("");
    piece.mesh.name = fs::path(in.path()).stem().string() + ":" + std::to_string(in.line());
    for (long i = 0; i < count; ++i) {
        piece.mesh.positions.push_back(vector3(in, "polygon vertex"));
        if (patch) piece.mesh.normals.push_back(vector3(in, "polygon normal"));
    }
    const glm::vec3 flat = faceNormal(piece.mesh.positions[0], piece.mesh.positions[1], piece.mesh.positions[2]);
    if (!patch) piece.mesh.normals.assign(piece.mesh.positions.size(), flat);
    for (glm::vec3& n : piece.mesh.normals) n = glm::length(n) > 0.0f ? glm::normalize(n) : flat;
    for (long i = 1; i + 1 < count; ++i)
        piece.mesh.indices.insert(piece.mesh.indices.end(), {0u, uint32_t(i), uint32_t(i + 1)});
    pieces_.push_back(std::move(piece));
}

// tt / ttp TEXTURE: one triangle with texture coordinates (ttp: and normals).
void AffReader::texturedTriangle(AffTokens& in, bool patch) {
    const std::string texture = texturePath(in, in.word("the texture's file name (tt FILE)"));
    addTriangles(in, 1);
    Piece piece;
    piece.node = currentNode();
    piece.look = look(texture);
    piece.mesh.name = fs::path(in.path()).stem().string() + ":" + std::to_string(in.line());
    for (int i = 0; i < 3; ++i) {
        piece.mesh.positions.push_back(vector3(in, "triangle vertex"));
        if (patch) piece.mesh.normals.push_back(vector3(in, "triangle normal"));
        const float u = in.number("texture coordinate u"), v = in.number("texture coordinate v");
        piece.mesh.texCoords.emplace_back(u, 1.0f - v);
    }
    const glm::vec3 flat = faceNormal(piece.mesh.positions[0], piece.mesh.positions[1], piece.mesh.positions[2]);
    if (!patch) piece.mesh.normals.assign(3, flat);
    for (glm::vec3& n : piece.mesh.normals) n = glm::length(n) > 0.0f ? glm::normalize(n) : flat;
    piece.mesh.indices = {0, 1, 2};
    pieces_.push_back(std::move(piece));
}

}  // namespace lidr::aff_import
