// buildPlan: lidr-bench's sweep groups expanded into runs, each combination probed on the live context (the mode's
// constructor runs every check it makes on a small stand-in scene), refused ones skipped with the library's reason.
#include <algorithm>
#include <set>

#include "bench_config.h"
#include "lidr/base/error.h"
#include "lidr/gl/render_targets.h"
#include "lidr/scene/primitives.h"
#include "lidr/technique/lidr_renderer.h"
#include "lidr/technique/packing_scheme.h"
#include "lidr/technique/volume_draw_plan.h"

namespace lidr::bench {

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


// Every name a group gives is checked before any probing, and its scenes are loaded (with --lights scattered).
void checkNamesAndLoadScenes(const std::vector<SweepGroup>& groups, uint32_t seed, std::map<std::string, Scene>& scenes,
                             const LightScatterOptions& extraLights, int camera) {
    const std::vector<std::string> modes = availableModes();
    const std::vector<std::string> schemes = packingSchemeNames();
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
}

// ---- each mode's own dimensions: one expander per mode with any (a mode without one is its base configuration)
using Configs = std::vector<ModeConfig>;

void lidrConfigs(const SweepGroup& g, const ModeConfig& base, Configs& configs) {
    for (const auto& scheme : g.schemes)
        // "auto" chooses its budget and width per frame: one configuration.
        for (int budget : scheme == "auto" ? std::vector<int>{0} : g.budgets)
            for (int bits : scheme == "auto" ? std::vector<int>{0} : g.indexBits)
                for (const auto& vt : g.volumeTests)
                    for (bool detail : g.volumeDetail)
                        for (bool tiles : g.volumeTiles)
                            for (int tileSize : g.volumeTileSizes)
                                for (bool regional : g.regionalIndices)
                                  for (const std::string& spans : g.msaaSpans) {
                                    ModeConfig c = base;
                                    c.msaaSpans = spans;
                                    c.regionalIndices = regional;
                                    c.scheme = scheme;
                                    c.budget = budget;
                                    c.indexBits = bits;
                                    c.volumeTest = volumeTestName(parseVolumeTest(vt));
                                    c.volumeDetail = detail;
                                    c.volumeTiles = tiles;
                                    c.volumeTileSize = tileSize;
                                    // Only the sphere test culls by tiles: one row for the others, and one
                                    // without tiles.
                                    const bool sphereTiles = tiles && c.volumeTest == "sphere";
                                    if (!tiles && c.volumeTest != "sphere") continue;
                                    if (!sphereTiles && tileSize != g.volumeTileSizes.front()) continue;
                                    // Regions need tiles and the automatic width.
                                    if ((!sphereTiles || scheme != "auto") && regional != g.regionalIndices.front())
                                        continue;
                                    // Under MSAA (single-sample lists) the library runs `sphere` as sphere-span:
                                    // the row says what ran.
                                    if (c.volumeTest == "sphere" && c.msaa > 0 && !c.perSample) c.volumeTest = "sphere-span";
                                    // The span storage is sphere-span's alone.
                                    if (c.volumeTest != "sphere-span" && spans != g.msaaSpans.front()) continue;
                                    if (c.volumeTest != "sphere-span") c.msaaSpans = "auto";
                                    configs.push_back(c);
                                }
}

void tiledConfigs(const SweepGroup& g, const ModeConfig& base, Configs& configs) {
    for (bool db : g.tiledDepthBounds) {
        ModeConfig c = base;
        c.tiledDepthBounds = db;
        configs.push_back(c);
    }
}

void clusteredConfigs(const SweepGroup& g, const ModeConfig& base, Configs& configs) {
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
}

void multipassConfigs(const SweepGroup& g, const ModeConfig& base, Configs& configs) {
    for (bool eightBit : g.multipassEightBit) {
        ModeConfig c = base;
        c.multipassEightBit = eightBit;
        configs.push_back(c);
    }
}

void deferredConfigs(const SweepGroup& g, const ModeConfig& base, Configs& configs) {
    for (bool stencil : g.deferredStencil) {
        ModeConfig c = base;
        c.deferredStencil = stencil;
        configs.push_back(c);
    }
}

using ConfigExpander = void (*)(const SweepGroup&, const ModeConfig&, Configs&);
const std::map<std::string, ConfigExpander>& modeExpanders() {
    static const std::map<std::string, ConfigExpander> expanders = {
        {"lidr", lidrConfigs}, {"tiled", tiledConfigs}, {"clustered", clusteredConfigs},
        {"forward-multipass", multipassConfigs}, {"deferred", deferredConfigs}};
    return expanders;
}

// Every configuration of a group, mode by mode: the settings every mode has (MSAA, per-sample, transparency), then
// the mode's own.
Configs configsOf(const SweepGroup& g) {
    Configs configs;
    for (const std::string& mode : g.modes) {
        ModeConfig base;
        base.mode = mode;
        const auto expander = modeExpanders().find(mode);
        for (int msaa : g.msaa)
            for (bool perSample : g.perSample)
                for (bool transparency : g.transparency) {
                    // Per-sample lists exist only with MSAA, and only in LIDR (and its reference).
                    if (perSample && (msaa == 0 || (mode != "lidr" && mode != "forward-brute"))) continue;
                    base.msaa = msaa;
                    base.perSample = perSample;
                    base.transparency = transparency;
                    if (expander != modeExpanders().end())
                        expander->second(g, base, configs);
                    else
                        configs.push_back(base);
                }
    }
    return configs;
}

// The library's answer for each combination, asked once (a probe renderer on a stand-in scene).
class Prober {
public:
    explicit Prober(const GlInfo& info) : info_(info) {}
    // "" where the library builds `c` for the scene at w x h, else its reason. A configuration over the memory
    // limit, or a GL failure, is an error rather than a skip.
    const std::string& reason(const ModeConfig& c, const std::string& sceneName, const Scene& scene, int w, int h) {
        const std::string key = sceneName + "|" + std::to_string(w) + "x" + std::to_string(h) + "|" + c.key();
        auto found = results_.find(key);
        if (found != results_.end()) return found->second;
        if (!probes_.count(sceneName)) probes_.emplace(sceneName, probeSceneFor(scene));
        // Before the probe allocates anything: an oversized configuration is an error, not a skip.
        const bool lidr = c.mode == "lidr";
        const bool autoLidr = lidr && c.scheme == "auto";  // at most budget 16, 16-bit
        checkRenderTargetMemory(w, h, c.msaa,
                                lidr ? indexBytesPerPixel(autoLidr ? 16 : c.budget, autoLidr ? 16 : c.indexBits) : 0,
                                lidr && c.perSample);
        std::string why;
        try {
            createBenchRenderer(c, info_, probes_.at(sceneName), w, h);
        } catch (const GlError&) {
            throw;  // a GL failure is a bug to see, not a combination to skip
        } catch (const Error& e) {
            why = e.what();
            if (why.empty()) why = "refused";
        }
        return results_[key] = why;
    }

private:
    const GlInfo& info_;
    std::map<std::string, std::string> results_;  // probe key -> "" (ok) or the library's reason
    std::map<std::string, Scene> probes_;
};

// For each value of each dimension of a group: "" when some combination used it, else the library's last reason.
class ValueUse {
public:
    void note(const ModeConfig& c, const std::string& reason) {
        note("mode", c.mode, reason);
        note("MSAA", str(c.msaa), reason);
        if (c.msaa > 0) note("per-sample", str(c.perSample), reason);
        note("transparency", str(c.transparency), reason);
        if (c.mode != "lidr") return;
        note("scheme", c.scheme, reason);
        if (c.scheme != "auto") {
            note("budget", str(c.budget), reason);
            note("index width", str(c.indexBits), reason);
        }
        note("volume test", c.volumeTest, reason);
    }
    // A value a person typed (SweepGroup::strictDimensions) that no combination could use is an error.
    void checkStrict(const SweepGroup& g) const {
        for (const auto& [value, reason] : use_)
            if (g.strictDimensions.count(value.first) && !reason.empty())
                throw Error("sweep '" + g.name + "': " + value.first + " " + value.second +
                            " works with none of the other settings asked for: " + reason);
    }

private:
    void note(const std::string& dimension, const std::string& v, const std::string& reason) {
        const auto value = std::make_pair(dimension, v);
        auto it = use_.find(value);
        if (it == use_.end())
            use_[value] = reason;
        else if (!it->second.empty())
            it->second = reason;
    }
    std::map<std::pair<std::string, std::string>, std::string> use_;
};

void throwNoRunnable(const SweepGroup& g, const Plan& plan) {
    std::set<std::string> reasons;
    for (const Skipped& s : plan.skipped)
        if (s.group == g.name) reasons.insert(s.reason);
    std::string all;
    for (const auto& r : reasons) all += "\n  " + r;
    throw Error("sweep '" + g.name + "' has no configuration the library can run:" + all);
}

// Groups runs by reference (scene, size, MSAA, transparency), first appearance first, forward-brute first
// within each: the reference is rendered once and its frames time forward-brute.
void orderByReference(Plan& plan) {
    std::map<std::string, size_t> firstSeen;
    for (const Run& r : plan.runs) firstSeen.emplace(refKey(r.scene, r.width, r.height, r.config), firstSeen.size());
    std::stable_sort(plan.runs.begin(), plan.runs.end(), [&](const Run& a, const Run& b) {
        const size_t ka = firstSeen.at(refKey(a.scene, a.width, a.height, a.config));
        const size_t kb = firstSeen.at(refKey(b.scene, b.width, b.height, b.config));
        if (ka != kb) return ka < kb;
        return (a.config.mode == "forward-brute") > (b.config.mode == "forward-brute");
    });
}

}  // namespace

Plan buildPlan(const std::vector<SweepGroup>& groups, const GlInfo& info, uint32_t seed,
               std::map<std::string, Scene>& scenes, const LightScatterOptions& extraLights, int camera) {
    checkNamesAndLoadScenes(groups, seed, scenes, extraLights, camera);  // every unknown name before any probing
    Plan plan;
    std::set<std::string> seen;
    Prober prober(info);
    for (const SweepGroup& g : groups) {
        ValueUse valueUse;
        size_t groupRuns = 0;
        const Configs configs = configsOf(g);
        for (const std::string& sceneName : g.scenes) {
            const Scene& scene = scenes.at(sceneName);
            for (auto [w, h] : g.resolutions) {
                if (w == 0) std::tie(w, h) = std::make_pair(scene.width, scene.height);
                for (const ModeConfig& c : configs) {
                    const std::string reason = prober.reason(c, sceneName, scene, w, h);
                    valueUse.note(c, reason);
                    if (!reason.empty()) {
                        plan.skipped.push_back({g.name, sceneName, c.key(), w, h, reason});
                        continue;
                    }
                    ++groupRuns;
                    if (seen.insert(sceneName + "|" + std::to_string(w) + "x" + std::to_string(h) + "|" + c.key()).second)
                        plan.runs.push_back({g.name, sceneName, w, h, c, g.reference});
                }
            }
        }
        if (groupRuns == 0) throwNoRunnable(g, plan);
        valueUse.checkStrict(g);
    }
    orderByReference(plan);
    return plan;
}

}  // namespace lidr::bench
