#pragma once
// What the files of the glTF importer share (not installed; the API is gltf_importer.h): the GltfReader, which
// turns a tinygltf model into lidr's Scene. Its members are defined by concern, one file each, as the
// validator's checks are (gltf_validator_internal.h):
//   gltf_importer.cpp           tinygltf (its implementation is compiled there), images decoded, the entry point,
//                               the node tree (transforms, the instanced-triangle limit)
//   gltf_import_geometry.cpp    a mesh primitive: its attributes, its triangles, its vertices in world space
//   gltf_import_materials.cpp   materials and their textures (KHR_texture_transform, emissive strength, ior,
//                               specular)
//   gltf_import_lights.cpp      KHR_lights_punctual lights and cameras
//   gltf_import_animation.cpp   the node tree as Scene::animation's nodes, what each node carries
// Each file that includes this one includes nlohmann json first, then tinygltf with the TINYGLTF_NO_INCLUDE_*
// defines below (gltf_importer.cpp adds TINYGLTF_IMPLEMENTATION and stb_image).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#ifndef TINYGLTF_NO_INCLUDE_JSON
#define TINYGLTF_NO_INCLUDE_JSON
#endif
#ifndef TINYGLTF_NO_INCLUDE_STB_IMAGE
#define TINYGLTF_NO_INCLUDE_STB_IMAGE
#endif
#ifndef TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#endif
#include <tiny_gltf.h>

#include "lidr/base/error.h"
#include "lidr/scene/io/file_checks.h"
#include "lidr/scene/io/gltf_accessors.h"
#include "lidr/scene/io/gltf_importer.h"
#include "lidr/scene/scene.h"

namespace lidr::gltf_import {

// Node trees deeper than this are refused (a cycle would otherwise recurse without end).
constexpr int maxNodeDepth = 256;

// Why each image that failed was not decoded, by image index (tinygltf turns a failure into a warning only).
using ImageFailures = std::map<int, std::string>;

// The bytes of element i of an accessor, checked against its buffer view and buffer (gltf_accessors.h).
using AccessorView = GltfAccessorView;

// v / |v|, or `fallback` where v has no usable length.
inline glm::vec3 normalizedOr(const glm::vec3& v, const glm::vec3& fallback) {
    const float length = glm::length(v);
    return std::isfinite(length) && length > 1e-20f ? v / length : fallback;
}

// A primitive's vertex attributes as accessors (absent ones empty), their counts checked against POSITION's.
struct PrimitiveAttributes {
    AccessorView positions, normals, texCoords, texCoords1, tangents;
    bool hasNormals = false, hasTexCoords = false, hasTexCoords1 = false, hasTangents = false;
};

class GltfReader {
public:
    GltfReader(Scene& scene, const std::string& path, const glm::mat4& transform, int overrideMaterial)
        : scene_(scene), path_(path), transform_(transform), overrideMaterial_(overrideMaterial) {}

    GltfContents read();

private:
    [[noreturn]] void fail(const std::string& problem) const { throw Error(path_ + ": " + problem); }
    void warn(const std::string& warning) { scene_.warnings.push_back(path_ + ": " + warning); }

    // ---- the file and the node tree (gltf_importer.cpp) ------------------------------------------------------
    void load();
    void checkMode(const tinygltf::Mesh& mesh, const tinygltf::Primitive& primitive) const;
    std::vector<int> rootNodes() const;
    static glm::mat4 localMatrix(const tinygltf::Node& node);
    size_t declaredTriangles(const tinygltf::Primitive& primitive) const;
    void checkInstancedTriangles(const std::vector<int>& roots) const;
    void visit(int nodeIndex, const glm::mat4& parent, int depth, int parentNode);

    // ---- animation (gltf_import_animation.cpp) ---------------------------------------------------------------
    int startAnimation();
    int addAnimationNode(int nodeIndex, const tinygltf::Node& node, const std::string& name, int parentNode);
    void carry(int animationNode, size_t meshesBefore, size_t lightsBefore, const glm::mat4& world);
    void finishAnimation();

    // ---- geometry (gltf_import_geometry.cpp) -----------------------------------------------------------------
    AccessorView view(int accessorIndex, const std::string& what, std::initializer_list<int> types,
                      std::initializer_list<int> componentTypes) const;
    void checkTriangleLimit(const std::string& what, size_t corners, int mode) const;
    bool readAttributes(const tinygltf::Primitive& primitive, const std::string& what, PrimitiveAttributes& out);
    std::vector<uint32_t> readTriangles(const tinygltf::Primitive& primitive, const std::string& what,
                                        size_t vertexCount);
    void addPrimitive(const tinygltf::Mesh& mesh, int meshIndex, size_t primitiveIndex, const glm::mat4& world);

    // ---- materials (gltf_import_materials.cpp) ---------------------------------------------------------------
    const tinygltf::Image& textureImage(int texture, const std::string& what);
    MaterialTexture readTexture(int texture, int texCoord, const tinygltf::ExtensionMap& extensions,
                                const std::string& what);
    std::string secondSetUser(int gltfMaterial);
    void warnSampler(int texture, const std::string& what);
    void readEmissiveStrength(const tinygltf::Material& source, Material& material);
    void readDielectricSpecular(const tinygltf::Material& source, const std::string& name, Material& material);
    void readMaterialFactors(const tinygltf::Material& source, const std::string& name, Material& material);
    void readMaterialTextures(const tinygltf::Material& source, const std::string& name, Material& material);
    int materialFor(int gltfMaterial);

    // ---- lights and cameras (gltf_import_lights.cpp) ---------------------------------------------------------
    static bool lidrShadowFlag(const tinygltf::Value& extras, bool& flag);
    void readLight(const tinygltf::Value& value, const std::string& nodeName, const glm::mat4& world,
                   const tinygltf::Value& nodeExtras);
    bool nodeDirection(const glm::mat4& world, const std::string& name, const std::string& nodeName, glm::vec3& out);
    void readDirectionalLight(const std::string& name, const std::string& nodeName, const glm::vec3& color,
                              const glm::mat4& world);
    void listCameras();
    void readCamera(const tinygltf::Node& node, const std::string& nodeName, const glm::mat4& world, int animationNode);

    Scene& scene_;
    const std::string& path_;
    const glm::mat4 transform_;
    const int overrideMaterial_;
    tinygltf::Model model_;
    std::string stem_;
    std::map<int, int> sceneMaterialOf_;
    std::map<int, std::shared_ptr<const ImageRGBA8>> decodedImages_;  // by glTF image index
    ImageFailures imageFailures_;
    GltfContents contents_;
    bool animated_ = false;              // the file has animations: its nodes join Scene::animation
    size_t nodeBase_ = 0;                // the first of this file's nodes in Scene::animation
    std::vector<int> nodeOf_;            // per glTF node, its AnimationNode (-1: not in the default scene)
    std::vector<int> directionalNodes_;  // the nodes of the directional lights read
};

}  // namespace lidr::gltf_import
