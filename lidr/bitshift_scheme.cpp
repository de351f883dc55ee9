#include "lidr/bitshift_scheme.h"

#include <algorithm>
#include <cmath>

#include "lidr/error.h"

namespace lidr {

BitShiftScheme::BitShiftScheme(const PackingConfig& config, const GlInfo& info) : PackingScheme(config) {
    (void)info;  // blend colour and stencil are GL 1.4 / 1.0: every context lidr accepts has them
    const int budget = config.budget, bits = config.indexBits;
    if (bits != 4 && bits != 8 && bits != 16)
        throw UnsupportedError("bitshift: index width must be 4, 8 or 16 bits, got " + std::to_string(bits));
    if (budget != 1 && budget != 2 && budget != 4 && budget != 8 && budget != 16)
        throw UnsupportedError("bitshift: budget must be 1, 2, 4, 8 or 16, got " + std::to_string(budget));
    // The widest k-bit group that still leaves `budget` slots in a byte; groups >= 1 bit.
    int k = std::min(8, bits);
    while (k > 1 && 8 / k < budget) k /= 2;
    if (8 / k < budget || (bits % k) != 0 || bits / k > 4)
        throw UnsupportedError("bitshift: budget " + std::to_string(budget) + " with " + std::to_string(bits) +
                               "-bit indices needs more than one RGBA8 target, not built yet (one target holds: "
                               "4-bit budget 1/2/4/8, 8-bit budget 1/2/4, 16-bit budget 1/2)");
    groupBits_ = k;
    channels_ = bits / k;
}

IndexColors BitShiftScheme::colorsFor(uint32_t index) const {
    IndexColors c{};
    const uint32_t mask = (1u << groupBits_) - 1u;
    for (int ch = 0; ch < channels_; ++ch) {
        const uint32_t group = (index >> (ch * groupBits_)) & mask;
        c[0][ch] = float(group << (8 - groupBits_)) / 255.0f;  // exactly the byte group << (8 - k)
    }
    return c;
}

void BitShiftScheme::encode(LightVolumePass& pass, const std::vector<VolumeLight>& lights) const {
    VolumeDraw d;
    d.name = "bitshift";
    d.slotLimit = config_.budget;
    if (groupBits_ < 8) {  // with 8-bit groups there is one slot: a plain write, nothing to shift
        d.blend = true;
        d.blendSrc = GL_ONE;
        d.blendDst = GL_CONSTANT_COLOR;
        d.blendColor = glm::vec4(1.0f / float(1 << groupBits_));
    }
    pass.draw(d, lights, [this](uint32_t index) { return colorsFor(index); });
}

ShaderDefines BitShiftScheme::unpackDefines() const {
    std::string weights = "vec4(";
    for (int ch = 0; ch < 4; ++ch) {
        const double w = ch < channels_ ? std::ldexp(1.0, ch * groupBits_) : 0.0;
        weights += std::to_string(static_cast<long>(w)) + ".0" + (ch < 3 ? ", " : ")");
    }
    return {{"LIDR_SLOTS", std::to_string(config_.budget)},
            {"LIDR_GROUP_SCALE", std::to_string(1 << (8 - groupBits_)) + ".0"},
            {"LIDR_GROUP_VALUES", std::to_string(1 << groupBits_) + ".0"},
            {"LIDR_CHANNEL_WEIGHTS", weights}};
}

std::vector<uint8_t> BitShiftScheme::encodePixel(const std::vector<uint32_t>& drawOrder) const {
    std::vector<uint8_t> texel(4, 0);
    const size_t kept = std::min<size_t>(drawOrder.size(), size_t(config_.budget));  // stencil cap
    for (size_t i = 0; i < kept; ++i) {
        const IndexColors c = colorsFor(drawOrder[i]);
        for (int ch = 0; ch < 4; ++ch) {
            const double src = std::round(double(c[0][ch]) * 255.0);  // the byte the shader writes
            const double dst = groupBits_ < 8 ? texel[ch] / double(1 << groupBits_) : 0.0;
            texel[ch] = static_cast<uint8_t>(std::min(255.0, std::nearbyint(src + dst)));  // round to nearest
        }
    }
    return texel;
}

std::vector<uint32_t> BitShiftScheme::decodePixel(const uint8_t* texels) const {
    // The shader's arithmetic, step for step, in float.
    float packed[4];
    for (int ch = 0; ch < 4; ++ch) packed[ch] = std::floor(float(texels[ch]) / 255.0f * 255.0f + 0.5f);
    const float scale = float(1 << (8 - groupBits_)), values = float(1 << groupBits_);
    std::vector<uint32_t> slots;
    for (int s = 0; s < config_.budget; ++s) {
        float index = 0.0f;
        for (int ch = 0; ch < 4; ++ch) {
            const float top = std::floor(packed[ch] * (1.0f / scale));
            packed[ch] = (packed[ch] - top * scale) * values;
            if (ch < channels_) index += top * std::ldexp(1.0f, ch * groupBits_);
        }
        slots.push_back(static_cast<uint32_t>(index));
    }
    return slots;
}

}  // namespace lidr
