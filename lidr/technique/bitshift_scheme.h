#pragma once
// CONSTANT_COLOR bit-shift packing (Trebilco 2007): blend ONE, CONSTANT_COLOR(2^-k) shifts each channel's
// old bits down by k and adds the new light's k-bit group on top. The index is split into k-bit groups, one
// per channel (C = width / k channels, over ceil(C / 4) targets written together through draw buffers); a
// channel of 8 bits holds 8 / k lights. k is the widest group that still gives the budget its slots:
// k = min(width, 8 / min(budget, 8)), which reproduces every row of the paper's table.
//
// Overflow: one light past 8/k would shift the oldest group out through round-to-nearest blending, which
// carries into the kept bits. A stencil rank window therefore lets exactly the first W = min(budget, 8/k)
// lights (in draw order, i.e. highest priority) write, and counts every light, so drops are known. Budget 16
// needs two windows of 8 (ranks 0..7, then 8..15 after a stencil restart) in two passes of the light volumes,
// each into its own set of targets: the paper's "use the stencil buffer when 8 overlaps have been reached".
// Budget 32 (the automatic budget's widest, 4- and 8-bit indices: 4 or 8 targets) takes four windows the same way.
#include "lidr/technique/packing_scheme.h"

namespace lidr {

class BitShiftScheme final : public PackingScheme {
public:
    BitShiftScheme(const PackingConfig& config, const GlInfo& info);
    int targetCount() const override { return windows_ * windowTargets_; }
    std::string stencilUse() const override;
    int geometryPasses() const override { return windows_; }
    std::vector<SchemeDraw> plan(const std::vector<VolumeLight>& lights, const LightVolumePass* pass) const override;
    std::string unpackShaderFile() const override { return "unpack_bitshift.glsl"; }
    ShaderDefines unpackDefines() const override;
    bool nullEndsList() const override { return true; }

    int groupBits() const { return groupBits_; }        // k
    int channels() const { return channels_; }          // C = width / k
    int windowSlots() const { return windowSlots_; }    // W: lights one window holds
    int windows() const { return windows_; }
    int windowTargets() const { return windowTargets_; }
    IndexColors colorsFor(uint32_t index) const;        // target-relative within a window

protected:
    std::vector<uint32_t> decodeBytes(const std::vector<ShaderFloat>& bytes) const override;

private:
    double lowWeight(int channel) const;   // LIDR_WEIGHTS_LOWt: 2^(c*k) for groups below bit 8, else 0
    double highWeight(int channel) const;  // LIDR_WEIGHTS_HIGHt: 2^(c*k - 8) for groups from bit 8, else 0
    int groupBits_ = 2, channels_ = 4, windowSlots_ = 4, windows_ = 1, windowTargets_ = 1;
};

}  // namespace lidr
