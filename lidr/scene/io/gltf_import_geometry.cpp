// The glTF importer's geometry: one mesh primitive's attributes and triangles (strips and fans unrolled), its
// vertices in world space (shared as the file has them, or three a triangle with flat normals), split spatially.
#include "lidr/scene/io/gltf_importer_internal.h"

#include <utility>

#include "lidr/scene/io/mesh_split.h"

namespace lidr::gltf_import {

namespace {

// A primitive's vertices as lidr draws them: in world space, checked finite, v flipped, and the triangles'
// winding kept counter-clockwise from outside under a mirroring transform.
class PrimitiveVertices {
public:
    PrimitiveVertices(const PrimitiveAttributes& a, const glm::mat4& world, const std::string& path,
                      const std::string& what)
        : a_(a), world_(world), linear_(world), normalMatrix_(glm::transpose(glm::inverse(linear_))),
          mirrored_(glm::determinant(linear_) < 0.0f), path_(path), what_(what) {}

    // Shared vertices, as the file has them.
    void appendShared(Mesh& out, const std::vector<uint32_t>& triangles) const {
        std::vector<uint32_t> remap(a_.positions.count, ~0u);
        for (size_t c = 0; c < triangles.size(); ++c) {
            const size_t corner = mirrored_ ? (c - c % 3) + (3 - c % 3) % 3 : c;  // 0, 2, 1 when mirrored
            const uint32_t source = triangles[corner];
            if (remap[source] == ~0u) {
                remap[source] = uint32_t(out.positions.size());
                out.positions.push_back(position(source));
                out.normals.push_back(normal(source));
                if (a_.hasTexCoords) out.texCoords.push_back(texCoord(a_.texCoords, source));
                if (a_.hasTexCoords1) out.texCoords1.push_back(texCoord(a_.texCoords1, source));
                if (a_.hasTangents) out.tangents.push_back(tangent(source));
            }
            out.indices.push_back(remap[source]);
        }
    }

    // Flat normals (the glTF specification's rule without NORMAL): three vertices per triangle.
    void appendFlat(Mesh& out, const std::vector<uint32_t>& triangles) const {
        for (size_t t = 0; t < triangles.size(); t += 3) {
            uint32_t source[3] = {triangles[t], triangles[t + 1], triangles[t + 2]};
            if (mirrored_) std::swap(source[1], source[2]);
            const glm::vec3 p[3] = {position(source[0]), position(source[1]), position(source[2])};
            const glm::vec3 normal = normalizedOr(glm::cross(p[1] - p[0], p[2] - p[0]), glm::vec3(0.0f, 1.0f, 0.0f));
            for (int k = 0; k < 3; ++k) {
                out.indices.push_back(uint32_t(out.positions.size()));
                out.positions.push_back(p[k]);
                out.normals.push_back(normal);
                if (a_.hasTexCoords) out.texCoords.push_back(texCoord(a_.texCoords, source[k]));
                if (a_.hasTexCoords1) out.texCoords1.push_back(texCoord(a_.texCoords1, source[k]));
            }
        }
    }

private:
    [[noreturn]] void fail(const std::string& problem) const { throw Error(path_ + ": " + what_ + ": " + problem); }

    glm::vec3 position(uint32_t i) const {
        const AccessorView& v = a_.positions;
        const glm::vec3 p(gltfComponent(v, i, 0), gltfComponent(v, i, 1), gltfComponent(v, i, 2));
        if (!isFinite(p)) fail("position " + std::to_string(i) + " is not finite");
        return glm::vec3(world_ * glm::vec4(p, 1.0f));
    }

    glm::vec3 normal(uint32_t i) const {
        const AccessorView& v = a_.normals;
        const glm::vec3 n(gltfComponent(v, i, 0), gltfComponent(v, i, 1), gltfComponent(v, i, 2));
        if (!isFinite(n)) fail("normal " + std::to_string(i) + " is not finite");
        return normalizedOr(normalMatrix_ * n, glm::vec3(0.0f, 1.0f, 0.0f));
    }

    glm::vec2 texCoord(const AccessorView& set, uint32_t i) const {
        // glTF puts v = 0 at the image's top; lidr (like OBJ) at the bottom.
        const glm::vec2 t(gltfComponent(set, i, 0), 1.0f - gltfComponent(set, i, 1));
        if (!std::isfinite(t.x) || !std::isfinite(t.y)) fail("texture coordinate " + std::to_string(i) + " is not finite");
        return t;
    }

    glm::vec4 tangent(uint32_t i) const {
        const AccessorView& v = a_.tangents;
        const glm::vec4 t(gltfComponent(v, i, 0), gltfComponent(v, i, 1), gltfComponent(v, i, 2), gltfComponent(v, i, 3));
        if (!isFinite(glm::vec3(t)) || !std::isfinite(t.w)) fail("tangent " + std::to_string(i) + " is not finite");
        // A mirroring transform turns the frame's handedness over (the normal follows the inverse transpose).
        const float w = (t.w < 0.0f ? -1.0f : 1.0f) * (mirrored_ ? -1.0f : 1.0f);
        return glm::vec4(normalizedOr(linear_ * glm::vec3(t), glm::vec3(1.0f, 0.0f, 0.0f)), w);
    }

    const PrimitiveAttributes& a_;
    const glm::mat4 world_;
    const glm::mat3 linear_, normalMatrix_;
    const bool mirrored_;
    const std::string& path_;
    const std::string& what_;
};

}  // namespace

AccessorView GltfReader::view(int accessorIndex, const std::string& what, std::initializer_list<int> types,
                              std::initializer_list<int> componentTypes) const {
    return gltfAccessorView(model_, path_, accessorIndex, what, types, componentTypes);
}

// Before the corner list is allocated: a strip or fan of n corners has n - 2 triangles, a list n / 3.
void GltfReader::checkTriangleLimit(const std::string& what, size_t corners, int mode) const {
    const size_t triangles =
        scene_.triangleCount() + (mode == TINYGLTF_MODE_TRIANGLES ? corners / 3 : corners < 2 ? 0 : corners - 2);
    if (triangles > maxSceneTriangles)
        fail(what + ": the scene would have at least " + std::to_string(triangles) + " triangles; at most " +
             std::to_string(maxSceneTriangles) + " are supported");
}

// The primitive's attributes into `out`; false (with a warning) where POSITION has no buffer view, so the
// primitive draws nothing and is left out.
bool GltfReader::readAttributes(const tinygltf::Primitive& primitive, const std::string& what, PrimitiveAttributes& out) {
    const auto attribute = [&](const char* name) {
        const auto it = primitive.attributes.find(name);
        return it == primitive.attributes.end() ? -1 : it->second;
    };
    if (attribute("POSITION") < 0) fail(what + ": no POSITION attribute");
    out.positions = view(attribute("POSITION"), what + " POSITION", {TINYGLTF_TYPE_VEC3}, {TINYGLTF_COMPONENT_TYPE_FLOAT});
    out.hasNormals = attribute("NORMAL") >= 0;
    if (out.hasNormals)
        out.normals = view(attribute("NORMAL"), what + " NORMAL", {TINYGLTF_TYPE_VEC3}, {TINYGLTF_COMPONENT_TYPE_FLOAT});
    // A texture coordinate set: float, or normalised unsigned byte / short (the specification's three).
    const auto texCoordView = [&](const char* name) {
        return attribute(name) >= 0 ? view(attribute(name), what + " " + name, {TINYGLTF_TYPE_VEC2},
                                           {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT})
                                    : AccessorView{};
    };
    out.hasTexCoords = attribute("TEXCOORD_0") >= 0;
    out.hasTexCoords1 = attribute("TEXCOORD_1") >= 0;
    out.texCoords = texCoordView("TEXCOORD_0");
    out.texCoords1 = texCoordView("TEXCOORD_1");
    // glTF: without NORMAL the flat normals are computed and TANGENT is ignored.
    out.hasTangents = out.hasNormals && attribute("TANGENT") >= 0;
    if (out.hasTangents)
        out.tangents = view(attribute("TANGENT"), what + " TANGENT", {TINYGLTF_TYPE_VEC4}, {TINYGLTF_COMPONENT_TYPE_FLOAT});
    // An accessor without a buffer view is all zeros: every triangle would be degenerate and draw nothing.
    if (!out.positions.data) {
        warn(what + ": POSITION has no buffer view (all zeros); the primitive draws nothing and is left out");
        return false;
    }
    const size_t count = out.positions.count;
    const auto checkCount = [&](bool has, const AccessorView& set, const char* name) {
        if (has && set.count != count)
            fail(what + ": " + std::to_string(set.count) + " " + name + " for " + std::to_string(count) + " positions");
    };
    checkCount(out.hasNormals, out.normals, "normals");
    checkCount(out.hasTexCoords, out.texCoords, "texture coordinates");
    checkCount(out.hasTexCoords1, out.texCoords1, "TEXCOORD_1 coordinates");
    checkCount(out.hasTangents, out.tangents, "tangents");
    return true;
}

// The primitive's triangles as vertex indices: its indices, or 0..count-1, with strips and fans unrolled; empty
// (with a warning) where the indices have no buffer view.
std::vector<uint32_t> GltfReader::readTriangles(const tinygltf::Primitive& primitive, const std::string& what,
                                                size_t vertexCount) {
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    std::vector<uint32_t> corners;
    if (primitive.indices >= 0) {
        const AccessorView indices = view(primitive.indices, what + " indices", {TINYGLTF_TYPE_SCALAR},
                                          {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                           TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT});
        if (!indices.data) {
            warn(what + ": indices have no buffer view (all zero); the primitive draws nothing and is left out");
            return {};
        }
        checkTriangleLimit(what, indices.count, mode);
        corners.resize(indices.count);
        for (size_t i = 0; i < indices.count; ++i) {
            corners[i] = gltfIndex(indices, i);
            if (corners[i] >= vertexCount)
                fail(what + ": index " + std::to_string(corners[i]) + " (element " + std::to_string(i) +
                     ") out of range (" + std::to_string(vertexCount) + " vertices)");
        }
    } else {
        checkTriangleLimit(what, vertexCount, mode);
        corners.resize(vertexCount);
        for (size_t i = 0; i < corners.size(); ++i) corners[i] = uint32_t(i);
    }
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (corners.size() % 3 != 0)
            fail(what + ": " + std::to_string(corners.size()) + " corners is not a whole number of triangles");
        return corners;
    }
    std::vector<uint32_t> triangles;
    for (size_t i = 2; i < corners.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_FAN)
            triangles.insert(triangles.end(), {corners[0], corners[i - 1], corners[i]});
        else if (i % 2 == 0)
            triangles.insert(triangles.end(), {corners[i - 2], corners[i - 1], corners[i]});
        else  // odd strip triangles swap two corners to keep the winding
            triangles.insert(triangles.end(), {corners[i - 1], corners[i - 2], corners[i]});
    }
    return triangles;
}

void GltfReader::addPrimitive(const tinygltf::Mesh& mesh, int meshIndex, size_t primitiveIndex, const glm::mat4& world) {
    const tinygltf::Primitive& primitive = mesh.primitives[primitiveIndex];
    const std::string what = "mesh " + std::to_string(meshIndex) + (mesh.name.empty() ? "" : " '" + mesh.name + "'") +
                             " primitive " + std::to_string(primitiveIndex);
    PrimitiveAttributes attributes;
    if (!readAttributes(primitive, what, attributes)) return;
    const std::vector<uint32_t> triangles = readTriangles(primitive, what, attributes.positions.count);
    if (scene_.triangleCount() + triangles.size() / 3 > maxSceneTriangles)
        fail("the scene would have " + std::to_string(scene_.triangleCount() + triangles.size() / 3) +
             " triangles; at most " + std::to_string(maxSceneTriangles) + " are supported");
    if (triangles.empty()) return;

    Mesh out;
    out.name = stem_ + "/" + (mesh.name.empty() ? "mesh " + std::to_string(meshIndex) : mesh.name) +
               (mesh.primitives.size() > 1 ? "/" + std::to_string(primitiveIndex) : "");
    out.material = materialFor(primitive.material);
    const std::string needsSecond = secondSetUser(primitive.material);
    if (!needsSecond.empty() && !attributes.hasTexCoords1)
        warn(what + ": " + needsSecond + " reads TEXCOORD_1, which the primitive does not have; drawn with TEXCOORD_0");
    const PrimitiveVertices vertices(attributes, world, path_, what);
    if (attributes.hasNormals)
        vertices.appendShared(out, triangles);
    else
        vertices.appendFlat(out, triangles);
    for (Mesh& part : splitMeshSpatially(std::move(out))) scene_.meshes.push_back(std::move(part));
}

}  // namespace lidr::gltf_import
