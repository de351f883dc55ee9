// lidr in the browser: the built-in room, or the user's own glTF / OBJ / scene file (by URL, file picker or
// drop; web/shell.html writes it into the page's memory file system and calls lidr_web_load), rendered with LIDR
// on WebGL 1 (the library's GLES 2.0 path), with the page's HTML controls calling the exported lidr_web_*
// functions, and a fly camera (WASD + mouse drag). A loaded model gets lights scattered over its surfaces
// (lidr::scatterLights, as --lights N). The image follows the window, or width / height in the URL query; the
// query (web/page_query.h, read once by lidr_web_query) also takes the settings, a model and bench=N, a timing run
// of every mode asked for. ?check runs the page's own check instead (web/web_check.h; CTest web.chromium).
#include "lidr/base/gl.h"

#include <emscripten.h>
#include <emscripten/html5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <set>
#include <string>

#include "depth_readback.h"
#include "fly_camera.h"
#include "frame_views.h"
#include "lidr/base/error.h"
#include "lidr/base/visualize.h"
#include "lidr/eval/image_compare.h"
#include "lidr/eval/light_coverage.h"
#include "lidr/modes/render_mode.h"
#include "lidr/modes/render_options.h"
#include "lidr/platform/context.h"
#include "lidr/render/present.h"
#include "lidr/render/shadow_atlas.h"
#include "lidr/scene/default_scene.h"
#include "lidr/scene/io/scene_loader.h"
#include "lidr/scene/render_mode_names.h"
#include "page_query.h"
#include "page_state.h"
#include "web_check.h"

using namespace lidr;
using namespace lidr::web;

namespace {

// A CPU image into the page's 2D canvas #view (shown in place of the WebGL canvas for the CPU-made views).
void showCpuImage(const ImageRGBA8& image) {
    EM_ASM({
        const canvas = document.getElementById('view');
        const ctx = canvas.getContext('2d');
        const data = new ImageData(new Uint8ClampedArray(HEAPU8.subarray($0, $0 + $1 * $2 * 4)), $1, $2);
        ctx.putImageData(data, 0, 0);
        canvas.style.display = 'block';
        document.getElementById('canvas').style.display = 'none';
    }, image.pixels.data(), image.width, image.height);
}

void showGlCanvas() {
    EM_ASM({
        document.getElementById('view').style.display = 'none';
        document.getElementById('canvas').style.display = 'block';
    });
}

ReferenceRenderer& reference() {
    if (!page->reference)
        page->reference = std::make_unique<ReferenceRenderer>(page->context->info(), page->scene, page->width,
                                                              page->height, int(page->scene.lights.size()));
    return *page->reference;
}

// Renders the debug view the settings ask for, after the frame (the CPU views read the frame back).
void drawView(const Camera& camera, const std::vector<PointLight>& lights, const ShadingParameters& shading) {
    const std::string& view = page->settings.view;
    if (view == "shadow-atlas") {
        const ShadowAtlas* atlas = page->renderer->shadowAtlas();
        if (!atlas) throw Error("no shadow maps drawn yet (no light casts a shadow in this frame)");
        if (!atlas->packed() && page->context->info().gles)
            throw Error("WebGL 1 cannot read a depth texture back: the atlas view needs the packed atlas");
        const int width = page->width, height = page->height;
        const ImageRGBA8 maps = atlas->image(std::min(width, height));
        ImageRGBA8 canvas(width, height);
        for (int y = 0; y < maps.height; ++y)
            for (int x = 0; x < maps.width; ++x)
                std::copy_n(maps.at(x, y), 4, canvas.at(x, y));
        for (int y = 0; y < height; ++y)
            for (int x = maps.width; x < width; ++x) canvas.at(x, y)[3] = 255;
        showCpuImage(canvas);
        const FrameStats& st = page->renderer->lastFrame();
        page->viewNote = "the shadow atlas (" + std::to_string(atlas->size()) + " texels, " +
                         std::to_string(atlas->tileSize()) + " a map): distance from the light, near white; " +
                         std::to_string(st.shadowCasters) + " casters, " + std::to_string(st.shadowMapsDrawn) +
                         " maps drawn this frame";
        return;
    }
    if (view == "frame") {
        page->presenter->present(page->renderer->targets(), 0);
        showGlCanvas();
        page->viewNote = "the " + page->renderer->modeName() + " frame";
        return;
    }
    ReferenceRenderer& ref = reference();
    placeAnimatedObjects(ref, page->scene, page->time);  // the frame's meshes where the animation has them
    ref.render(camera, lights, shading);
    if (view == "reference") {
        page->presenter->present(ref.targets(), 0);
        showGlCanvas();
        page->viewNote = "the brute-force reference (every light at every pixel)";
        return;
    }
    const ImageRGBA8 image = page->renderer->targets().readColor(), refImage = ref.targets().readColor();
    if (view == "difference") {
        const ImageError e = compareImages(image, refImage);
        showCpuImage(differenceImage(image, refImage));
        char note[160];
        std::snprintf(note, sizeof note, "|frame - reference| x16: max error %d, PSNR %.1f dB", e.maxAbsError, e.psnr);
        page->viewNote = note;
        return;
    }
    // index-lists / overlap: LIDR's lists decoded on the CPU, against the CPU truth from the depth read back.
    auto& lidr = dynamic_cast<LidrRenderer&>(*page->renderer);
    if (!page->depthReadback)
        page->depthReadback =
            std::make_unique<web::DepthReadback>(page->context->info(), page->scene, page->width, page->height);
    const CameraMatrices m = cameraMatrices(camera, page->width, page->height);
    const CoverageTruth truth = computeCoverage(page->depthReadback->read(m), m, lights);
    const ListCheck lists = checkIndexLists(truth, lidr.scheme(), lidr.readIndexTargets(), uint32_t(lights.size()),
                                            lidr.frameLightIndices(), lidr.frameIndexRegions());
    const int budget = lidr.scheme().config().budget;
    if (view == "index-lists") {
        showCpuImage(indexListImage(page->width, page->height, lists.decoded));
        page->viewNote = "decoded index lists (one colour per light), " + std::to_string(lists.droppedLightPixels) +
                         " dropped light-pixels";
    } else {
        std::vector<int> counts(size_t(page->width) * size_t(page->height));
        for (size_t p = 0; p < counts.size(); ++p) counts[p] = truth.count(p);
        showCpuImage(overlapHeatMap(page->width, page->height, counts, budget, &truth.surface));
        page->viewNote = "lights touching each surface (CPU truth), budget " + std::to_string(budget) +
                         ": blue to yellow within, red past it; max " + std::to_string(truth.maxOverlap());
    }
}

void moveCamera(float dt) {
    glm::vec3 local(0.0f);
    auto down = [](const char* k) { return page->keysDown.count(k) > 0; };
    if (down("KeyW")) local.z += 1.0f;
    if (down("KeyS")) local.z -= 1.0f;
    if (down("KeyD")) local.x += 1.0f;
    if (down("KeyA")) local.x -= 1.0f;
    if (down("KeyE")) local.y += 1.0f;
    if (down("KeyQ")) local.y -= 1.0f;
    const float speed = page->moveSpeed * (down("ShiftLeft") || down("ShiftRight") ? 4.0f : 1.0f);
    if (local != glm::vec3(0.0f)) page->followSceneCamera = false;
    page->camera.move(local, speed * dt);
}

// A keyframed scene plays its time range over and over; others run on.
float loopedTime(float t) {
    const SceneAnimation& a = page->scene.animation;
    if (!(a.end > a.start) || t <= a.end) return t;
    return a.start + std::fmod(t - a.start, a.end - a.start);
}


void frame() {
    const double now = emscripten_get_now();
    const float dt = page->lastFrameMs > 0.0 ? float(std::min(0.1, (now - page->lastFrameMs) / 1000.0)) : 0.0f;
    if (page->lastFrameMs > 0.0) page->frameMsAverage = 0.9 * page->frameMsAverage + 0.1 * (now - page->lastFrameMs);
    page->lastFrameMs = now;
    if (!page->settings.paused) page->time = loopedTime(page->time + dt);
    moveCamera(dt);
    try {
        // The scene's animation at the page's time: moving meshes re-placed (nothing uploaded again), the camera on
        // its node while followed; currentLights takes the lights at the same time.
        placeAnimatedObjects(*page->renderer, page->scene, page->time);
        if (page->followSceneCamera) page->camera.reset(cameraAt(page->scene, page->time));
        const Camera camera = page->camera.camera();
        ShadingParameters shading;
        const std::vector<PointLight> lights = currentLights(camera, shading);
        page->renderMsLast = renderTimed(camera, lights, shading);
        page->renderMsAverage = page->renderMsAverage > 0.0 ? 0.9 * page->renderMsAverage + 0.1 * page->renderMsLast
                                                            : page->renderMsLast;
        drawView(camera, lights, shading);
    } catch (const std::exception& e) {
        page->message = e.what();
    }
}

EM_BOOL onKey(int type, const EmscriptenKeyboardEvent* e, void*) {
    if (type == EMSCRIPTEN_EVENT_KEYDOWN) page->keysDown.insert(e->code);
    if (type == EMSCRIPTEN_EVENT_KEYUP) page->keysDown.erase(e->code);
    return EM_FALSE;  // the HTML controls still get their keys
}

EM_BOOL onMouse(int type, const EmscriptenMouseEvent* e, void*) {
    if (type == EMSCRIPTEN_EVENT_MOUSEDOWN) page->dragging = true;
    if (type == EMSCRIPTEN_EVENT_MOUSEUP) page->dragging = false;
    if (type == EMSCRIPTEN_EVENT_MOUSEMOVE && page->dragging) {
        page->followSceneCamera = false;
        page->camera.turn(float(e->movementX) * 0.004f, -float(e->movementY) * 0.004f);
    }
    return EM_TRUE;
}


std::string jsonEscape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n') {
            out += "\\n";
            continue;
        }
        out += c;
    }
    return out;
}

}  // namespace

extern "C" {

// Sets one setting by name ("mode", "scheme", "budget", "index-bits", "view", "lights", "paused", "shadows":
// off, scene or K, "shadow-filter": nearest or pcf, "environment": auto, default, none or the path of a .hdr
// the page wrote, "environment-intensity": a number >= 0, "time": the animation's time in seconds, "follow-camera":
// 1 to ride on the scene's animated camera again), returns 1 when applied, 0 when refused (lidr_web_status() then
// carries the reason).
EMSCRIPTEN_KEEPALIVE int lidr_web_set(const char* name, const char* value) {
    Settings s = page->settings;
    const std::string n = name, v = value;
    try {
        if (n == "time" || n == "follow-camera") {  // the clock and the camera: no renderer to rebuild
            const float number = std::stof(v);
            if (!std::isfinite(number)) throw Error(n + " must be a finite number, got '" + v + "'");
            if (n == "time") page->time = number;
            else page->followSceneCamera = number != 0.0f && page->scene.animation.cameraNode >= 0;
            return 1;
        }
        setFromText(s, n, v);
    } catch (const std::exception& e) {
        page->message = e.what();
        return 0;
    }
    return applySettings(s) ? 1 : 0;
}

// Opens a scene file the page wrote into its memory file system (glTF .gltf/.glb, .obj, a lidr .json scene)
// with `lights` lights (its own, then scattered over it; 0: its own, or 256 when it has none). Returns 1 when
// it renders, 0 when it was refused (the scene shown before stays; lidr_web_status() carries the reason).
EMSCRIPTEN_KEEPALIVE int lidr_web_load(const char* path, int lights) {
    Scene loaded;
    try {
        loaded = loadScene(path);
    } catch (const std::exception& e) {
        page->message = e.what();
        return 0;
    }
    Scene oldFile = std::move(page->fileScene), oldScene = page->scene;
    const std::string oldName = page->sceneName;
    const bool oldModel = page->model;
    const Settings oldSettings = page->settings;
    page->fileScene = std::move(loaded);
    page->model = true;
    page->sceneName = path;
    Settings wanted = page->settings;
    wanted.lightCount = lights > 0 ? lights : page->fileScene.lights.empty() ? 256 : int(page->fileScene.lights.size());
    wanted.lightCount = std::min(wanted.lightCount, kMaxModelLights);
    if (!applySettings(wanted, true)) {
        const std::string why = page->message;
        page->fileScene = std::move(oldFile);
        page->scene = std::move(oldScene);
        page->sceneName = oldName;
        page->model = oldModel;
        page->settings = oldSettings;
        applySettings(oldSettings, true);
        page->message = std::string(path) + ": " + why + " (kept " + oldName + ")";
        return 0;
    }
    page->camera.reset(page->scene.camera);
    page->time = page->scene.time;
    page->followSceneCamera = page->scene.animation.cameraNode >= 0;
    page->moveSpeed = std::max(0.5f, 0.15f * glm::length(page->scene.boundsMax() - page->scene.boundsMin()));
    if (page->message.empty() && !page->fileScene.warnings.empty())
        page->message = std::to_string(page->fileScene.warnings.size()) + " warning(s) reading " + path;
    return 1;
}

// One frame of the current scene and settings from its own camera at its own time, read back (the model check:
// web/run_chromium_check.py compares it with the native renderer's frame). Returns the RGBA pixels, rows top
// first, the page's width x height (lidr_web_status); nullptr when the frame was refused (the reason in lidr_web_status()).
EMSCRIPTEN_KEEPALIVE const uint8_t* lidr_web_fixed_frame() {
    static ImageRGBA8 image;
    try {
        page->camera.reset(page->scene.camera);
        page->time = page->scene.time;
        placeAnimatedObjects(*page->renderer, page->scene, page->time);
        ShadingParameters shading;
        const std::vector<PointLight> lights = currentLights(page->scene.camera, shading);
        page->renderer->render(page->scene.camera, lights, shading);  // as lidr-web-native-frame
        image = page->renderer->targets().readColor();
        page->presenter->present(page->renderer->targets(), 0);
        showGlCanvas();
        return image.pixels.data();
    } catch (const std::exception& e) {
        page->message = e.what();
        return nullptr;
    }
}

// A reason the page's script found (a file it could not fetch, a model past the memory estimate), shown as the
// library's are.
EMSCRIPTEN_KEEPALIVE void lidr_web_set_message(const char* text) { page->message = text; }

// Back to the built-in room (its own lights, the count it had).
EMSCRIPTEN_KEEPALIVE void lidr_web_room() {
    DefaultSceneOptions sceneOptions;
    sceneOptions.width = page->width;
    sceneOptions.height = page->height;
    page->fileScene = makeDefaultScene(sceneOptions);
    page->model = false;
    page->sceneName = "built-in room";
    Settings wanted = page->settings;
    wanted.lightCount = int(page->fileScene.lights.size());
    applySettings(wanted, true);
    page->camera.reset(page->scene.camera);
    page->time = 2.0f;
    page->followSceneCamera = false;
    page->moveSpeed = std::max(0.5f, 0.15f * glm::length(page->scene.boundsMax() - page->scene.boundsMin()));
}

// One animation frame with the current view, as the loop draws it (the model check's views); 1 when it drew
// without an error, 0 otherwise (the reason in lidr_web_status()).
EMSCRIPTEN_KEEPALIVE int lidr_web_draw_frame() {
    page->message.clear();
    frame();
    return page->message.empty() ? 1 : 0;
}

// Starts the animation loop (the page calls it unless it runs its check).
EMSCRIPTEN_KEEPALIVE void lidr_web_start() { emscripten_set_main_loop(frame, 0, 0); }

EMSCRIPTEN_KEEPALIVE void lidr_web_reset_camera() { page->camera.reset(page->scene.camera); }

// The page's state for its panel, as JSON.
EMSCRIPTEN_KEEPALIVE const char* lidr_web_status() {
    static std::string json;
    const Settings& s = page->settings;
    char figures[768];
    size_t triangles = 0;
    for (const Mesh& m : page->scene.meshes) triangles += m.indices.size() / 3;
    std::snprintf(figures, sizeof figures,
                  "\"frameMs\":%.2f,\"renderMs\":%.2f,\"renderMsLast\":%.2f,\"time\":%.2f,\"budget\":%d,"
                  "\"indexBits\":%d,\"lights\":%d,\"maxLights\":%d,\"fileLights\":%d,\"triangles\":%zu,"
                  "\"model\":%s,\"paused\":%s,\"shadowCasters\":%d,\"shadowMapsDrawn\":%d,"
                  "\"environmentIntensity\":%g,\"timeStart\":%g,\"timeEnd\":%g,\"frames\":%d,"
                  "\"animated\":%s,\"sceneCamera\":%s,\"followCamera\":%s,\"width\":%d,\"height\":%d",
                  page->frameMsAverage, page->renderMsAverage, page->renderMsLast, page->time, s.budget, s.indexBits,
                  s.lightCount, maxLights(), int(page->fileScene.lights.size()), triangles,
                  page->model ? "true" : "false", s.paused ? "true" : "false",
                  page->renderer ? page->renderer->lastFrame().shadowCasters : 0,
                  page->renderer ? page->renderer->lastFrame().shadowMapsDrawn : 0, double(s.environmentIntensity),
                  double(page->scene.animation.start), double(page->scene.animation.end), page->scene.animation.frames,
                  page->scene.animation.end > page->scene.animation.start ? "true" : "false",
                  page->scene.animation.cameraNode >= 0 ? "true" : "false", page->followSceneCamera ? "true" : "false",
                  page->width, page->height);
    std::string warnings;
    for (const std::string& w : page->fileScene.warnings)
        warnings += (warnings.empty() ? "\"" : ",\"") + jsonEscape(w) + "\"";
    json = "{\"gl\":\"" + jsonEscape(page->context->info().summary()) + "\",\"mode\":\"" + s.mode +
           "\",\"scheme\":\"" + s.scheme + "\",\"shadows\":\"" + s.shadows + "\",\"environment\":\"" +
           jsonEscape(s.environment) + "\",\"environmentFrame\":\"" +
           jsonEscape(page->renderer ? page->renderer->lastFrame().environment : std::string("none")) + "\",\"view\":\"" + s.view + "\",\"viewNote\":\"" + jsonEscape(page->viewNote) +
           "\",\"message\":\"" + jsonEscape(page->message) + "\",\"scene\":\"" + jsonEscape(page->sceneName) +
           "\",\"warnings\":[" + warnings + "]," + figures + "}";
    return json.c_str();
}

// The URL query (location.search), read by web::parsePageQuery: its settings applied together (refused as
// lidr_web_set refuses one), the rest returned as JSON for the page's script, which fetches the scene and the
// environment, sizes the image and starts a bench run: {"ok", "message", "scene", "environment", "lights",
// "width", "height", "bench", "benchModes", "check", "checkModel", "checkLarge", "checkHuge"}.
EMSCRIPTEN_KEEPALIVE const char* lidr_web_query(const char* search) {
    static std::string json;
    web::PageQuery q;
    std::string problem;
    try {
        q = web::parsePageQuery(search);
        Settings wanted = page->settings;
        for (const auto& [name, value] : q.settings) setFromText(wanted, name, value);
        if (!applySettings(wanted)) problem = page->message;
    } catch (const std::exception& e) {
        problem = e.what();
        page->message = problem;
    }
    std::string modes;
    for (const std::string& m : q.benchModes) modes += (modes.empty() ? "\"" : ",\"") + jsonEscape(m) + "\"";
    const auto text = [](const std::string& s) { return "\"" + jsonEscape(s) + "\""; };
    json = "{\"ok\":" + std::string(problem.empty() ? "true" : "false") + ",\"message\":" + text(problem) +
           ",\"scene\":" + text(q.scene) + ",\"environment\":" + text(q.environment) +
           ",\"lights\":" + std::to_string(q.lights) + ",\"width\":" + std::to_string(q.width) +
           ",\"height\":" + std::to_string(q.height) + ",\"bench\":" + std::to_string(q.bench) +
           ",\"benchModes\":[" + modes + "],\"check\":" + (q.check ? "true" : "false") +
           ",\"checkModel\":" + text(q.checkModel) + ",\"checkLarge\":" + text(q.checkLarge) +
           ",\"checkHuge\":" + text(q.checkHuge) + "}";
    return json.c_str();
}

// The image at width x height (the page calls it as its window changes, or once with the query's size); 1 when
// applied, 0 when refused (the reason in lidr_web_status()).
EMSCRIPTEN_KEEPALIVE int lidr_web_resize(int width, int height) { return resizePage(width, height) ? 1 : 0; }

// A timing run (bench=N): `frames` frames of each mode in `modes` (comma-separated; empty: every mode). Prints
// the table to the console and returns it for the page to show.
EMSCRIPTEN_KEEPALIVE const char* lidr_web_bench(int frames, const char* modes) {
    static std::string table;
    if (frames < 1 || frames > web::kMaxBenchFrames) {
        page->message = "bench: 1 to " + std::to_string(web::kMaxBenchFrames) + " frames, got " + std::to_string(frames);
        return "";
    }
    table = runBench(frames, web::commaList(modes ? modes : ""));
    std::printf("%s", table.c_str());
    std::fflush(stdout);
    return table.c_str();
}

// The choices of the page's mode, scheme, budget and index-bits menus, and their help, from the library's option
// table (lidr/modes/render_options.h) and mode table (renderModes(): each mode's one-line description), less
// `auto`, which needs occlusion or timer queries WebGL 1 does not have: {"mode": {"help": ..., "choices":
// [[value, description], ...]}, ...}.
EMSCRIPTEN_KEEPALIVE const char* lidr_web_controls() {
    static std::string json;
    json = "{";
    for (const char* name : {"mode", "scheme", "budget", "index-bits"}) {
        const RenderOption* option = findRenderOption(name);
        if (!option) continue;
        std::string choices;
        for (const std::string& value : option->choices) {
            if (value == "auto") continue;
            std::string description;
            if (option->name == "mode")
                for (const RenderModeInfo& m : renderModes())
                    if (value == m.name) description = m.description;
            choices += std::string(choices.empty() ? "" : ",") + "[\"" + jsonEscape(value) + "\",\"" +
                       jsonEscape(description) + "\"]";
        }
        json += std::string(json.size() > 1 ? "," : "") + "\"" + name + "\":{\"help\":\"" + jsonEscape(option->help) +
                "\",\"choices\":[" + choices + "]}";
    }
    json += "}";
    return json.c_str();
}

// The check web.chromium runs (?check): fixed frames against the CPU model, the truth and the reference.
EMSCRIPTEN_KEEPALIVE const char* lidr_web_check() {
    static std::string report;
    const web::CheckResult r = web::runPageCheck(page->context->info(), 256, 192);
    report = r.report;
    return report.c_str();
}

}  // extern "C"

int main() {
    page = new Page;
    try {
        ContextOptions options;
        options.backend = ContextBackend::WebGl;
        options.windowWidth = page->width;
        options.windowHeight = page->height;
        page->context = GlContext::create(options);
        DefaultSceneOptions sceneOptions;
        sceneOptions.width = page->width;
        sceneOptions.height = page->height;
        page->fileScene = makeDefaultScene(sceneOptions);
        page->scene = page->fileScene;
        page->camera.reset(page->scene.camera);
        page->moveSpeed = std::max(0.5f, 0.15f * glm::length(page->scene.boundsMax() - page->scene.boundsMin()));
        page->presenter = std::make_unique<FramePresenter>();
        if (!applySettings(page->settings)) std::fprintf(stderr, "lidr-web: %s\n", page->message.c_str());
    } catch (const std::exception& e) {
        page->message = e.what();
        std::fprintf(stderr, "lidr-web: %s\n", e.what());
        EM_ASM({ if (Module.onLidrError) Module.onLidrError(UTF8ToString($0)); }, page->message.c_str());
        return 1;
    }
    emscripten_set_keydown_callback(EMSCRIPTEN_EVENT_TARGET_DOCUMENT, nullptr, EM_FALSE, onKey);
    emscripten_set_keyup_callback(EMSCRIPTEN_EVENT_TARGET_DOCUMENT, nullptr, EM_FALSE, onKey);
    emscripten_set_mousedown_callback("#canvas", nullptr, EM_FALSE, onMouse);
    emscripten_set_mousedown_callback("#view", nullptr, EM_FALSE, onMouse);
    emscripten_set_mouseup_callback(EMSCRIPTEN_EVENT_TARGET_DOCUMENT, nullptr, EM_FALSE, onMouse);
    emscripten_set_mousemove_callback(EMSCRIPTEN_EVENT_TARGET_DOCUMENT, nullptr, EM_FALSE, onMouse);
    EM_ASM({ if (Module.onLidrReady) Module.onLidrReady(); });
    return 0;
}
