// lidr-viewer's keyboard and mouse: the key bindings, the fly camera's movement and look, the animation clock.
#include "lidr/base/gl.h"  // GLEW before anything that includes GL/gl.h (GLFW does)

#include "viewer.h"

#include <cmath>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "viewer_internal.h"

namespace lidr::viewer {

void keyCallback(GLFWwindow* w, int key, int /*scancode*/, int action, int mods) {
    if (action != GLFW_PRESS) return;
    if (ImGui::GetCurrentContext() && ImGui::GetIO().WantTextInput) return;
    if (auto* v = static_cast<Viewer*>(glfwGetWindowUserPointer(w))) v->onKeyPress(key, mods);
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
            animTime_ = loopedTime(animTime_ + kStepSeconds);
            markDirty();
            break;
        case GLFW_KEY_R: resetAll(); break;
        case GLFW_KEY_C: computeRequested_ = true; break;
        case GLFW_KEY_TAB: showUi_ = !showUi_; break;
        case GLFW_KEY_M: {  // next mode (Shift: previous)
            const std::vector<std::string>& modes = renderModeNames();
            const size_t n = modes.size();
            size_t i = 0;
            while (i < n && rc_.mode() != modes[i]) ++i;
            changeSetting("mode", modes[(i + (shift ? n - 1 : 1)) % n]);
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
        case GLFW_KEY_F5: reloadScene(); break;
        default: break;
    }
}

void Viewer::resetAll() {
    camera_.reset(scene_.camera);
    followSceneCamera_ = scene_.animation.cameraNode >= 0;
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
        followSceneCamera_ = false;  // flying leaves the scene's animated camera where it was
        camera_.move(local, speed * dt);
        markDirty();
    }
    // Mouse look: drag with the right button, or the left one outside the panel.
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window_, &x, &y);
    const bool look = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                      (!io.WantCaptureMouse && glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS);
    if (look && cursorKnown_ && (x != lastCursorX_ || y != lastCursorY_)) {
        followSceneCamera_ = false;
        camera_.turn(float(x - lastCursorX_) * 0.004f, -float(y - lastCursorY_) * 0.004f);
        markDirty();
    }
    lastCursorX_ = x;
    lastCursorY_ = y;
    cursorKnown_ = true;
    if (!paused_ && dt > 0.0f) {
        animTime_ = loopedTime(animTime_ + dt * animSpeed_);
        markDirty();
    }
}

// A keyframed scene plays its range over and over (an AFF file's `a`, a glTF's clips); others run on.
float Viewer::loopedTime(float t) const {
    const SceneAnimation& a = scene_.animation;
    if (!(a.end > a.start) || t <= a.end) return t;
    return a.start + std::fmod(t - a.start, a.end - a.start);
}

}  // namespace lidr::viewer
