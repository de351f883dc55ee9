#pragma once
// Image error against a reference: the accuracy figures every mode and scheme is judged by. They compare the
// 8-bit images as rendered, i.e. after the output transform (tone map, sRGB encoding; doc/colour.md): the
// error a viewer sees, not an error in linear light.
#include <optional>

#include "lidr/base/image.h"

namespace lidr {

struct ImageError {
    int maxAbsError = 0;          // largest |a - b| over RGB channels, in 8-bit steps
    double rmse = 0.0;            // over RGB channels, in 8-bit steps
    double psnr = 0.0;            // dB, peak 255; infinity when identical
    long differingPixels = 0;     // pixels with any RGB channel different
    long pixelsOverThreshold = 0; // pixels with a channel differing by more than `threshold`
    long comparedPixels = 0;
};

// Compares RGB of a and b (same size, else lidr::Error). `mask`, if given, selects the pixels compared
// (non-zero first byte of its RGBA pixel).
ImageError compareImages(const ImageRGBA8& a, const ImageRGBA8& b, int threshold = 1,
                         const std::vector<uint8_t>* mask = nullptr);

// Per-pixel |a - b| (max over RGB), scaled by `gain`, as a grey image, for looking at.
ImageRGBA8 differenceImage(const ImageRGBA8& a, const ImageRGBA8& b, int gain = 16);

}  // namespace lidr
