#include "bench_config.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <map>
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

namespace {
// "SCENE-shadows-K": SCENE with its K brightest lights that can touch its view casting shadows
// (chooseShadowCasters, lidr/render/shadow_casters.h); renderFrame turns shadows on for it (benchShading).
Scene loadWithShadowCasters(const std::string& name, size_t marker, uint32_t seed, int camera) {
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

Scene makeOverlapScene(const std::string& name, uint32_t seed) {
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

Scene makeHeavySceneByName(const std::string& name, uint32_t seed) {
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

// The built-in scenes by name (room, overlap-K, many-N-*, bart-robots-*, heavy-T, hall-N / city-N, spots-N);
// false for any other name.
bool makeBuiltInScene(const std::string& name, uint32_t seed, Scene& scene) {
    if (name == "room") {
        DefaultSceneOptions o;
        o.seed = seed;
        scene = makeDefaultScene(o);
        return true;
    }
    if (startsWith(name, "overlap-")) {
        scene = makeOverlapScene(name, seed);
        return true;
    }
    if (makeManyLightSceneByName(name, scene, seed)) return true;
    if (makeBartSceneByName(name, scene, seed, benchBartFolder())) return true;
    if (startsWith(name, "heavy-")) {
        scene = makeHeavySceneByName(name, seed);
        return true;
    }
    return makeOccludedSceneByName(name, scene, seed) || makeSpotSceneByName(name, scene, seed);
}

// A scene file ("file:PATH" or a path ending in a known extension); "" for a built-in name.
std::string sceneFilePath(const std::string& name) {
    if (startsWith(name, "file:")) return name.substr(5);
    std::string path;
    for (const char* extension : {".json", ".gltf", ".glb", ".obj", ".aff", ".nff"})
        if (name.size() > std::strlen(extension) && name.compare(name.size() - std::strlen(extension), std::string::npos, extension) == 0)
            path = name;
    return path;
}
}  // namespace

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
    const size_t marker = name.rfind("-shadows-");
    if (marker != std::string::npos && !startsWith(name, "file:")) return loadWithShadowCasters(name, marker, seed, camera);
    const std::string cameraOption = "--camera " + std::to_string(camera) + ": ";
    const std::string path = sceneFilePath(name);
    if (camera >= 0 && path.empty())
        throw Error(cameraOption + "scene '" + name + "' is built in and has no cameras; --camera picks a camera of the "
                    "glTF files in --scenes");
    Scene builtIn;
    if (makeBuiltInScene(name, seed, builtIn)) return builtIn;
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
    const std::string spans = volumeTest == "sphere-span" && msaaSpans != "auto" ? " " + msaaSpans : "";
    if (mode == "lidr" && scheme == "auto")
        return "lidr auto " + volumeTest + spans + (volumeDetail ? " detail" : "") + meshes + global;
    if (mode == "lidr")
        return "lidr " + scheme + " b" + std::to_string(budget) + " " + std::to_string(indexBits) + "-bit " + volumeTest +
               spans + (volumeDetail ? " detail" : "") + meshes;
    if (mode == "tiled") return tiledDepthBounds ? "tiled min/max" : "tiled no-min/max";
    if (mode == "clustered") {
        if (clusterTileSize == 0 && clusterSlices == 0 && clusterSlicing.empty() && clusterOccupancy < 0) return mode;
        const ModeConfig c = withClusterDefaults();
        return "clustered t" + std::to_string(c.clusterTileSize) + " s" + std::to_string(c.clusterSlices) + " " +
               c.clusterSlicing + (c.clusterOccupancy == 1 ? " occupied" : "");
    }
    if (mode == "forward-multipass" && multipassEightBit) return mode + " 8-bit";
    if (mode == "deferred" && deferredStencil) return "deferred-stencil";
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
    o.msaaSpans = parseDepthSpanStorage(c.msaaSpans);
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
    o.deferred.stencil = c.mode == "deferred" && c.deferredStencil;
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

}  // namespace lidr::bench
