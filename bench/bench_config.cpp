#include "bench_config.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <set>

#include "lidr/eval/bench_scenes.h"
#include "lidr/scene/default_scene.h"
#include "lidr/base/error.h"
#include "lidr/gl/render_targets.h"
#include "lidr/technique/lidr_renderer.h"
#include "lidr/technique/packing_scheme.h"
#include "lidr/scene/primitives.h"
#include "lidr/modes/reference_renderer.h"
#include "lidr/scene/io/bart_scene.h"
#include "lidr/scene/io/scene_loader.h"
#include "lidr/eval/controlled_scenes.h"

// The render-mode factory (lidr/modes/render_mode.h) builds every mode the library has. Until it exists, the
// bench builds the two modes it can name itself.
#if __has_include("lidr/modes/render_mode.h")
#include "lidr/modes/render_mode.h"
#include "lidr/render/shadow_casters.h"
#define LIDR_BENCH_HAS_MODE_FACTORY 1
#else
#define LIDR_BENCH_HAS_MODE_FACTORY 0
#endif

namespace lidr::bench {

namespace {

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// Parses the whole string as a positive int, or returns -1.
int positiveInt(const std::string& s) {
    if (s.empty() || s.size() > 9 || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return -1;
    const int v = std::stoi(s);
    return v > 0 ? v : -1;
}

}  // namespace

std::string joinNames(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

// ---- scenes ---------------------------------------------------------------------------------------------

std::string& benchBartFolder() {
    static std::string folder;
    return folder;
}

std::string sceneNameHelp() {
    return "room (default room, 255 lights), overlap-K (every lit pixel covered by exactly K lights, K >= 1), "
           "many-N-top / many-N-fp (N lights, 4..65535, top-down / first-person), heavy-T (the room with about T "
           "triangles, e.g. heavy-250k, heavy-1m), hall-N / city-N (deep, occluded scenes: a pillared hall and a city "
           "block grid with N lights of 1-4 m, e.g. hall-255), spots-N / spots-N-points (many-N-top with the particles "
           "as spot lights aimed down, or the same lights as points), file:PATH or a path ending in .json, .gltf, .glb "
           "or .obj, a BART scene (.aff: its own lights), bart-robots-many / bart-robots-few (BART's Robots with the "
           "Tiled Shading paper's 924 static lights or one light on each robot, from --bart; doc/bart.md); any of them "
           "with -shadows-K (its K brightest lights that can touch the view cast shadows, e.g. "
           "hall-255-shadows-32; doc/shadows.md), and then with +environment (lit by the built-in studio "
           "environment too, e.g. hall-255+environment; --environment none,default runs each scene both ways)";
}

Scene loadBenchScene(const std::string& name, uint32_t seed, int camera) {
    // "SCENE+environment": SCENE lit by the built-in environment too (issue 39), its ambient and lights as they are.
    const std::string withEnvironment = "+environment";
    if (name.size() > withEnvironment.size() &&
        name.compare(name.size() - withEnvironment.size(), withEnvironment.size(), withEnvironment) == 0 &&
        !startsWith(name, "file:")) {
        Scene scene = loadBenchScene(name.substr(0, name.size() - withEnvironment.size()), seed, camera);
        scene.environment = defaultEnvironment();
        scene.name = name;
        return scene;
    }
    // "SCENE-shadows-K": SCENE with its K brightest lights that can touch its view casting shadows
    // (chooseShadowCasters, lidr/render/shadow_casters.h); renderFrame turns shadows on for it (benchShading).
    const size_t marker = name.rfind("-shadows-");
    if (marker != std::string::npos && !startsWith(name, "file:")) {
        const std::string countText = name.substr(marker + 9);
        const int k = countText == "0" ? 0 : positiveInt(countText);
        if (k < 0)
            throw Error("bad scene name '" + name + "': SCENE-shadows-K needs a whole number K >= 0 of shadow casters "
                        "(valid: " + sceneNameHelp() + ")");
        Scene scene = loadBenchScene(name.substr(0, marker), seed, camera);
        const int chosen = chooseShadowCasters(scene.lights, cameraMatrices(scene.camera, scene.width, scene.height), k);
        if (chosen < k)
            throw Error("scene '" + name + "': only " + std::to_string(chosen) + " of its " +
                        std::to_string(scene.lights.size()) + " lights can cast shadows into its view, " +
                        std::to_string(k) + " asked for");
        scene.name = name;
        return scene;
    }
    const std::string cameraOption = "--camera " + std::to_string(camera) + ": ";
    std::string path;
    if (startsWith(name, "file:"))
        path = name.substr(5);
    else
        for (const char* extension : {".json", ".gltf", ".glb", ".obj", ".aff", ".nff"})
            if (name.size() > std::strlen(extension) && name.compare(name.size() - std::strlen(extension), std::string::npos, extension) == 0)
                path = name;
    if (camera >= 0 && path.empty())
        throw Error(cameraOption + "scene '" + name + "' is built in and has no cameras; --camera picks a camera of the "
                    "glTF files in --scenes");
    if (name == "room") {
        DefaultSceneOptions o;
        o.seed = seed;
        return makeDefaultScene(o);
    }
    if (startsWith(name, "overlap-")) {
        const int k = positiveInt(name.substr(8));
        if (k < 1) throw Error("bad scene name '" + name + "': overlap-K needs a positive K (valid: " + sceneNameHelp() + ")");
        ControlledOverlapOptions o;
        o.overlap = k;
        o.clusters = 9;
        o.maxLights = 9 * k <= 255 ? 255 : 65535;  // 9 clusters of k lights, within 8-bit indices up to k = 28
        o.width = 1024;
        o.height = 768;
        o.seed = seed;
        return makeControlledOverlapScene(o);
    }
    Scene many;
    if (makeManyLightSceneByName(name, many, seed)) return many;
    if (makeBartSceneByName(name, many, seed, benchBartFolder())) return many;
    if (startsWith(name, "heavy-")) {
        std::string t = name.substr(6);
        long scale = 1;
        if (!t.empty() && (t.back() == 'k' || t.back() == 'm')) {
            scale = t.back() == 'k' ? 1000 : 1000000;
            t.pop_back();
        }
        const int n = positiveInt(t);
        if (n < 1 || long(n) * scale > 20000000)
            throw Error("bad scene name '" + name + "': use heavy-T with T triangles, 1..20m, e.g. heavy-250k (valid: " +
                        sceneNameHelp() + ")");
        return makeHeavyScene(long(n) * scale, 1024, 768, seed);
    }
    Scene occluded;
    if (makeOccludedSceneByName(name, occluded, seed)) return occluded;
    if (makeSpotSceneByName(name, occluded, seed)) return occluded;
    if (path.empty()) throw Error("unknown scene '" + name + "' (valid: " + sceneNameHelp() + ")");
    if (!std::filesystem::exists(path)) throw Error("scene file '" + path + "' does not exist");
    Scene scene = loadScene(path);
    if (camera >= 0) {
        try {
            chooseView(scene, camera);
            scene.validate();
        } catch (const Error& e) {
            throw Error(cameraOption + "scene '" + name + "': " + e.what());
        }
    }
    return scene;
}

// ---- configurations -------------------------------------------------------------------------------------

std::string ModeConfig::label() const {
    const std::string meshes = volumeTest != "sphere" ? ""
                               : !volumeTiles          ? " meshes"
                               : volumeTileSize != 16  ? " tiles" + std::to_string(volumeTileSize)
                                                       : "";
    const std::string global = volumeTest == "sphere" && volumeTiles && !regionalIndices ? " global-indices" : "";
    if (mode == "lidr" && scheme == "auto") return "lidr auto " + volumeTest + (volumeDetail ? " detail" : "") + meshes + global;
    if (mode == "lidr")
        return "lidr " + scheme + " b" + std::to_string(budget) + " " + std::to_string(indexBits) + "-bit " + volumeTest +
               (volumeDetail ? " detail" : "") + meshes;
    if (mode == "tiled") return tiledDepthBounds ? "tiled min/max" : "tiled no-min/max";
    if (mode == "clustered") {
        if (clusterTileSize == 0 && clusterSlices == 0 && clusterSlicing.empty() && clusterOccupancy < 0) return mode;
        const ModeConfig c = withClusterDefaults();
        return "clustered t" + std::to_string(c.clusterTileSize) + " s" + std::to_string(c.clusterSlices) + " " +
               c.clusterSlicing + (c.clusterOccupancy == 1 ? " occupied" : "");
    }
    if (mode == "forward-multipass" && multipassEightBit) return mode + " 8-bit";
    return mode;
}

ModeConfig ModeConfig::withClusterDefaults() const {
    const ClusteredOptions defaults;
    ModeConfig c = *this;
    if (c.clusterTileSize == 0) c.clusterTileSize = defaults.tileSize;
    if (c.clusterSlices == 0) c.clusterSlices = defaults.slices;
    if (c.clusterSlicing.empty()) c.clusterSlicing = clusterSlicingName(defaults.slicing);
    if (c.clusterOccupancy < 0) c.clusterOccupancy = defaults.occupiedClusters ? 1 : 0;
    return c;
}

std::string ModeConfig::key() const {
    return label() + (msaa > 0 ? " msaa" + std::to_string(msaa) + (perSample ? " per-sample" : "") : "") +
           (transparency ? "" : " opaque");
}

ModeConfig referenceConfigFor(const ModeConfig& config) {
    ModeConfig r;
    r.mode = "forward-brute";
    r.msaa = config.msaa;
    r.perSample = config.perSample;
    r.transparency = config.transparency;
    return r;
}

std::vector<std::string> availableModes() {
#if LIDR_BENCH_HAS_MODE_FACTORY
    return renderModeNames();
#else
    return {"lidr", "forward-brute"};
#endif
}

namespace {

LidrOptions lidrOptionsFor(const ModeConfig& c) {
    LidrOptions o;
    o.packing.scheme = parsePackingScheme(c.scheme);
    o.packing.budget = c.budget;
    o.packing.indexBits = c.indexBits;
    o.volumeTest = parseVolumeTest(c.volumeTest);
    o.volumeDetail = c.volumeDetail;
    o.tileCulledVolumes = c.volumeTiles;
    o.volumeTileSize = c.volumeTileSize;
    o.regionalIndices = c.regionalIndices;
    o.msaaSamples = c.msaa;
    o.perSampleIndices = c.perSample;
    o.transparency = c.transparency;
    return o;
}

}  // namespace

namespace {
std::unique_ptr<Renderer> createUntimedRenderer(const ModeConfig& c, const GlInfo& info, const Scene& scene, int width,
                                                int height);
}

// Every renderer the bench measures times each frame's own passes (waiting for GPU queries).
std::unique_ptr<Renderer> createBenchRenderer(const ModeConfig& c, const GlInfo& info, const Scene& scene, int width,
                                              int height) {
    std::unique_ptr<Renderer> r = createUntimedRenderer(c, info, scene, width, height);
    r->setTiming(true, true);
    return r;
}

namespace {
std::unique_ptr<Renderer> createUntimedRenderer(const ModeConfig& c, const GlInfo& info, const Scene& scene, int width,
                                                int height) {
    if (c.perSample && c.mode == "forward-brute")  // the factory has no per-sample shading for the reference
        return std::make_unique<ReferenceRenderer>(info, scene, width, height,
                                                   std::max<int>(1, int(scene.lights.size())), false, c.msaa,
                                                   c.transparency, true);
    if (c.perSample && c.mode != "lidr") throw UnsupportedError("per-sample index lists are LIDR's; " + c.mode + " has none");
#if LIDR_BENCH_HAS_MODE_FACTORY
    // What the factory's options cannot express is refused here, so no row claims a setting it did not use.
    const bool sceneHasTransparency = std::any_of(scene.materials.begin(), scene.materials.end(),
                                                  [](const Material& m) { return m.opacity < 1.0f; });
    if (c.mode == "forward-multipass" && c.transparency && sceneHasTransparency)
        throw UnsupportedError("forward-multipass does not draw transparent meshes (additive light passes cannot "
                               "alpha-blend); measure it with transparency off");
    RenderModeOptions o;
    o.mode = c.mode;
    if (c.mode == "lidr") o.lidr = lidrOptionsFor(c);
    // Only the tiled rows choose their depth bounds; `auto` runs its tiled candidate with the library's default
    // (min/max on), as lidr-demo --mode auto does: with ModeConfig's `false` it timed a slower tiled than the
    // tiled rows and kept LIDR where they put tiled ahead (city-255).
    if (c.mode == "tiled") o.tiled.depthBounds = c.tiledDepthBounds;
    if (c.clusterTileSize) o.clustered.tileSize = c.clusterTileSize;
    if (c.clusterSlices) o.clustered.slices = c.clusterSlices;
    if (!c.clusterSlicing.empty()) o.clustered.slicing = parseClusterSlicing(c.clusterSlicing);
    if (c.clusterOccupancy >= 0) o.clustered.occupiedClusters = c.clusterOccupancy == 1;
    o.multipass.halfFloatAccumulation = !(c.mode == "forward-multipass" && c.multipassEightBit);
    o.msaaSamples = c.msaa;
    o.transparency = c.transparency;
    return createRenderer(o, info, scene, width, height);
#else
    if (c.mode == "forward-brute")
        return std::make_unique<ReferenceRenderer>(info, scene, width, height,
                                                   std::max<int>(1, int(scene.lights.size())), false, c.msaa,
                                                   c.transparency);
    if (c.mode == "lidr") return std::make_unique<LidrRenderer>(info, scene, lidrOptionsFor(c), width, height);
    throw Error("unknown render mode '" + c.mode + "' (valid: " + joinNames(availableModes()) +
                "; this build's library has no render-mode factory yet)");
#endif
}
}  // namespace

// ---- sweeps ---------------------------------------------------------------------------------------------

std::pair<int, int> parseResolution(const std::string& text) {
    if (text == "scene") return {0, 0};
    const size_t x = text.find('x');
    const int w = x == std::string::npos ? -1 : positiveInt(text.substr(0, x));
    const int h = x == std::string::npos ? -1 : positiveInt(text.substr(x + 1));
    if (w < 1 || h < 1) throw Error("bad resolution '" + text + "' (use WIDTHxHEIGHT, e.g. 1024x768, or 'scene')");
    return {w, h};
}

// The library's schemes and "auto" (bit-shift with the budget and the width chosen per frame).
std::vector<std::string> schemesWithAuto() {
    std::vector<std::string> s = packingSchemeNames();
    s.push_back("auto");
    return s;
}

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

std::vector<SweepGroup> fullPreset() {
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

std::vector<SweepGroup> sweepPreset(const std::string& name, bool quick) {
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
    std::vector<SweepGroup> groups;
    if (name == "lights") {
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
    if (name == "triangles") {
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
    if (name == "hall") {
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
    if (name == "shadows") {
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
    if (name == "clusters") {
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
    if (name == "peers") {
        // Issue 37's best-peer targets (bench_peer_targets.cpp): LIDR's default configuration against tiled forward
        // (min/max), clustered forward (its default grid), multi-pass and --mode auto in the same interleaved rounds,
        // opaque (every mode draws the same), on the deep scenes and the many-light ones at 1024x768, against the
        // reference.
        SweepGroup g = base;
        g.name = "peers";
        g.scenes = quick ? std::vector<std::string>{"hall-64"}
                         : std::vector<std::string>{"hall-255", "city-255", "hall-1024", "many-4096-top", "many-4096-fp"};
        g.resolutions = {quick ? std::make_pair(96, 72) : std::make_pair(1024, 768)};
        for (const std::string& have : availableModes())
            if (have == "auto") g.modes.push_back(have);
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
        return groups;
    }
    throw Error("unknown sweep '" + name + "' (valid: " + joinNames(sweepNames()) + ")");
}

namespace {

std::string refKey(const std::string& scene, int w, int h, const ModeConfig& c) {
    return scene + "|" + std::to_string(w) + "x" + std::to_string(h) + "|" + referenceConfigFor(c).key();
}

// A small stand-in for `scene` with the same lights, materials and camera: building a renderer for it runs
// every check the mode's constructor makes (scheme x budget x width x light count, MSAA, volume test,
// resolution) without uploading the real geometry.
Scene probeSceneFor(const Scene& scene) {
    Scene probe;
    probe.name = scene.name + "-probe";
    probe.materials = scene.materials;
    for (size_t m = 0; m < scene.materials.size(); ++m)
        addPlane(probe, glm::vec3(0.0f, 0.01f * float(m), 0.0f), glm::vec2(1.0f), int(m));
    probe.lights = scene.lights;
    probe.lightPaths = scene.lightPaths;
    probe.camera = scene.camera;
    probe.width = scene.width;
    probe.height = scene.height;
    return probe;
}

template <typename T>
std::string str(const T& v) {
    if constexpr (std::is_same_v<T, bool>)
        return v ? "on" : "off";
    else if constexpr (std::is_same_v<T, std::string>)
        return v;
    else
        return std::to_string(v);
}

}  // namespace

Plan buildPlan(const std::vector<SweepGroup>& groups, const GlInfo& info, uint32_t seed,
               std::map<std::string, Scene>& scenes, const LightScatterOptions& extraLights, int camera) {
    const std::vector<std::string> modes = availableModes();
    const std::vector<std::string> schemes = packingSchemeNames();
    // Names first: every unknown name is reported before any probing.
    for (const SweepGroup& g : groups) {
        if (g.scenes.empty() || g.modes.empty() || g.resolutions.empty())
            throw Error("sweep '" + g.name + "' needs at least one scene, mode and resolution");
        for (const std::string& m : g.modes)
            if (std::find(modes.begin(), modes.end(), m) == modes.end())
                throw Error("unknown render mode '" + m + "' (valid: " + joinNames(modes) + ")");
        for (const std::string& s : g.schemes)
            if (s != "auto" && std::find(schemes.begin(), schemes.end(), s) == schemes.end())
                throw Error("unknown packing scheme '" + s + "' (valid: auto, " + joinNames(schemes) + ")");
        for (const std::string& v : g.volumeTests) parseVolumeTest(v);  // throws naming the valid ones
        for (int b : g.budgets)
            if (b < 1) throw Error("budget must be >= 1, got " + std::to_string(b));
        for (int b : g.indexBits)
            if (b < 1) throw Error("index width must be >= 1 bit, got " + std::to_string(b));
        for (int s : g.msaa)
            if (s < 0) throw Error("MSAA samples must be >= 0, got " + std::to_string(s));
        for (const std::string& name : g.scenes)
            if (!scenes.count(name)) {
                Scene scene = loadBenchScene(name, seed, camera);
                if (extraLights.count > 0) {
                    LightScatterOptions scatter = extraLights;
                    scatter.seed = seed;
                    addScatteredLights(scene, scatter);  // throws naming the limit for too many lights
                    scene.validate();
                }
                scenes.emplace(name, std::move(scene));
            }
    }

    Plan plan;
    std::set<std::string> seen;
    std::map<std::string, std::string> probeResults;  // probe key -> "" (ok) or the library's reason
    std::map<std::string, Scene> probes;
    for (const SweepGroup& g : groups) {
        // For each value of each dimension: did any combination in this group accept it, and if not, why.
        // (dimension, value) -> "" when some combination used it, else the library's last reason.
        std::map<std::pair<std::string, std::string>, std::string> valueUse;
        auto note = [&](const std::string& dimension, const std::string& v, const std::string& reason) {
            const auto value = std::make_pair(dimension, v);
            auto it = valueUse.find(value);
            if (it == valueUse.end())
                valueUse[value] = reason;
            else if (!it->second.empty())
                it->second = reason;
        };
        size_t groupRuns = 0;
        for (const std::string& sceneName : g.scenes) {
            const Scene& scene = scenes.at(sceneName);
            if (!probes.count(sceneName)) probes.emplace(sceneName, probeSceneFor(scene));
            for (auto [w, h] : g.resolutions) {
                if (w == 0) std::tie(w, h) = std::make_pair(scene.width, scene.height);
                std::vector<ModeConfig> configs;
                for (const std::string& mode : g.modes) {
                    ModeConfig base;
                    base.mode = mode;
                    for (int msaa : g.msaa)
                      for (bool perSample : g.perSample)
                        for (bool transparency : g.transparency) {
                            // Per-sample lists exist only with MSAA, and only in LIDR (and its reference).
                            if (perSample && (msaa == 0 || (mode != "lidr" && mode != "forward-brute"))) continue;
                            base.msaa = msaa;
                            base.perSample = perSample;
                            base.transparency = transparency;
                            if (mode == "lidr") {
                                for (const auto& scheme : g.schemes)
                                    // "auto" chooses its budget and width per frame: one configuration.
                                    for (int budget : scheme == "auto" ? std::vector<int>{0} : g.budgets)
                                        for (int bits : scheme == "auto" ? std::vector<int>{0} : g.indexBits)
                                            for (const auto& vt : g.volumeTests)
                                                for (bool detail : g.volumeDetail)
                                                    for (bool tiles : g.volumeTiles)
                                                    for (int tileSize : g.volumeTileSizes)
                                                    for (bool regional : g.regionalIndices) {
                                                        ModeConfig c = base;
                                                        c.regionalIndices = regional;
                                                        c.scheme = scheme;
                                                        c.budget = budget;
                                                        c.indexBits = bits;
                                                        c.volumeTest = volumeTestName(parseVolumeTest(vt));
                                                        c.volumeDetail = detail;
                                                        c.volumeTiles = tiles;
                                                        c.volumeTileSize = tileSize;
                                                        // Only the sphere test culls by tiles: one row for the
                                                        // others, and one without tiles.
                                                        if (!tiles && c.volumeTest != "sphere") continue;
                                                        if ((!tiles || c.volumeTest != "sphere") &&
                                                            tileSize != g.volumeTileSizes.front())
                                                            continue;
                                                        // Regions need tiles and the automatic width.
                                                        if ((!tiles || c.volumeTest != "sphere" || scheme != "auto") &&
                                                            regional != g.regionalIndices.front())
                                                            continue;
                                                        configs.push_back(c);
                                                    }
                            } else if (mode == "tiled") {
                                for (bool db : g.tiledDepthBounds) {
                                    ModeConfig c = base;
                                    c.tiledDepthBounds = db;
                                    configs.push_back(c);
                                }
                            } else if (mode == "clustered") {
                                for (int tile : g.clusterTileSizes)
                                    for (int slices : g.clusterSlices)
                                        for (const std::string& slicing : g.clusterSlicings)
                                            for (int occupancy : g.clusterOccupancy) {
                                                ModeConfig c = base;
                                                c.clusterTileSize = tile;
                                                c.clusterSlices = slices;
                                                c.clusterSlicing = slicing;
                                                c.clusterOccupancy = occupancy;
                                                configs.push_back(c);
                                            }
                            } else if (mode == "forward-multipass") {
                                for (bool eightBit : g.multipassEightBit) {
                                    ModeConfig c = base;
                                    c.multipassEightBit = eightBit;
                                    configs.push_back(c);
                                }
                            } else {
                                configs.push_back(base);
                            }
                        }
                }
                for (const ModeConfig& c : configs) {
                    const std::string probeKey = sceneName + "|" + std::to_string(w) + "x" + std::to_string(h) + "|" + c.key();
                    if (!probeResults.count(probeKey)) {
                        // Before the probe allocates anything: an oversized configuration is an error, not a skip.
                        const bool lidr = c.mode == "lidr";
                        const bool autoLidr = lidr && c.scheme == "auto";  // at most budget 16, 16-bit
                        checkRenderTargetMemory(w, h, c.msaa,
                                                lidr ? indexBytesPerPixel(autoLidr ? 16 : c.budget, autoLidr ? 16 : c.indexBits) : 0,
                                                lidr && c.perSample);
                        std::string reason;
                        try {
                            createBenchRenderer(c, info, probes.at(sceneName), w, h);
                        } catch (const GlError&) {
                            throw;  // a GL failure is a bug to see, not a combination to skip
                        } catch (const Error& e) {
                            reason = e.what();
                            if (reason.empty()) reason = "refused";
                        }
                        probeResults[probeKey] = reason;
                    }
                    const std::string& reason = probeResults[probeKey];
                    note("mode", c.mode, reason);
                    note("MSAA", str(c.msaa), reason);
                    if (c.msaa > 0) note("per-sample", str(c.perSample), reason);
                    note("transparency", str(c.transparency), reason);
                    if (c.mode == "lidr") {
                        note("scheme", c.scheme, reason);
                        if (c.scheme != "auto") {
                            note("budget", str(c.budget), reason);
                            note("index width", str(c.indexBits), reason);
                        }
                        note("volume test", c.volumeTest, reason);
                    }
                    if (!reason.empty()) {
                        plan.skipped.push_back({g.name, sceneName, c.key(), w, h, reason});
                        continue;
                    }
                    ++groupRuns;
                    Run run{g.name, sceneName, w, h, c, g.reference};
                    if (seen.insert(sceneName + "|" + std::to_string(w) + "x" + std::to_string(h) + "|" + c.key()).second)
                        plan.runs.push_back(run);
                }
            }
        }
        if (groupRuns == 0) {
            std::set<std::string> reasons;
            for (const Skipped& s : plan.skipped)
                if (s.group == g.name) reasons.insert(s.reason);
            std::string all;
            for (const auto& r : reasons) all += "\n  " + r;
            throw Error("sweep '" + g.name + "' has no configuration the library can run:" + all);
        }
        for (const auto& [value, reason] : valueUse)
            if (g.strictDimensions.count(value.first) && !reason.empty())
                throw Error("sweep '" + g.name + "': " + value.first + " " + value.second +
                            " works with none of the other settings asked for: " + reason);
    }
    // Group runs by reference (scene, size, MSAA, transparency), first appearance first, forward-brute first
    // within each: the reference is rendered once and its frames time forward-brute.
    std::map<std::string, size_t> firstSeen;
    for (const Run& r : plan.runs) firstSeen.emplace(refKey(r.scene, r.width, r.height, r.config), firstSeen.size());
    std::stable_sort(plan.runs.begin(), plan.runs.end(), [&](const Run& a, const Run& b) {
        const size_t ka = firstSeen.at(refKey(a.scene, a.width, a.height, a.config));
        const size_t kb = firstSeen.at(refKey(b.scene, b.width, b.height, b.config));
        if (ka != kb) return ka < kb;
        return (a.config.mode == "forward-brute") > (b.config.mode == "forward-brute");
    });
    return plan;
}

}  // namespace lidr::bench
