// lidr in the browser: the built-in room rendered with LIDR on WebGL 1 (the library's GLES 2.0 path), with the
// page's HTML controls (web/shell.html) calling the exported lidr_web_* functions, and a fly camera (WASD + mouse
// drag). ?check in the URL runs the page's own check instead (web/web_check.h; CTest web.chromium).
#include "lidr/base/gl.h"

#include <emscripten.h>
#include <emscripten/html5.h>

#include <algorithm>
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
#include "lidr/platform/context.h"
#include "lidr/render/present.h"
#include "lidr/scene/default_scene.h"
#include "web_check.h"

using namespace lidr;

namespace {

constexpr int kWidth = 640, kHeight = 480;

// What the HTML controls set. Budgets and widths are fixed numbers: the automatic budget measures the overlap
// with occlusion queries, which WebGL 1 does not have (doc/web.md).
struct Settings {
    std::string mode = "lidr";  // lidr, tiled, forward-multipass, forward-brute
    std::string scheme = "bitshift";
    int budget = 4;
    int indexBits = 8;
    std::string view = "frame";  // frame, reference, difference, index-lists, overlap
    int lightCount = 255;
    bool paused = false;
};

struct Page {
    std::unique_ptr<GlContext> context;
    Scene scene;
    Settings settings;
    std::unique_ptr<Renderer> renderer;
    std::unique_ptr<ReferenceRenderer> reference;  // built on first use by a view that needs it
    std::unique_ptr<web::DepthReadback> depthReadback;
    std::unique_ptr<FramePresenter> presenter;
    viewer::FlyCamera camera;
    float moveSpeed = 3.0f;
    float time = 2.0f;
    double lastFrameMs = 0.0, frameMsAverage = 0.0, renderMsAverage = 0.0;
    std::set<std::string> keysDown;
    bool dragging = false;
    std::string message;  // the last refusal or error, shown in red
    std::string viewNote;  // what the current debug view shows
};
Page* page = nullptr;

std::vector<PointLight> currentLights() {
    std::vector<PointLight> lights = page->scene.lightsAt(page->time);
    if (int(lights.size()) > page->settings.lightCount) lights.resize(size_t(page->settings.lightCount));
    return lights;
}

std::unique_ptr<Renderer> makeRenderer(const Settings& s) {
    RenderModeOptions o;
    o.mode = s.mode;
    o.lidr.packing = {parsePackingScheme(s.scheme), s.budget, s.indexBits};
    o.transparency = true;
    return createRenderer(o, page->context->info(), page->scene, kWidth, kHeight);
}

// Applies new settings; anything the library refuses keeps the old ones and says why (as lidr-viewer does).
bool applySettings(const Settings& wanted) {
    const bool rebuild = wanted.mode != page->settings.mode || wanted.scheme != page->settings.scheme ||
                         wanted.budget != page->settings.budget || wanted.indexBits != page->settings.indexBits ||
                         !page->renderer;
    try {
        if (wanted.lightCount < 1 || wanted.lightCount > int(page->scene.lights.size()))
            throw Error("light count: 1 to " + std::to_string(page->scene.lights.size()) + ", got " +
                        std::to_string(wanted.lightCount));
        if (wanted.view != "frame" && wanted.view != "reference" && wanted.view != "difference" &&
            wanted.view != "index-lists" && wanted.view != "overlap")
            throw Error("view '" + wanted.view + "' (valid: frame, reference, difference, index-lists, overlap)");
        if ((wanted.view == "index-lists" || wanted.view == "overlap") && wanted.mode != "lidr")
            throw Error("the " + wanted.view + " view shows LIDR's index lists: choose mode lidr");
        if (rebuild) {
            std::unique_ptr<Renderer> r = makeRenderer(wanted);
            r->setTiming(true, true);  // CPU clock around glFinish per pass: WebGL 1 has no timer queries lidr uses
            page->renderer = std::move(r);
        }
        page->settings = wanted;
        page->message.clear();
        return true;
    } catch (const std::exception& e) {
        page->message = e.what();
        return false;
    }
}

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
        page->reference = std::make_unique<ReferenceRenderer>(page->context->info(), page->scene, kWidth, kHeight,
                                                              int(page->scene.lights.size()));
    return *page->reference;
}

// Renders the debug view the settings ask for, after the frame (the CPU views read the frame back).
void drawView(const Camera& camera, const std::vector<PointLight>& lights, const ShadingParameters& shading) {
    const std::string& view = page->settings.view;
    if (view == "frame") {
        page->presenter->present(page->renderer->targets(), 0);
        showGlCanvas();
        page->viewNote = "the " + page->renderer->modeName() + " frame";
        return;
    }
    ReferenceRenderer& ref = reference();
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
        page->depthReadback = std::make_unique<web::DepthReadback>(page->context->info(), page->scene, kWidth, kHeight);
    const CameraMatrices m = cameraMatrices(camera, kWidth, kHeight);
    const CoverageTruth truth = computeCoverage(page->depthReadback->read(m), m, lights);
    const ListCheck lists = checkIndexLists(truth, lidr.scheme(), lidr.readIndexTargets(), uint32_t(lights.size()),
                                            lidr.frameLightIndices());
    const int budget = lidr.scheme().config().budget;
    if (view == "index-lists") {
        showCpuImage(indexListImage(kWidth, kHeight, lists.decoded));
        page->viewNote = "decoded index lists (one colour per light), " + std::to_string(lists.droppedLightPixels) +
                         " dropped light-pixels";
    } else {
        std::vector<int> counts(size_t(kWidth) * kHeight);
        for (size_t p = 0; p < counts.size(); ++p) counts[p] = truth.count(p);
        showCpuImage(overlapHeatMap(kWidth, kHeight, counts, budget, &truth.surface));
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
    page->camera.move(local, speed * dt);
}

void frame() {
    const double now = emscripten_get_now();
    const float dt = page->lastFrameMs > 0.0 ? float(std::min(0.1, (now - page->lastFrameMs) / 1000.0)) : 0.0f;
    if (page->lastFrameMs > 0.0) page->frameMsAverage = 0.9 * page->frameMsAverage + 0.1 * (now - page->lastFrameMs);
    page->lastFrameMs = now;
    if (!page->settings.paused) page->time += dt;
    moveCamera(dt);
    try {
        const Camera camera = page->camera.camera();
        const std::vector<PointLight> lights = currentLights();
        const ShadingParameters shading{page->scene.ambient, page->scene.backgroundColor};
        const FrameStats& stats = page->renderer->render(camera, lights, shading);
        page->renderMsAverage = 0.9 * page->renderMsAverage + 0.1 * stats.frameMilliseconds();
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
    if (type == EMSCRIPTEN_EVENT_MOUSEMOVE && page->dragging)
        page->camera.turn(float(e->movementX) * 0.004f, -float(e->movementY) * 0.004f);
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

// Sets one setting by name ("mode", "scheme", "budget", "index-bits", "view", "lights", "paused"), returns 1 when
// applied, 0 when refused (lidr_web_status() then carries the reason).
EMSCRIPTEN_KEEPALIVE int lidr_web_set(const char* name, const char* value) {
    Settings s = page->settings;
    const std::string n = name, v = value;
    try {
        if (n == "mode") s.mode = v;
        else if (n == "scheme") s.scheme = v;
        else if (n == "budget") s.budget = std::stoi(v);
        else if (n == "index-bits") s.indexBits = std::stoi(v);
        else if (n == "view") s.view = v;
        else if (n == "lights") s.lightCount = std::stoi(v);
        else if (n == "paused") s.paused = v == "1" || v == "true";
        else throw Error("unknown setting '" + n + "' (mode, scheme, budget, index-bits, view, lights, paused)");
    } catch (const std::logic_error&) {
        page->message = "setting " + n + ": a number, got '" + v + "'";
        return 0;
    } catch (const std::exception& e) {
        page->message = e.what();
        return 0;
    }
    return applySettings(s) ? 1 : 0;
}

// Starts the animation loop (the page calls it unless it runs its check).
EMSCRIPTEN_KEEPALIVE void lidr_web_start() { emscripten_set_main_loop(frame, 0, 0); }

EMSCRIPTEN_KEEPALIVE void lidr_web_reset_camera() { page->camera.reset(page->scene.camera); }

// The page's state for its panel, as JSON.
EMSCRIPTEN_KEEPALIVE const char* lidr_web_status() {
    static std::string json;
    const Settings& s = page->settings;
    char figures[256];
    std::snprintf(figures, sizeof figures,
                  "\"frameMs\":%.2f,\"renderMs\":%.2f,\"time\":%.2f,\"budget\":%d,\"indexBits\":%d,\"lights\":%d,"
                  "\"paused\":%s",
                  page->frameMsAverage, page->renderMsAverage, page->time, s.budget, s.indexBits, s.lightCount,
                  s.paused ? "true" : "false");
    json = "{\"gl\":\"" + jsonEscape(page->context->info().summary()) + "\",\"mode\":\"" + s.mode +
           "\",\"scheme\":\"" + s.scheme + "\",\"view\":\"" + s.view + "\",\"viewNote\":\"" + jsonEscape(page->viewNote) +
           "\",\"message\":\"" + jsonEscape(page->message) + "\"," + figures + "}";
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
        options.windowWidth = kWidth;
        options.windowHeight = kHeight;
        page->context = GlContext::create(options);
        DefaultSceneOptions sceneOptions;
        sceneOptions.width = kWidth;
        sceneOptions.height = kHeight;
        page->scene = makeDefaultScene(sceneOptions);
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
