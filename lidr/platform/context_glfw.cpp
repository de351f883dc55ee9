// GLFW window backends, for the interactive demo and the viewer. Needs a display (X11 or Wayland); headless
// tools use EGL. glfw: a desktop GL 2.1 (or compatible higher) context; glfw-gles2: an OpenGL ES 2.0 context
// made through EGL (GLFW_EGL_CONTEXT_API), on which the renderer takes its ES path (doc/contexts.md).
#include <GLFW/glfw3.h>

#include <string>

#include "lidr/platform/context.h"
#include "lidr/base/error.h"

namespace lidr::detail {
namespace {

std::string lastGlfwError() {
    const char* desc = nullptr;
    int code = glfwGetError(&desc);
    return code == GLFW_NO_ERROR ? std::string("no detail") : std::string(desc ? desc : "unknown GLFW error");
}

class GlfwContext final : public GlContext {
public:
    GlfwContext(const ContextOptions& o, bool gles2) {
        if (!glfwInit()) throw UnsupportedError("glfwInit failed: " + lastGlfwError());
        glfwDefaultWindowHints();
        if (gles2) {
            // ES 2.0 through EGL (GLX can make ES contexts only with GLX_EXT_create_context_es2_profile; EGL is
            // what ES 2.0-class boards have). Mesa answers with ES 3.2 unless MESA_GLES_VERSION_OVERRIDE=2.0;
            // either way lidr takes the ES 2.0 path (GlInfo::gles), checked below.
            glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
            glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
            glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
            glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
        } else {
            glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
            glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);  // legacy context: GL 2.1 or any compatible higher
            glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
        }
        glfwWindowHint(GLFW_VISIBLE, o.visibleWindow ? GLFW_TRUE : GLFW_FALSE);
        window_ = glfwCreateWindow(o.windowWidth, o.windowHeight, o.windowTitle.c_str(), nullptr, nullptr);
        if (!window_) {
            std::string why = lastGlfwError();
            glfwTerminate();
            throw UnsupportedError("glfwCreateWindow failed: " + why);
        }
        makeCurrent();
        glfwSwapInterval(0);
        try {
            initialiseGl(gles2 ? "glfw-gles2" : "glfw");
            if (gles2 && !info_.gles)
                throw UnsupportedError("asked for OpenGL ES 2.0, the window's context is '" + info_.version + "'");
        } catch (...) {
            glfwDestroyWindow(window_);
            window_ = nullptr;
            glfwTerminate();
            throw;
        }
    }
    ~GlfwContext() override {
        if (window_) glfwDestroyWindow(window_);
        glfwTerminate();
    }
    void makeCurrent() override { glfwMakeContextCurrent(window_); }
    void swapBuffers() override { glfwSwapBuffers(window_); }
    bool shouldClose() const override { return glfwWindowShouldClose(window_); }
    void pollEvents() override { glfwPollEvents(); }
    void* nativeWindow() const override { return window_; }

private:
    GLFWwindow* window_ = nullptr;
};

}  // namespace

std::unique_ptr<GlContext> createGlfw(const ContextOptions& o) { return std::make_unique<GlfwContext>(o, false); }
std::unique_ptr<GlContext> createGlfwGles2(const ContextOptions& o) { return std::make_unique<GlfwContext>(o, true); }

}  // namespace lidr::detail
