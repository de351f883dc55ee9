#pragma once
// Images for people: the decoded index lists and the overlap heat map.
#include <cstdint>
#include <vector>

#include "lidr/base/image.h"

namespace lidr {

// Each light index gets a fixed colour; a pixel shows the mean colour of its listed lights, black for none.
ImageRGBA8 indexListImage(int width, int height, const std::vector<std::vector<uint32_t>>& lists);
// Lights per pixel: black 0, blue -> green -> yellow up to `budget`, red past it (white at 2x budget).
// Pixels with no geometry (surface mask 0) are dark grey.
ImageRGBA8 overlapHeatMap(int width, int height, const std::vector<int>& counts, int budget,
                          const std::vector<uint8_t>* surface = nullptr);

}  // namespace lidr
