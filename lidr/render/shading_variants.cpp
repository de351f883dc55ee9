#include "lidr/render/shading_variants.h"

#include <algorithm>
#include <string>

namespace lidr {

namespace {
// Bits 16 and up (material_variants.h uses 0-12).
constexpr uint32_t kDirectional = 1u << 16;         // LIDR_DIRECTIONAL_LIGHTS defined ...
constexpr int kDirectionalCountShift = 17;          // ... as bits 17-19 (0-4 suns)
constexpr uint32_t kOutput = 1u << 20;              // LIDR_TONE_MAP defined ...
constexpr int kToneMapShift = 21;                   // ... as bits 21-22
constexpr uint32_t kSrgb = 1u << 23;                // LIDR_SRGB_OUTPUT 1
constexpr uint32_t kMaxSuns = 7;                    // what bits 17-19 hold (the shader's arrays hold 4)
constexpr uint32_t kRegionMap = 1u << 24;           // LIDR_REGION_MAP defined ...
constexpr uint32_t kRegionMapOn = 1u << 25;         // ... as 1 (else 0)
constexpr uint32_t kEnvironment = 1u << 26;         // LIDR_ENVIRONMENT defined ...
constexpr int kEnvironmentLookupShift = 27;         // ... as bits 27-28 (EnvironmentLookup)
constexpr uint32_t kEnvironmentRgbm = 1u << 29;     // LIDR_ENVIRONMENT_RGBM 1
}  // namespace

namespace {
// Declared and used: depth_only.frag includes output_transform.glsl for its MASK variant alone.
bool uses(const gl::Program& program, const char* uniform) {
    return program.declares(uniform) && program.location(uniform) >= 0;
}
}  // namespace

uint32_t shadingVariantKey(const gl::Program& program, size_t directionalLights, const OutputTransform& output) {
    uint32_t key = 0;
    if (uses(program, "uDirectionalLightCount"))
        key |= kDirectional | (uint32_t(std::min<size_t>(directionalLights, kMaxSuns)) << kDirectionalCountShift);
    if (uses(program, "uToneMap"))
        key |= kOutput | (uint32_t(output.toneMap) << kToneMapShift) | (output.srgb ? kSrgb : 0u);
    return key;
}

uint32_t regionMapVariantKey(const gl::Program& program, bool regions) {
    return uses(program, "uLidrRegionMap") ? kRegionMap | (regions ? kRegionMapOn : 0u) : 0u;
}

const char* environmentLookupName(EnvironmentLookup lookup) {
    switch (lookup) {
    case EnvironmentLookup::None: return "none";
    case EnvironmentLookup::Lod: return "lod";
    case EnvironmentLookup::Bias: return "bias";
    case EnvironmentLookup::DiffuseOnly: return "diffuse-only";
    }
    return "?";
}

uint32_t environmentVariantKey(const gl::Program& program, EnvironmentLookup lookup, bool rgbm) {
    if (!uses(program, "uAmbient")) return 0;
    return kEnvironment | (uint32_t(lookup) << kEnvironmentLookupShift) |
           (rgbm && lookup != EnvironmentLookup::None ? kEnvironmentRgbm : 0u);
}

ShaderDefines shadingVariantDefines(uint32_t key) {
    ShaderDefines defines;
    if (key & kEnvironment) {
        defines.push_back({"LIDR_ENVIRONMENT", std::to_string((key >> kEnvironmentLookupShift) & 3u)});
        defines.push_back({"LIDR_ENVIRONMENT_RGBM", (key & kEnvironmentRgbm) ? "1" : "0"});
    }
    if (key & kRegionMap) defines.push_back({"LIDR_REGION_MAP", (key & kRegionMapOn) ? "1" : "0"});
    if (key & kDirectional)
        defines.push_back({"LIDR_DIRECTIONAL_LIGHTS", std::to_string((key >> kDirectionalCountShift) & kMaxSuns)});
    if (key & kOutput) {
        defines.push_back({"LIDR_TONE_MAP", std::to_string((key >> kToneMapShift) & 3u)});
        defines.push_back({"LIDR_SRGB_OUTPUT", (key & kSrgb) ? "1" : "0"});
    }
    return defines;
}

}  // namespace lidr
