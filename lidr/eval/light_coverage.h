#pragma once
// CPU ground truth for light lists: which lights touch each pixel's surface (reconstructed from the depth
// buffer), and what a decoded index list dropped or got wrong against that truth.
#include <cstdint>
#include <vector>

#include "lidr/scene/camera.h"
#include "lidr/base/image.h"
#include "lidr/technique/packing_scheme.h"
#include "lidr/technique/volume_tiles.h"
#include "lidr/scene/scene.h"

namespace lidr {

// Lights whose sphere strictly contains each pixel's surface point, as a compressed row per pixel; for a spot
// light, also inside its cone. A light within `band` (relative to its radius) of the surface is neither
// required nor counted: there its contribution is below 2 * band of its peak, and depth-buffer precision cannot
// tell in or out; likewise a spot light whose cone ramp (0 at the outer cone, 1 at the inner) is below `band`
// (its cone term, the ramp squared, is below band^2 there).
struct CoverageTruth {
    int width = 0, height = 0;
    std::vector<uint32_t> offsets;  // width * height + 1
    std::vector<uint32_t> lights;   // 1-based light indices, ascending per pixel
    std::vector<uint8_t> surface;   // 1 where the pixel has geometry (depth < 1)
    int count(size_t pixel) const { return static_cast<int>(offsets[pixel + 1] - offsets[pixel]); }
    int maxOverlap() const;
};

CoverageTruth computeCoverage(const ImageFloat& depth, const CameraMatrices& camera,
                              const std::vector<PointLight>& lights, float band = 2e-3f);

// MSAA (sphere-span): per pixel, the lights a sample needs: those whose sphere (radius x (1 - band)) contains
// one of the points on the pixel centre's eye ray at the window depths of surfaceDepths (each image one point a
// pixel, >= 1: none; LidrRenderer::readDepthSpans: the nearest sample's surface, the centre's, the farthest
// sample's). A spot light also needs that point inside its cone (ramp above band). With the centre's depth alone,
// computeCoverage's truth.
CoverageTruth computeSpanCoverage(const std::vector<ImageFloat>& surfaceDepths, const CameraMatrices& camera,
                                  const std::vector<PointLight>& lights, float band = 2e-3f);

// Per pixel, the lights whose sphere scaled by `inflate` crosses the eye ray between the near plane and the
// pixel's opaque surface (the far plane where there is none): what a front-face volume pass marks. With
// `inflate` >= the volume mesh's outside radius it never counts fewer than the GPU marks.
std::vector<int> frontFaceCounts(const ImageFloat& depth, const CameraMatrices& camera,
                                 const std::vector<PointLight>& lights, float inflate);
// The same with one inflation factor per light (the volume each light is drawn with).
std::vector<int> frontFaceCounts(const ImageFloat& depth, const CameraMatrices& camera,
                                 const std::vector<PointLight>& lights, const std::vector<float>& inflate);

// A grid's per-pixel light lists (the tiled and clustered modes: one flat list of entries, each list at an offset
// with a count, ascending) against the truth. listOfPixel: per pixel, rows top to bottom as the truth's, the
// list it shaded with (< 0: none).
struct PixelListCheck {
    long truthPairs = 0;         // (pixel, light) pairs of the truth
    long missingPairs = 0;       // ... whose light is missing from the pixel's list
    long pixelsWithMissing = 0;
    long listPairs = 0;          // entries of the surface pixels' lists, summed over the pixels
    long extraPairs = 0;         // listed, not touching the pixel's surface: listPairs - (truthPairs - missingPairs)
    long surfaceWithoutList = 0; // surface pixels with no list (listOfPixel < 0)
    // The conservative test's overhead: lights a pixel loops over that do not light it, per light that does.
    double extraPerTruePair() const { return truthPairs > 0 ? double(extraPairs) / double(truthPairs) : 0.0; }
};
PixelListCheck checkPixelLists(const CoverageTruth& truth, const std::vector<int>& listOfPixel,
                               const std::vector<uint32_t>& entries, const std::vector<uint32_t>& offsets,
                               const std::vector<int>& counts);

struct ListCheck {
    long droppedLightPixels = 0;  // (pixel, light) pairs: light touches the surface, missing from the list
    long pixelsWithDrops = 0;
    int maxDroppedPerPixel = 0;
    long invalidSlots = 0;        // decoded indices that name no light, or repeat one
    long slotsUsed = 0;           // non-empty slots over all pixels
    int maxSlotsUsed = 0;
    std::vector<uint8_t> droppedPerPixel;
    std::vector<std::vector<uint32_t>> decoded;  // per pixel, the non-empty slots in unpack order
};

// Decodes every pixel of the index targets with the scheme's CPU model and checks it against the truth.
// sceneIndexOf: the frame's compact numbering (LidrRenderer::frameLightIndices); empty when indices are the
// scene's own. regions: the frame's region-local numbering (LidrRenderer::frameIndexRegions), where on.
ListCheck checkIndexLists(const CoverageTruth& truth, const PackingScheme& scheme,
                          const std::vector<ImageRGBA8>& indexTargets, uint32_t lightCount,
                          const std::vector<uint32_t>& sceneIndexOf = {}, const IndexRegions& regions = {});

}  // namespace lidr
