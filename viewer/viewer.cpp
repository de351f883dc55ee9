// lidr-viewer's lifecycle and frame loop: the window and context, the renderer's frames, the window's size, and
// putting the frame (or a debug view) on screen. The other concerns have files of their own: viewer_settings,
// viewer_input, viewer_panel, viewer_debug_views, viewer_script_runner, viewer_files.
#include "lidr/base/gl.h"  // GLEW before anything that includes GL/gl.h (GLFW does)

#include "viewer.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl2.h>

#include "imgui_es2.h"
#include "lidr/gl/render_targets.h"
#include "lidr/modes/auto_mode_renderer.h"
#include "lidr/render/present.h"
#include "viewer_internal.h"

namespace lidr::viewer {

// ES 2.0 has no glDrawBuffer / glReadBuffer: the window's framebuffer is its back buffer.
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

Viewer::Viewer(const demo::SceneChoice& sceneChoice, const demo::RendererChoice& rc, const ViewerOptions& options)
    : sceneChoice_(sceneChoice), options_(options) {
    if (rc.context != "auto" && rc.context != "glfw" && rc.context != "glfw-gles2")
        throw Error("lidr-viewer draws into a window: --context must be glfw, glfw-gles2 (OpenGL ES 2.0) or auto, got '" +
                    rc.context + "'");
    if (!options_.scriptFile.empty()) script_ = parseScript(options_.scriptFile);
    fileScene_ = sceneChoice.load();
    scene_ = fileScene_;
    scenePath_ = sceneChoice.sceneFile;
    width_ = scene_.width;
    height_ = scene_.height;
    // The settings as the UI shows them: the scene's choices made explicit.
    rc_ = rc;
    const RenderModeOptions first = rc.renderModeOptions(scene_);  // throws on a bad name
    rc_.set("mode", first.mode);
    rc_.set("msaa", std::to_string(first.msaaSamples));
    rc_.set("transparency", first.transparency ? "on" : "off");
    demo::checkTargetMemory(scene_, first);
    initialChoice_ = rc_;
    shading_ = sceneShading(scene_);
    camera_.reset(scene_.camera);
    followSceneCamera_ = scene_.animation.cameraNode >= 0;
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
    addTextureUnitWarnings();
    for (const std::string& w : fileScene_.warnings) std::cout << "lidr-viewer: warning: " << w << std::endl;
    glfwSetWindowUserPointer(window_, this);
    glfwSetKeyCallback(window_, keyCallback);  // before ImGui's, which chains to it
    glfwSetDropCallback(window_, dropCallback);

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

void Viewer::renderFrame() {
    try {
        // The scene's animation at the clock's time: its moving meshes re-placed (no geometry uploaded again), the
        // camera on its node while following it; currentLights takes the lights at the same time.
        placeAnimatedObjects(*renderer_, scene_, animTime_);
        if (followSceneCamera_) camera_.reset(cameraAt(scene_, animTime_));
        ShadingParameters shading;
        const std::vector<PointLight> lights = currentLights(&shading);
        const FrameStats& st = renderer_->render(camera_.camera(), lights, shading);
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
    if (auto* clustered = dynamic_cast<const ClusteredRenderer*>(&drawingRenderer());
        clustered && view_ == View::TileHeatMap)
        tileHeat_ = clustered->clusterHeatMap(16);
    if (view_ == View::ShadowAtlas) {
        const ShadowAtlas* atlas = drawingRenderer().shadowAtlas();
        shadowAtlasView_ = atlas ? atlas->image(1024) : ImageRGBA8{};
        checkGl("viewer: reading the shadow atlas");
    }
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

ImageRGBA8 Viewer::readWindow(int fbw, int fbh) const {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!gles_) glReadBuffer(GL_BACK);
    return readPixelsRGBA8(fbw, fbh);
}

void Viewer::drawWindow(int fbw, int fbh) {
    resetStateForWindow(fbw, fbh, gles_);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    const ImageRGBA8* image = shownView();
    if (image) {
        const long stamp = view_ == View::TileHeatMap || view_ == View::ShadowAtlas ? frameNumber_ : eval_.frame;
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
            openPendingFile();
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
