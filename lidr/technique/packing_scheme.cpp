#include "lidr/technique/packing_scheme.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <cmath>

#include "lidr/technique/bitshift_scheme.h"
#include "lidr/technique/cpu_sorted_scheme.h"
#include "lidr/base/error.h"
#include "lidr/render/gpu_scene.h"
#include "lidr/render/light_table.h"
#include "lidr/technique/max_stencil_scheme.h"

namespace lidr {

SchemeDraw rankWindowDraw(PackingSchemeKind scheme, int window, int windowSlots, int windows,
                          const std::vector<VolumeLight>& lights, std::function<IndexColors(uint32_t index)> colors) {
    SchemeDraw sd;
    sd.draw.name = packingSchemeName(scheme) + std::string("-window-") + std::to_string(window);
    sd.draw.rankFirst = window * windowSlots;
    sd.draw.rankCount = windowSlots;
    sd.draw.restartCount = window < windows - 1;  // drawn last to first
    sd.lights = lights;
    sd.colors = std::move(colors);
    return sd;
}

std::string PackingScheme::describe() const {
    return std::string(packingSchemeName(config_.scheme)) + " budget " + std::to_string(config_.budget) + ", " +
           std::to_string(config_.indexBits) +
           "-bit indices, " + std::to_string(targetCount()) + " target" + (targetCount() > 1 ? "s" : "") + ", " +
           std::to_string(geometryPasses()) + " volume pass" + (geometryPasses() > 1 ? "es" : "") + ", stencil: " +
           stencilUse();
}

const char* packingSchemeName(PackingSchemeKind kind) {
    switch (kind) {
    case PackingSchemeKind::Auto: return "auto";
    case PackingSchemeKind::BitShift: return "bitshift";
    case PackingSchemeKind::MaxStencil: return "max-stencil";
    case PackingSchemeKind::CpuSorted: return "cpu-sorted";
    }
    return "?";
}

std::vector<PackingSchemeKind> packingSchemes() {
    return {PackingSchemeKind::BitShift, PackingSchemeKind::MaxStencil, PackingSchemeKind::CpuSorted};
}

std::vector<std::string> packingSchemeNames() {
    std::vector<std::string> names;
    for (PackingSchemeKind kind : packingSchemes()) names.emplace_back(packingSchemeName(kind));
    return names;
}

namespace {
std::string validSchemeNames() {
    std::string valid;
    for (const auto& n : packingSchemeNames()) valid += (valid.empty() ? "" : ", ") + n;
    return valid;
}
}  // namespace

PackingSchemeKind parsePackingScheme(const std::string& name) {
    if (name == "auto") return PackingSchemeKind::Auto;
    if (name == "bitshift") return PackingSchemeKind::BitShift;
    if (name == "max-stencil" || name == "max") return PackingSchemeKind::MaxStencil;
    if (name == "cpu-sorted" || name == "sorted") return PackingSchemeKind::CpuSorted;
    throw UnsupportedError("unknown packing scheme '" + name + "' (valid: auto, " + validSchemeNames() + ")");
}

std::unique_ptr<PackingScheme> createPackingScheme(const PackingConfig& config, const GlInfo& info) {
    if (config.autoScheme() || config.budget == PackingConfig::kAuto || config.indexBits == PackingConfig::kAuto)
        throw Error(std::string("createPackingScheme: '") + packingSchemeName(config.scheme) + "' budget " +
                    std::to_string(config.budget) + ", " + std::to_string(config.indexBits) +
                    "-bit is automatic; LidrRenderer resolves it per frame");
    switch (config.scheme) {
    case PackingSchemeKind::BitShift: return std::make_unique<BitShiftScheme>(config, info);
    case PackingSchemeKind::MaxStencil: return std::make_unique<MaxStencilScheme>(config, info);
    case PackingSchemeKind::CpuSorted: return std::make_unique<CpuSortedScheme>(config, info);
    case PackingSchemeKind::Auto: break;
    }
    throw UnsupportedError("unknown packing scheme " + std::to_string(int(config.scheme)) + " (valid: " +
                           validSchemeNames() + ")");
}

void checkPackingConfig(const PackingConfig& c) {
    const int b = c.budget, w = c.indexBits;
    const std::string scheme = packingSchemeName(c.scheme);
    if (w != 4 && w != 8 && w != 16)
        throw UnsupportedError(scheme + ": index width must be 4, 8 or 16 bits, got " + std::to_string(w));
    if (b == 32 && c.scheme != PackingSchemeKind::BitShift)
        throw UnsupportedError(scheme + ": budget 32 is bit-shift packing's only (four rank windows); " + scheme +
                               " takes 1, 2, 4, 8 or 16 lights per pixel");
    if (b != 1 && b != 2 && b != 4 && b != 8 && b != 16 && b != 32)
        throw UnsupportedError(scheme + ": budget must be 1, 2, 4, 8, 16 or 32 (bitshift) lights per pixel, got " +
                               std::to_string(b));
}

void checkContextFor(const std::string& what, const GlInfo& info, int targets, int drawTargets) {
    if (targets > kMaxIndexTargets)
        throw UnsupportedError(what + " needs " + std::to_string(targets) + " index targets; lidr binds at most " +
                               std::to_string(kMaxIndexTargets));
    if (info.framebufferObject && targets > info.maxColorAttachments)
        throw UnsupportedError(what + " needs " + std::to_string(targets) + " FBO colour attachments; this context has " +
                               std::to_string(info.maxColorAttachments) + " (choose a smaller budget or width)" +
                               (info.gles && !info.drawBuffers ? "; OpenGL ES 2.0 has one without EXT_draw_buffers" : ""));
    if (drawTargets > 1 && (!info.drawBuffers || drawTargets > info.maxDrawBuffers))
        throw UnsupportedError(what + " writes " + std::to_string(drawTargets) + " targets at once; this context has " +
                               std::to_string(info.drawBuffers ? info.maxDrawBuffers : 1) +
                               " draw buffers (choose a smaller budget or width)" +
                               (info.gles && !info.drawBuffers ? "; OpenGL ES 2.0 has one without EXT_draw_buffers" : ""));
    const int units = gl::kUnitHighestShading + 1;
    if (info.maxTextureUnits < units)
        throw UnsupportedError(what + ": the forward pass binds index textures and the light table on " +
                               std::to_string(units) + " texture units; this context has " +
                               std::to_string(info.maxTextureUnits));
}

void PackingScheme::encode(LightVolumePass& pass, const std::vector<VolumeLight>& lights) const {
    for (const SchemeDraw& d : plan(lights, &pass)) pass.draw(d.draw, d.lights, d.colors);
}

namespace {
double blendFactor(GLenum f, float constant, const BlendModel& m) {
    switch (f) {
    case GL_ONE: return 1.0;
    case GL_ZERO: return 0.0;
    case GL_CONSTANT_COLOR:
        return m.quantisedConstant ? std::nearbyint(double(constant) * 255.0) / 255.0 : double(constant);
    default: throw Error("CPU blend model: unsupported blend factor");
    }
}
}  // namespace

std::vector<uint8_t> PackingScheme::encodePixel(const std::vector<uint32_t>& drawOrder, const BlendModel& model,
                                                int* stencilCount) const {
    std::vector<VolumeLight> lights;
    for (uint32_t index : drawOrder) lights.push_back({index, glm::vec4(0.0f, 0.0f, -10.0f, 1.0f)});
    std::vector<uint8_t> bytes(size_t(targetCount()) * 4, 0);
    int count = 0;  // the stencil's light count (saturating INCR)
    for (const SchemeDraw& sd : plan(lights, nullptr)) {
        const VolumeDraw& d = sd.draw;
        if (d.restartCount) count = 0;
        const int mask = d.rankCount > 0 ? (~(d.rankCount - 1)) & 0xFF : 0;
        for (const VolumeLight& l : sd.lights) {
            const bool passes = d.rankCount == 0 || (count & mask) == d.rankFirst;
            if (passes && d.writesColor()) {
                const IndexColors c = sd.colors(l.index);
                for (int t = 0; t < d.targetCount; ++t)
                    for (int ch = 0; ch < 4; ++ch) {
                        if (!d.colorMask[ch]) continue;
                        uint8_t& dst = bytes[size_t(d.firstTarget + t) * 4 + ch];
                        const double src = std::nearbyint(std::clamp(double(c[t][ch]), 0.0, 1.0) * 255.0);
                        double v = src;
                        if (d.blend && d.blendEquation == GL_MAX) {
                            v = std::max(src, double(dst));
                        } else if (d.blend) {
                            if (d.blendEquation != GL_FUNC_ADD) throw Error("CPU blend model: unsupported equation");
                            v = src * blendFactor(d.blendSrc, d.blendColor[ch], model) +
                                double(dst) * blendFactor(d.blendDst, d.blendColor[ch], model);
                            v = model.truncate ? std::floor(v + 1e-9) : std::nearbyint(v);
                        }
                        dst = static_cast<uint8_t>(std::clamp(v, 0.0, 255.0));
                    }
            }
            count = std::min(count + 1, 255);
        }
    }
    if (stencilCount) *stencilCount = count;
    return bytes;
}

uint32_t indexFromHalves(ShaderFloat low, ShaderFloat high) {
    const auto isByte = [](double v) { return std::isfinite(v) && v >= 0.0 && v <= 255.0 && v == std::floor(v); };
    if (!isByte(low.v) || !isByte(high.v)) return 0xFFFFFFFFu;
    return uint32_t(low.v) + 256u * uint32_t(high.v);
}

std::vector<uint32_t> PackingScheme::decodeReads(const float* reads, FloatPrecision p) const {
    std::vector<ShaderFloat> bytes;
    bytes.reserve(size_t(targetCount()) * 4);
    for (int i = 0; i < targetCount() * 4; ++i) bytes.push_back(lidrBytesFor(ShaderFloat(reads[i], p)));
    return decodeBytes(bytes);
}

std::vector<uint32_t> PackingScheme::decodePixel(const uint8_t* texels) const {
    // lidrBytes(byte / 255) == byte in every precision (proven in tests), so the exact bytes go straight in.
    std::vector<ShaderFloat> bytes;
    bytes.reserve(size_t(targetCount()) * 4);
    for (int i = 0; i < targetCount() * 4; ++i) bytes.emplace_back(double(texels[i]), FloatPrecision::Fp32);
    return decodeBytes(bytes);
}

std::vector<uint32_t> PackingScheme::keptLights(const std::vector<uint32_t>& drawOrder) const {
    std::vector<uint32_t> kept(drawOrder.begin(), drawOrder.begin() + std::min<size_t>(drawOrder.size(), config_.budget));
    std::sort(kept.begin(), kept.end());
    return kept;
}

}  // namespace lidr
