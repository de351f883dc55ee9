#include "lidr/render/material_variants.h"

#include "lidr/gl/bindings.h"

namespace lidr {

const TextureSlotInfo& textureSlotInfo(TextureSlot slot) {
    static const TextureSlotInfo slots[kTextureSlots] = {
        {"base colour", "LIDR_BASE_COLOR_TEXTURE", "LIDR_BASE_COLOR_UV", "uMaterialTexture", "uBaseColorUvTransform",
         gl::kUnitMaterial, true},
        {"emissive", "LIDR_EMISSIVE_TEXTURE", "LIDR_EMISSIVE_UV", "uEmissiveTexture", "uEmissiveUvTransform",
         gl::kUnitEmissive, true},
        {"metallic-roughness", "LIDR_METALLIC_ROUGHNESS_TEXTURE", "LIDR_METALLIC_ROUGHNESS_UV",
         "uMetallicRoughnessTexture", "uMetallicRoughnessUvTransform", gl::kUnitMetallicRoughness, false},
        {"occlusion", "LIDR_OCCLUSION_TEXTURE", "LIDR_OCCLUSION_UV", "uOcclusionTexture", "uOcclusionUvTransform",
         gl::kUnitOcclusion, false},
        {"normal", "LIDR_NORMAL_TEXTURE", "LIDR_NORMAL_UV", "uNormalTexture", "uNormalUvTransform", gl::kUnitNormal,
         false},
    };
    return slots[int(slot)];
}

const MaterialTexture* materialTexture(const Material& m, TextureSlot slot) {
    switch (slot) {
    case TextureSlot::Emissive: return &m.emissiveTexture;
    case TextureSlot::MetallicRoughness: return &m.metallicRoughnessTexture;
    case TextureSlot::Occlusion: return &m.occlusionTexture;
    case TextureSlot::Normal: return &m.normalTexture;
    default: return nullptr;
    }
}

const TextureMapping& textureMapping(const Material& m, TextureSlot slot) {
    const MaterialTexture* t = materialTexture(m, slot);
    return t ? t->mapping : m.diffuseMapping;
}

uint32_t materialFeatures(const Material& material, uint32_t loadedSlots) {
    uint32_t key = 0;
    for (int i = 0; i < kTextureSlots; ++i) {
        const TextureSlot slot = TextureSlot(i);
        if (!(loadedSlots & (1u << i))) continue;
        key |= material_feature::texture(slot);
        if (textureMapping(material, slot).texCoord == 1) key |= material_feature::secondSet(slot);
    }
    // Blended materials are drawn after the opaque ones without a depth test of their own: no cut-out there.
    if (material.alphaMode == AlphaMode::Mask && material.opacity >= 1.0f) key |= material_feature::alphaMask;
    if (!material.dielectric.isDefault()) key |= material_feature::dielectricSpecular;
    return key;
}

uint32_t depthFeatures(uint32_t features) {
    using namespace material_feature;
    if (!(features & alphaMask)) return 0;
    return features & (alphaMask | texture(TextureSlot::BaseColor) | secondSet(TextureSlot::BaseColor));
}

ShaderDefines materialDefines(uint32_t features) {
    ShaderDefines defines;
    bool secondSetUsed = false;
    for (int i = 0; i < kTextureSlots; ++i) {
        const TextureSlot slot = TextureSlot(i);
        if (!(features & material_feature::texture(slot))) continue;
        const bool second = (features & material_feature::secondSet(slot)) != 0;
        defines.push_back({textureSlotInfo(slot).define, "1"});
        defines.push_back({textureSlotInfo(slot).uvDefine, second ? "1" : "0"});
        secondSetUsed = secondSetUsed || second;
    }
    if (secondSetUsed) defines.push_back({"LIDR_TEXCOORD1", "1"});
    if (features & material_feature::alphaMask) defines.push_back({"LIDR_ALPHA_MASK", "1"});
    if (features & material_feature::dielectricSpecular) defines.push_back({"LIDR_DIELECTRIC_SPECULAR", "1"});
    return defines;
}

bool textureSlotFits(TextureSlot slot, int textureUnits) { return textureSlotInfo(slot).unit < textureUnits; }

std::string textureUnitWarning(const Material& material, TextureSlot slot, int textureUnits) {
    return "material '" + material.name + "': the " + textureSlotInfo(slot).what + " texture is not drawn: it needs texture unit " +
           std::to_string(textureSlotInfo(slot).unit) + " and this context has " + std::to_string(textureUnits);
}

std::vector<std::string> textureUnitWarnings(const Scene& scene, int textureUnits) {
    std::vector<std::string> lines;
    for (const Material& m : scene.materials)
        for (int i = 0; i < kTextureSlots; ++i) {
            const TextureSlot slot = TextureSlot(i);
            const MaterialTexture* t = materialTexture(m, slot);
            const bool present = t ? t->present() : (m.diffuseImage || !m.diffuseTexture.empty());
            if (present && !textureSlotFits(slot, textureUnits)) lines.push_back(textureUnitWarning(m, slot, textureUnits));
        }
    return lines;
}

}  // namespace lidr
