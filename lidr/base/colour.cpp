#include "lidr/base/colour.h"

#include <algorithm>
#include <cmath>

namespace lidr {

double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

double linearToSrgb(double c) { return c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055; }

glm::vec3 srgbToLinear(const glm::vec3& c) {
    return {float(srgbToLinear(double(c.r))), float(srgbToLinear(double(c.g))), float(srgbToLinear(double(c.b)))};
}

glm::vec3 displayColourToLinear(const glm::vec3& c) {
    const float peak = std::max(c.r, std::max(c.g, c.b));
    return peak <= 1.0f ? srgbToLinear(c) : peak * srgbToLinear(c / peak);
}

}  // namespace lidr
