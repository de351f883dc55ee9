#pragma once
// MAX blend + stencil packing (Trebilco 2007 after T. Farrar), extended from 4 to 16 overlaps.
// Blend equation MAX; a light writes (index, 1 - index) into a channel pair, so a pair that two lights reach
// ends up holding (max index, 1 - min index). The stencil ranks the lights marking each pixel in draw order
// (GL_INCR counts every mark) and a masked GL_EQUAL lets pass w take exactly ranks 2w and 2w + 1 into channel
// pair w (target w / 2; RG for even w, BA for odd). One pass of light volumes per pair, the count restarted
// (stencil cleared) before each: budget 2 one pass, 4 two (the paper's), 8 four, 16 eight passes.
// 16-bit indices: MAX cannot merge two 16-bit values held in two channels (each channel would take its
// maximum from a different light), so each window takes ONE light, as (low byte, high byte): budget b uses
// b passes and b / 2 targets. 4-bit indices use the 8-bit layout (a channel cannot MAX two nibbles apart).
// Overflow: ranks past the budget match no window; they are counted, never written.
#include "lidr/technique/packing_scheme.h"

namespace lidr {

class MaxStencilScheme final : public PackingScheme {
public:
    MaxStencilScheme(const PackingConfig& config, const GlInfo& info);
    int targetCount() const override { return (windows_ + 1) / 2; }
    std::string stencilUse() const override;
    int geometryPasses() const override { return windows_; }
    std::vector<SchemeDraw> plan(const std::vector<VolumeLight>& lights, const LightVolumePass* pass) const override;
    std::string unpackShaderFile() const override { return "unpack_max_stencil.glsl"; }
    ShaderDefines unpackDefines() const override;
    bool nullEndsList() const override { return true; }

    int windowSlots() const { return windowSlots_; }  // 2 (4/8-bit, budget >= 2) or 1
    int windows() const { return windows_; }
    IndexColors colorsFor(uint32_t index) const;

protected:
    std::vector<uint32_t> decodeBytes(const std::vector<ShaderFloat>& bytes) const override;

private:
    int windowSlots_ = 2, windows_ = 2;
};

}  // namespace lidr
