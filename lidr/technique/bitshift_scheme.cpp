#include "lidr/technique/bitshift_scheme.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <cmath>

#include "lidr/base/error.h"

namespace lidr {

BitShiftScheme::BitShiftScheme(const PackingConfig& config, const GlInfo& info) : PackingScheme(config) {
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
    return windows_ > 1 ? "rank windows 0-7 and 8-15 (restarted count) + light count"
                        : "rank window 0-" + std::to_string(windowSlots_ - 1) + " + light count";
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
    for (int w = 0; w < windows_; ++w) {
        SchemeDraw sd = rankWindowDraw("bitshift", w, windowSlots_, lights, [this](uint32_t i) { return colorsFor(i); });
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

ShaderDefines BitShiftScheme::unpackDefines() const {
    ShaderDefines d = {{"LIDR_SLOTS", std::to_string(config_.budget)},
                       {"LIDR_INDEX_TARGETS", std::to_string(targetCount())},
                       {"LIDR_WINDOWS", std::to_string(windows_)},
                       {"LIDR_WINDOW_TARGETS", std::to_string(windowTargets_)},
                       {"LIDR_WINDOW_SLOTS", std::to_string(windowSlots_) + ".0"},
                       {"LIDR_GROUP_SCALE", std::to_string(1 << (8 - groupBits_)) + ".0"},
                       {"LIDR_GROUP_VALUES", std::to_string(1 << groupBits_) + ".0"}};
    for (int t = 0; t < 4; ++t) {
        double w[4];
        for (int ch = 0; ch < 4; ++ch) {
            const int c = t * 4 + ch;
            w[ch] = c < channels_ ? std::ldexp(1.0, c * groupBits_) : 0.0;
        }
        d.push_back({"LIDR_WEIGHTS" + std::to_string(t), glslVec4(w)});
    }
    return d;
}

std::vector<uint32_t> BitShiftScheme::decodeBytes(const std::vector<ShaderFloat>& bytes) const {
    // unpack_bitshift.glsl, step for step.
    const FloatPrecision p = bytes[0].p;
    const ShaderFloat invScale(1.0 / double(1 << (8 - groupBits_)), p), scale(double(1 << (8 - groupBits_)), p),
        values(double(1 << groupBits_), p);
    std::vector<uint32_t> slots;
    for (int w = 0; w < windows_; ++w) {
        std::vector<ShaderFloat> packed(bytes.begin() + w * windowTargets_ * 4,
                                        bytes.begin() + (w + 1) * windowTargets_ * 4);
        for (int s = 0; s < windowSlots_; ++s) {
            ShaderFloat index(0.0, p);
            for (int t = 0; t < windowTargets_; ++t) {
                ShaderFloat dot(0.0, p);
                for (int ch = 0; ch < 4; ++ch) {
                    ShaderFloat& v = packed[t * 4 + ch];
                    const ShaderFloat top = floorOf(v * invScale);
                    v = (v - top * scale) * values;
                    const int c = t * 4 + ch;
                    const ShaderFloat weight(c < channels_ ? std::ldexp(1.0, c * groupBits_) : 0.0, p);
                    dot = ch == 0 ? top * weight : dot + top * weight;
                }
                index = t == 0 ? dot : index + dot;
            }
            slots.push_back(std::isfinite(index.v) && index.v >= 0.0 ? static_cast<uint32_t>(index.v) : 0xFFFFFFFFu);
        }
    }
    return slots;
}

}  // namespace lidr
