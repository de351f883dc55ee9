#pragma once
// Accuracy of one LIDR frame: its image against the brute-force reference, and its index lists against the
// CPU truth of which lights touch each pixel. Shared by lidr-demo, lidr-bench and the tests.
#include <vector>

#include "lidr/eval/image_compare.h"
#include "lidr/technique/lidr_renderer.h"
#include "lidr/eval/light_coverage.h"

namespace lidr {

// A pixel whose samples' depths differ by more than this (window depth; 24-bit rounding is 6e-8) is an edge pixel.
constexpr float kEdgeDepthMargin = 1e-5f;

struct FrameEvaluation {
    CoverageTruth truth;            // lights touching each surface pixel
    ListCheck lists;                // decoded lists against the truth
    std::vector<int> marked;        // lights the volume test marked per pixel (GPU stencil count), or truth
    int maxTruthOverlap = 0;        // most lights touching one pixel's surface
    int maxMarked = 0;              // most lights marking one pixel
    long pixelsOverBudget = 0;      // surface pixels where a marking light was not kept (see withinBudget)
    // Lights a front-face pass marks per pixel (CPU, conservative), when transparent layers read front-face
    // lists; else empty.
    std::vector<int> frontFaceMarked;
    // 1 where every list the pixel reads holds all its lights: the main one by the GPU count (marked <= budget;
    // with CPU sorting, which drops whole lights, also no dropped mark), the front-face one of transparent
    // layers by the conservative CPU count.
    std::vector<uint8_t> withinBudget;
    std::vector<int> droppedMarks;  // per pixel: marks the index lists do not hold (GPU count - kept slots)
    // sphere-span (MSAA): pixels whose samples shade more than one depth, and the lists against the lights the
    // samples' surfaces need (computeSpanCoverage at the nearest sample's surface, the centre's and the farthest
    // sample's; a superset of `truth`'s). Empty/0 for the other tests.
    long edgePixels = 0;
    long edgePixelsSeveralSurfaces = 0;  // ... with samples at more than one depth on one side of the centre
    int edgeMarksMax = 0;                // lights marked on an edge pixel: the most, the mean
    double edgeMarksMean = 0.0;
    CoverageTruth spanTruth;
    ListCheck spanLists;
    ImageError error;               // whole image against the reference
    ImageError errorWithinBudget;   // only pixels marked by <= budget lights
};

FrameEvaluation evaluateFrame(const LidrRenderer& renderer, const Camera& camera,
                              const std::vector<PointLight>& lights, const ImageRGBA8& image,
                              const ImageRGBA8& reference);

}  // namespace lidr
