#include "lidr/technique/cpu_sorted_scheme.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <cmath>

#include "lidr/base/error.h"
#include "lidr/scene/sphere_bounds.h"

namespace lidr {

ScreenFootprint screenFootprint(const CameraMatrices& m, const glm::vec4& posRadius, float outside) {
    ScreenFootprint f{0, 0, m.width - 1, m.height - 1};
    const glm::vec3 c(posRadius);
    const float r = posRadius.w * outside;
    float minX = 1e30f, minY = 1e30f, maxX = -1e30f, maxY = -1e30f;
    for (int k = 0; k < 8; ++k) {
        const glm::vec3 corner = c + r * glm::vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
        const glm::vec4 clip = m.viewProjection * glm::vec4(corner, 1.0f);
        if (!(clip.w > m.nearPlane * 0.5f)) return f;  // reaches behind the near plane (or NaN): the whole target
        const float sx = (clip.x / clip.w * 0.5f + 0.5f) * m.width;
        const float sy = (clip.y / clip.w * 0.5f + 0.5f) * m.height;
        if (!std::isfinite(sx) || !std::isfinite(sy)) return f;  // overflowed: the whole target (conservative)
        minX = std::min(minX, sx), maxX = std::max(maxX, sx);
        minY = std::min(minY, sy), maxY = std::max(maxY, sy);
    }
    // One pixel of slack on each side for rasterisation and rounding; clamped in float before converting, so
    // a huge coordinate cannot overflow an int. Wholly off screen gives an empty footprint (x0 > x1 or y0 > y1).
    f.x0 = clampToInt(std::floor(minX) - 1.0f, 0, m.width, 0);
    f.y0 = clampToInt(std::floor(minY) - 1.0f, 0, m.height, 0);
    f.x1 = clampToInt(std::ceil(maxX) + 1.0f, -1, m.width - 1, m.width - 1);
    f.y1 = clampToInt(std::ceil(maxY) + 1.0f, -1, m.height - 1, m.height - 1);
    return f;
}

CpuSortedScheme::CpuSortedScheme(const PackingConfig& config, const GlInfo& info)
    : PackingScheme(PackingSchemeKind::CpuSorted, config) {
    checkPackingConfig(config);
    if (info.framebufferObject) checkContextFor("cpu-sorted " + describe(), info, targetCount(), 1);
}

bool CpuSortedScheme::mayShareAPixel(const VolumeLight& a, const VolumeLight& b, const LightVolumePass& pass) {
    if (!pass.geometry().marksWithinLightFootprints()) return true;  // e.g. a test's per-pixel lists
    const float outsideA = pass.outsideRadiusFor(a), outsideB = pass.outsideRadiusFor(b);  // the volumes drawn
    const CameraMatrices& cam = pass.camera();
    if (!screenFootprint(cam, a.posRadius, outsideA).overlaps(screenFootprint(cam, b.posRadius, outsideB))) return false;
    // Back-face and front-face tests: footprints. The exact tests mark surface points within outside * radius.
    if (pass.test() != VolumeTest::ExactStencil && pass.test() != VolumeTest::Sphere) return true;
    if (pass.marksWholeFootprint(a) || pass.marksWholeFootprint(b)) return true;
    // Exact test: a marked surface point lies inside the volume mesh, within outside * radius of the centre.
    const float reach = (a.posRadius.w * outsideA + b.posRadius.w * outsideB) * 1.001f + 1e-4f;
    return glm::length(glm::vec3(a.posRadius) - glm::vec3(b.posRadius)) < reach;
}

std::vector<int> CpuSortedScheme::assignGroups(const std::vector<VolumeLight>& lights, const LightVolumePass* pass) const {
    std::vector<int> group(lights.size(), -1);
    std::vector<std::vector<size_t>> members(size_t(config_.budget));
    for (size_t i = 0; i < lights.size(); ++i) {
        for (int g = 0; g < config_.budget; ++g) {
            bool free = true;
            for (size_t j : members[size_t(g)])
                if (!pass || mayShareAPixel(lights[i], lights[j], *pass)) {
                    free = false;
                    break;
                }
            if (free) {
                group[i] = g;
                members[size_t(g)].push_back(i);
                break;
            }
        }
    }
    return group;
}

IndexColors CpuSortedScheme::colorsFor(uint32_t index, int g) const {
    IndexColors c{};
    if (config_.indexBits == 16) {
        const float low = byteColor(index & 0xFFu), high = byteColor(index >> 8);
        c[0] = glm::vec4(low, high, low, high);
    } else if (config_.indexBits == 4) {
        c[0] = glm::vec4(byteColor(g % 2 == 0 ? index : index << 4));
    } else {
        c[0] = glm::vec4(byteColor(index));
    }
    return c;
}

std::vector<SchemeDraw> CpuSortedScheme::plan(const std::vector<VolumeLight>& lights, const LightVolumePass* pass) const {
    const std::vector<int> group = assignGroups(lights, pass);
    std::vector<SchemeDraw> draws;
    for (int g = 0; g < config_.budget; ++g) {
        SchemeDraw sd;
        VolumeDraw& d = sd.draw;
        d.name = "cpu-sorted-group-" + std::to_string(g);
        // First channel of the slot in the channel stream.
        const int channel = config_.indexBits == 16 ? 2 * g : (config_.indexBits == 8 ? g : g / 2);
        d.firstTarget = channel / 4;
        d.targetCount = 1;
        d.colorMask = glm::bvec4(false);
        d.colorMask[channel % 4] = true;
        if (config_.indexBits == 16) d.colorMask[channel % 4 + 1] = true;
        if (config_.indexBits == 4) {  // two groups share a channel: add the nibbles
            d.blend = true;
            d.blendSrc = GL_ONE;
            d.blendDst = GL_ONE;
        }
        for (size_t i = 0; i < lights.size(); ++i)
            if (group[i] == g) sd.lights.push_back(lights[i]);
        sd.colors = [this, g](uint32_t index) { return colorsFor(index, g); };
        if (!sd.lights.empty()) draws.push_back(std::move(sd));
    }
    SchemeDraw dropped;  // counted by the stencil, written nowhere
    dropped.draw.name = "cpu-sorted-dropped";
    dropped.draw.colorMask = glm::bvec4(false);
    for (size_t i = 0; i < lights.size(); ++i)
        if (group[i] < 0) dropped.lights.push_back(lights[i]);
    dropped.colors = [](uint32_t) { return IndexColors{}; };
    if (!dropped.lights.empty()) draws.push_back(std::move(dropped));
    return draws;
}

ShaderDefines CpuSortedScheme::unpackDefines() const {
    return {{"LIDR_SLOTS", std::to_string(config_.budget)},
            {"LIDR_INDEX_TARGETS", std::to_string(targetCount())},
            {"LIDR_SLOT_BITS", std::to_string(config_.indexBits)}};
}

std::vector<uint32_t> CpuSortedScheme::decodeBytes(const std::vector<ShaderFloat>& bytes) const {
    // unpack_cpu_sorted.glsl, step for step.
    const FloatPrecision p = bytes[0].p;
    auto out = [](ShaderFloat v) { return std::isfinite(v.v) && v.v >= 0.0 ? static_cast<uint32_t>(v.v) : 0xFFFFFFFFu; };
    std::vector<uint32_t> slots;
    for (int g = 0; g < config_.budget; ++g) {
        if (config_.indexBits == 16) {
            slots.push_back(indexFromHalves(bytes[size_t(2 * g)], bytes[size_t(2 * g + 1)]));  // (low, high)
        } else if (config_.indexBits == 4) {
            const ShaderFloat byte = bytes[size_t(g / 2)];
            const ShaderFloat high = floorOf(byte * ShaderFloat(1.0 / 16.0, p));
            slots.push_back(out(g % 2 == 0 ? byte - high * ShaderFloat(16.0, p) : high));
        } else {
            slots.push_back(out(bytes[size_t(g)]));
        }
    }
    return slots;
}

}  // namespace lidr
