#pragma once
// lidr-viewer: the interactive viewer (GLFW window, Dear ImGui panel). It owns one lidr::Renderer built from
// demo::RendererChoice (the same settings lidr-demo takes on its command line) and rebuilds it whenever a
// setting changes; a setting the library refuses is reverted and its reason shown. Debug views come from the
// code lidr-demo --headless writes its PNGs with (demo/frame_views.h, lidr/eval).
#include <array>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "demo_options.h"
#include "fly_camera.h"
#include "lidr/base/image.h"
#include "lidr/eval/image_compare.h"
#include "lidr/platform/context.h"
#include "lidr/modes/render_mode.h"
#include "script.h"

struct GLFWwindow;

namespace lidr {
class FramePresenter;
}

namespace lidr::viewer {

class ImGuiEs2Renderer;

enum class View { Frame, Difference, IndexLists, Overlap, Marked, TileHeatMap, ShadowAtlas };
constexpr int kViewCount = 7;
// "frame", "difference", "index-lists", "overlap", "marked", "tile-heatmap", "shadow-atlas"
const char* viewName(View v);

struct ViewerOptions {
    std::string outDir = "viewer-out";  // screenshots (F12) and saved artefacts (F11) go here
    std::string scriptFile;             // empty: interactive
    bool hidden = false;                // an invisible window (tests; needs a GLX that renders to one)
    bool startPaused = false;
    bool fixedSize = false;             // keep --width/--height when the window is resized (the frame is scaled)
};

class Viewer {
public:
    // Loads the scene, opens the window (GLFW backends only: glfw, desktop GL; glfw-gles2, OpenGL ES 2.0) and
    // builds the first renderer; throws lidr::Error
    // (bad options, no display, a first configuration the library refuses).
    Viewer(const demo::SceneChoice& sceneChoice, const demo::RendererChoice& rc, const ViewerOptions& options);
    ~Viewer();
    // Runs until Esc, the window is closed or the script ends. Returns the exit code: 0, or 1 after a failed
    // script check or an error (printed to stderr).
    int run();

    // Called from the GLFW key callback and from the script's press action.
    void onKeyPress(int key, int mods);
    // Called from the GLFW drop callback and from the script's drop action: the file to open next frame
    // (viewer_files.cpp).
    void onDrop(const std::vector<std::string>& paths);

private:
    struct Evaluation {  // what "compute" (C) found for one frame; stale once the frame changes
        bool valid = false;
        long frame = -1;
        ImageError error, errorWithinBudget;  // the second: pixels whose lists hold every light (LIDR)
        bool listsChecked = false;
        long droppedLightPixels = 0, pixelsOverBudget = 0, invalidSlots = 0;
        int maxOverlap = 0, maxMarked = 0;
        std::map<View, ImageRGBA8> images;
        ImageRGBA8 reference;
    };

    bool apply(const demo::RendererChoice& next, const std::string& what);
    bool changeSetting(const std::string& name, const std::string& value);  // UI and script; false: refused
    std::string setting(const std::string& name) const;
    int maxLightsFor(const demo::RendererChoice& rc) const;
    // The lights of this frame (the light count, the animation), with castsShadow as the shadow setting says
    // (the rule's K brightest seen from the current camera); `shading`: the frame's shading with its shadows.
    std::vector<PointLight> currentLights(ShadingParameters* shading = nullptr) const;
    demo::ShadowChoice shadowChoice(const demo::RendererChoice& rc) const;
    void renderFrame();
    // The renderer that drew the last frame: the automatic mode's current candidate, else renderer_.
    const Renderer& drawingRenderer() const;
    // Re-renders at the window's framebuffer size when it changed (unless --fixed-size); a size the library
    // refuses (target memory) keeps the old one, scaled, with the reason in the status line.
    void followWindowSize(int fbw, int fbh);
    void drawWindow(int fbw, int fbh);
    const ImageRGBA8* shownView() const;  // the debug view's image on screen; nullptr: the frame
    void buildUi(int fbw, int fbh);
    void uiSettings();
    void uiStats();
    void uiViews();
    bool viewAvailable(View v, std::string* why = nullptr) const;
    void computeViews();
    void markDirty() { dirty_ = true; }
    void processInput(float dt);
    void saveScreenshot(const std::string& file);
    void saveAll(const std::string& dir);
    ImageRGBA8 readWindow(int fbw, int fbh) const;
    void resetAll();
    // Files (viewer_files.cpp): open a scene file in place of the current one (kept, with the reason in the
    // status line, when it cannot be read or rendered), reload it (F5), scatter lights over it.
    void openPendingFile();
    bool openScene(const std::string& path, const std::string& what, bool keepCamera);
    void reloadScene();
    // scene_ = fileScene_ plus `count` lights scattered over it (lidr::scatterLights); throws lidr::Error.
    void scatterOver(int count);
    // Adds to fileScene_'s warnings the material textures this context has no unit for (ES 2.0 guarantees 8;
    // lidr-demo prints the same lines), so the terminal and the file panel show them.
    void addTextureUnitWarnings();
    void uiFile();
    // Script: runs actions until one waits; throws ScriptFailure on a failed check.
    void stepScript(int fbw, int fbh);
    void runAction(const ScriptAction& a, int fbw, int fbh);

    demo::SceneChoice sceneChoice_;
    demo::RendererChoice initialChoice_, rc_;
    ViewerOptions options_;
    Scene fileScene_;       // the scene as read (the built-in room, --scene or a dropped file)
    Scene scene_;           // fileScene_ with scatteredLights_ more lights: what is rendered
    std::string scenePath_;  // empty: the built-in room
    int scatteredLights_ = 0;
    int scatterDraft_ = 0;  // the panel's slider while it is dragged
    bool scatterDragged_ = false;
    std::optional<std::string> pendingOpen_;
    int width_ = 0, height_ = 0;          // the render size (follows the window unless --fixed-size)
    int refusedWidth_ = 0, refusedHeight_ = 0;  // a window size the library refused, not tried again
    std::unique_ptr<GlContext> context_;
    GLFWwindow* window_ = nullptr;
    // --context glfw-gles2: ImGui drawn by imgui_es2.h (the OpenGL2 backend is fixed function), the frame put
    // into the window by FramePresenter (ES 2.0 has no glBlitFramebuffer).
    bool gles_ = false;
    std::unique_ptr<ImGuiEs2Renderer> es2Ui_;
    std::unique_ptr<FramePresenter> presenter_;
    std::unique_ptr<Renderer> renderer_;
    RenderModeOptions modeOptions_;
    ShadingParameters shading_;

    FlyCamera camera_;
    float moveSpeed_ = 3.0f;  // scene units per second
    double lastCursorX_ = 0.0, lastCursorY_ = 0.0;
    bool cursorKnown_ = false;
    float animTime_ = 0.0f, animSpeed_ = 1.0f;
    // The camera rides on the scene's animated camera (an AFF `k camera`, a glTF camera on an animated node) until
    // the user flies it; the panel's checkbox puts it back.
    bool followSceneCamera_ = false;
    float loopedTime(float t) const;
    bool paused_ = false;
    int lightCount_ = 0;
    long frameNumber_ = 0;
    bool dirty_ = true;
    bool showUi_ = true;
    bool quit_ = false;
    bool computeRequested_ = false;
    std::optional<std::string> pendingScreenshot_, pendingSave_;
    int screenshotCounter_ = 0, saveCounter_ = 0;

    View view_ = View::Frame;
    Evaluation eval_;
    unsigned viewTexture_ = 0;
    View uploadedView_ = View::Frame;
    long uploadedFrame_ = -2;
    ImageRGBA8 tileHeat_;
    ImageRGBA8 shadowAtlasView_;  // View::ShadowAtlas, read each frame while shown

    std::string status_;  // the last setting change: applied, or refused and why
    bool lastRefused_ = false;
    std::map<std::string, std::deque<float>> history_;  // per pass, the last kHistory frames (ms)
    std::vector<std::string> passOrder_;
    std::deque<float> frameHistory_;
    float panelMin_[2] = {0, 0}, panelMax_[2] = {0, 0};

    // script state
    std::vector<ScriptAction> script_;
    size_t scriptPos_ = 0;
    int scriptWait_ = 0;
    std::set<int> scriptHeld_;
    glm::vec3 markPosition_{0.0f}, markForward_{0.0f}, markRight_{0.0f};
    ImageRGBA8 markFrame_;
    bool marked_ = false;
    std::map<std::string, std::pair<ImageRGBA8, ImageRGBA8>> screenshots_;  // file -> (window, frame shown)
};

}  // namespace lidr::viewer
