#pragma once
// What every render mode is: LIDR ("lidr"), tiled ("tiled") and clustered ("clustered") forward, multi-pass forward
// ("forward-multipass"), the brute-force reference ("forward-brute") and "auto". Each holds its FrameResources: the
// same scene, camera, light table layout and shading function, so their images and times compare like for like.
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "lidr/gl/frame_timer.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/render_targets.h"
#include "lidr/gl/saved_gl_state.h"
#include "lidr/render/frame_pass.h"
#include "lidr/render/gpu_scene.h"
#include "lidr/render/output_transform.h"
#include "lidr/render/shadow_settings.h"
#include "lidr/scene/environment.h"
#include "lidr/scene/scene.h"

namespace lidr {

class FrameResources;
class ShadowAtlas;

// The frame's image-based environment light (issue 39): every mode adds it once per pixel with the ambient
// (shading.glsl's lidrEnvironment: diffuse from its spherical harmonics, specular from its prefiltered cube and the
// split-sum table). No map: none, the frame is drawn as before environments existed.
struct EnvironmentLight {
    std::shared_ptr<const Environment> map{};  // lidr::defaultEnvironment(), lidr::loadEnvironment(file); null: none
    float intensity = 1.0f;                   // scales the radiance; finite, >= 0
    // The specular lookup: Lod where the context can (GlInfo::textureLod), else Bias; Bias or DiffuseOnly force
    // those (each renderer says which ran: FrameStats::environment). None is the same as no map.
    enum class Lookup { Automatic, Bias, DiffuseOnly };
    Lookup lookup = Lookup::Automatic;
    bool on() const { return bool(map); }
};

struct ShadingParameters {
    glm::vec3 ambient{0.04f};     // linear
    glm::vec3 background{0.0f};   // linear, cleared to its output-transformed value
    OutputTransform output{};     // exposure, tone map, sRGB encoding (lidr/render/output_transform.h)
    // Not indexed: every mode adds them in its forward pass (at most maxDirectionalLights; shading.glsl).
    std::vector<DirectionalLight> directionalLights{};
    ShadowSettings shadows{};  // the lights with castsShadow cast shadows when enabled (issue 30)
    EnvironmentLight environment{};  // none by default (the scene's: sceneShading)
};

// The scene's own shading: its ambient, background, directional lights and environment, with `output`.
ShadingParameters sceneShading(const Scene& scene, const OutputTransform& output = OutputTransform{});
// What every mode's render() checks before any work: the directional lights (validateDirectionalLights), the
// environment's intensity (finite, >= 0).
void checkShadingParameters(const ShadingParameters& shading);

// What LIDR's automatic configuration chose for a frame (zeros in other modes and for fixed choices).
struct AutoDecision {
    bool autoBudget = false, autoIndexBits = false;
    int budget = 0;          // packed with (after any re-pack)
    int indexBits = 0;
    int visibleLights = 0;   // lights given an index this frame
    int indexRegions = 0;    // screen regions numbering their own lights (LidrOptions::regionalIndices); 0: one numbering
    int measuredBudget = 0;  // the smallest budget that dropped nothing, measured (0: more than 16 overlap)
    long overflowPixels = 0; // pixels whose overlap exceeded the final budget (nonzero only above the largest:
                             // 32 at 4- and 8-bit indices, 16 at 16-bit)
    int repacks = 0;         // volume passes drawn again this frame with a larger budget
    // The transparent layers' own front-face lists (0: none drawn this frame)
    int transparentBudget = 0, measuredTransparentBudget = 0;
    // Non-empty where an automatic budget was asked for and the context cannot measure it (no occlusion
    // queries, OpenGL ES 2.0): the budget is LidrRenderer::kBudgetWithoutOcclusionQueries, fixed.
    const char* budgetFallback = "";
    // Tile-culled volumes (LidrOptions::tileCulledVolumes): the pixels the main volume pass rasterised per screen
    // pixel (every rank window and re-pack); -1 without tiles. Above kAreaBoundPerPixel the frame is area-bound:
    // its volume pass costs more than a tiled forward pass's light loop may save (doc/auto.md), and the summary
    // says so; `--mode auto` times the modes and picks the faster.
    double volumeAreaPerPixel = -1.0;
    bool areaBound = false;
    static constexpr double kAreaBoundPerPixel = 16.0;
    // Tile culling's measured worth, from the last frame that culled by tiles (this one or up to
    // LidrRenderer::kTileCullingRecheckFrames before): the volume-mesh pixels it saved (the drawn lights' sphere
    // rectangles in every draw, minus the quads), in screens; -1 before any. tilesSkippedForSaving: this frame drew
    // volume meshes because that saving, scaled to this frame's lights, was under kTileCullingMinSaving.
    double tileSavingScreens = -1.0;
    bool tilesSkippedForSaving = false;
    // MSAA with the samples' distances: the opaque pass skipped the light lists of fragments that keep no sample
    // (LidrOptions::hiddenFragmentSkip).
    bool hiddenFragmentSkip = false;
};

struct FrameStats {
    std::vector<PassTime> passes;  // in order; frame time is their sum
    const char* timingMethod = "";
    int sceneLights = 0;
    int drawnLights = 0;  // lights the frame used after culling
    long volumeDrawCalls = 0;
    GlCallCounters glCalls;  // what the frame asked of GL: state calls issued and skipped, draws, binds (gl_state.h)
    int transparentVolumeLights = 0;  // LIDR: lights drawn into the transparent layers' front-face lists
    bool transparentVolumePassSkipped = false;  // LIDR: no transparent surface in view, no pass drawn
    bool volumePassSkipped = false;  // LIDR: no light reaches a visible surface: no volume pass, no index read
    int shadowCasters = 0;    // lights whose shadow maps the frame used
    int shadowMapsDrawn = 0;  // shadow-atlas tiles drawn this frame (0 when nothing changed: ShadowAtlas)
    // The environment light as this frame looked it up (EnvironmentMaps::describe): "none", or its name, lookup,
    // storage and size, and why the specular term was left out where it was.
    std::string environment = "none";
    AutoDecision autoDecision;
    // Timing (Renderer::setTiming): `passes` belong to the frame this many frames before this one (deferred
    // GPU timer queries; 0 for the CPU method or when waiting). Empty `passes`: timing off or nothing yet.
    int timingLag = 0;
    double frameMilliseconds() const;
};

// What every mode's render() opens with, as one scope: the caller's GL state saved (given back when the scope
// ends: doc/embedding.md), the frame's stats started afresh with the timing method and the scene's light count,
// and the frame's GL calls counted into them (GlCallCount writes them when the scope ends).
class FrameScope {
public:
    FrameScope(FrameStats& stats, const FrameTimer& timer, size_t sceneLights) : counted_(stats.glCalls) {
        stats = FrameStats{};
        stats.timingMethod = timer.method();
        stats.sceneLights = static_cast<int>(sceneLights);
    }

private:
    SavedGlState callerState_;
    GlCallCount counted_;
};

// What a mode adds to FrameStats about its own frame (Renderer::modeStatistics): the tiled grid, the clustered grid,
// multi-pass's accumulation target, the automatic mode's choice. Tools print them without knowing the mode's class.
struct ModeStatistic {
    using Value = std::variant<long long, double, bool, std::string, std::vector<std::string>>;
    std::string name;  // snake_case: lidr-demo's summary.json key
    Value value;
};
// A statistic from a number, flag or text: integers as long long, floating point as double.
template <class T>
ModeStatistic modeStatistic(std::string name, const T& value) {
    if constexpr (std::is_same_v<T, bool>)
        return {std::move(name), value};
    else if constexpr (std::is_integral_v<T>)
        return {std::move(name), static_cast<long long>(value)};
    else if constexpr (std::is_floating_point_v<T>)
        return {std::move(name), static_cast<double>(value)};
    else
        return {std::move(name), ModeStatistic::Value(value)};
}
struct ModeStatistics {
    std::string section;  // "tiled", "clustered", "multipass", "auto_mode"; empty: the mode adds none
    std::vector<ModeStatistic> values;
    std::string line;     // the same in one line of a text summary, its label first ("tiled      32 px tiles ...")
    // The value named `name`; throws lidr::Error where there is none.
    const ModeStatistic::Value& at(const std::string& name) const;
};

class Renderer {
public:
    virtual ~Renderer() = default;
    virtual std::string modeName() const = 0;
    // Renders one frame (light i has index i + 1); the result stays in targets() until the next call.
    virtual const FrameStats& render(const Camera& camera, const std::vector<PointLight>& lights,
                                     const ShadingParameters& shading) = 0;
    // What the frames are drawn with (lidr/render/frame_resources.h): the scene on the GPU, the targets, the light
    // table, the shadow maps, the environment light's maps and the timer; every mode holds one (the automatic mode
    // answers with the candidate that drew its last frame).
    virtual const FrameResources& frame() const = 0;
    // The passes of this renderer's frame in order, as its options and context built it (FramePass: name, reads,
    // writes, when; lidr/render/frame_pass.h). FrameStats::passes times them by these names; `lidr-demo
    // --list-passes MODE` prints them.
    virtual std::vector<FramePass> passes() const = 0;
    const RenderTargets& targets() const;  // the last frame's image until the next render()
    // Bytes of per-frame light data on the GPU beyond the light table (index targets, light grid).
    virtual size_t lightDataBytes() const { return 0; }
    // The last frame's statistics particular to this mode (none by default; LIDR's are FrameStats::autoDecision).
    virtual ModeStatistics modeStatistics() const { return {}; }
    // The shadow maps the last frame used (null: no frame with shadows yet): debug views read it.
    const ShadowAtlas* shadowAtlas() const;
    const FrameStats& lastFrame() const { return stats_; }
    // Per-pass timing, off by default (a mode's options may turn it on too). On: GPU timer queries read a
    // frame or more later without stalling (FrameStats::timingLag), or, with waitForResults, this frame's
    // (stalls; lidr-demo and lidr-bench); on software rasterisers glFinish around each pass (gl/frame_timer.h).
    virtual void setTiming(bool on, bool waitForResults = false);

    // Dynamic scenes (doc/embedding.md, "Moving, adding and removing objects"): without rebuilding the renderer.
    // Objects are the Scene's meshes by index (at identity: their positions are world space) and those
    // addObject returns. Lights need nothing of this: render() takes them every frame. Each throws lidr::Error
    // (unknown id, a transform not finite, affine and invertible, a bad mesh or material, a transparent object
    // for a renderer built without transparent layers) before changing anything.
    void setObjectTransform(ObjectId id, const glm::mat4& objectToWorld);
    ObjectId addObject(const Mesh& mesh, const Material& material);
    void removeObject(ObjectId id);
    // The GPU scenes this renderer draws, changed together by the three calls above (the automatic mode: every
    // candidate's). For inspection; change objects through the calls above.
    virtual std::vector<GpuScene*> gpuScenes();
    // Throws lidr::Error where this renderer cannot draw an object of that material (addObject asks first).
    virtual void checkObjectMaterial(const Material&) const {}

protected:
    // frame(), to change (setTiming, gpuScenes).
    FrameResources& mutableFrame() { return const_cast<FrameResources&>(frame()); }

    FrameStats stats_;
};

// Places the scene's moving meshes (lidr/scene/animation.h, movingMeshes) where its animation puts them at time t,
// through Renderer::setObjectTransform: no geometry is uploaded again, and the static meshes are not touched (passes
// that keep what they drew, the shadow maps, redraw only near what moved). Returns how many objects were placed. The
// frame at t is then render(cameraAt(scene, t), scene.lightsAt(t), ...). The renderer must have been built from
// `scene` (its objects are the scene's meshes by index).
size_t placeAnimatedObjects(Renderer& renderer, const Scene& scene, float t);

}  // namespace lidr
