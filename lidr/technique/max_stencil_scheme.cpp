#include "lidr/technique/max_stencil_scheme.h"
#include "lidr/base/gl.h"

#include <cmath>

#include "lidr/base/error.h"

namespace lidr {

MaxStencilScheme::MaxStencilScheme(const PackingConfig& config, const GlInfo& info)
    : PackingScheme(PackingSchemeKind::MaxStencil, config) {
    checkPackingConfig(config);
    windowSlots_ = (config.indexBits == 16 || config.budget == 1) ? 1 : 2;
    windows_ = config.budget / windowSlots_;
    // GL_MAX is GL 1.4 (EXT_blend_minmax), stencil GL 1.0: every desktop context lidr accepts has them; OpenGL
    // ES 2.0 has GL_MAX only with EXT_blend_minmax.
    if (!info.blendMinMax)
        throw UnsupportedError("max-stencil packs with the GL_MAX blend equation; this context lacks it "
                               "(OpenGL ES 2.0 needs EXT_blend_minmax): use --scheme bitshift");
    if (info.framebufferObject) checkContextFor("max-stencil " + describe(), info, targetCount(), 1);
}

std::string MaxStencilScheme::stencilUse() const {
    return std::to_string(windows_) + " rank window" + (windows_ > 1 ? "s" : "") + " of " +
           std::to_string(windowSlots_) + " (count restarted per pass) + light count";
}

IndexColors MaxStencilScheme::colorsFor(uint32_t index) const {
    IndexColors c{};
    if (config_.indexBits == 16) {
        const float low = byteColor(index & 0xFFu), high = byteColor(index >> 8);
        c[0] = glm::vec4(low, high, low, high);
    } else {
        const float v = byteColor(index), inverse = byteColor(255u - index);  // (index, 1 - index) in bytes
        c[0] = glm::vec4(v, inverse, v, inverse);
    }
    return c;
}

std::vector<SchemeDraw> MaxStencilScheme::plan(const std::vector<VolumeLight>& lights, const LightVolumePass*) const {
    std::vector<SchemeDraw> draws;
    for (int w = windows_ - 1; w >= 0; --w) {  // last to first (rankWindowDraw)
        SchemeDraw sd = rankWindowDraw(PackingSchemeKind::MaxStencil, w, windowSlots_, windows_, lights,
                                       [this](uint32_t i) { return colorsFor(i); });
        VolumeDraw& d = sd.draw;
        d.firstTarget = w / 2;
        d.targetCount = 1;
        d.colorMask = (w % 2 == 0) ? glm::bvec4(true, true, false, false) : glm::bvec4(false, false, true, true);
        d.blend = true;
        d.blendEquation = GL_MAX;
        d.blendSrc = GL_ONE;
        d.blendDst = GL_ONE;
        draws.push_back(std::move(sd));
    }
    return draws;
}

ShaderDefines MaxStencilScheme::unpackDefines() const {
    ShaderDefines d = {{"LIDR_SLOTS", std::to_string(config_.budget)},
                       {"LIDR_INDEX_TARGETS", std::to_string(targetCount())},
                       {"LIDR_WINDOW_SLOTS", std::to_string(windowSlots_)}};
    if (config_.indexBits == 16) d.push_back({"LIDR_INDEX_HALVES", "1"});
    return d;
}

std::vector<uint32_t> MaxStencilScheme::decodeBytes(const std::vector<ShaderFloat>& bytes) const {
    // unpack_max_stencil.glsl, step for step.
    const FloatPrecision p = bytes[0].p;
    auto out = [](ShaderFloat v) { return std::isfinite(v.v) && v.v >= 0.0 ? static_cast<uint32_t>(v.v) : 0xFFFFFFFFu; };
    std::vector<uint32_t> slots;
    for (int w = 0; w < windows_; ++w) {
        const ShaderFloat a = bytes[size_t(w) * 2], b = bytes[size_t(w) * 2 + 1];
        if (windowSlots_ == 2) {
            const ShaderFloat high = a, low = ShaderFloat(255.0, p) - b;
            slots.push_back(out(high));
            const bool none = high.v < 0.5 || std::fabs((low - high).v) < 0.5;
            slots.push_back(none ? 0u : out(low));
        } else if (config_.indexBits == 16) {
            slots.push_back(indexFromHalves(a, b));  // the shader returns (low, high), never one float
        } else {
            slots.push_back(out(a));
        }
    }
    return slots;
}

}  // namespace lidr
