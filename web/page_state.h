#pragma once
// The page's state (web/lidr_web.cpp is the page; doc/web.md): what the controls set (Settings), what the page
// holds (Page, one, `page`), and what changes it: settings applied with the library's checks, the image's size, a
// frame timed, the bench run. Emscripten only (the page's GL context); the plain C++ parts are page_query.h and
// page_bench.h.
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "depth_readback.h"
#include "fly_camera.h"
#include "lidr/modes/reference_renderer.h"
#include "lidr/modes/render_mode.h"
#include "lidr/platform/context.h"
#include "lidr/render/present.h"
#include "lidr/scene/scene.h"

namespace lidr::web {

// The image before the page sizes it (and the size the checks use): 640x480.
constexpr int kStartWidth = 640, kStartHeight = 480;

// What the HTML controls set. Budgets and widths are fixed numbers: the automatic budget measures the overlap
// with occlusion queries, which WebGL 1 does not have (doc/web.md).
struct Settings {
    std::string mode = "lidr";  // lidr, tiled, clustered, forward-multipass, forward-brute
    std::string scheme = "bitshift";
    int budget = 4;
    int indexBits = 8;
    std::string view = "frame";  // frame, reference, difference, index-lists, overlap
    int lightCount = 255;  // the room: its first N lights; a model: its own, then scattered ones up to N
    bool paused = false;
    std::string shadows = "off";  // off, scene (the lights' own flags), or K: the K brightest lights in view
    bool shadowFilter = false;    // filtered shadow edges (ShadowSettings::filtered)
    // The environment light (doc/colour.md): auto (a model gets the built-in studio room in place of the uniform
    // ambient, the room none), default, none, or a .hdr the page wrote into its file system; and its intensity.
    std::string environment = "auto";
    float environmentIntensity = 1.0f;
};

// The page's shadow atlas: 2048 texels a side, the largest tile (up to 512) that holds the casters' maps.
constexpr int kShadowAtlasSize = 2048;

// A model's light count reaches this many (16-bit indices hold 65535; the slider stops sooner, for a frame
// time a browser bears).
constexpr int kMaxModelLights = 16384;

struct Page {
    std::unique_ptr<GlContext> context;
    int width = kStartWidth, height = kStartHeight;  // the image: the canvases' size and the renderers' targets
    Scene fileScene;  // the room or the model as read
    Scene scene;      // what is rendered: fileScene, plus the lights scattered over a model
    std::string sceneName = "built-in room";
    bool model = false;  // a loaded file, not the room
    Settings settings;
    std::unique_ptr<Renderer> renderer;
    std::unique_ptr<ReferenceRenderer> reference;  // built on first use by a view that needs it
    std::unique_ptr<web::DepthReadback> depthReadback;
    std::unique_ptr<FramePresenter> presenter;
    viewer::FlyCamera camera;
    float moveSpeed = 3.0f;
    float time = 2.0f;
    // A keyframed scene's camera (an AFF `k camera`, a glTF camera on an animated node) is followed until the user
    // flies or turns the camera.
    bool followSceneCamera = false;
    double lastFrameMs = 0.0, frameMsAverage = 0.0, renderMsAverage = 0.0, renderMsLast = 0.0;
    std::set<std::string> keysDown;
    bool dragging = false;
    std::string message;  // the last refusal or error, shown in red
    std::string viewNote;  // what the current debug view shows
    std::shared_ptr<const Environment> environmentFile;  // the last .hdr read, for environment = its path
    std::string environmentFileName;
};
extern Page* page;

// The most lights the light control offers: a model's kMaxModelLights, the room's own.
int maxLights();
// The scene for a light count: the room keeps its lights (the count picks the first N when drawing); a model
// gets count - its own lights scattered over it (none when it has enough).
Scene sceneWithLights(const Scene& file, bool model, int count);
// The frame's lights, with castsShadow as the shadow setting says, and its shading (shadows on or off).
std::vector<PointLight> currentLights(const Camera& camera, ShadingParameters& shading);
// Applies new settings; anything the library refuses keeps the old ones and says why in page->message (as
// lidr-viewer does). `sceneChanged`: page->fileScene is new (the renderer and the views' helpers are made again).
bool applySettings(Settings wanted, bool sceneChanged = false);
// One setting by its name and text (lidr_web_set's names); throws lidr::Error for an unknown name or a number
// that is not one. The value itself is checked by applySettings and the library.
void setFromText(Settings& s, const std::string& n, const std::string& v);
// One frame of the page's renderer, finished by a 1-pixel read, in milliseconds.
double renderTimed(const Camera& camera, const std::vector<PointLight>& lights, const ShadingParameters& shading);
// The image at `width` x `height`; false, keeping the old size, where refused (the reason in page->message).
bool resizePage(int width, int height);
// bench=N: the table of N timed frames of each mode in `modes` (empty: every mode but auto).
std::string runBench(int frames, std::vector<std::string> modes);

}  // namespace lidr::web
