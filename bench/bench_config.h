#pragma once
// What lidr-bench measures: scenes by name, render-mode configurations, and the sweep that expands lists of
// both into runs. Modes, schemes, budgets and widths come from the library (the render-mode factory,
// packingSchemeNames(), the schemes' UnsupportedError); nothing here lists what a scheme can do.
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "lidr/platform/context.h"
#include "lidr/render/renderer.h"
#include "lidr/scene/light_scatter.h"
#include "lidr/scene/scene.h"

namespace lidr::bench {

// ---- scenes ---------------------------------------------------------------------------------------------
// "room" (default room, 255 lights), "overlap-K" (controlled overlap, K lights on every lit pixel),
// "many-N-top" / "many-N-fp" (N lights, top-down / first-person), "heavy-T" (the room with about T
// triangles, T a number with an optional k or m suffix: heavy-250k, heavy-1m), or a scene file ("file:PATH",
// or a path ending in .json).
std::string sceneNameHelp();
// Where bart-robots-many / bart-robots-few are read from (lidr-bench --bart; lidr/scene/io/bart_scene.h).
std::string& benchBartFolder();
// Throws lidr::Error naming the valid forms for an unknown name or a file that does not load.
// `camera` >= 0 (lidr-bench --camera N): a glTF file's camera N (chooseView), before the -shadows-K casters are
// chosen from the view; an error for a scene that is not a glTF file with that camera.
Scene loadBenchScene(const std::string& name, uint32_t seed, int camera = -1);

// ---- configurations -------------------------------------------------------------------------------------
struct ModeConfig {
    std::string mode;             // a render-mode name
    // mode "lidr"
    std::string scheme;
    int budget = 0;
    int indexBits = 0;
    std::string volumeTest;       // backface, exact, frontface
    bool volumeDetail = false;    // LidrOptions::volumeDetail: coarse volumes for lights small on screen
    bool volumeTiles = true;      // LidrOptions::tileCulledVolumes (the sphere test): false draws volume meshes
    int volumeTileSize = 16;      // LidrOptions::volumeTileSize
    bool regionalIndices = true;  // LidrOptions::regionalIndices (automatic width, tiles, over 255 lights)
    std::string msaaSpans = "auto";  // LidrOptions::msaaSpans (sphere-span): auto, samples, moments
    // mode "tiled"
    bool tiledDepthBounds = false;
    // mode "clustered" (ClusteredOptions): 0, "" and -1 leave the library's default
    int clusterTileSize = 0, clusterSlices = 0;
    std::string clusterSlicing;   // exponential, near-slice
    int clusterOccupancy = -1;    // 0 off, 1 on
    // mode "forward-multipass": its passes summed in the 8-bit colour target (MultipassOptions::
    // halfFloatAccumulation false) rather than in half float where the context has it
    bool multipassEightBit = false;
    // mode "deferred": light volumes with the stencil test (DeferredOptions::stencil), the paper's Deferred-Stencil
    bool deferredStencil = false;
    // every mode
    int msaa = 0;
    // With MSAA: LIDR's per-sample index lists (LidrOptions::perSampleIndices) and a reference shaded per
    // sample; else one index list per pixel.
    bool perSample = false;
    bool transparency = true;
    // "lidr bitshift b4 8-bit backface", "tiled min/max", "clustered" (the library's default grid), "clustered t32 s16
    // exponential occupied" (a grid asked for: tile size, slices, slicing, occupancy), "forward-brute", ...
    std::string label() const;
    std::string key() const;      // label + msaa + transparency: unique per configuration
    // A copy with the clustered grid's unset fields filled with the library's defaults (what the row ran with).
    ModeConfig withClusterDefaults() const;
};

// Render modes the bench can build: the library's factory where it has one, in its order.
std::vector<std::string> availableModes();
std::string joinNames(const std::vector<std::string>& names);
// Builds the renderer; throws what the mode's constructor throws (UnsupportedError / lidr::Error) for
// settings it cannot do, before any drawing.
std::unique_ptr<Renderer> createBenchRenderer(const ModeConfig& config, const GlInfo& info, const Scene& scene,
                                              int width, int height);
// Which forward-brute configuration judges `config`: same MSAA and transparency.
ModeConfig referenceConfigFor(const ModeConfig& config);

// ---- sweeps ---------------------------------------------------------------------------------------------
// One cartesian sweep: every scene x resolution x mode, and for each mode the dimensions it has.
struct SweepGroup {
    std::string name;
    std::vector<std::string> scenes;
    std::vector<std::pair<int, int>> resolutions;  // (0, 0): the scene's own
    std::vector<std::string> modes;
    std::vector<std::string> schemes;
    std::vector<int> budgets;
    std::vector<int> indexBits;
    std::vector<std::string> volumeTests;
    std::vector<int> msaa;
    std::vector<bool> perSample;  // per-sample MSAA index lists off/on; used only where MSAA > 0
    std::vector<std::string> msaaSpans{"auto"};  // sphere-span's storage of the samples' surfaces (LIDR, MSAA)
    std::vector<bool> transparency;
    std::vector<bool> tiledDepthBounds;
    // The clustered grids (cartesian, like the rest); the defaults: the library's one grid.
    std::vector<int> clusterTileSizes{0}, clusterSlices{0};
    std::vector<std::string> clusterSlicings{""};
    std::vector<int> clusterOccupancy{-1};
    std::vector<bool> multipassEightBit{false};
    std::vector<bool> deferredStencil{false};
    std::vector<bool> volumeDetail{false};
    std::vector<bool> volumeTiles{true};
    std::vector<int> volumeTileSizes{16};
    std::vector<bool> regionalIndices{true};
    // Dimensions whose list a person typed ("mode", "scheme", "budget", "index width", "volume test",
    // "MSAA", "transparency"): a typed value that no combination can use is an error. Lists left at their
    // defaults and the presets sweep "whatever the library supports" and only list what it refused.
    std::set<std::string> strictDimensions;
    // false: timing only, no forward-brute reference (the light-count sweep: brute force over 16,384 lights
    // takes minutes a frame on llvmpipe); the rows have no error columns.
    bool reference = true;
};

struct Run {
    std::string group;
    std::string scene;
    int width = 0, height = 0;
    ModeConfig config;
    bool reference = true;  // SweepGroup::reference of its group: judged against forward-brute
};

struct Skipped {
    std::string group, scene, label;
    int width = 0, height = 0;
    std::string reason;
};

struct Plan {
    std::vector<Run> runs;        // ordered so each reference (scene, size, MSAA, transparency) is made once
    std::vector<Skipped> skipped; // combinations the library refused, with its reason
};

// The presets: a seconds-long smoke run, and the documented full run (doc/benchmarks.md).
std::vector<SweepGroup> quickPreset();
// fullPreset() includes the scaling sweeps (sweepPreset("lights"), sweepPreset("triangles")).
std::vector<SweepGroup> fullPreset();

// The sweeps, by name (sweepNames()): "lights" (frame time against light count, many-N-fp with N = 64 .. 16384),
// "triangles" (frame time against scene triangles, the room and heavy-T up to 1 M), "hall" and "shadows", each over
// LIDR (bitshift, budgets 4 and 8, volume tests backface and sphere where the library has it), tiled min/max,
// clustered (the default grid) and forward-multipass; and "clusters", the clustered grid's own sweep of tile sizes,
// slice counts, slicings and occupancy on the bench scenes (doc/clustered.md; not part of fullPreset); "peers",
// issue 37's targets: LIDR's default, tiled, clustered, multi-pass and --mode auto on hall-255, city-255, hall-1024
// and many-4096 at 1024x768 (doc/benchmarks.md; not part of fullPreset either). `quick`: a
// seconds-long version (tiny resolution, fewer points) for tests.
std::vector<std::string> sweepNames();
// Throws lidr::Error naming the valid sweeps.
std::vector<SweepGroup> sweepPreset(const std::string& name, bool quick = false);
// The volume tests the scaling sweeps use: backface, and sphere when parseVolumeTest knows it.
std::vector<std::string> sweepVolumeTests();

// Checks every name (scenes, modes, schemes, volume tests) and every combination against the library, on
// the live context, before anything is measured. A combination the library refuses is skipped and listed;
// a value that no combination of its group can use, or a group with no runnable configuration, is a
// lidr::Error that says why and lists what is valid. `scenes` is filled with the loaded scenes.
// `extraLights` (count > 0: lidr-bench --lights N): scattered over every scene after it is loaded.
// `camera` >= 0: every scene's view is its glTF file's camera N (loadBenchScene).
Plan buildPlan(const std::vector<SweepGroup>& groups, const GlInfo& info, uint32_t seed,
               std::map<std::string, Scene>& scenes, const LightScatterOptions& extraLights = {}, int camera = -1);

// "1024x768" -> (1024, 768); "scene" -> (0, 0). Throws lidr::Error.
std::pair<int, int> parseResolution(const std::string& text);

}  // namespace lidr::bench
