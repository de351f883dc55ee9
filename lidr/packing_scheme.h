#pragma once
// A packing scheme turns "these lights touch this pixel" into bytes of RGBA8 index targets using only the
// fixed-function blender (and stencil), and says how a GLSL 1.20 shader reads them back. Every scheme has
// a bit-exact CPU model (encodePixel / decodePixel) that the GPU results are tested against.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "lidr/context.h"
#include "lidr/light_volume_pass.h"
#include "lidr/shader_source.h"

namespace lidr {

struct PackingConfig {
    std::string scheme = "bitshift";
    int budget = 4;      // light slots per pixel
    int indexBits = 8;   // 4 (15 lights), 8 (255), 16 (65,535)
};

class PackingScheme {
public:
    virtual ~PackingScheme() = default;
    const PackingConfig& config() const { return config_; }
    virtual std::string name() const = 0;  // e.g. "bitshift"
    std::string describe() const;          // "bitshift budget 4, 8-bit indices, 1 target"
    uint32_t maxLights() const { return (1u << config_.indexBits) - 1u; }
    virtual int targetCount() const = 0;
    size_t indexBytes(int width, int height) const { return size_t(targetCount()) * width * height * 4; }

    // Draws the lights (highest priority first) into the index targets of the pass.
    virtual void encode(LightVolumePass& pass, const std::vector<VolumeLight>& lightsInPriorityOrder) const = 0;

    // The unpack file that replaces "lidr_unpack.glsl" in forward shaders, and its defines.
    virtual std::string unpackShaderFile() const = 0;
    virtual ShaderDefines unpackDefines() const = 0;

    // CPU model. encodePixel: the bytes (targetCount * 4, target-major) that drawing `drawOrder` at one pixel
    // leaves behind, blender and stencil included. decodePixel: the slot indices the unpack shader visits,
    // in its order (0 = empty slot).
    virtual std::vector<uint8_t> encodePixel(const std::vector<uint32_t>& drawOrder) const = 0;
    virtual std::vector<uint32_t> decodePixel(const uint8_t* texels) const = 0;

protected:
    explicit PackingScheme(PackingConfig c) : config_(std::move(c)) {}
    PackingConfig config_;
};

// Throws UnsupportedError (before any drawing) for a budget or width the scheme cannot do, or a context
// without what the scheme needs; the message lists what is valid.
std::unique_ptr<PackingScheme> createPackingScheme(const PackingConfig& config, const GlInfo& info);
std::vector<std::string> packingSchemeNames();

}  // namespace lidr
