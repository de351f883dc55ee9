#pragma once
// The frame's output transform (shaders/common/output_transform.glsl): every mode shades in linear light, then
// scales by the exposure, tone-maps with a named operator and encodes to sRGB, so that 8-bit targets, PNGs and
// windows hold display values. Error figures (PSNR and the rest) are taken on that encoded image, the one a
// viewer sees. The functions below are the CPU model of the shader's steps, in double precision, for tests and
// tools that predict pixels.
#include <string>

#include <glm/glm.hpp>

#include "lidr/base/colour.h"  // srgbToLinear, linearToSrgb

namespace lidr {

enum class ToneMap {
    None,        // clamped to [0, 1]: linear values pass unchanged below 1
    PbrNeutral,  // Khronos PBR Neutral: base colours under moderate light stay as authored, highlights roll off
    AcesFitted,  // ACES filmic, Stephen Hill's fit of the RRT + ODT: more contrast, hues shift towards white
};

struct OutputTransform {
    ToneMap toneMap = ToneMap::PbrNeutral;
    float exposureStops = 0.0f;  // linear light x 2^stops before the tone map
    bool srgb = true;            // false: linear values written (tests whose bounds are in linear 8-bit steps)
    // No exposure, no tone map, no encoding: the shaded sum written as it is (clamped by the 8-bit target).
    static OutputTransform linear() { return {ToneMap::None, 0.0f, false}; }
};

// "none", "pbr-neutral", "aces"; parseToneMap throws lidr::Error naming `what` and the accepted names.
const char* toneMapName(ToneMap t);
ToneMap parseToneMap(const std::string& name, const std::string& what);
const char* toneMapNames();  // "none, pbr-neutral, aces"

glm::dvec3 toneMapped(const glm::dvec3& color, ToneMap t);
// The shader's lidrOutput: exposure, tone map, clamp, encoding; channels in [0, 1] before the 8-bit rounding.
glm::dvec3 applyOutputTransform(const glm::dvec3& linearColor, const OutputTransform& output);

}  // namespace lidr
