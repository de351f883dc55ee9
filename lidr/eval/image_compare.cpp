#include "lidr/eval/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "lidr/base/error.h"

namespace lidr {

ImageError compareImages(const ImageRGBA8& a, const ImageRGBA8& b, int threshold, const std::vector<uint8_t>* mask) {
    if (a.width != b.width || a.height != b.height)
        throw Error("compareImages: sizes differ (" + std::to_string(a.width) + "x" + std::to_string(a.height) +
                    " vs " + std::to_string(b.width) + "x" + std::to_string(b.height) + ")");
    const size_t n = static_cast<size_t>(a.width) * a.height;
    if (mask && mask->size() != n) throw Error("compareImages: mask size differs from the images");
    ImageError e;
    double sumSq = 0.0;
    for (size_t i = 0; i < n; ++i) {
        if (mask && (*mask)[i] == 0) continue;
        ++e.comparedPixels;
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(a.pixels[i * 4 + c]) - int(b.pixels[i * 4 + c]));
            worst = std::max(worst, d);
            sumSq += double(d) * d;
        }
        e.maxAbsError = std::max(e.maxAbsError, worst);
        if (worst > 0) ++e.differingPixels;
        if (worst > threshold) ++e.pixelsOverThreshold;
    }
    const double count = 3.0 * std::max<long>(e.comparedPixels, 1);
    e.rmse = std::sqrt(sumSq / count);
    e.psnr = e.rmse == 0.0 ? std::numeric_limits<double>::infinity() : 20.0 * std::log10(255.0 / e.rmse);
    return e;
}

ImageRGBA8 differenceImage(const ImageRGBA8& a, const ImageRGBA8& b, int gain) {
    if (a.width != b.width || a.height != b.height) throw Error("differenceImage: sizes differ");
    ImageRGBA8 out(a.width, a.height);
    for (size_t i = 0; i < out.pixels.size() / 4; ++i) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a.pixels[i * 4 + c]) - int(b.pixels[i * 4 + c])));
        const uint8_t v = static_cast<uint8_t>(std::min(255, worst * gain));
        out.pixels[i * 4 + 0] = out.pixels[i * 4 + 1] = out.pixels[i * 4 + 2] = v;
        out.pixels[i * 4 + 3] = 255;
    }
    return out;
}

}  // namespace lidr
