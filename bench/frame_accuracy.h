#pragma once
// One frame of a mode judged against the brute-force reference of the same frame: the image error, and where the
// mode keeps per-pixel light lists (LIDR's index lists, tiled's tile lists, clustered's cluster lists) those lists
// against the CPU truth of which lights touch each pixel's surface: light-pixels dropped, shaded, and the truth.
#include <vector>

#include "lidr/eval/image_compare.h"
#include "lidr/eval/light_coverage.h"
#include "lidr/render/renderer.h"

namespace lidr::bench {

struct FrameAccuracy {
    ImageError error;
    bool hasLists = false;  // the lists below were checked (LIDR, tiled, clustered, tiled deferred; deferred: its
                            // per-pixel count of light shaders run; not with MSAA)
    long droppedLightPixels = 0;   // (pixel, light) pairs whose light touches the pixel and is not in its list
    long pixelsWithDrops = 0;
    long trueLightPixels = 0;      // (pixel, light) pairs of the truth: the fewest lighting computations that are exact
    long shadedLightPixels = 0;    // entries of the surface pixels' lists: the lighting computations the mode makes
    // LIDR: surface pixels where more lights mark the pixel than its budget holds (its lists drop some by design,
    // the lowest priority first), and the image error over the other pixels alone. 0 and `error` elsewhere.
    long pixelsOverBudget = 0;
    ImageError errorWithinBudget;
    // How many times the frame ran the lighting function (lidrShadeLight) in its opaque shading, the paper's Figure
    // 3: LIDR the filled slots it shades; tiled, clustered and tiled deferred the entries of each surface pixel's
    // list; deferred (stencil on or off) the light shaders its accumulation target counted, every pixel;
    // multi-pass forward its light passes' fragment shader invocations (where the context counts them);
    // brute force surface pixels x lights. -1: not counted (MSAA, ES 2.0 deferred, the automatic mode).
    long lightingComputations = -1;
};

// The frame `renderer` drew last (its colour `image`) against `reference`. `camera` and `lights` are the frame's.
FrameAccuracy judgeFrame(Renderer& renderer, const Camera& camera, const std::vector<PointLight>& lights,
                         const ImageRGBA8& image, const ImageRGBA8& reference);

// The lighting computations of the frame `renderer` drew last (FrameAccuracy::lightingComputations; -1 where not
// counted). Reads the frame's depth and its lists or counts back: for measuring runs, after the frame's timing.
// Each pixel's list of a tiled, tiled-deferred or clustered frame (the mode's own grid) against the CPU truth:
// missing, extra and listed pairs. Throws lidr::Error for a mode without such lists.
PixelListCheck checkGridLists(const Renderer& renderer, const CoverageTruth& truth, int width, int height);

long countLightingComputations(Renderer& renderer, const Camera& camera, const std::vector<PointLight>& lights);

}  // namespace lidr::bench
