// GLEW before anything that includes GL/gl.h (GLFW does).
#include "lidr/base/gl.h"

#include "viewer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl2.h>
#include <nlohmann/json.hpp>

#include "frame_views.h"
#include "imgui_es2.h"
#include "lidr/base/error.h"
#include "lidr/eval/artefacts.h"
#include "lidr/eval/frame_evaluation.h"
#include "lidr/gl/render_targets.h"
#include "lidr/modes/auto_mode_renderer.h"
#include "lidr/render/present.h"

namespace lidr::viewer {
namespace {

constexpr size_t kHistory = 120;
constexpr float kStepSeconds = 1.0f / 30.0f;  // one animation step (N), and a scripted frame's time

struct ScriptFailure : Error {
    using Error::Error;
};

const char* const kModes[] = {"lidr", "tiled", "forward-multipass", "forward-brute", "auto"};
constexpr int kModeCount = 5;
const char* const kSchemes[] = {"auto", "bitshift", "max-stencil", "cpu-sorted"};
const char* const kBudgets[] = {"auto", "1", "2", "4", "8", "16"};
const char* const kIndexBits[] = {"auto", "4", "8", "16"};
const char* const kVolumeTests[] = {"auto", "sphere", "sphere-ray", "backface", "exact", "frontface"};
const int kMsaa[] = {0, 2, 4, 8, 16};
const int kTileSizes[] = {8, 16, 32, 64};

std::string bytesText(double b) {
    char s[64];
    if (b >= 1024.0 * 1024.0)
        std::snprintf(s, sizeof s, "%.2f MiB", b / (1024.0 * 1024.0));
    else
        std::snprintf(s, sizeof s, "%.1f KiB", b / 1024.0);
    return s;
}

int keyFromName(const std::string& n) {
    std::string u;
    for (char c : n) u += char(std::toupper(static_cast<unsigned char>(c)));
    if (u.size() == 1 && u[0] >= 'A' && u[0] <= 'Z') return GLFW_KEY_A + (u[0] - 'A');
    if (u.size() == 1 && u[0] >= '0' && u[0] <= '9') return GLFW_KEY_0 + (u[0] - '0');
    if (u.size() >= 2 && u[0] == 'F' && std::all_of(u.begin() + 1, u.end(), ::isdigit)) {
        const int f = std::stoi(u.substr(1));
        if (f >= 1 && f <= 12) return GLFW_KEY_F1 + f - 1;
    }
    if (u == "ESC" || u == "ESCAPE") return GLFW_KEY_ESCAPE;
    if (u == "SPACE") return GLFW_KEY_SPACE;
    if (u == "TAB") return GLFW_KEY_TAB;
    if (u == "PERIOD" || u == ".") return GLFW_KEY_PERIOD;
    if (u == "SHIFT") return GLFW_KEY_LEFT_SHIFT;
    return -1;
}

void keyCallback(GLFWwindow* w, int key, int /*scancode*/, int action, int mods) {
    if (action != GLFW_PRESS) return;
    if (ImGui::GetCurrentContext() && ImGui::GetIO().WantTextInput) return;
    if (auto* v = static_cast<Viewer*>(glfwGetWindowUserPointer(w))) v->onKeyPress(key, mods);
}

// What the ImGui OpenGL2 backend (fixed function, client-side arrays) and the ES 2.0 one (imgui_es2.h) need
// after lidr's passes. ES 2.0 has no glDrawBuffer / glReadBuffer: the window's framebuffer is its back buffer.
void resetStateForWindow(int fbw, int fbh, bool gles) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!gles) {
        glDrawBuffer(GL_BACK);
        glReadBuffer(GL_BACK);
    }
    glViewport(0, 0, fbw, fbh);
    glUseProgram(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    GLint attribs = 0;
    glGetIntegerv(GL_MAX_VERTEX_ATTRIBS, &attribs);
    for (GLint i = 0; i < attribs; ++i) glDisableVertexAttribArray(GLuint(i));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
    checkGl("viewer: resetting state for the window");
}

bool compareOp(double a, const std::string& op, double b) {
    if (op == "==") return a == b;
    if (op == "!=") return a != b;
    if (op == "<") return a < b;
    if (op == "<=") return a <= b;
    if (op == ">") return a > b;
    return a >= b;
}

}  // namespace

const char* viewName(View v) {
    switch (v) {
        case View::Frame: return "frame";
        case View::Difference: return "difference";
        case View::IndexLists: return "index-lists";
        case View::Overlap: return "overlap";
        case View::Marked: return "marked";
        case View::TileHeatMap: return "tile-heatmap";
    }
    return "?";
}

Viewer::Viewer(const demo::SceneChoice& sceneChoice, const demo::RendererChoice& rc, const ViewerOptions& options)
    : sceneChoice_(sceneChoice), options_(options) {
    if (rc.context != "auto" && rc.context != "glfw" && rc.context != "glfw-gles2")
        throw Error("lidr-viewer draws into a window: --context must be glfw, glfw-gles2 (OpenGL ES 2.0) or auto, got '" +
                    rc.context + "'");
    if (!options_.scriptFile.empty()) script_ = parseScript(options_.scriptFile);
    scene_ = sceneChoice.load();
    width_ = scene_.width;
    height_ = scene_.height;
    // The settings as the UI shows them: the scene's choices made explicit.
    rc_ = rc;
    const RenderModeOptions first = rc.renderModeOptions(scene_);  // throws on a bad name
    rc_.mode = first.mode;
    rc_.msaa = first.msaaSamples;
    rc_.transparency = first.transparency ? "on" : "off";
    demo::checkTargetMemory(scene_, first);
    initialChoice_ = rc_;
    shading_ = {scene_.ambient, scene_.backgroundColor};
    camera_.reset(scene_.camera);
    moveSpeed_ = std::max(0.5f, 0.15f * glm::length(scene_.boundsMax() - scene_.boundsMin()));
    animTime_ = scene_.time;
    paused_ = options_.startPaused;
    lightCount_ = int(scene_.lights.size());

    ContextOptions co;
    co.backend = rc.context == "glfw-gles2" ? ContextBackend::GlfwGles2 : ContextBackend::Glfw;
    co.visibleWindow = !options_.hidden;
    co.windowWidth = width_;
    co.windowHeight = height_;
    co.windowTitle = "lidr-viewer";
    context_ = GlContext::create(co);
    window_ = static_cast<GLFWwindow*>(context_->nativeWindow());
    gles_ = context_->info().gles;
    std::cout << "GL: " << context_->info().summary() << std::endl;
    glfwSetWindowUserPointer(window_, this);
    glfwSetKeyCallback(window_, keyCallback);  // before ImGui's, which chains to it

    if (!apply(rc_, "the configuration")) throw Error(status_);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the working folder
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    if (gles_) {
        es2Ui_ = std::make_unique<ImGuiEs2Renderer>();
        presenter_ = std::make_unique<FramePresenter>();
    } else {
        ImGui_ImplOpenGL2_Init();
    }
    checkGl("viewer: starting Dear ImGui");
}

Viewer::~Viewer() {
    renderer_.reset();
    if (viewTexture_) glDeleteTextures(1, &viewTexture_);
    presenter_.reset();
    if (ImGui::GetCurrentContext()) {
        if (es2Ui_)
            es2Ui_.reset();
        else
            ImGui_ImplOpenGL2_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }
}

int Viewer::maxLightsFor(const demo::RendererChoice& rc) const {
    const int sceneLights = int(scene_.lights.size());
    // (An automatic index width widens to what the visible lights need, up to 16 bits.)
    if (rc.mode != "lidr" || rc.scheme == "auto") return sceneLights;
    for (int bits : {4, 8, 16})
        if (rc.indexBits == std::to_string(bits)) return std::min(sceneLights, (1 << bits) - 1);
    return sceneLights;
}

std::vector<PointLight> Viewer::currentLights() const {
    std::vector<PointLight> l = scene_.lightsAt(animTime_);
    if (int(l.size()) > lightCount_) l.resize(size_t(lightCount_));
    return l;
}

bool Viewer::apply(const demo::RendererChoice& next, const std::string& what) {
    const int oldCount = lightCount_;
    try {
        const RenderModeOptions mo = next.renderModeOptions(scene_);
        demo::checkTargetMemory(scene_, mo);
        // An index width holds (1 << bits) - 1 lights: the renderer is built for the lights the slider allows.
        const int maxLights = maxLightsFor(next);
        Scene renderScene = scene_;
        if (int(renderScene.lights.size()) > maxLights) {
            renderScene.lights.resize(size_t(maxLights));
            if (!renderScene.lightPaths.empty()) renderScene.lightPaths.resize(size_t(maxLights));
        }
        // All the lights the old configuration allowed stays "all"; a smaller count stays, within the new limit.
        lightCount_ = lightCount_ >= maxLightsFor(rc_) ? maxLights : std::min(lightCount_, maxLights);
        std::unique_ptr<Renderer> r = createRenderer(mo, context_->info(), renderScene, width_, height_);
        r->setTiming(true);  // the panel's per-pass times: read a frame or more late, never stalling
        r->render(camera_.camera(), currentLights(), shading_);  // a refusal at draw time reverts too
        checkGl("viewer: first frame of the new configuration");
        renderer_ = std::move(r);
        rc_ = next;
        modeOptions_ = mo;
        history_.clear();
        passOrder_.clear();
        frameHistory_.clear();
        status_ = what + " applied";
        std::cout << "lidr-viewer: " << status_ << std::endl;
        lastRefused_ = false;
        eval_ = {};
        markDirty();
        return true;
    } catch (const std::exception& e) {
        while (glGetError() != GL_NO_ERROR) {
        }
        lightCount_ = oldCount;
        status_ = what + " refused: " + e.what();
        lastRefused_ = true;
        std::cerr << "lidr-viewer: " << status_ << std::endl;
        return false;
    }
}

bool Viewer::changeSetting(const std::string& name, const std::string& value) {
    auto toInt = [&](const std::string& v) {
        size_t used = 0;
        int i = 0;
        try {
            i = std::stoi(v, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != v.size()) throw Error("setting " + name + ": '" + v + "' is not a whole number");
        return i;
    };
    auto toBool = [&](const std::string& v) {
        if (v == "on" || v == "true" || v == "1") return true;
        if (v == "off" || v == "false" || v == "0") return false;
        throw Error("setting " + name + ": '" + v + "' is not on or off");
    };
    if (name == "lights") {
        const int n = toInt(value);
        const int maxL = maxLightsFor(rc_);
        if (n < 0 || n > maxL)
            throw Error("setting lights: " + value + " is outside 0.." + std::to_string(maxL) +
                        (maxL < int(scene_.lights.size()) ? " (the index width's limit)" : ""));
        lightCount_ = n;
        markDirty();
        return true;
    }
    if (name == "view") {
        for (int i = 0; i < kViewCount; ++i)
            if (value == viewName(View(i))) {
                std::string why;
                if (!viewAvailable(View(i), &why)) {
                    status_ = std::string("view ") + value + " refused: " + why;
                    lastRefused_ = true;
                    return false;
                }
                view_ = View(i);
                if (view_ != View::Frame && view_ != View::TileHeatMap) computeRequested_ = true;
                return true;
            }
        throw Error("setting view: unknown view '" + value +
                    "' (frame, difference, index-lists, overlap, marked, tile-heatmap)");
    }
    if (name == "paused") {
        paused_ = toBool(value);
        return true;
    }
    if (name == "speed") {
        const int percent = toInt(value);
        if (percent < 0 || percent > 400) throw Error("setting speed: a percentage from 0 to 400, got " + value);
        animSpeed_ = float(percent) / 100.0f;
        return true;
    }
    demo::RendererChoice next = rc_;
    if (name == "mode") next.mode = value;
    else if (name == "scheme") {
        next.scheme = value;
        // The automatic scheme chooses budget and width itself; a named scheme other than bit-shift needs a fixed
        // budget (only bit-shift's stencil count measures one): the choices the library would refuse are made
        // for the user, who can change them after.
        if (value == "auto") next.budget = next.indexBits = "auto";
        else if (value != "bitshift" && next.budget == "auto") next.budget = "8";
    }
    else if (name == "budget") next.budget = value;
    else if (name == "index-bits") next.indexBits = value;
    else if (name == "volume-test") next.volumeTest = value;
    else if (name == "msaa") next.msaa = toInt(value);
    else if (name == "per-sample") next.msaaPerSample = toBool(value);
    else if (name == "transparency") next.transparency = toBool(value) ? "on" : "off";
    else if (name == "volume-detail") next.volumeDetail = toBool(value);
    else if (name == "tile-size") next.tileSize = toInt(value);
    else if (name == "depth-bounds") next.noDepthBounds = !toBool(value);
    else if (name == "half-z") next.halfZ = toBool(value);
    else
        throw Error("unknown setting '" + name +
                    "' (mode, scheme, budget, index-bits, volume-test, msaa, per-sample, transparency, volume-detail, "
                    "tile-size, depth-bounds, half-z, lights, view, paused, speed)");
    return apply(next, name + " " + value);
}

std::string Viewer::setting(const std::string& name) const {
    if (name == "mode") return rc_.mode;
    if (name == "scheme") return rc_.scheme;
    if (name == "budget") return rc_.budget;
    if (name == "index-bits") return rc_.indexBits;
    if (name == "volume-test") return rc_.volumeTest;
    if (name == "msaa") return std::to_string(rc_.msaa.value_or(0));
    if (name == "per-sample") return rc_.msaaPerSample ? "on" : "off";
    if (name == "transparency") return rc_.transparency;
    if (name == "volume-detail") return rc_.volumeDetail ? "on" : "off";
    if (name == "tile-size") return std::to_string(rc_.tileSize);
    if (name == "depth-bounds") return rc_.noDepthBounds ? "off" : "on";
    if (name == "half-z") return rc_.halfZ ? "on" : "off";
    if (name == "lights") return std::to_string(lightCount_);
    if (name == "view") return viewName(view_);
    if (name == "paused") return paused_ ? "on" : "off";
    throw Error("unknown setting '" + name + "'");
}

bool Viewer::viewAvailable(View v, std::string* why) const {
    auto no = [&](const char* reason) {
        if (why) *why = reason;
        return false;
    };
    const bool lidrMode = dynamic_cast<const LidrRenderer*>(&drawingRenderer()) != nullptr;
    switch (v) {
        case View::Frame:
        case View::Difference: return true;
        case View::IndexLists:
        case View::Overlap:
        case View::Marked:
            if (!lidrMode) return no("index lists and light counts exist in the lidr mode only");
            if (rc_.msaaPerSample) return no("per-sample index targets are multisample textures: they cannot be read back");
            return true;
        case View::TileHeatMap:
            if (!dynamic_cast<const TiledRenderer*>(&drawingRenderer())) return no("the tile heat map is the tiled mode's");
            return true;
    }
    return false;
}

void Viewer::onKeyPress(int key, int mods) {
    const bool shift = mods & GLFW_MOD_SHIFT;
    switch (key) {
        case GLFW_KEY_ESCAPE: quit_ = true; break;
        case GLFW_KEY_P:
        case GLFW_KEY_SPACE: paused_ = !paused_; break;
        case GLFW_KEY_PERIOD:
        case GLFW_KEY_N:
            paused_ = true;
            animTime_ += kStepSeconds;
            markDirty();
            break;
        case GLFW_KEY_R: resetAll(); break;
        case GLFW_KEY_C: computeRequested_ = true; break;
        case GLFW_KEY_TAB: showUi_ = !showUi_; break;
        case GLFW_KEY_M: {  // next mode (Shift: previous)
            int i = 0;
            while (i < kModeCount && rc_.mode != kModes[i]) ++i;
            changeSetting("mode", kModes[(i + (shift ? kModeCount - 1 : 1)) % kModeCount]);
            break;
        }
        case GLFW_KEY_V: {  // next available view
            for (int k = 1; k <= kViewCount; ++k) {
                const View v = View((int(view_) + k) % kViewCount);
                if (viewAvailable(v)) {
                    changeSetting("view", viewName(v));
                    break;
                }
            }
            break;
        }
        case GLFW_KEY_F12: pendingScreenshot_ = ""; break;
        case GLFW_KEY_F11: pendingSave_ = ""; break;
        default: break;
    }
}

void Viewer::resetAll() {
    camera_.reset(scene_.camera);
    animTime_ = scene_.time;
    animSpeed_ = 1.0f;
    view_ = View::Frame;
    lightCount_ = int(scene_.lights.size());
    if (!apply(initialChoice_, "reset")) lightCount_ = maxLightsFor(rc_);
    markDirty();
}

void Viewer::processInput(float dt) {
    const ImGuiIO& io = ImGui::GetIO();
    auto down = [&](int key) {
        return scriptHeld_.count(key) || (!io.WantCaptureKeyboard && glfwGetKey(window_, key) == GLFW_PRESS);
    };
    glm::vec3 local(0.0f);
    if (down(GLFW_KEY_W)) local.z += 1.0f;
    if (down(GLFW_KEY_S)) local.z -= 1.0f;
    if (down(GLFW_KEY_D)) local.x += 1.0f;
    if (down(GLFW_KEY_A)) local.x -= 1.0f;
    if (down(GLFW_KEY_E)) local.y += 1.0f;
    if (down(GLFW_KEY_Q)) local.y -= 1.0f;
    const float speed = moveSpeed_ * (down(GLFW_KEY_LEFT_SHIFT) || down(GLFW_KEY_RIGHT_SHIFT) ? 4.0f : 1.0f);
    if (local != glm::vec3(0.0f)) {
        camera_.move(local, speed * dt);
        markDirty();
    }
    // Mouse look: drag with the right button, or the left one outside the panel.
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window_, &x, &y);
    const bool look = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                      (!io.WantCaptureMouse && glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS);
    if (look && cursorKnown_ && (x != lastCursorX_ || y != lastCursorY_)) {
        camera_.turn(float(x - lastCursorX_) * 0.004f, -float(y - lastCursorY_) * 0.004f);
        markDirty();
    }
    lastCursorX_ = x;
    lastCursorY_ = y;
    cursorKnown_ = true;
    if (!paused_ && dt > 0.0f) {
        animTime_ += dt * animSpeed_;
        markDirty();
    }
}

void Viewer::renderFrame() {
    try {
        const FrameStats& st = renderer_->render(camera_.camera(), currentLights(), shading_);
        checkGl("viewer: rendering the frame");
        float total = 0.0f;
        for (const PassTime& p : st.passes) {
            auto& h = history_[p.pass];
            if (std::find(passOrder_.begin(), passOrder_.end(), p.pass) == passOrder_.end()) passOrder_.push_back(p.pass);
            h.push_back(float(p.milliseconds));
            if (h.size() > kHistory) h.pop_front();
            total += float(p.milliseconds);
        }
        frameHistory_.push_back(total);
        if (frameHistory_.size() > kHistory) frameHistory_.pop_front();
    } catch (const GlError&) {
        throw;
    } catch (const std::exception& e) {  // e.g. the light count: revert to the initial configuration
        status_ = std::string("frame refused: ") + e.what();
        lastRefused_ = true;
        std::cerr << "lidr-viewer: " << status_ << std::endl;
        lightCount_ = std::min(lightCount_, maxLightsFor(rc_));
    }
    if (auto* tiled = dynamic_cast<const TiledRenderer*>(&drawingRenderer()); tiled && view_ == View::TileHeatMap)
        tileHeat_ = tiled->tileHeatMap(16);
}

const Renderer& Viewer::drawingRenderer() const {
    if (const auto* autoMode = dynamic_cast<const AutoModeRenderer*>(renderer_.get())) return autoMode->lastRenderer();
    return *renderer_;
}

void Viewer::followWindowSize(int fbw, int fbh) {
    if (options_.fixedSize || fbw <= 0 || fbh <= 0) return;  // 0 x 0: minimised
    if (fbw == width_ && fbh == height_) return;
    if (fbw == refusedWidth_ && fbh == refusedHeight_) return;
    const int oldWidth = width_, oldHeight = height_;
    width_ = fbw;
    height_ = fbh;
    const std::string what = "window size " + std::to_string(fbw) + "x" + std::to_string(fbh);
    if (apply(rc_, what)) {
        refusedWidth_ = refusedHeight_ = 0;
    } else {
        width_ = oldWidth;
        height_ = oldHeight;
        refusedWidth_ = fbw;
        refusedHeight_ = fbh;
    }
}

void Viewer::computeViews() {
    const auto lights = currentLights();
    const Camera cam = camera_.camera();
    Evaluation ev;
    ev.frame = frameNumber_;
    const ImageRGBA8 frame = renderer_->targets().readColor();
    auto reference = demo::makeReference(context_->info(), scene_, modeOptions_, width_, height_, int(lights.size()));
    reference->render(cam, lights, shading_);
    ev.reference = reference->targets().readColor();
    reference.reset();
    ev.error = compareImages(frame, ev.reference);
    ev.images[View::Difference] = differenceImage(frame, ev.reference);
    if (const auto* lidr = dynamic_cast<const LidrRenderer*>(&drawingRenderer()); lidr && !lidr->options().perSampleIndices) {
        const FrameEvaluation fe = evaluateFrame(*lidr, cam, lights, frame, ev.reference);
        const demo::LidrViews lv = demo::lidrViews(fe, width_, height_, lidr->scheme().config().budget);
        ev.images[View::IndexLists] = lv.indexLists;
        ev.images[View::Overlap] = lv.overlap;
        ev.images[View::Marked] = lv.marked;
        ev.listsChecked = true;
        ev.droppedLightPixels = fe.lists.droppedLightPixels;
        ev.invalidSlots = fe.lists.invalidSlots;
        ev.pixelsOverBudget = fe.pixelsOverBudget;
        ev.maxOverlap = fe.maxTruthOverlap;
        ev.maxMarked = fe.maxMarked;
        ev.errorWithinBudget = fe.errorWithinBudget;
    }
    if (const auto* tiled = dynamic_cast<const TiledRenderer*>(&drawingRenderer()))
        ev.images[View::TileHeatMap] = tiled->tileHeatMap(16);
    checkGl("viewer: computing the debug views");
    ev.valid = true;
    eval_ = std::move(ev);
    dirty_ = false;
}

ImageRGBA8 Viewer::readWindow(int fbw, int fbh) const {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!gles_) glReadBuffer(GL_BACK);
    return readPixelsRGBA8(fbw, fbh);
}

const ImageRGBA8* Viewer::shownView() const {
    if (view_ == View::TileHeatMap && tileHeat_.width > 0) return &tileHeat_;
    if (view_ != View::Frame && view_ != View::TileHeatMap && eval_.valid && eval_.images.count(view_))
        return &eval_.images.at(view_);
    return nullptr;
}

void Viewer::drawWindow(int fbw, int fbh) {
    resetStateForWindow(fbw, fbh, gles_);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    const ImageRGBA8* image = shownView();
    if (image) {
        const long stamp = view_ == View::TileHeatMap ? frameNumber_ : eval_.frame;
        if (!viewTexture_) glGenTextures(1, &viewTexture_);
        glBindTexture(GL_TEXTURE_2D, viewTexture_);
        if (uploadedView_ != view_ || uploadedFrame_ != stamp) {
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            glTexImage2D(GL_TEXTURE_2D, 0, gles_ ? GL_RGBA : GL_RGBA8, image->width, image->height, 0, GL_RGBA,
                         GL_UNSIGNED_BYTE, image->pixels.data());  // ES 2.0: the unsized format
            uploadedView_ = view_;
            uploadedFrame_ = stamp;
        }
        glBindTexture(GL_TEXTURE_2D, 0);
        checkGl("viewer: uploading the debug view");
        // Rows are stored top to bottom, so texture row 0 is the image's top: uv (0, 0) at the top left.
        ImGui::GetBackgroundDrawList()->AddImage(reinterpret_cast<ImTextureID>(intptr_t(viewTexture_)), ImVec2(0, 0),
                                                 ImVec2(float(fbw), float(fbh)));
    } else if (gles_) {
        // ES 2.0 has no blit: one textured triangle (the same size copies pixel for pixel, another scales by
        // the nearest texel).
        presenter_->present(renderer_->targets(), 0, 0, 0, fbw, fbh);
    } else {
        const RenderTargets& t = renderer_->targets();
        glBindFramebuffer(GL_READ_FRAMEBUFFER, t.colorFramebuffer().id());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        const bool same = fbw == t.width() && fbh == t.height();
        glBlitFramebuffer(0, 0, t.width(), t.height(), 0, 0, fbw, fbh, GL_COLOR_BUFFER_BIT, same ? GL_NEAREST : GL_LINEAR);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        checkGl("viewer: showing the frame");
    }
}

void Viewer::uiSettings() {
    auto combo = [&](const char* label, const std::string& current, const auto& items, const std::string& setting,
                     auto text, auto enabled) {
        if (ImGui::BeginCombo(label, current.c_str())) {
            for (const auto& item : items) {
                const std::string t = text(item);
                std::string why;
                const bool ok = enabled(item, &why);
                if (ImGui::Selectable(t.c_str(), t == current, ok ? 0 : ImGuiSelectableFlags_Disabled) && t != current)
                    changeSetting(setting, t);
                if (!ok && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", why.c_str());
            }
            ImGui::EndCombo();
        }
    };
    auto str = [](const auto& v) {
        std::ostringstream s;
        s << v;
        return s.str();
    };
    auto always = [](const auto&, std::string*) { return true; };
    const GlInfo& info = context_->info();
    combo("mode (M)", rc_.mode, kModes, "mode", str, always);
    const bool lidrMode = rc_.mode == "lidr";
    ImGui::BeginDisabled(!lidrMode);
    combo("scheme", rc_.scheme, kSchemes, "scheme", str, always);
    ImGui::BeginDisabled(rc_.scheme == "auto");
    combo("budget", rc_.budget, kBudgets, "budget", str, [&](const char* b, std::string* why) {
        if (std::string(b) == "auto" && rc_.scheme != "bitshift" && rc_.scheme != "auto") {
            *why = "an automatic budget is measured from bit-shift packing's stencil count";
            return false;
        }
        return true;
    });
    combo("index bits", rc_.indexBits, kIndexBits, "index-bits", str, always);
    ImGui::EndDisabled();
    if (rc_.scheme == "auto" && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("the automatic scheme chooses budget and index width per frame: name a scheme to fix them");
    combo("volume test", rc_.volumeTest, kVolumeTests, "volume-test", str, always);
    bool detail = rc_.volumeDetail;
    if (ImGui::Checkbox("coarse volumes for small lights", &detail)) changeSetting("volume-detail", detail ? "on" : "off");
    ImGui::EndDisabled();
    if (!lidrMode && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("scheme, budget, index width and volume test are the lidr mode's");
    ImGui::BeginDisabled(rc_.mode != "tiled");
    combo("tile size", std::to_string(rc_.tileSize), kTileSizes, "tile-size", str, always);
    bool bounds = !rc_.noDepthBounds, halfZ = rc_.halfZ;
    if (ImGui::Checkbox("tile depth bounds", &bounds)) changeSetting("depth-bounds", bounds ? "on" : "off");
    ImGui::SameLine();
    if (ImGui::Checkbox("half-Z", &halfZ)) changeSetting("half-z", halfZ ? "on" : "off");
    ImGui::EndDisabled();
    combo("MSAA", std::to_string(rc_.msaa.value_or(0)), kMsaa, "msaa", str, [&](int s, std::string* why) {
        if (s == 0) return true;
        if (!info.multisampleFbo) {
            *why = "this context has no multisample framebuffers";
            return false;
        }
        if (s > info.maxSamples) {
            *why = "GL_MAX_SAMPLES is " + std::to_string(info.maxSamples);
            return false;
        }
        return true;
    });
    bool perSample = rc_.msaaPerSample;
    const bool perSampleOk = info.multisampleTexture && info.sampleShading;
    ImGui::BeginDisabled(!lidrMode || !perSampleOk);
    if (ImGui::Checkbox("per-sample index lists", &perSample)) changeSetting("per-sample", perSample ? "on" : "off");
    ImGui::EndDisabled();
    if (!perSampleOk && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("needs GL 3.2 multisample textures and sample shading; this context has GL %s", info.version.c_str());
    bool transparency = rc_.transparency == "on";
    if (ImGui::Checkbox("transparency", &transparency)) changeSetting("transparency", transparency ? "on" : "off");
    if (!status_.empty()) {
        if (lastRefused_) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", status_.c_str());
        if (lastRefused_) ImGui::PopStyleColor();
    }
}

void Viewer::uiStats() {
    const FrameStats& st = renderer_->lastFrame();
    const bool gpu = std::string(st.timingMethod) == "gpu-timer-query";
    ImGui::Text("times: %s", gpu ? "GPU timer queries" : "CPU clock around glFinish per pass");
    std::vector<float> values(frameHistory_.begin(), frameHistory_.end());
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "frame %.2f ms", values.empty() ? 0.0 : double(values.back()));
    // (PlotLines takes a width of 0 as "item width" but no negative one: give the pixels.)
    ImGui::PlotLines("##frame", values.data(), int(values.size()), 0, overlay, 0.0f, FLT_MAX,
                     ImVec2(ImGui::GetContentRegionAvail().x, 50));
    if (ImGui::BeginTable("passes", 3, ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthStretch, 2.0f);
        ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthFixed, ImGui::GetFontSize() * 5.0f);
        ImGui::TableSetupColumn("history", ImGuiTableColumnFlags_WidthStretch, 1.0f);
        for (const std::string& p : passOrder_) {
            const auto& h = history_[p];
            std::vector<float> v(h.begin(), h.end());
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(p.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%.2f ms", v.empty() ? 0.0 : double(v.back()));
            ImGui::TableNextColumn();
            ImGui::PlotLines(("##" + p).c_str(), v.data(), int(v.size()), 0, nullptr, 0.0f, FLT_MAX,
                             ImVec2(std::max(20.0f, ImGui::GetContentRegionAvail().x), 16));
        }
        ImGui::EndTable();
    }
    ImGui::Text("lights: %d of %d visible (drawn), %ld volume draws", st.drawnLights, int(currentLights().size()),
                st.volumeDrawCalls);
    const bool fresh = eval_.valid && !dirty_;
    if (!eval_.valid) {
        ImGui::TextDisabled("dropped / overlap / error: press C (compute)");
    } else {
        if (!fresh) ImGui::TextDisabled("(figures of an earlier frame: press C)");
        const double psnr = std::isinf(eval_.error.psnr) ? 999.0 : eval_.error.psnr;
        if (eval_.listsChecked) {
            ImGui::Text("max overlap %d (marked %d), dropped light-pixels %ld", eval_.maxOverlap, eval_.maxMarked,
                        eval_.droppedLightPixels);
            ImGui::Text("pixels over budget %ld, invalid slots %ld", eval_.pixelsOverBudget, eval_.invalidSlots);
        }
        ImGui::Text("vs reference: max error %d, PSNR %.1f dB", eval_.error.maxAbsError, psnr);
        if (eval_.listsChecked)
            ImGui::Text("  lists within budget: max error %d, PSNR %.1f dB",
                        eval_.errorWithinBudget.maxAbsError,
                        std::isinf(eval_.errorWithinBudget.psnr) ? 999.0 : eval_.errorWithinBudget.psnr);
    }
    const auto* lidrRenderer = dynamic_cast<const LidrRenderer*>(&drawingRenderer());
    if (lidrRenderer) {
        const AutoDecision& d = st.autoDecision;
        const PackingConfig& c = lidrRenderer->scheme().config();
        if (d.autoBudget || d.autoIndexBits)
            ImGui::TextWrapped("automatic: budget %d%s, %d-bit indices for %d visible lights, re-packed %d times", c.budget,
                               d.autoBudget ? (d.measuredBudget ? " (measured)" : " (overlap above 16)") : " (fixed)",
                               c.indexBits, d.visibleLights, d.repacks);
    }
    if (const auto* autoMode = dynamic_cast<const AutoModeRenderer*>(renderer_.get()))
        ImGui::TextWrapped("auto mode: drawing with %s; %s", autoMode->lastMode().c_str(), autoMode->reason().c_str());
    // The index targets the last frame used (an automatic budget and width change them).
    const unsigned long long targets = estimateRenderTargetBytes(
        width_, height_, rc_.msaa.value_or(0),
        lidrRenderer ? indexBytesPerPixel(lidrRenderer->scheme().config().budget, lidrRenderer->scheme().config().indexBits) : 0,
        lidrRenderer && rc_.msaaPerSample);
    size_t table = 0;
    if (auto* l = dynamic_cast<const LidrRenderer*>(&drawingRenderer())) table = l->lightTable().bytes();
    if (auto* t = dynamic_cast<const TiledRenderer*>(&drawingRenderer())) table = t->lightTable().bytes();
    ImGui::Text("memory: targets %s (estimate), light data %s", bytesText(double(targets)).c_str(),
                bytesText(double(renderer_->lightDataBytes())).c_str());
    if (table) ImGui::Text("light table %s", bytesText(double(table)).c_str());
}

void Viewer::uiViews() {
    for (int i = 0; i < kViewCount; ++i) {
        std::string why;
        const bool ok = viewAvailable(View(i), &why);
        ImGui::BeginDisabled(!ok);
        if (ImGui::RadioButton(viewName(View(i)), view_ == View(i))) changeSetting("view", viewName(View(i)));
        ImGui::EndDisabled();
        if (!ok && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", why.c_str());
        if (i % 3 != 2) ImGui::SameLine();
    }
    if (ImGui::Button("compute (C)")) computeRequested_ = true;
    ImGui::SameLine();
    ImGui::TextDisabled("reference, difference, lists: on demand");
}

void Viewer::buildUi(int fbw, int fbh) {
    if (!showUi_) return;
    const GlInfo& info = context_->info();
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(std::min(400.0f, fbw * 0.5f), std::max(200.0f, fbh - 16.0f)), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.88f);
    ImGui::Begin("lidr-viewer (Tab hides)");
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 7.5f);  // room for the labels
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    panelMin_[0] = pos.x, panelMin_[1] = pos.y, panelMax_[0] = pos.x + size.x, panelMax_[1] = pos.y + size.y;
    ImGui::TextWrapped("%s", info.renderer.c_str());
    ImGui::TextWrapped("GL %s, GLSL %s, %s", info.version.c_str(), info.glslVersion.c_str(), info.backend.c_str());
    ImGui::Text("%s, %dx%d, %d lights", scene_.name.c_str(), width_, height_, int(scene_.lights.size()));
    if (ImGui::CollapsingHeader("settings", ImGuiTreeNodeFlags_DefaultOpen)) uiSettings();
    if (ImGui::CollapsingHeader("frame", ImGuiTreeNodeFlags_DefaultOpen)) uiStats();
    if (ImGui::CollapsingHeader("debug view (V)", ImGuiTreeNodeFlags_DefaultOpen)) uiViews();
    if (ImGui::CollapsingHeader("animation and camera", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGui::Checkbox("pause (P)", &paused_);
        ImGui::SameLine();
        if (ImGui::Button("step (N)")) onKeyPress(GLFW_KEY_N, 0);
        ImGui::SameLine();
        ImGui::Text("t = %.2f s", double(animTime_));
        ImGui::SliderFloat("speed", &animSpeed_, 0.0f, 4.0f, "%.2fx");
        int lights = lightCount_;
        const int maxL = maxLightsFor(rc_);
        if (ImGui::SliderInt("lights", &lights, 0, maxL) && lights != lightCount_) changeSetting("lights", std::to_string(lights));
        if (maxL < int(scene_.lights.size()))
            ImGui::TextDisabled("%s-bit indices hold %d lights: the slider stops there", rc_.indexBits.c_str(), maxL);
        const glm::vec3 p = camera_.position();
        ImGui::Text("camera (%.2f, %.2f, %.2f), yaw %.0f, pitch %.0f", double(p.x), double(p.y), double(p.z),
                    double(glm::degrees(camera_.yaw())), double(glm::degrees(camera_.pitch())));
        ImGui::SliderFloat("move speed", &moveSpeed_, 0.1f, 50.0f, "%.1f /s", ImGuiSliderFlags_Logarithmic);
        if (ImGui::Button("reset (R)")) resetAll();
        ImGui::SameLine();
        if (ImGui::Button("screenshot (F12)")) pendingScreenshot_ = "";
        ImGui::SameLine();
        if (ImGui::Button("save all (F11)")) pendingSave_ = "";
    }
    if (ImGui::CollapsingHeader("controls")) {
        ImGui::TextWrapped(
            "WASD move, Q/E down/up, Shift faster; drag with the right mouse button (or the left one outside this "
            "panel) to look. P/Space pause, N step, M next mode, V next view, C compute the debug views, R reset, "
            "F12 screenshot, F11 save screenshot + frame + views + raw artefacts, Tab hide the panel, Esc quit.");
    }
    ImGui::PopItemWidth();
    ImGui::End();
}

void Viewer::saveScreenshot(const std::string& file) {
    int fbw = 0, fbh = 0;
    glfwGetFramebufferSize(window_, &fbw, &fbh);
    const std::filesystem::path p(file);
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    ImageRGBA8 shot = readWindow(fbw, fbh);
    for (size_t i = 3; i < shot.pixels.size(); i += 4) shot.pixels[i] = 255;  // the window's alpha is not an image's
    writePng(file, shot);
    // What the window shows under the panel: the debug view's image, else the frame.
    const ImageRGBA8* view = shownView();
    screenshots_[file] = {shot, view ? *view : renderer_->targets().readColor()};
    std::cout << "lidr-viewer: wrote " << file << std::endl;
}

void Viewer::saveAll(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw Error("cannot create folder '" + dir + "': " + ec.message());
    auto path = [&](const char* f) { return (std::filesystem::path(dir) / f).string(); };
    saveScreenshot(path("screenshot.png"));
    writePng(path("frame.png"), renderer_->targets().readColor());
    if (!eval_.valid || dirty_) computeViews();
    writePng(path("reference.png"), eval_.reference);
    for (const auto& [v, img] : eval_.images) {
        std::string f = viewName(v);
        std::replace(f.begin(), f.end(), '-', '_');
        writePng(path((f + ".png").c_str()), img);
    }
    if (const auto* lidr = dynamic_cast<const LidrRenderer*>(&drawingRenderer()); lidr && !lidr->options().perSampleIndices) {
        const auto lights = currentLights();
        FrameArtefacts a;
        a.indexTargets = lidr->readIndexTargets();
        a.depth = lidr->targets().readDepth();
        a.lightCounts = lidr->readLightCounts();
        a.camera = cameraMatrices(camera_.camera(), width_, height_);
        a.lights = lights;
        if (!lidr->frameLightIndices().empty()) {  // compact numbering (automatic width), as lidr-demo --dump
            a.lights.clear();
            for (uint32_t sceneIndex : lidr->frameLightIndices()) a.lights.push_back(lights[sceneIndex - 1]);
        }
        a.drawOrder = LidrRenderer::drawOrder(a.lights);
        writeFrameArtefacts(path("dump"), a, lidr->scheme());
    }
    checkGl("viewer: saving artefacts");
    const Camera c = camera_.camera();
    nlohmann::json j;
    for (const char* s : {"mode", "scheme", "budget", "index-bits", "volume-test", "msaa", "per-sample", "transparency",
                          "tile-size", "depth-bounds", "half-z", "lights", "view", "paused"})
        j["settings"][s] = setting(s);
    j["camera"] = {{"position", {c.position.x, c.position.y, c.position.z}},
                   {"target", {c.target.x, c.target.y, c.target.z}}};
    j["time"] = animTime_;
    j["gl"] = {{"renderer", context_->info().renderer}, {"version", context_->info().version}};
    j["drawn_lights"] = renderer_->lastFrame().drawnLights;
    j["error"] = {{"max_abs_error", eval_.error.maxAbsError},
                  {"psnr_db", std::isinf(eval_.error.psnr) ? 999.0 : eval_.error.psnr}};
    if (eval_.listsChecked)
        j["error"]["within_budget"] = {{"max_abs_error", eval_.errorWithinBudget.maxAbsError},
                                       {"psnr_db", std::isinf(eval_.errorWithinBudget.psnr) ? 999.0 : eval_.errorWithinBudget.psnr}};
    if (eval_.listsChecked)
        j["lights"] = {{"dropped_light_pixels", eval_.droppedLightPixels}, {"max_overlap_touching", eval_.maxOverlap},
                       {"max_marked", eval_.maxMarked}};
    std::ofstream(path("state.json")) << j.dump(2) << "\n";
    std::cout << "lidr-viewer: saved " << dir << std::endl;
}

void Viewer::runAction(const ScriptAction& a, int fbw, int fbh) {
    auto fail = [&](const std::string& why) {
        throw ScriptFailure("script line " + std::to_string(a.line) + " '" + a.text + "' failed: " + why);
    };
    const std::string& v = a.verb;
    if (v == "wait") {
        scriptWait_ = scriptInt(a, 0);
    } else if (v == "key") {
        const int k = keyFromName(a.args[0]);
        if (k < 0) fail("unknown key '" + a.args[0] + "'");
        scriptHeld_.insert(k);
        scriptWait_ = scriptInt(a, 1);
    } else if (v == "press") {
        const int k = keyFromName(a.args[0]);
        if (k < 0) fail("unknown key '" + a.args[0] + "'");
        onKeyPress(k, 0);
    } else if (v == "mouse") {
        camera_.turn(float(scriptNumber(a, 0)) * 0.004f, -float(scriptNumber(a, 1)) * 0.004f);
        markDirty();
    } else if (v == "set") {
        try {
            changeSetting(a.args[0], a.args[1]);
        } catch (const GlError&) {
            throw;
        } catch (const std::exception& e) {
            fail(e.what());
        }
    } else if (v == "compute") {
        computeViews();
    } else if (v == "screenshot") {
        saveScreenshot(a.args[0]);
    } else if (v == "capture") {
        writePng(a.args[0], renderer_->targets().readColor());
    } else if (v == "save") {
        saveAll(a.args[0]);
    } else if (v == "mark") {
        markPosition_ = camera_.position();
        markForward_ = camera_.forward();
        markRight_ = camera_.right();
        markFrame_ = renderer_->targets().readColor();
        marked_ = true;
    } else if (v == "expect-moved") {
        if (!marked_) fail("no 'mark' before it");
        const glm::vec3 d = camera_.position() - markPosition_;
        const std::string& dir = a.args[0];
        float along = 0.0f;
        if (dir == "forward") along = glm::dot(d, markForward_);
        else if (dir == "back") along = -glm::dot(d, markForward_);
        else if (dir == "right") along = glm::dot(d, markRight_);
        else if (dir == "left") along = -glm::dot(d, markRight_);
        else if (dir == "up") along = d.y;
        else if (dir == "down") along = -d.y;
        else fail("direction must be forward, back, left, right, up or down");
        const double min = scriptNumber(a, 1);
        if (along < min)
            fail("the camera moved " + std::to_string(along) + " " + dir + " (of " + std::to_string(glm::length(d)) +
                 " in all), less than " + a.args[1]);
        const ImageError e = compareImages(renderer_->targets().readColor(), markFrame_);
        std::cout << "lidr-viewer: " << a.text << ": moved " << along << " " << dir << " (" << glm::length(d)
                  << " in all), " << e.differingPixels << " pixels changed" << std::endl;
        if (e.differingPixels < long(width_) * height_ / 100)
            fail("the frame hardly changed: " + std::to_string(e.differingPixels) + " pixels differ");
    } else if (v == "expect-match") {
        const ImageRGBA8 want = readPng(a.args[0]);
        const ImageRGBA8 got = renderer_->targets().readColor();
        if (want.width != got.width || want.height != got.height)
            fail("size " + std::to_string(got.width) + "x" + std::to_string(got.height) + " against " +
                 std::to_string(want.width) + "x" + std::to_string(want.height));
        const ImageError e = compareImages(got, want);
        const double psnr = std::isinf(e.psnr) ? 999.0 : e.psnr;
        std::cout << "lidr-viewer: " << a.text << ": max error " << e.maxAbsError << ", PSNR " << psnr << " dB, "
                  << e.differingPixels << " pixels differ" << std::endl;
        if (e.maxAbsError > scriptInt(a, 1) || psnr < scriptNumber(a, 2))
            fail("max error " + std::to_string(e.maxAbsError) + ", PSNR " + std::to_string(psnr) + " dB");
    } else if (v == "expect-view-match") {
        if (!eval_.valid && view_ != View::TileHeatMap) fail("no debug view computed");
        const ImageRGBA8* got = view_ == View::TileHeatMap ? &tileHeat_
                                : eval_.images.count(view_) ? &eval_.images.at(view_) : nullptr;
        if (!got || got->width == 0) fail(std::string("view ") + viewName(view_) + " has no image");
        const ImageRGBA8 want = readPng(a.args[0]);
        if (want.width != got->width || want.height != got->height) fail("image sizes differ");
        const ImageError e = compareImages(*got, want);
        std::cout << "lidr-viewer: " << a.text << ": max error " << e.maxAbsError << ", " << e.differingPixels
                  << " pixels differ" << std::endl;
        if (e.maxAbsError > scriptInt(a, 1)) fail("max error " + std::to_string(e.maxAbsError));
    } else if (v == "expect-ui") {
        const auto it = screenshots_.find(a.args[0]);
        if (it == screenshots_.end()) fail("no screenshot was written to that file by this script");
        const ImageRGBA8 shot = readPng(a.args[0]);  // from disk: the file is what is judged
        const ImageRGBA8& frame = it->second.second;
        if (shot.width != fbw || shot.height != fbh) fail("the screenshot is not the window's size");
        if (frame.width != shot.width || frame.height != shot.height)
            fail("window " + std::to_string(shot.width) + "x" + std::to_string(shot.height) + " is not the frame's size");
        const int x0 = int(panelMin_[0]) + 2, y0 = int(panelMin_[1]) + 2;
        const int x1 = std::min(int(panelMax_[0]) - 2, shot.width), y1 = std::min(int(panelMax_[1]) - 2, shot.height);
        if (x1 - x0 < 50 || y1 - y0 < 50) fail("the UI panel is not on screen");
        long inside = 0, insideDiff = 0, outside = 0, outsideDiff = 0;
        for (int y = 0; y < shot.height; ++y)
            for (int x = 0; x < shot.width; ++x) {
                const uint8_t* s = shot.at(x, y);
                const uint8_t* f = frame.at(x, y);
                const int d = std::max({std::abs(s[0] - f[0]), std::abs(s[1] - f[1]), std::abs(s[2] - f[2])});
                const bool in = x >= x0 && x < x1 && y >= y0 && y < y1;
                const bool near = x >= x0 - 6 && x < x1 + 6 && y >= y0 - 6 && y < y1 + 6;
                if (in) inside++, insideDiff += d > 8;
                else if (!near) outside++, outsideDiff += d > 1;
            }
        std::cout << "lidr-viewer: " << a.text << ": panel " << x0 << "," << y0 << "-" << x1 << "," << y1 << ", "
                  << insideDiff << " of " << inside << " panel pixels differ from what is shown under it, " << outsideDiff << " of "
                  << outside << " outside" << std::endl;
        if (insideDiff < inside / 2) fail("the panel's pixels look like the frame's: no UI drawn");
        if (outsideDiff > outside / 1000) fail("outside the panel the window does not show the frame (or the debug view) it should");
    } else if (v == "expect-stat") {
        const std::string& n = a.args[0];
        double value = 0.0;
        const bool needEval = n == "max-error" || n == "psnr" || n == "dropped" || n == "max-overlap" || n == "max-marked";
        if (needEval && (!eval_.valid || dirty_)) fail("no up-to-date figures: add 'compute' first");
        if ((n == "dropped" || n == "max-overlap" || n == "max-marked") && !eval_.listsChecked)
            fail("no index lists checked in this mode");
        if (n == "drawn-lights") value = renderer_->lastFrame().drawnLights;
        else if (n == "lights") value = double(currentLights().size());
        else if (n == "time") value = animTime_;
        else if (n == "frames") value = double(frameNumber_);
        else if (n == "volume-draws") value = double(renderer_->lastFrame().volumeDrawCalls);
        else if (n == "max-error") value = eval_.error.maxAbsError;
        else if (n == "psnr") value = std::isinf(eval_.error.psnr) ? 999.0 : eval_.error.psnr;
        else if (n == "dropped") value = double(eval_.droppedLightPixels);
        else if (n == "max-overlap") value = eval_.maxOverlap;
        else if (n == "max-marked") value = eval_.maxMarked;
        else fail("unknown figure '" + n + "' (drawn-lights, lights, time, frames, volume-draws, max-error, psnr, dropped, max-overlap, max-marked)");
        std::cout << "lidr-viewer: " << a.text << ": " << n << " = " << value << std::endl;
        if (!compareOp(value, a.args[1], scriptNumber(a, 2))) fail(n + " is " + std::to_string(value));
    } else if (v == "expect-setting") {
        std::string got;
        try {
            got = setting(a.args[0]);
        } catch (const Error& e) {
            fail(e.what());
        }
        if (got != a.args[1]) fail(a.args[0] + " is " + got);
    } else if (v == "expect-refused") {
        if (!lastRefused_) fail("the last change was applied: " + status_);
        std::cout << "lidr-viewer: " << a.text << ": " << status_ << std::endl;
    } else if (v == "expect-applied") {
        if (lastRefused_) fail(status_);
    } else if (v == "expect-file") {
        if (!std::filesystem::is_regular_file(a.args[0]) || std::filesystem::file_size(a.args[0]) == 0)
            fail("no such file, or it is empty");
    } else if (v == "resize") {
        const int w = scriptInt(a, 0), h = scriptInt(a, 1);
        if (w < 1 || h < 1) fail("the size must be positive");
        glfwSetWindowSize(window_, w, h);
    } else if (v == "expect-size") {
        const RenderTargets& t = renderer_->targets();
        std::cout << "lidr-viewer: " << a.text << ": frame " << t.width() << "x" << t.height() << ", window " << fbw
                  << "x" << fbh << std::endl;
        if (t.width() != scriptInt(a, 0) || t.height() != scriptInt(a, 1))
            fail("the frame is " + std::to_string(t.width()) + "x" + std::to_string(t.height()));
    } else if (v == "expect-mode-views") {
        // In the automatic mode the views follow the candidate that drew the frame.
        const Renderer& drawing = drawingRenderer();
        const bool lidrDrew = dynamic_cast<const LidrRenderer*>(&drawing) != nullptr;
        const bool tiledDrew = dynamic_cast<const TiledRenderer*>(&drawing) != nullptr;
        std::cout << "lidr-viewer: " << a.text << ": " << renderer_->modeName() << " drew with " << drawing.modeName()
                  << std::endl;
        std::string why;
        for (View view : {View::IndexLists, View::Overlap, View::Marked})
            if (viewAvailable(view, &why) != (lidrDrew && !rc_.msaaPerSample))
                fail(std::string("view ") + viewName(view) + (lidrDrew ? " not offered: " + why : " offered"));
        if (viewAvailable(View::TileHeatMap, &why) != tiledDrew)
            fail(std::string("the tile heat map ") + (tiledDrew ? "not offered: " + why : "offered"));
        if (!eval_.valid || dirty_) fail("no up-to-date figures: add 'compute' first");
        if (eval_.listsChecked != (lidrDrew && !rc_.msaaPerSample))
            fail(lidrDrew ? "the index lists of the LIDR frame were not checked" : "index lists checked without LIDR");
        if (lidrDrew && (eval_.images.count(View::IndexLists) == 0 || eval_.images.at(View::IndexLists).width != width_))
            fail("no index-list image of the frame's size");
    } else if (v == "quit") {
        quit_ = true;
    }
}

void Viewer::stepScript(int fbw, int fbh) {
    if (scriptWait_ > 0 && --scriptWait_ > 0) return;
    scriptHeld_.clear();
    while (scriptWait_ == 0 && scriptPos_ < script_.size() && !quit_) runAction(script_[scriptPos_++], fbw, fbh);
    if (scriptPos_ >= script_.size() && scriptWait_ == 0) quit_ = true;  // a script ends the viewer
}

int Viewer::run() {
    const bool scripted = !options_.scriptFile.empty();
    double last = glfwGetTime();
    try {
        while (!quit_ && !context_->shouldClose()) {
            context_->pollEvents();
            const double now = glfwGetTime();
            // Scripted runs advance a fixed step per frame, so what they check does not depend on speed.
            const float dt = scripted ? kStepSeconds : float(std::min(0.1, now - last));
            last = now;
            if (!gles_) ImGui_ImplOpenGL2_NewFrame();  // (the ES renderer made its font texture at the start)
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            processInput(dt);
            int fbw = 0, fbh = 0;
            glfwGetFramebufferSize(window_, &fbw, &fbh);
            followWindowSize(fbw, fbh);
            renderFrame();
            if (computeRequested_ || (dirty_ && paused_ && view_ != View::Frame && view_ != View::TileHeatMap)) {
                computeRequested_ = false;
                computeViews();
            }
            drawWindow(fbw, fbh);
            buildUi(fbw, fbh);
            ImGui::Render();
            resetStateForWindow(fbw, fbh, gles_);
            if (es2Ui_)
                es2Ui_->render(ImGui::GetDrawData(), fbw, fbh);
            else
                ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
            checkGl("viewer: drawing the UI");
            if (pendingScreenshot_) {
                char name[64];
                std::snprintf(name, sizeof name, "screenshot-%03d.png", screenshotCounter_++);
                saveScreenshot((std::filesystem::path(options_.outDir) / name).string());
                pendingScreenshot_.reset();
            }
            if (pendingSave_) {
                char name[64];
                std::snprintf(name, sizeof name, "capture-%03d", saveCounter_++);
                saveAll((std::filesystem::path(options_.outDir) / name).string());
                pendingSave_.reset();
            }
            if (scripted) stepScript(fbw, fbh);
            context_->swapBuffers();
            ++frameNumber_;
        }
    } catch (const ScriptFailure& e) {
        std::cerr << "lidr-viewer: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "lidr-viewer: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

}  // namespace lidr::viewer
