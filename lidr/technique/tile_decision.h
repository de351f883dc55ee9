#pragma once
// The tile decision of a LIDR frame (LidrOptions::tileCulledVolumes; doc/architecture.md, "One frame of LIDR"):
// whether the frame reads its pre-pass depth back per tile and draws its light volumes as screen quads over the
// tiles they reach (volume_tiles.h), or draws volume meshes. Tiles pay for the read-back and a CPU pass over
// it, so a frame takes them only where its lights' volumes would cover at least kMinArea screens (their sphere
// rectangles, summed), and, once a tile frame has measured what they saved, only where that saving, scaled by
// the lights' area since, reaches kMinSaving screens, or where they narrowed the index width (or numbered by
// region). After kRecheckFrames frames of volume meshes they measure again. CPU only: the renderer reports each
// frame's outcome (recordTileFrame, recordMeshFrame) and asks before the next (decide).
#include <cstddef>
#include <vector>

#include "lidr/scene/camera.h"
#include "lidr/scene/scene.h"

namespace lidr {

class TileDecision {
public:
    // The lights' summed pixel rectangles, in screens, from which a frame culls by tiles.
    static constexpr double kMinArea = 1.0;
    // Once a tile frame has measured it: tiles only where they save this many screens of volume pixels (the
    // read-back costs about half a screen of volume fragments on llvmpipe, doc/benchmarks.md) ...
    static constexpr double kMinSaving = 0.75;
    // ... re-measured after this many frames without tiles.
    static constexpr int kRecheckFrames = 16;

    struct Choice {
        bool tiles = false;
        bool skippedForSaving = false;  // volume meshes: the last tile frame measured too small a saving
        double rectArea = 0.0;          // the lights' summed sphere rectangles it was decided on, in pixels
    };
    // This frame's choice from its lights' summed sphere rectangles (lightRectArea), in pixels.
    Choice decide(double rectArea, double screenPixels) const;

    // What a frame that culled by tiles measured.
    struct TileFrame {
        double rectArea = 0.0;      // Choice::rectArea
        double meshRectArea = 0.0;  // the sphere rectangles of the lights volume meshes would have drawn, in pixels
        long quadPixels = 0;        // pixels the tile quads covered, every draw of the main volume pass
        long stepLights = 0;        // lights asked for by those draws, once per draw
        size_t volumes = 0;         // the pass's entries (a light once per index region it reaches)
        bool narrower = false;      // the tiles narrowed the index width or numbered by region
    };
    // The volume-mesh pixels the tiles saved, in screens: the meshes would have covered the drawn lights'
    // rectangles in every draw (rank window, re-pack) the quads were drawn in.
    static double savingScreens(const TileFrame& frame, double screenPixels);
    void recordTileFrame(const TileFrame& frame, double screenPixels);
    void recordMeshFrame();  // a frame drawn with volume meshes

    bool measured() const { return measured_; }
    // The last tile frame's saving in screens (savingScreens); -1 before any.
    double lastSavingScreens() const { return measured_ ? savingScreens_ : -1.0; }
    int framesSinceMeasured() const { return framesSince_; }

private:
    bool measured_ = false;
    double savingScreens_ = 0.0;
    double rectArea_ = 0.0;   // the lights' rectangle area then
    bool narrower_ = false;
    int framesSince_ = 0;     // frames drawn since
};

// Pixels of the light's sphere rectangle on screen (0 off screen): about what its volume mesh covers.
double sphereRectPixels(const CameraMatrices& camera, const PointLight& light);
// Summed pixel rectangles of the lights' spheres (a bound on what their volume meshes would cover).
double lightRectArea(const CameraMatrices& camera, const std::vector<PointLight>& lights);

}  // namespace lidr
