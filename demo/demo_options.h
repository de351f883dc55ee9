#pragma once
// Command-line options shared by lidr-demo (and later lidr-bench): scene choice and renderer settings.
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "lidr/platform/context.h"
#include "lidr/technique/lidr_renderer.h"
#include "lidr/modes/render_mode.h"
#include "lidr/modes/render_options.h"
#include "lidr/render/renderer.h"
#include "lidr/scene/scene.h"

namespace lidr::demo {

// ../shared/bart-robots beside lidr's source tree (the scene of the paper's evaluation, BART's Robots).
std::string defaultBartFolder();

struct SceneChoice {
    std::string sceneFile;  // empty: the built-in default room
    std::optional<int> width, height;  // unset: the scene's (an explicit 0 is an error, not "unset")
    std::optional<double> time;  // unset: the scene's; set: a finite number of seconds >= 0
    std::optional<int> frame;    // --frame N: the time of frame N of the scene's animation range (AFF's `a`)
    std::string bart = defaultBartFolder();  // --bart: where bart-robots-many / -few are read from
    unsigned seed = 1;
    bool smoothNormals = false;  // OBJ faces without normals get smooth ones (ObjImportOptions)
    std::optional<int> lights;          // --lights N: N seeded lights scattered over the surfaces (light_scatter.h)
    std::optional<double> lightRadius;  // --light-radius R (with --lights); unset: automatic
    std::optional<double> spotShare;    // --spot-share F (with --lights): that share of them are spot lights
    bool defaultRig = true;             // a scene without lights gets addDefaultLightRig (--no-default-lights: off)
    std::optional<int> camera;          // --camera N: a glTF model's camera N (chooseView); unset: its first
    // --environment: auto (glTF and OBJ models the default environment, scene files and built-in scenes their own),
    // default, none or a file (lidr::loadEnvironment); --environment-intensity (unset: the scene's, 1).
    std::string environment = "auto";
    std::optional<double> environmentIntensity;
    std::string exportEnvironment;  // --export-environment FILE.hdr: the environment's panorama (level 0), written on load
    void addOptions(CLI::App& app);
    Scene load() const;  // throws lidr::Error
    // The environment `load` gives `scene`, read from `modelFile` (empty: a scene file or a built-in scene); also
    // applied by the viewer when it opens a file. Prints progress on stderr where reading takes over a second.
    void applyEnvironment(Scene& scene, bool model) const;
};

// The time of frame `frame` of the scene's animation range; throws lidr::Error for a scene without a frame count
// or a frame outside it.
float frameTimeOf(const Scene& scene, int frame);

// --shadows and its settings, checked (RendererChoice::shadowChoice), applied to each frame's lights and shading.
struct ShadowChoice {
    enum class Casters { Off, Scene, Brightest };
    Casters casters = Casters::Off;
    int brightest = 0;             // Casters::Brightest: K (chooseShadowCasters)
    ShadowSettings settings{};     // enabled unless Off
    bool automaticTile = true;     // --shadow-atlas without :TILE: the largest tile (<= 512) the casters' maps fit
    bool lidrMode = false;         // the lookup setting applies (describe() names it)
    // Sets the lights' castsShadow (Scene: left as the scene says; Brightest: the rule, with the scene's camera)
    // and shading.shadows. Throws lidr::Error where the casters' maps cannot fit the atlas.
    void apply(const Scene& scene, std::vector<PointLight>& lights, ShadingParameters& shading) const;
    // The same with the rule's view given (the viewer's and the page's moving camera).
    void apply(const CameraMatrices& view, std::vector<PointLight>& lights, ShadingParameters& shading) const;
    // "8 brightest, atlas 4096 (512-texel tiles, chosen to fit), lookup volume, filter nearest"; `used`: apply()'s.
    std::string describe(const ShadowSettings& used) const;
};

// The renderer settings, by name, as lidr::renderOptions() declares them (lidr/modes/render_options.h): the command
// line is made from that table and checked by it, and the viewer changes the same values.
struct RendererChoice {
    RenderOptionValues values;   // checked (setRenderOption); a name left out takes its default
    std::string context = "auto";  // the GL context (lidr/platform/context.h): not a renderer setting
    // The value of `name` (given or default), whether it was given, and a checked change.
    std::string get(const std::string& name) const { return renderOptionValue(values, name); }
    bool given(const std::string& name) const { return values.count(name) != 0; }
    void set(const std::string& name, const std::string& value) { setRenderOption(values, name, value); }
    std::string mode() const { return get("mode"); }  // empty: the scene's
    // One command-line option per renderOptions() row (and --context), each checked as it is parsed.
    void addOptions(CLI::App& app);
    // --shadows and the --shadow-* options, checked against each other and the mode; throws lidr::Error.
    ShadowChoice shadowChoice(const std::string& mode) const;
    OutputTransform outputTransform() const { return outputTransformFrom(values); }
    LidrOptions lidrOptions(const Scene& scene) const { return lidrOptionsFrom(values, scene); }
    // Every mode's settings; the mode is --mode, else the scene's. Throws lidr::Error.
    RenderModeOptions renderModeOptions(const Scene& scene) const { return renderModeOptionsFrom(values, scene); }
    ContextOptions contextOptions() const;
};

// lidr-demo --list-options: every renderOptions() row as NAME, TYPE, DEFAULT ("-": none), MODES ("all" or
// comma-separated), CHOICES (comma-separated, "-": none), tab-separated, one a line.
void printRenderOptions(std::ostream& out);

// Throws lidr::Error when the render targets the options ask for would need more than maxRenderTargetBytes
// (lidr/gl/render_targets.h); called after the scene is loaded and before any context is created.
void checkTargetMemory(const Scene& scene, const RenderModeOptions& options);

}  // namespace lidr::demo
