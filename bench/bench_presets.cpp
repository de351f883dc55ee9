// lidr-bench's presets: --quick, --full and the named sweeps (--sweep lights, triangles, hall, shadows, clusters,
// peers), as sweep groups (bench_config.h).
#include <map>

#include "bench_config.h"
#include "lidr/base/error.h"
#include "lidr/technique/packing_scheme.h"
#include "lidr/technique/volume_draw_plan.h"

namespace lidr::bench {

namespace {
// The library's schemes and "auto" (bit-shift with the budget and the width chosen per frame).
std::vector<std::string> schemesWithAuto() {
    std::vector<std::string> s = packingSchemeNames();
    s.push_back("auto");
    return s;
}
}  // namespace

std::vector<SweepGroup> quickPreset() {
    SweepGroup g;
    g.name = "quick";
    g.scenes = {"overlap-2", "room"};
    g.resolutions = {{96, 72}};
    g.modes = availableModes();
    g.schemes = schemesWithAuto();
    g.budgets = {1, 4};
    g.indexBits = {8};
    g.volumeTests = {"backface", "frontface"};
    g.msaa = {0};
    g.perSample = {false};
    g.transparency = {false};  // every mode draws the same (forward-multipass draws no transparent meshes)
    g.tiledDepthBounds = {true, false};
    return {g};
}

namespace {
// The full run's default-room groups: every mode, scheme, budget, width and volume test; with transparency; MSAA.
std::vector<SweepGroup> roomPresetGroups() {
    const std::vector<int> budgets{1, 2, 4, 8, 16};
    std::vector<SweepGroup> groups;
    SweepGroup room;  // the targets: every mode, scheme, budget, width and volume test on the default room
    room.name = "room";
    room.scenes = {"room"};
    room.resolutions = {{1024, 768}};
    room.modes = availableModes();
    room.schemes = schemesWithAuto();
    room.budgets = budgets;
    room.indexBits = {8, 16};
    room.volumeTests = {"sphere", "backface", "exact", "frontface"};  // sphere: the default
    room.msaa = {0};
    room.perSample = {false};
    // Opaque first: forward-multipass draws no transparent meshes, so the like-for-like comparison of every
    // mode (the targets) is the opaque one.
    room.transparency = {false};
    room.tiledDepthBounds = {true, false};
    groups.push_back(room);

    SweepGroup roomTransparent = room;  // transparency on: 8-bit only (the width changes no pass)
    roomTransparent.name = "room-transparent";
    roomTransparent.indexBits = {8};
    roomTransparent.transparency = {true};
    groups.push_back(roomTransparent);

    SweepGroup variants = room;  // MSAA 4x, one index list per pixel and per-sample lists, at budget 4
    variants.name = "room-msaa";
    variants.tiledDepthBounds = {true};
    variants.budgets = {4};
    variants.indexBits = {8};
    variants.volumeTests = {"backface", "frontface"};  // back-face needs per-sample lists under MSAA; sphere reads
                                                        // single-sample depth (refused with MSAA)
    // 320x240: brute force with 4x MSAA costs seconds a frame at this size on llvmpipe, shaded per sample
    // four times that; at 1024x768 the two references alone would take minutes.
    variants.resolutions = {{320, 240}};
    variants.msaa = {0, 4};
    variants.perSample = {false, true};  // per-sample index lists where the context has them (GL 3.2)
    variants.transparency = {false};  // opaque: forward-multipass, which draws no glass, is compared too
    groups.push_back(variants);
    return groups;
}

// The full run's other scenes: controlled overlap, many lights, the occluded hall and city, spot lights.
std::vector<SweepGroup> scenePresetGroups() {
    const std::vector<int> budgets{1, 2, 4, 8, 16};
    std::vector<SweepGroup> groups;
    SweepGroup overlap;  // cost and drops against a known overlap
    overlap.name = "overlap";
    overlap.scenes = {"overlap-1", "overlap-2", "overlap-4", "overlap-8", "overlap-16"};
    overlap.resolutions = {{512, 384}};
    overlap.modes = availableModes();
    overlap.schemes = schemesWithAuto();
    overlap.budgets = budgets;
    overlap.indexBits = {4, 8};  // 4-bit holds 15 lights: overlap-1 only (16-bit: the many-light scenes)
    overlap.volumeTests = {"sphere", "backface"};
    overlap.msaa = {0};
    overlap.perSample = {false};
    overlap.transparency = {true};
    overlap.tiledDepthBounds = {true, false};
    groups.push_back(overlap);

    SweepGroup many = overlap;  // many lights: 16-bit indices
    many.name = "many-lights";
    many.scenes = {"many-1024-top", "many-1024-fp", "many-4096-top", "many-4096-fp"};
    many.indexBits = {16};
    many.transparency = {false};  // the room's glass: opaque, so forward-multipass is measured too
    groups.push_back(many);

    SweepGroup occluded;  // deep, occluded scenes (issue 25): the volume pass's cost against its culling
    occluded.name = "occluded";
    occluded.scenes = {"hall-255", "hall-1024", "city-255", "city-1024"};
    occluded.resolutions = {{1024, 768}};
    occluded.modes = availableModes();
    occluded.schemes = {"bitshift", "auto"};
    occluded.budgets = {8, 16};
    occluded.indexBits = {16};  // 1,024 lights; the automatic width narrows where fewer are visible
    occluded.volumeTests = {"sphere"};
    occluded.volumeTiles = {true, false};
    occluded.msaa = {0};
    occluded.perSample = {false};
    occluded.transparency = {false};
    occluded.tiledDepthBounds = {true};
    groups.push_back(occluded);

    SweepGroup spots = occluded;  // spot lights (issue 29): the cone against the same lights as spheres
    spots.name = "spots";
    spots.scenes = {"spots-1024", "spots-1024-points"};
    spots.volumeTests = {"sphere", "exact"};
    spots.volumeTiles = {true};
    groups.push_back(spots);
    return groups;
}
}  // namespace

std::vector<SweepGroup> fullPreset() {
    std::vector<SweepGroup> groups = roomPresetGroups();
    for (const SweepGroup& g : scenePresetGroups()) groups.push_back(g);
    for (const std::string& sweep : sweepNames())
        if (sweep != "clusters" && sweep != "peers")  // the clustered grid's own sweep and the peers': by name
            for (const SweepGroup& g : sweepPreset(sweep)) groups.push_back(g);
    return groups;
}

std::vector<std::string> sweepNames() { return {"lights", "triangles", "hall", "shadows", "clusters", "peers"}; }

std::vector<std::string> sweepVolumeTests() {
    std::vector<std::string> tests{"backface"};
    try {
        parseVolumeTest("sphere");  // a library without the sphere test throws here: the sweeps skip it
        tests.push_back("sphere");
    } catch (const Error&) {
    }
    return tests;
}

namespace {
std::vector<SweepGroup> lightsSweep(const SweepGroup& base, bool quick) {
    std::vector<SweepGroup> groups;
    // One group per light count: 8-bit indices hold 255 lights, past that 16-bit. Timing only: brute
    // force over 16,384 lights takes minutes a frame on llvmpipe.
    const std::vector<int> counts = quick ? std::vector<int>{64, 1024} : std::vector<int>{64, 256, 1024, 4096, 16384};
    for (int n : counts) {
        SweepGroup g = base;
        g.name = "lights";
        g.scenes = {"many-" + std::to_string(n) + "-fp"};
        g.resolutions = {quick ? std::make_pair(64, 48) : std::make_pair(512, 384)};
        g.indexBits = {n > 255 ? 16 : 8};
        g.reference = false;
        groups.push_back(g);
    }
    return groups;
}

std::vector<SweepGroup> trianglesSweep(const SweepGroup& base, bool quick) {
    std::vector<SweepGroup> groups;
    // The room (about 40 k triangles) and heavy-T: the same 255 lights, camera and draw calls as the
    // room plus a fixed set of spheres tessellated ever finer.
    SweepGroup g = base;
    g.name = "triangles";
    g.scenes = quick ? std::vector<std::string>{"room", "heavy-100k"}
                     : std::vector<std::string>{"room", "heavy-100k", "heavy-250k", "heavy-500k", "heavy-1m"};
    g.resolutions = {quick ? std::make_pair(64, 48) : std::make_pair(512, 384)};
    g.indexBits = {8};
    groups.push_back(g);
    return groups;
}

std::vector<SweepGroup> hallSweep(const SweepGroup& base, bool quick) {
    std::vector<SweepGroup> groups;
    // The occluded hall against its light count: LIDR's volume pass against tiled forward's per-tile lists.
    const std::vector<int> counts = quick ? std::vector<int>{64, 1024} : std::vector<int>{64, 256, 1024, 4096};
    for (int n : counts) {
        SweepGroup g = base;
        g.name = "hall";
        g.scenes = {"hall-" + std::to_string(n)};
        g.resolutions = {quick ? std::make_pair(64, 48) : std::make_pair(512, 384)};
        g.indexBits = {n > 255 ? 16 : 8};
        g.reference = false;
        groups.push_back(g);
    }
    return groups;
}

std::vector<SweepGroup> shadowsSweep(const SweepGroup& base, bool quick) {
    std::vector<SweepGroup> groups;
    // Shadow-casting lights among 255 and 1,024 in the hall (issue 30; doc/shadows.md): the cost of the maps
    // (first frame) and of the lookups (every frame), per mode. Timing only, as the hall sweep.
    const std::vector<int> counts = quick ? std::vector<int>{255} : std::vector<int>{255, 1024};
    const std::vector<int> casters = quick ? std::vector<int>{0, 8} : std::vector<int>{0, 8, 32, 128};
    for (int n : counts) {
        SweepGroup g = base;
        g.name = "shadows";
        for (int k : casters) g.scenes.push_back("hall-" + std::to_string(n) + "-shadows-" + std::to_string(k));
        g.resolutions = {quick ? std::make_pair(64, 48) : std::make_pair(512, 384)};
        g.schemes = {"auto"};
        g.volumeTests = {"sphere"};
        g.indexBits = {n > 255 ? 16 : 8};
        g.reference = false;
        groups.push_back(g);
    }
    return groups;
}

std::vector<SweepGroup> clustersSweep(const SweepGroup& base, bool quick) {
    std::vector<SweepGroup> groups;
    // The clustered grid against the bench scenes (doc/clustered.md, "Sweep"): tile sizes x slice counts x both
    // slicings over the dense grid, and the occupied-cluster step at the middle sizes; tiled forward (min/max)
    // and LIDR's default beside them. Every clustered row is judged against the reference and the CPU truth.
    SweepGroup grids = base;
    grids.name = "clusters";
    grids.scenes = quick ? std::vector<std::string>{"hall-64"}
                         : std::vector<std::string>{"room", "hall-255", "hall-1024", "city-255", "many-4096-top"};
    grids.resolutions = {quick ? std::make_pair(96, 72) : std::make_pair(1024, 768)};
    grids.modes = {"clustered", "tiled", "lidr"};
    grids.schemes = {"auto"};
    grids.volumeTests = {"sphere"};
    grids.indexBits = {16};
    grids.clusterTileSizes = quick ? std::vector<int>{16, 32} : std::vector<int>{16, 32, 64};
    grids.clusterSlices = quick ? std::vector<int>{8, 16} : std::vector<int>{8, 16, 32, 64};
    grids.clusterSlicings = {"exponential", "near-slice"};
    grids.clusterOccupancy = {0};
    groups.push_back(grids);
    SweepGroup occupied = grids;
    occupied.modes = {"clustered"};
    occupied.clusterSlices = quick ? std::vector<int>{16} : std::vector<int>{16, 32};
    occupied.clusterSlicings = {"exponential"};
    occupied.clusterOccupancy = {1};
    groups.push_back(occupied);
    return groups;
}

std::vector<SweepGroup> peersSweep(const SweepGroup& base, bool quick) {
    std::vector<SweepGroup> groups;
    // Issue 37's best-peer targets (bench_peer_targets.cpp): LIDR's default configuration against tiled forward
    // (min/max), clustered forward (its default grid), multi-pass, deferred (with and without the stencil test),
    // tiled deferred and --mode auto in the same interleaved rounds,
    // opaque (every mode draws the same), on the deep scenes and the many-light ones at 1024x768, against the
    // reference.
    SweepGroup g = base;
    g.name = "peers";
    g.scenes = quick ? std::vector<std::string>{"hall-64"}
                     : std::vector<std::string>{"hall-255", "city-255", "hall-1024", "many-4096-top", "many-4096-fp"};
    g.resolutions = {quick ? std::make_pair(96, 72) : std::make_pair(1024, 768)};
    // The deferred modes (doc/deferred.md): deferred with and without the stencil test, tiled deferred.
    for (const std::string& have : availableModes())
        if (have == "auto" || have == "deferred" || have == "tiled-deferred") g.modes.push_back(have);
    g.deferredStencil = {false, true};
    g.schemes = {"auto"};
    g.volumeTests = {"sphere"};
    g.indexBits = {16};
    groups.push_back(g);
    // Issue 43: the same modes under MSAA 4x, transparency off and on (multi-pass draws no transparent mesh:
    // it has the opaque rows only), on the MSAA targets' scenes.
    SweepGroup msaa = g;
    msaa.scenes = quick ? std::vector<std::string>{"hall-64"}
                        : std::vector<std::string>{"hall-255", "room", "hall-1024", "city-255"};
    msaa.msaa = {4};
    msaa.transparency = {false, true};
    groups.push_back(msaa);
    if (quick) return groups;
    // Issue 45: where the papers say LIDR or deferred should win: transparency without MSAA (deferred draws its
    // transparent meshes forward), 64 shadowed lights (every mode reads the same atlas), and 1920x1080 (more pixels
    // per light: the G-buffer's bandwidth against LIDR's second geometry pass).
    SweepGroup transparent = g;
    transparent.scenes = {"hall-255", "room"};
    transparent.transparency = {true};
    groups.push_back(transparent);
    SweepGroup shadowed = g;
    shadowed.scenes = {"hall-255-shadows-64"};
    groups.push_back(shadowed);
    SweepGroup large = g;
    large.scenes = {"hall-255", "hall-1024"};
    large.resolutions = {std::make_pair(1920, 1080)};
    groups.push_back(large);
    SweepGroup largeMsaa = msaa;
    largeMsaa.scenes = {"hall-255"};
    largeMsaa.resolutions = {std::make_pair(1920, 1080)};
    largeMsaa.transparency = {true};
    groups.push_back(largeMsaa);
    return groups;
}

using SweepMaker = std::vector<SweepGroup> (*)(const SweepGroup& base, bool quick);
// The sweeps by name (sweepNames()), each a function of the base group and --quick.
const std::map<std::string, SweepMaker>& sweepMakers() {
    static const std::map<std::string, SweepMaker> makers = {
        {"lights", lightsSweep}, {"triangles", trianglesSweep}, {"hall", hallSweep},
        {"shadows", shadowsSweep}, {"clusters", clustersSweep}, {"peers", peersSweep}};
    return makers;
}

// What every sweep starts from: the modes the library has among LIDR, tiled, clustered and multi-pass, opaque.
SweepGroup sweepBase() {
    SweepGroup base;
    base.modes.clear();
    for (const char* m : {"lidr", "tiled", "clustered", "forward-multipass"})  // those the library has, in this order
        for (const std::string& have : availableModes())
            if (have == m) base.modes.push_back(have);
    base.schemes = {"bitshift", "auto"};
    base.budgets = {4, 8};
    base.volumeTests = sweepVolumeTests();
    base.msaa = {0};
    base.perSample = {false};
    base.transparency = {false};  // forward-multipass draws no transparent meshes: all modes draw the same
    base.tiledDepthBounds = {true};
    return base;
}
}  // namespace

std::vector<SweepGroup> sweepPreset(const std::string& name, bool quick) {
    const auto maker = sweepMakers().find(name);
    if (maker == sweepMakers().end())
        throw Error("unknown sweep '" + name + "' (valid: " + joinNames(sweepNames()) + ")");
    return maker->second(sweepBase(), quick);
}

}  // namespace lidr::bench
