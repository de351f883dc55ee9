#pragma once
// CONSTANT_COLOR bit-shift packing (Trebilco 2007): blend ONE, CONSTANT_COLOR(2^-k) shifts each channel's
// old bits down by k and adds the new light's k-bit group on top. The index is split into k-bit groups, one
// per channel; a channel of 8 bits then holds 8/k lights.
//
// Overflow: one light past 8/k would shift the oldest group out through round-to-nearest blending, which
// carries into the kept bits. The stencil therefore caps writes at the slot count (first lights in draw
// order, i.e. highest priority, are kept) and counts every light, so drops are known.
#include "lidr/packing_scheme.h"

namespace lidr {

class BitShiftScheme final : public PackingScheme {
public:
    BitShiftScheme(const PackingConfig& config, const GlInfo& info);
    std::string name() const override { return "bitshift"; }
    int targetCount() const override { return 1; }
    void encode(LightVolumePass& pass, const std::vector<VolumeLight>& lights) const override;
    std::string unpackShaderFile() const override { return "unpack_bitshift.glsl"; }
    ShaderDefines unpackDefines() const override;
    std::vector<uint8_t> encodePixel(const std::vector<uint32_t>& drawOrder) const override;
    std::vector<uint32_t> decodePixel(const uint8_t* texels) const override;

    int groupBits() const { return groupBits_; }  // k
    int channels() const { return channels_; }     // index bits / k
    IndexColors colorsFor(uint32_t index) const;

private:
    int groupBits_ = 2, channels_ = 4;
};

}  // namespace lidr
