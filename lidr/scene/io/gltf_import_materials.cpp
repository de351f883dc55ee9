// The glTF importer's materials: metallic-roughness factors, alpha modes, the extensions lidr draws
// (KHR_texture_transform, KHR_materials_emissive_strength, KHR_materials_ior, KHR_materials_specular) and textures.
#include "lidr/scene/io/gltf_importer_internal.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <glm/gtc/type_ptr.hpp>

#include "lidr/base/colour.h"

namespace lidr::gltf_import {

// The decoded image of glTF texture `texture`; fails naming `what` for an index out of range or an image
// that is missing or not decoded to RGBA8.
const tinygltf::Image& GltfReader::textureImage(int texture, const std::string& what) {
    if (texture < 0 || size_t(texture) >= model_.textures.size())
        fail(what + " " + std::to_string(texture) + " out of range (" + std::to_string(model_.textures.size()) +
             " textures)");
    const int source = model_.textures[size_t(texture)].source;
    if (source < 0 || size_t(source) >= model_.images.size())
        fail(what + ": texture " + std::to_string(texture) + " has no image (source " + std::to_string(source) + ")");
    const tinygltf::Image& image = model_.images[size_t(source)];
    if (image.width <= 0 || image.height <= 0 || image.image.size() != size_t(image.width) * size_t(image.height) * 4) {
        const auto failure = imageFailures_.find(source);  // the file and the decoder's reason, where known
        fail(what + ": " + (failure != imageFailures_.end() ? failure->second
                                                            : "image " + std::to_string(source) + " was not loaded"));
    }
    return image;
}

// A glTF textureInfo as lidr draws it: the decoded image (shared by every texture of the same image), its
// name, the coordinate set (texCoord, or KHR_texture_transform's override) and the transform, turned into
// lidr's texture space (v up: flipped on import, rows flipped on upload) as F T F with F (u, v) = (u, 1 - v).
MaterialTexture GltfReader::readTexture(int texture, int texCoord, const tinygltf::ExtensionMap& extensions, const std::string& what) {
    warnSampler(texture, what);
    const tinygltf::Image& image = textureImage(texture, what);
    const int source = model_.textures[size_t(texture)].source;
    MaterialTexture out;
    std::shared_ptr<const ImageRGBA8>& decoded = decodedImages_[source];
    if (!decoded) {
        auto pixels = std::make_shared<ImageRGBA8>(image.width, image.height);
        pixels->pixels = image.image;
        decoded = std::move(pixels);
    }
    out.image = decoded;
    out.name = image.uri.rfind("data:", 0) == 0 || image.uri.empty()
                   ? path_ + "#image" + std::to_string(source)
                   : (std::filesystem::path(path_).parent_path() / image.uri).lexically_normal().string();
    // The validator held every field to its type and to finite floats.
    glm::dvec2 offset(0.0), scale(1.0);
    double rotation = 0.0;
    const auto transform = extensions.find("KHR_texture_transform");
    if (transform != extensions.end()) {
        const tinygltf::Value& t = transform->second;
        const auto pair = [&](const char* field, glm::dvec2& into) {
            if (t.Has(field))
                into = glm::dvec2(t.Get(field).Get(0).GetNumberAsDouble(), t.Get(field).Get(1).GetNumberAsDouble());
        };
        pair("offset", offset);
        pair("scale", scale);
        if (t.Has("rotation")) rotation = t.Get("rotation").GetNumberAsDouble();
        if (t.Has("texCoord")) texCoord = t.Get("texCoord").GetNumberAsInt();
    }
    if (texCoord != 0 && texCoord != 1) {
        warn(what + " uses TEXCOORD_" + std::to_string(texCoord) + "; lidr reads TEXCOORD_0 and TEXCOORD_1, drawn with TEXCOORD_0");
        texCoord = 0;
    }
    out.mapping.texCoord = texCoord;
    // The extension's matrix: translation x rotation x scale, rotating the UVs counter-clockwise by `rotation`
    // (its example: offset (0, 1), rotation pi/2, scale 0.5 reads the image's lower left quadrant).
    const double c = std::cos(rotation), s = std::sin(rotation);
    const glm::dmat3 translate(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
    const glm::dmat3 rotate(c, -s, 0, s, c, 0, 0, 0, 1);
    const glm::dmat3 scaling(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
    const glm::dmat3 flip(1, 0, 0, 0, -1, 0, 0, 1, 1);
    out.mapping.transform = glm::mat3(flip * translate * rotate * scaling * flip);
    for (int i = 0; i < 9; ++i)  // each field is a finite float, but their sums can still overflow one
        if (!std::isfinite(glm::value_ptr(out.mapping.transform)[i]))
            fail(what + ": KHR_texture_transform (offset " + str(offset.x) + " " + str(offset.y) + ", rotation " +
                 str(rotation) + ", scale " + str(scale.x) + " " + str(scale.y) + ") is not finite as a float matrix");
    return out;
}

// The name of a texture of glTF material `gltfMaterial` that reads the second coordinate set; empty if none.
std::string GltfReader::secondSetUser(int gltfMaterial) {
    if (overrideMaterial_ >= 0 || gltfMaterial < 0 || size_t(gltfMaterial) >= model_.materials.size()) return {};
    const int scene = materialFor(gltfMaterial);
    const Material& m = scene_.materials[size_t(scene)];
    if (m.diffuseMapping.texCoord == 1) return "the base colour texture";
    if (m.emissiveTexture.mapping.texCoord == 1) return "the emissive texture";
    if (m.metallicRoughnessTexture.mapping.texCoord == 1) return "the metallic-roughness texture";
    if (m.occlusionTexture.mapping.texCoord == 1) return "the occlusion texture";
    if (m.normalTexture.mapping.texCoord == 1) return "the normal texture";
    return {};
}

// lidr samples every texture with REPEAT and trilinear filtering: another wrap or filter is a warning.
void GltfReader::warnSampler(int texture, const std::string& what) {
    const int sampler = model_.textures[size_t(texture)].sampler;
    if (sampler < 0 || size_t(sampler) >= model_.samplers.size()) return;
    const tinygltf::Sampler& s = model_.samplers[size_t(sampler)];
    const int repeat = 10497, nearest = 9728, nearestMipmapNearest = 9984;
    if (s.wrapS != repeat || s.wrapT != repeat)
        warn(what + ": sampler wrap " + std::to_string(s.wrapS) + " / " + std::to_string(s.wrapT) +
             " is drawn as REPEAT");
    if (s.magFilter == nearest || s.minFilter == nearest || s.minFilter == nearestMipmapNearest)
        warn(what + ": sampler's nearest filtering is drawn trilinear");
}

// KHR_materials_emissive_strength: the emissive factor times emissiveStrength (the validator held it to a
// float >= 0; the factor is at most 1, so the product stays finite). The shared shading adds the emission in
// every mode (shading.glsl, lidrAmbient), unclamped, in linear light.
void GltfReader::readEmissiveStrength(const tinygltf::Material& source, Material& material) {
    const auto it = source.extensions.find("KHR_materials_emissive_strength");
    if (it == source.extensions.end()) return;
    const tinygltf::Value& strength = it->second.Get("emissiveStrength");
    if (!strength.IsNumber() && !strength.IsInt()) return;  // the extension's default, 1
    material.emissive *= float(strength.GetNumberAsDouble());
}

// KHR_materials_ior and KHR_materials_specular's factors (validated): the dielectric's F0 and F90, drawn by
// every mode through the material's shader variant. Their two textures are not drawn: lidr's material
// textures and light tables take texture units 0..15 (WebGL's usual 16), and 16 is the shadow atlas'.
void GltfReader::readDielectricSpecular(const tinygltf::Material& source, const std::string& name, Material& material) {
    const auto ior = source.extensions.find("KHR_materials_ior");
    if (ior != source.extensions.end() && ior->second.Has("ior"))
        material.dielectric.ior = float(ior->second.Get("ior").GetNumberAsDouble());
    const auto specular = source.extensions.find("KHR_materials_specular");
    if (specular == source.extensions.end()) return;
    const tinygltf::Value& s = specular->second;
    if (s.Has("specularFactor")) material.dielectric.weight = float(s.Get("specularFactor").GetNumberAsDouble());
    if (s.Has("specularColorFactor"))
        for (int c = 0; c < 3; ++c)
            material.dielectric.color[c] = float(s.Get("specularColorFactor").Get(c).GetNumberAsDouble());
    for (const char* texture : {"specularTexture", "specularColorTexture"})
        if (s.Has(texture))
            warn(name + ": KHR_materials_specular " + texture +
                 " is not drawn (no texture unit is left for it); its factors are");
}

// The factors, alpha mode and extensions of `source` (named `name` in messages) into `material`.
void GltfReader::readMaterialFactors(const tinygltf::Material& source, const std::string& name, Material& material) {
    const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
    glm::vec4 base(1.0f);
    for (size_t c = 0; c < 4 && c < pbr.baseColorFactor.size(); ++c) base[int(c)] = float(pbr.baseColorFactor[c]);
    if (!(base.r >= 0 && base.g >= 0 && base.b >= 0 && base.a >= 0 && base.a <= 1 && isFinite(glm::vec3(base))))
        fail(name + ": baseColorFactor must be finite with colour >= 0 and alpha in [0, 1]");
    const float metallic = glm::clamp(float(pbr.metallicFactor), 0.0f, 1.0f);
    const float roughness = glm::clamp(float(pbr.roughnessFactor), 0.0f, 1.0f);
    material.diffuse = glm::vec3(base);
    for (size_t c = 0; c < 3 && c < source.emissiveFactor.size(); ++c) material.emissive[int(c)] = float(source.emissiveFactor[c]);
    if (!(isFinite(material.emissive) && glm::all(glm::greaterThanEqual(material.emissive, glm::vec3(0.0f)))))
        fail(name + ": emissiveFactor must be finite and >= 0, got " + str(material.emissive));
    // lidr's BRDF is glTF's: the factors as they are (specular and shininess stay unused defaults)
    material.metallicRoughness = true;
    material.metallic = metallic;
    material.roughness = roughness;
    if (source.alphaMode == "BLEND") {
        material.opacity = base.a;
    } else if (source.alphaMode == "MASK") {
        material.alphaMode = AlphaMode::Mask;
        if (!(std::isfinite(source.alphaCutoff) && source.alphaCutoff >= 0.0 && source.alphaCutoff <= 1.0))
            fail(name + ": alphaCutoff must be in [0, 1], got " + std::to_string(source.alphaCutoff));
        // The test is factor alpha x texel alpha < cutoff; the shaders test the texel alone against the cutoff
        // divided by the factor's alpha (above 1: everything is cut, as factor alpha 0 cuts everything).
        const float cutoff = float(source.alphaCutoff);
        material.alphaCutoff = base.a > 0.0f ? std::min(cutoff / base.a, 2.0f) : (cutoff > 0.0f ? 2.0f : 0.0f);
    }
    material.doubleSided = source.doubleSided;
    readEmissiveStrength(source, material);
    readDielectricSpecular(source, name, material);
}

// Every texture is read per pixel by the material's shader variant (lidr/render/material_variants.h).
void GltfReader::readMaterialTextures(const tinygltf::Material& source, const std::string& name, Material& material) {
    const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
    if (source.emissiveTexture.index >= 0)
        material.emissiveTexture = readTexture(source.emissiveTexture.index, source.emissiveTexture.texCoord,
                                               source.emissiveTexture.extensions, name + ": emissive texture");
    if (pbr.metallicRoughnessTexture.index >= 0)  // glTF: roughness in G, metallic in B, linear data
        material.metallicRoughnessTexture =
            readTexture(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                        pbr.metallicRoughnessTexture.extensions, name + ": metallic-roughness texture");
    if (source.occlusionTexture.index >= 0) {
        material.occlusionTexture = readTexture(source.occlusionTexture.index, source.occlusionTexture.texCoord,
                                                source.occlusionTexture.extensions, name + ": occlusion texture");
        if (!(std::isfinite(source.occlusionTexture.strength) && source.occlusionTexture.strength >= 0.0 &&
              source.occlusionTexture.strength <= 1.0))
            fail(name + ": occlusionTexture strength must be in [0, 1], got " +
                 std::to_string(source.occlusionTexture.strength));
        material.occlusionTexture.scale = float(source.occlusionTexture.strength);
    }
    if (source.normalTexture.index >= 0) {
        material.normalTexture = readTexture(source.normalTexture.index, source.normalTexture.texCoord,
                                             source.normalTexture.extensions, name + ": normal texture");
        if (!std::isfinite(source.normalTexture.scale))
            fail(name + ": normalTexture scale is not finite");
        material.normalTexture.scale = float(source.normalTexture.scale);
    }
    const int texture = pbr.baseColorTexture.index;
    if (texture >= 0) {
        const MaterialTexture read = readTexture(texture, pbr.baseColorTexture.texCoord,
                                                 pbr.baseColorTexture.extensions, name + ": base colour texture");
        material.diffuseImage = read.image;
        material.diffuseTexture = read.name;
        material.diffuseMapping = read.mapping;
    }
}

int GltfReader::materialFor(int gltfMaterial) {
    if (overrideMaterial_ >= 0) return overrideMaterial_;
    if (gltfMaterial < 0) return findOrAddDefaultMaterial(scene_);
    if (size_t(gltfMaterial) >= model_.materials.size())
        fail("material " + std::to_string(gltfMaterial) + " out of range (" + std::to_string(model_.materials.size()) +
             " materials)");
    const auto known = sceneMaterialOf_.find(gltfMaterial);
    if (known != sceneMaterialOf_.end()) return known->second;
    const tinygltf::Material& source = model_.materials[size_t(gltfMaterial)];
    const std::string name = "material " + std::to_string(gltfMaterial) + (source.name.empty() ? "" : " '" + source.name + "'");
    Material material;
    material.name = source.name.empty() ? stem_ + "/material " + std::to_string(gltfMaterial) : source.name;
    readMaterialFactors(source, name, material);
    readMaterialTextures(source, name, material);
    const int index = findOrAddMaterial(scene_, material);
    sceneMaterialOf_[gltfMaterial] = index;
    return index;
}

}  // namespace lidr::gltf_import
