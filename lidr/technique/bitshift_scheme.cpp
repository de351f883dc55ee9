#include "lidr/technique/bitshift_scheme.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <cmath>

#include "lidr/base/error.h"

namespace lidr {

BitShiftScheme::BitShiftScheme(const PackingConfig& config, const GlInfo& info)
    : PackingScheme(PackingSchemeKind::BitShift, config) {
    checkPackingConfig(config);
    const int budget = config.budget, bits = config.indexBits;
    groupBits_ = std::min(bits, 8 / std::min(budget, 8));
    channels_ = bits / groupBits_;
    windowSlots_ = std::min(budget, 8 / groupBits_);
    windows_ = budget / windowSlots_;
    windowTargets_ = (channels_ + 3) / 4;
    // Blend colour and stencil are GL 1.4 / 1.0; draw buffers and attachments depend on the row.
    if (info.framebufferObject) checkContextFor("bitshift " + describe(), info, targetCount(), windowTargets_);
}

std::string BitShiftScheme::stencilUse() const {
    if (windows_ == 1) return "rank window 0-" + std::to_string(windowSlots_ - 1) + " + light count";
    std::string s = "rank windows";
    for (int w = 0; w < windows_; ++w)
        s += (w == 0 ? " " : w + 1 == windows_ ? " and " : ", ") + std::to_string(w * windowSlots_) + "-" +
             std::to_string((w + 1) * windowSlots_ - 1);
    return s + " (restarted count) + light count";
}

IndexColors BitShiftScheme::colorsFor(uint32_t index) const {
    IndexColors c{};
    const uint32_t mask = (1u << groupBits_) - 1u;
    for (int ch = 0; ch < channels_; ++ch) {
        const uint32_t group = (index >> (ch * groupBits_)) & mask;
        c[ch / 4][ch % 4] = byteColor(group << (8 - groupBits_));  // exactly the byte group << (8 - k)
    }
    return c;
}

std::vector<SchemeDraw> BitShiftScheme::plan(const std::vector<VolumeLight>& lights, const LightVolumePass*) const {
    std::vector<SchemeDraw> draws;
    for (int w = windows_ - 1; w >= 0; --w) {  // last to first (rankWindowDraw)
        SchemeDraw sd = rankWindowDraw(PackingSchemeKind::BitShift, w, windowSlots_, windows_, lights,
                                       [this](uint32_t i) { return colorsFor(i); });
        VolumeDraw& d = sd.draw;
        d.firstTarget = w * windowTargets_;
        d.targetCount = windowTargets_;
        d.colorMask = glm::bvec4(channels_ > 0, channels_ > 1, channels_ > 2, channels_ > 3);
        if (windowSlots_ > 1) {  // one slot per window is a plain write: nothing to shift
            d.blend = true;
            d.blendSrc = GL_ONE;
            d.blendDst = GL_CONSTANT_COLOR;
            d.blendColor = glm::vec4(1.0f / float(1 << groupBits_));
        }
        draws.push_back(std::move(sd));
    }
    return draws;
}

namespace {
std::string glslVec4(const double v[4]) {
    std::string s = "vec4(";
    for (int i = 0; i < 4; ++i) s += std::to_string(static_cast<long>(v[i])) + ".0" + (i < 3 ? ", " : ")");
    return s;
}
}  // namespace

// Channel c of a window holds bits [c*k, c*k + k) of the index: below bit 8 they weigh into the low byte, from
// bit 8 on into the high byte (k divides 8, so no group straddles bit 8).
double BitShiftScheme::lowWeight(int c) const {
    return c < channels_ && c * groupBits_ < 8 ? std::ldexp(1.0, c * groupBits_) : 0.0;
}
double BitShiftScheme::highWeight(int c) const {
    return c < channels_ && c * groupBits_ >= 8 ? std::ldexp(1.0, c * groupBits_ - 8) : 0.0;
}

ShaderDefines BitShiftScheme::unpackDefines() const {
    ShaderDefines d = {{"LIDR_SLOTS", std::to_string(config_.budget)},
                       {"LIDR_INDEX_TARGETS", std::to_string(targetCount())},
                       {"LIDR_WINDOWS", std::to_string(windows_)},
                       {"LIDR_WINDOW_TARGETS", std::to_string(windowTargets_)},
                       {"LIDR_WINDOW_SLOTS", std::to_string(windowSlots_) + ".0"},
                       {"LIDR_GROUP_SCALE", std::to_string(1 << (8 - groupBits_)) + ".0"},
                       {"LIDR_GROUP_VALUES", std::to_string(1 << groupBits_) + ".0"}};
    for (int t = 0; t < 4; ++t) {
        double low[4], high[4];
        for (int ch = 0; ch < 4; ++ch) {
            low[ch] = lowWeight(t * 4 + ch);
            high[ch] = highWeight(t * 4 + ch);
        }
        d.push_back({"LIDR_WEIGHTS_LOW" + std::to_string(t), glslVec4(low)});
        d.push_back({"LIDR_WEIGHTS_HIGH" + std::to_string(t), glslVec4(high)});
    }
    return d;
}

std::vector<uint32_t> BitShiftScheme::decodeBytes(const std::vector<ShaderFloat>& bytes) const {
    // unpack_bitshift.glsl, step for step.
    const FloatPrecision p = bytes[0].p;
    const ShaderFloat invScale(1.0 / double(1 << (8 - groupBits_)), p), scale(double(1 << (8 - groupBits_)), p),
        values(double(1 << groupBits_), p);
    std::vector<uint32_t> slots;
    slots.reserve(size_t(windows_) * size_t(windowSlots_));
    std::vector<ShaderFloat> shifted = bytes;  // each window shifts its own targets' bytes in place
    for (int w = 0; w < windows_; ++w) {
        ShaderFloat* packed = shifted.data() + w * windowTargets_ * 4;
        for (int s = 0; s < windowSlots_; ++s) {
            // The index's low and high bytes, weighted separately (lidrHalves): never one float above 255.
            ShaderFloat low(0.0, p), high(0.0, p);
            for (int t = 0; t < windowTargets_; ++t) {
                ShaderFloat dotLow(0.0, p), dotHigh(0.0, p);
                for (int ch = 0; ch < 4; ++ch) {
                    ShaderFloat& v = packed[t * 4 + ch];
                    const ShaderFloat top = floorOf(v * invScale);
                    v = (v - top * scale) * values;
                    const ShaderFloat wLow(lowWeight(t * 4 + ch), p), wHigh(highWeight(t * 4 + ch), p);
                    dotLow = ch == 0 ? top * wLow : dotLow + top * wLow;
                    dotHigh = ch == 0 ? top * wHigh : dotHigh + top * wHigh;
                }
                low = t == 0 ? dotLow : low + dotLow;
                high = t == 0 ? dotHigh : high + dotHigh;
            }
            slots.push_back(indexFromHalves(low, high));
        }
    }
    return slots;
}

}  // namespace lidr
