#include "demo_options.h"

#include "lidr/base/gl.h"
#include "lidr/scene/default_scene.h"
#include "lidr/scene/light_scatter.h"
#include "lidr/base/error.h"
#include "lidr/gl/render_targets.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <cmath>
#include <initializer_list>
#include <iostream>
#include <limits>
#include <sstream>
#include "lidr/technique/packing_scheme.h"
#include "lidr/scene/io/environment_file.h"
#include "lidr/scene/io/file_checks.h"
#include "lidr/scene/io/bart_scene.h"
#include "lidr/scene/io/scene_loader.h"
#include "lidr/eval/bench_scenes.h"
#include "lidr/render/shadow_atlas.h"
#include "lidr/render/shadow_casters.h"

namespace lidr::demo {

std::string defaultBartFolder() { return std::string(LIDR_SOURCE_DIR) + "/../shared/bart-robots"; }

void SceneChoice::addOptions(CLI::App& app) {
    app.add_option("--scene", sceneFile, "Scene file: a lidr scene (.json, see doc/scene-format.md), a glTF (.gltf, .glb) or OBJ (.obj) model, "
                   "a BART scene (.aff), or a built-in bench scene: hall-N / city-N (occluded, N lights, e.g. hall-255), "
                   "spots-N / spots-N-points, many-N-top / many-N-fp (the room's geometry with N lights), "
                   "bart-robots-many / bart-robots-few (BART's Robots with the Tiled Shading paper's 924 static or one "
                   "light per robot, doc/bart.md); default: the built-in room");
    app.add_option("--bart", bart, "Where bart-robots-many / -few are read from: a folder with aff/Robot.aff, or an AFF file")
        ->capture_default_str();
    app.add_flag("--smooth-normals", smoothNormals,
                 "OBJ models: smooth normals for faces without vn, whatever their smoothing group (a scene file's "
                 "model may say otherwise with \"smooth_normals\")");
    app.add_option("--width", width, "Override the scene's width in pixels");
    app.add_option("--height", height, "Override the scene's height in pixels");
    app.add_option("--time", time,
                   "Animation time in seconds, a finite number >= 0 (default: the scene's): lights on paths, keyframed "
                   "meshes, lights and camera (glTF animations, AFF keyframes) are shown there");
    app.add_option("--frame", frame,
                   "Show frame N (from 0) of the scene's animation: the time start + N (end - start) / (frames - 1) of its "
                   "range (an AFF file's `a START END FRAMES`); instead of --time");
    app.add_option("--seed", seed, "Seed of the built-in room's lights, and of --lights");
    app.add_option("--lights", lights,
                   "Add N seeded point lights scattered over the scene's surfaces (1 .. 65535 with the scene's own)");
    app.add_option("--light-radius", lightRadius,
                   "Radius of the --lights lights in scene units (default: automatic, from the surface area and N)");
    app.add_option("--spot-share", spotShare,
                   "Make this share (0..1) of the --lights lights spot lights aimed back at their surface (60-degree "
                   "cones; default 0)");
    app.add_option("--camera", camera,
                   "View a glTF model (--scene FILE.gltf / .glb) through its camera N: the index in the file's cameras "
                   "array, from 0; in a scene file, its glTF models' cameras in model order (default: the first camera "
                   "met in the default scene's node order unless a scene file gives \"camera\", else a view framing "
                   "the bounds); yfov is kept, the aspect is the image's. Orthographic cameras are refused");
    app.add_flag("!--no-default-lights", defaultRig,
                 "Leave a scene without lights unlit (default: a key light at the eye, and ambient 0.1 where there is no "
                 "environment, doc/colour.md)");
    app.add_option("--environment", environment,
                   "Image-based environment light: auto (default: glTF and OBJ models get the built-in studio room, "
                   "scene files and built-in scenes keep their own, none unless they ask), default, none, an "
                   "equirectangular .hdr panorama or a folder of six faces px nx py ny pz nz (doc/colour.md, "
                   "\"Environment light\")")
        ->capture_default_str();
    app.add_option("--environment-intensity", environmentIntensity,
                   "Scale of the environment light's radiance, a finite number >= 0 (default: the scene's, 1)");
    app.add_option("--export-environment", exportEnvironment,
                   "Also write the environment light as an equirectangular Radiance HDR panorama (1024 x 512, three.js's "
                   "mapping; scripts/threejs_compare.py gives it to three.js)");
}

namespace {
// Prints each step of a long environment read on stderr, from the first that ends over a second after the start
// (the ones before it with it), with the seconds so far.
EnvironmentProgress slowStepsOnStderr() {
    struct State {
        std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
        std::vector<std::string> pending;
        bool printing = false;
    };
    auto state = std::make_shared<State>();
    return [state](const std::string& step) {
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - state->start).count();
        char line[64];
        std::snprintf(line, sizeof line, " (%.1f s)", seconds);
        state->pending.push_back("environment: " + step + line);
        if (!state->printing && seconds < 1.0) return;
        state->printing = true;
        for (const std::string& l : state->pending) std::cerr << l << "\n";
        state->pending.clear();
    };
}
}  // namespace

void SceneChoice::applyEnvironment(Scene& scene, bool model) const {
    if (environmentIntensity) {
        if (!(std::isfinite(*environmentIntensity) && *environmentIntensity >= 0.0 &&
              *environmentIntensity <= double(std::numeric_limits<float>::max())))
            throw Error("--environment-intensity must be a finite number >= 0, got " + std::to_string(*environmentIntensity));
        scene.environmentIntensity = float(*environmentIntensity);
    }
    if (environment == "auto") {
        if (model) giveModelDefaultEnvironment(scene);
        return;
    }
    scene.environment = loadEnvironment(environment, slowStepsOnStderr());
    if (model && scene.environment) scene.ambient = glm::vec3(0.0f);
}

namespace {
void exportEnvironmentPanorama(const Scene& scene, const std::string& file) {
    if (!scene.environment)
        throw Error("--export-environment writes the environment light, and this scene has none (--environment default)");
    writeHdr(file, equirectFromCube(scene.environment->specular[0], 1024));
    std::cout << "environment " << scene.environment->name << " written to " << file << " (1024 x 512)\n";
}
}  // namespace

float frameTimeOf(const Scene& scene, int frame) {
    const SceneAnimation& a = scene.animation;
    if (a.frames <= 0)
        throw Error("--frame " + std::to_string(frame) + ": the scene gives no frame count (" +
                    (a.moves() ? "a glTF animation is timed in seconds" : "it has no keyframe animation") +
                    "); use --time SECONDS");
    if (frame < 0 || frame >= a.frames)
        throw Error("--frame must be 0 .. " + std::to_string(a.frames - 1) + " (the scene's " + std::to_string(a.frames) +
                    " frames over " + std::to_string(a.start) + " .. " + std::to_string(a.end) + " s), got " +
                    std::to_string(frame));
    return a.frameTime(frame);
}

namespace {
// --lights N (with --light-radius, --spot-share): N seeded lights scattered over the scene's surfaces.
void addScatteredLightsChosen(const SceneChoice& c, Scene& scene) {
    const auto& lights = c.lights;
    const auto& lightRadius = c.lightRadius;
    const auto& spotShare = c.spotShare;
    const unsigned seed = c.seed;
    if (lightRadius && !lights) throw Error("--light-radius sets the radius of --lights: give --lights N too");
    if (spotShare && !lights) throw Error("--spot-share sets the spot lights among --lights: give --lights N too");
    if (lights) {
        LightScatterOptions scatter;
        scatter.count = *lights;
        scatter.seed = seed;
        if (lightRadius) {
            if (!(std::isfinite(*lightRadius) && *lightRadius > 0.0 && *lightRadius <= double(maxLightRadius)))
                throw Error("--light-radius must be a finite number > 0, got " + std::to_string(*lightRadius));
            scatter.radius = float(*lightRadius);
        }
        if (spotShare) {
            if (!(*spotShare >= 0.0 && *spotShare <= 1.0))
                throw Error("--spot-share must be a number in [0, 1], got " + std::to_string(*spotShare));
            scatter.spotShare = float(*spotShare);
        }
        addScatteredLights(scene, scatter);
        std::cout << "lights     " << *lights << " scattered over the surfaces, radius "
                  << (lightRadius ? *lightRadius : double(defaultScatterRadius(scene, *lights))) << ", seed " << seed
                  << (scatter.spotShare > 0.0f ? ", spot share " + std::to_string(scatter.spotShare) : std::string())
                  << "\n";
    }
}
}  // namespace

Scene SceneChoice::load() const {
    // Checked first, before the scene is built; float(time) must also stay finite.
    if (time && !(std::isfinite(*time) && *time >= 0.0 && *time <= double(std::numeric_limits<float>::max()))) {
        std::ostringstream value;
        value << *time;
        throw Error("--time must be a finite number of seconds >= 0 (leave it out for the scene's own time), got " +
                    value.str());
    }
    if (time && frame) throw Error("--time and --frame both say when to show the scene: give one");
    const auto cameraOption = [&] { return "--camera " + std::to_string(*camera) + ": "; };
    Scene scene;
    if (camera && sceneFile.empty())
        throw Error(cameraOption() + "the built-in room has no cameras; --camera picks a camera of a glTF model "
                    "(--scene FILE.gltf)");
    bool model = false;  // a glTF or OBJ model (no environment of its own)
    if (sceneFile.empty()) {
        DefaultSceneOptions o;
        o.seed = seed;
        if (time) o.time = float(*time);
        scene = makeDefaultScene(o);
    } else if (std::string bartLights; makeBartSceneByName(sceneFile, scene, seed, bart, &bartLights)) {
        std::cout << "lights     " << bartLights << "\n";
        if (time) poseScene(scene, float(*time));
    } else if (makeOccludedSceneByName(sceneFile, scene, seed) || makeSpotSceneByName(sceneFile, scene, seed) ||
               makeManyLightSceneByName(sceneFile, scene, seed)) {
        if (time) scene.time = float(*time);
    } else {
        ObjImportOptions objOptions;
        objOptions.smoothNormals = smoothNormals;
        scene = loadScene(sceneFile, objOptions);
        if (time) poseScene(scene, float(*time));
        const std::string ext = lowerCaseExtension(sceneFile);
        model = ext == ".gltf" || ext == ".glb" || ext == ".obj";
    }
    if (frame) poseScene(scene, frameTimeOf(scene, *frame));
    // Before the lights: the default rig puts its key light at the eye.
    if (camera) {
        try {
            chooseView(scene, *camera);
        } catch (const Error& e) {
            throw Error(cameraOption() + e.what());
        }
    }
    if (!scene.views.empty()) {
        const size_t count = scene.views.size();
        std::cout << "camera     "
                  << (scene.view >= 0 ? scene.views[size_t(scene.view)].name
                                      : std::string("a view framing the bounds (no camera lidr can draw)"))
                  << (camera ? " (--camera)" : "") << "; the scene has " << count << (count == 1 ? " camera" : " cameras")
                  << (camera || count == 1 ? "" : " (--camera N picks another)") << "\n";
    }
    applyEnvironment(scene, model);
    if (!exportEnvironment.empty()) exportEnvironmentPanorama(scene, exportEnvironment);
    addScatteredLightsChosen(*this, scene);
    if (defaultRig && addDefaultLightRig(scene))
        std::cout << "lights     none in the scene: the default rig (a key light at the eye, radius "
                  << scene.lights.back().radius
                  << (scene.environment ? "; with the environment" : "; ambient at least 0.1")
                  << "; --no-default-lights to leave it unlit)\n";
    if (width) scene.width = *width;
    if (height) scene.height = *height;
    scene.validate();
    return scene;
}

void RendererChoice::addOptions(CLI::App& app) {
    for (const RenderOption& row : renderOptions()) {
        const std::string name = row.name;
        if (row.type == RenderOptionType::Flag) {
            app.add_flag_callback("--" + name, [this, name] { set(name, "on"); }, row.help);
            continue;
        }
        CLI::Option* option = app.add_option_function<std::string>(
            "--" + name,
            [this, name](const std::string& value) {
                try {
                    set(name, value);
                } catch (const Error& e) {
                    throw CLI::ValidationError(std::string("error: ") + e.what());  // the library's message
                }
            },
            row.help);
        option->type_name(row.typeName());
        if (!row.defaultValue.empty()) option->default_str(row.defaultValue);
        if (name == "depth-bits") // --context sits among the renderer's settings in --help, as before
            app.add_option("--context", context,
                           "GL context: auto, egl, egl-device, egl-gles2, glfw, glfw-gles2, osmesa (env LIDR_CONTEXT; "
                           "--window: glfw or glfw-gles2)");
    }
}

void printRenderOptions(std::ostream& out) {
    auto join = [](const std::vector<std::string>& items, const char* none) {
        std::string s;
        for (const std::string& i : items) s += (s.empty() ? "" : ",") + i;
        return s.empty() ? std::string(none) : s;
    };
    static const char* const kTypes[] = {"flag", "int", "number", "choice", "text"};
    for (const RenderOption& o : renderOptions())
        out << o.name << "\t" << kTypes[int(o.type)] << "\t" << (o.defaultValue.empty() ? "-" : o.defaultValue) << "\t"
            << join(o.modes, "all") << "\t" << join(o.choices, "-") << "\n";
}

namespace {
bool powerOfTwo(long v) { return v > 0 && (v & (v - 1)) == 0; }

long atlasNumber(const std::string& text, const std::string& whole) {
    if (text.empty() || text.size() > 6 || !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
        throw Error("--shadow-atlas must be SIZE or SIZE:TILE (whole numbers of texels, e.g. 4096:256), got '" + whole + "'");
    return std::stol(text);
}
}  // namespace

ShadowChoice RendererChoice::shadowChoice(const std::string& mode) const {
    ShadowChoice c;
    const std::string shadows = get("shadows");
    const std::optional<std::string> shadowLookup =
        given("shadow-lookup") ? std::optional<std::string>(get("shadow-lookup")) : std::nullopt;
    const std::optional<std::string> shadowFilter =
        given("shadow-filter") ? std::optional<std::string>(get("shadow-filter")) : std::nullopt;
    const std::optional<std::string> shadowAtlas =
        given("shadow-atlas") ? std::optional<std::string>(get("shadow-atlas")) : std::nullopt;
    if (shadows == "off") {
        for (const auto* given : {&shadowLookup, &shadowFilter, &shadowAtlas})
            if (*given)
                throw Error("--shadow-lookup, --shadow-filter and --shadow-atlas set up shadows: add --shadows scene or "
                            "--shadows K");
        return c;
    }
    if (shadows == "scene") {
        c.casters = ShadowChoice::Casters::Scene;
    } else {
        const bool digits = !shadows.empty() && shadows.size() <= 5 &&
                            std::all_of(shadows.begin(), shadows.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
        if (!digits || std::stoi(shadows) > 65535)
            throw Error("--shadows must be off, scene or a number of lights K in 0..65535, got '" + shadows + "'");
        c.casters = ShadowChoice::Casters::Brightest;
        c.brightest = std::stoi(shadows);
    }
    c.settings.enabled = true;
    c.lidrMode = mode == "lidr";
    const std::string lookup = shadowLookup.value_or("forward");
    if (lookup != "volume" && lookup != "forward")
        throw Error("--shadow-lookup must be volume or forward, got '" + lookup + "'");
    if (shadowLookup && mode != "lidr")
        throw Error("--shadow-lookup says where LIDR applies shadows; the " + mode +
                    " mode looks them up as it shades (use --mode lidr, or leave it out)");
    c.settings.lidrLookup = lookup == "volume" ? ShadowLookup::VolumePass : ShadowLookup::ForwardPass;
    const std::string filter = shadowFilter.value_or("nearest");
    if (filter != "nearest" && filter != "pcf")
        throw Error("--shadow-filter must be nearest or pcf, got '" + filter + "'");
    c.settings.filtered = filter == "pcf";
    c.settings.atlas.size = 4096;
    if (shadowAtlas) {
        const size_t colon = shadowAtlas->find(':');
        const long size = atlasNumber(shadowAtlas->substr(0, colon), *shadowAtlas);
        if (!powerOfTwo(size) || size < 16 || size > 8192)
            throw Error("--shadow-atlas: SIZE must be a power of two from 16 to 8192 texels, got " + std::to_string(size));
        c.settings.atlas.size = int(size);
        if (colon != std::string::npos) {
            const long tile = atlasNumber(shadowAtlas->substr(colon + 1), *shadowAtlas);
            if (!powerOfTwo(tile) || tile < 16 || tile > size)
                throw Error("--shadow-atlas: TILE must be a power of two from 16 to SIZE (" + std::to_string(size) +
                            "), got " + std::to_string(tile));
            c.settings.atlas.tileSize = int(tile);
            c.automaticTile = false;
        }
    }
    if (c.automaticTile) c.settings.atlas.tileSize = std::min(512, c.settings.atlas.size);
    return c;
}

void ShadowChoice::apply(const Scene& scene, std::vector<PointLight>& lights, ShadingParameters& shading) const {
    apply(cameraMatrices(scene.camera, scene.width, scene.height), lights, shading);
}

void ShadowChoice::apply(const CameraMatrices& view, std::vector<PointLight>& lights, ShadingParameters& shading) const {
    shading.shadows = settings;
    if (casters == Casters::Off) return;
    if (casters == Casters::Brightest) chooseShadowCasters(lights, view, brightest);
    for (size_t i = 0; i < lights.size(); ++i)  // the scene's own flags: a cone one map cannot cover
        if (lights[i].castsShadow && lights[i].isSpot() && !(lights[i].outerConeAngle <= kMaxShadowConeAngle))
            throw Error("--shadows scene: light " + std::to_string(i) + " is a spot light of " +
                        std::to_string(int(std::lround(glm::degrees(lights[i].outerConeAngle)))) +
                        " degrees marked to cast; one shadow map covers cones up to " +
                        std::to_string(int(std::lround(glm::degrees(kMaxShadowConeAngle)))) +
                        " degrees (the K brightest leave such lights out)");
    if (!automaticTile) return;  // the atlas refuses casters it cannot hold, naming the count
    try {
        shading.shadows.atlas.tileSize = shadowTileToFit(lights, settings.atlas.size);
    } catch (const Error& e) {
        throw Error(std::string("--") + e.what() + " (--shadow-atlas)");  // the library's "shadows: the casters ..."
    }
}

std::string ShadowChoice::describe(const ShadowSettings& used) const {
    if (casters == Casters::Off) return "off";
    std::ostringstream s;
    s << (casters == Casters::Scene ? std::string("the scene's flags") : std::to_string(brightest) + " brightest")
      << ", atlas " << used.atlas.size << " (" << used.atlas.tileSize << "-texel tiles"
      << (automaticTile ? ", chosen to fit" : "") << ")";
    if (lidrMode) s << ", lookup " << (settings.lidrLookup == ShadowLookup::VolumePass ? "volume" : "forward");
    s << ", filter "
      << (settings.filtered ? "pcf" : "nearest");
    return s.str();
}

void checkTargetMemory(const Scene& scene, const RenderModeOptions& options) {
    const bool lidr = options.mode == "lidr";
    checkRenderTargetMemory(scene.width, scene.height, options.msaaSamples,
                            lidr ? indexBytesPerPixel(options.lidr.packing.autoBudget() ? 16 : options.lidr.packing.budget,
                                                      options.lidr.packing.autoIndexBits()
                                                          ? AutoConfiguration::indexBitsFor(std::min<int>(65535, int(scene.lights.size())))
                                                          : options.lidr.packing.indexBits)
                                 : 0,
                            lidr && options.lidr.perSampleIndices);
}

ContextOptions RendererChoice::contextOptions() const {
    ContextOptions o;
    o.backend = parseContextBackend(context);
    return o;
}

}  // namespace lidr::demo
