#pragma once
// Per-pixel material textures as shader variants (the Filament / bgfx way): a material's features (which textures
// it has, which coordinate set each reads, alpha MASK, a dielectric F0 / F90 of its own) are bits of a key; each
// program that draws the scene (every mode's shading pass, the brute-force reference, the depth pre-passes)
// compiles, on first use, the variant of its own sources with the key's defines (gl::Program::variant) and draws
// the material with it. A material without textures draws with the program as written: key 0.
// shaders/common/material.glsl reads the defines.
#include <cstdint>
#include <string>
#include <vector>

#include "lidr/gl/shader_source.h"
#include "lidr/scene/scene.h"

namespace lidr {

enum class TextureSlot { BaseColor, Emissive, MetallicRoughness, Occlusion, Normal };
constexpr int kTextureSlots = 5;

// What a slot is called in the shaders and in messages, where its texture is bound, and how it is stored.
struct TextureSlotInfo {
    const char* what;       // "base colour", ...
    const char* define;     // LIDR_<NAME>_TEXTURE
    const char* uvDefine;   // LIDR_<NAME>_UV: 0 or 1
    const char* sampler;    // the sampler uniform
    const char* transform;  // the KHR_texture_transform matrix uniform
    int unit;               // texture unit (lidr/gl/bindings.h)
    bool srgb;              // colour (sRGB-encoded) or data (linear)
};
const TextureSlotInfo& textureSlotInfo(TextureSlot slot);

namespace material_feature {
constexpr uint32_t texture(TextureSlot slot) { return 1u << int(slot); }          // the slot's texture is read
constexpr uint32_t secondSet(TextureSlot slot) { return 1u << (8 + int(slot)); }  // ... from TEXCOORD_1
constexpr uint32_t alphaMask = 1u << 5;
constexpr uint32_t dielectricSpecular = 1u << 6;  // KHR_materials_ior / _specular: F0 and F90 from uniforms
}  // namespace material_feature

// The material's key, given which of its textures the scene has loaded (bit i: slot i; a texture dropped for
// want of texture units is not read).
uint32_t materialFeatures(const Material& material, uint32_t loadedSlots);
// What a depth-only pass (pre-pass, tiled pre-Z) needs of it: the MASK test and the base colour texture it reads.
uint32_t depthFeatures(uint32_t features);
// The defines of a key (empty for 0).
ShaderDefines materialDefines(uint32_t features);
// The slot's texture of a material (base colour: nothing here; GpuScene reads diffuseTexture / diffuseImage).
const MaterialTexture* materialTexture(const Material& material, TextureSlot slot);
// The slot's mapping (texture coordinate set and transform).
const TextureMapping& textureMapping(const Material& material, TextureSlot slot);

// A texture whose unit the context does not have (OpenGL ES 2.0 guarantees 8) is left out of its material's
// variant. The warning line for it; and the lines for every such texture of a scene (tools print them with the
// scene's warnings, before drawing).
bool textureSlotFits(TextureSlot slot, int textureUnits);
std::string textureUnitWarning(const Material& material, TextureSlot slot, int textureUnits);
std::vector<std::string> textureUnitWarnings(const Scene& scene, int textureUnits);

}  // namespace lidr
