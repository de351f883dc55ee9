#include "lidr/render/output_transform.h"

#include <algorithm>
#include <cmath>

#include "lidr/base/error.h"

namespace lidr {

const char* toneMapName(ToneMap t) {
    switch (t) {
        case ToneMap::None: return "none";
        case ToneMap::PbrNeutral: return "pbr-neutral";
        case ToneMap::AcesFitted: return "aces";
    }
    return "?";
}

const char* toneMapNames() { return "none, pbr-neutral, aces"; }

ToneMap parseToneMap(const std::string& name, const std::string& what) {
    for (ToneMap t : {ToneMap::None, ToneMap::PbrNeutral, ToneMap::AcesFitted})
        if (name == toneMapName(t)) return t;
    throw Error(what + ": unknown tone map '" + name + "' (one of " + toneMapNames() + ")");
}

namespace {
glm::dvec3 pbrNeutral(glm::dvec3 c) {
    const double x = std::min({c.r, c.g, c.b});
    const double offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    c -= offset;
    const double peak = std::max({c.r, c.g, c.b});
    const double start = 0.76, d = 1.0 - start;
    if (peak < start) return c;
    const double newPeak = 1.0 - d * d / (peak + d - start);
    c *= newPeak / peak;
    const double g = 1.0 - 1.0 / (0.15 * (peak - newPeak) + 1.0);
    return c * (1.0 - g) + glm::dvec3(newPeak) * g;
}

glm::dvec3 acesFitted(const glm::dvec3& c) {
    glm::dvec3 v(glm::dot(glm::dvec3(0.59719, 0.35458, 0.04823), c), glm::dot(glm::dvec3(0.07600, 0.90834, 0.01566), c),
                 glm::dot(glm::dvec3(0.02840, 0.13383, 0.83777), c));
    const glm::dvec3 a = v * (v + 0.0245786) - 0.000090537;
    const glm::dvec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
    v = a / b;
    return {glm::dot(glm::dvec3(1.60475, -0.53108, -0.07367), v), glm::dot(glm::dvec3(-0.10208, 1.10813, -0.00605), v),
            glm::dot(glm::dvec3(-0.00327, -0.07276, 1.07602), v)};
}
}  // namespace

glm::dvec3 toneMapped(const glm::dvec3& color, ToneMap t) {
    switch (t) {
        case ToneMap::None: return color;
        case ToneMap::PbrNeutral: return pbrNeutral(color);
        case ToneMap::AcesFitted: return acesFitted(color);
    }
    return color;
}

glm::dvec3 applyOutputTransform(const glm::dvec3& linearColor, const OutputTransform& output) {
    glm::dvec3 c = glm::max(linearColor * std::exp2(double(output.exposureStops)), glm::dvec3(0.0));
    c = glm::clamp(toneMapped(c, output.toneMap), 0.0, 1.0);
    if (output.srgb)
        for (int i = 0; i < 3; ++i) c[i] = linearToSrgb(c[i]);
    return c;
}

}  // namespace lidr
