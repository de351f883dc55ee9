#include "lidr/base/visualize.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace lidr {

static glm::vec3 indexColor(uint32_t index) {
    uint32_t h = index * 2654435761u;
    h ^= h >> 15;
    h *= 2246822519u;
    h ^= h >> 13;
    return glm::vec3(0.25f) + 0.75f * glm::vec3((h & 0xFF) / 255.0f, ((h >> 8) & 0xFF) / 255.0f, ((h >> 16) & 0xFF) / 255.0f);
}

ImageRGBA8 indexListImage(int width, int height, const std::vector<std::vector<uint32_t>>& lists) {
    ImageRGBA8 img(width, height);
    for (size_t p = 0; p < lists.size() && p < size_t(width) * height; ++p) {
        glm::vec3 c(0.0f);
        for (uint32_t i : lists[p]) c += indexColor(i);
        if (!lists[p].empty()) c /= float(lists[p].size());
        for (int k = 0; k < 3; ++k) img.pixels[p * 4 + k] = static_cast<uint8_t>(std::lround(c[k] * 255.0f));
        img.pixels[p * 4 + 3] = 255;
    }
    return img;
}

ImageRGBA8 overlapHeatMap(int width, int height, const std::vector<int>& counts, int budget,
                          const std::vector<uint8_t>* surface) {
    ImageRGBA8 img(width, height);
    const glm::vec3 ramp[] = {{0, 0, 0.6f}, {0, 0.8f, 0.2f}, {1, 1, 0}};
    for (size_t p = 0; p < counts.size() && p < size_t(width) * height; ++p) {
        glm::vec3 c(0.0f);
        const int n = counts[p];
        if (surface && !(*surface)[p]) {
            c = glm::vec3(0.12f);
        } else if (n == 0) {
            c = glm::vec3(0.0f);
        } else if (n <= budget) {
            const float t = budget > 1 ? float(n - 1) / float(budget - 1) * 2.0f : 2.0f;
            const int i = std::min(1, int(t));
            c = glm::mix(ramp[i], ramp[i + 1], t - float(i));
        } else {
            const float t = std::min(1.0f, float(n - budget) / float(std::max(budget, 1)));
            c = glm::mix(glm::vec3(1, 0, 0), glm::vec3(1), t);
        }
        for (int k = 0; k < 3; ++k) img.pixels[p * 4 + k] = static_cast<uint8_t>(std::lround(c[k] * 255.0f));
        img.pixels[p * 4 + 3] = 255;
    }
    return img;
}

}  // namespace lidr
