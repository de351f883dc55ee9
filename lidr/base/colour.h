#pragma once
// The sRGB transfer function (IEC 61966-2-1): encoded display values <-> linear light, per channel.
#include <glm/glm.hpp>

namespace lidr {

double srgbToLinear(double encoded);
double linearToSrgb(double linear);
// Per channel, for colours authored as display values (colour pickers, MTL files): decoded to linear light.
glm::vec3 srgbToLinear(const glm::vec3& encoded);
// A colour authored as a display value that may also carry strength above 1 (MTL Ke 4 3 2, a bright light):
// up to 1 decoded per channel; above, the hue (colour / its largest channel) decoded and the strength kept
// linear, so that 2 x white is twice white, not 5.3 x. The two agree at 1.
glm::vec3 displayColourToLinear(const glm::vec3& color);

}  // namespace lidr
