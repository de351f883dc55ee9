#pragma once
// The frame plan of LIDR (doc/architecture.md, "One frame of LIDR"), on the CPU: which lights get an index this
// frame, the numbers they get, the screen regions that number their own lights, and the index width. Lights are
// taken in draw order (priority high to low, then index). One that cannot touch a visible surface gets no
// index: outside the view frustum, touching no mesh's bounds, or (tile-culled volumes) reaching no surface of
// the pre-pass depth, unless it reaches a transparent mesh. With an automatic width the rest are numbered
// 1..n in draw order and only they go into the light table; with more than 255 of them and tiles, the screen
// may be split into regions that number apart in 8 bits (LidrOptions::regionalIndices).
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "lidr/scene/camera.h"
#include "lidr/scene/scene.h"
#include "lidr/technique/auto_configuration.h"
#include "lidr/technique/light_volume_geometry.h"
#include "lidr/technique/volume_tiles.h"

namespace lidr {

// Lights in the order the volume pass draws them: priority high to low, then index low to high (1-based).
std::vector<uint32_t> drawOrder(const std::vector<PointLight>& lights);

// What the plan asks about a light's sphere (centre, radius): LidrRenderer answers from its meshes' bounds and
// its volume pass's tiles, a test from boxes and rectangles of its own.
struct FramePlanQueries {
    std::function<bool(const glm::vec4&)> touchesScene;        // reaches some mesh's bounds
    std::function<bool(const glm::vec4&)> reachesTransparent;  // reaches a transparent mesh's bounds
    // With tiles only: whether the sphere may mark a pixel of this frame, and the regions (bit r: region r) of
    // `regions` whose tiles it reaches.
    std::function<bool(const glm::vec4&)> reachesTiles;
    std::function<uint32_t(const glm::vec4&, const IndexRegions&)> regionsReached;
};

struct FramePlanSettings {
    bool cullLights = true;         // LidrOptions::cullLights
    bool tiles = false;             // the tile decision's: the volumes are culled by tiles this frame
    bool transparentLists = false;  // transparent layers are drawn: a light reaching one keeps its index
    // Automatic width: visible lights numbered 1..n in draw order, the width its choice for the widest
    // numbering (AutoConfiguration::chooseIndexBits). nullptr: the scene's own numbering at fixedIndexBits.
    AutoConfiguration* autoWidth = nullptr;
    int fixedIndexBits = 8;
    // Region-local numbering may be tried (LidrOptions::regionalIndices on an opaque, single-sampled frame with
    // a float light table); it is where the width is automatic, tiles are drawn and over 255 lights are indexed.
    bool regionalIndices = false;
    int maxRegions = 32;
    int tilesX = 0, tilesY = 0, tileSize = 16;  // the tile grid (VolumeTiles)
    int tableCapacity = 255;                    // entries the light table holds: the regions' rows and the tile map's
    // Per scene light, the first shadow-atlas tile of the sphere test's shadow test (ShadowLookup::VolumePass,
    // VolumeLight::shadowTile); nullptr: none.
    const std::vector<int>* shadowTiles = nullptr;
};

struct FramePlan {
    // What the volume pass draws, in draw order; `index` is the number the lists hold. With regions a light is
    // an entry per region it reaches, marking that region's tiles only.
    std::vector<VolumeLight> volumes;
    // Automatic width: the light table's entries (entry k - 1 holds index k; with regions, row * 256 + k - 1 that
    // of index k in region `row`) and each entry's scene index (1-based; 0: an unused entry). Both empty: the
    // indices are the scene's own.
    std::vector<PointLight> tableLights;
    std::vector<uint32_t> frameLights;
    IndexRegions regions;   // off: one numbering
    int drawnLights = 0;    // lights given an index
    int widestList = 0;     // the most lights one numbering holds: drawnLights, or the widest region's
    int indexBits = 8;
    bool compactNumbering = false;
    // With tiles: the lights volume meshes would have drawn (all that pass the frustum and mesh tests) and their
    // summed sphere rectangles in pixels, what the tile decision measures the tiles against.
    int meshLights = 0;
    double meshRectArea = 0.0;

    bool lightless() const { return volumes.empty(); }
    // The tiles gave a narrower index width than volume meshes would have, or numbered by region.
    bool tilesNarrowed() const;
};

FramePlan planFrame(const CameraMatrices& camera, const std::vector<PointLight>& lights,
                    const FramePlanSettings& settings, const FramePlanQueries& queries);

// Region-local numbering of a plan's globally numbered lights (the k-d split of the tiles; the plan stays global
// where 8 bits cannot be had within settings.maxRegions regions or the table's capacity).
void numberByRegion(FramePlan& plan, const FramePlanSettings& settings, const FramePlanQueries& queries);

}  // namespace lidr
