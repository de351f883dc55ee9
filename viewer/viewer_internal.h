#pragma once
// What the viewer's source files share (viewer.cpp, viewer_settings.cpp, viewer_input.cpp, viewer_panel.cpp,
// viewer_debug_views.cpp, viewer_script_runner.cpp, viewer_files.cpp): constants and small helpers.
#include <cstddef>

#include "lidr/base/error.h"

struct GLFWwindow;

namespace lidr::viewer {

constexpr size_t kHistory = 120;
constexpr float kStepSeconds = 1.0f / 30.0f;  // one animation step (N), and a scripted frame's time

// A failed script check: ends the run with exit code 1.
struct ScriptFailure : Error {
    using Error::Error;
};

// The renderer settings' menus take their values from lidr::renderOptions() (viewer_panel.cpp).

// GLFW's key callback (viewer_input.cpp): forwards presses to Viewer::onKeyPress unless ImGui takes text.
void keyCallback(GLFWwindow* w, int key, int scancode, int action, int mods);
// GLFW's drop callback (viewer_files.cpp): hands the dropped paths to Viewer::onDrop.
void dropCallback(GLFWwindow* w, int count, const char** paths);
// What the ImGui OpenGL2 backend (fixed function, client-side arrays) and the ES 2.0 one (imgui_es2.h) need
// after lidr's passes (viewer.cpp).
void resetStateForWindow(int fbw, int fbh, bool gles);

}  // namespace lidr::viewer
