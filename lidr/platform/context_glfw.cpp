// GLFW window backend, for the interactive demo. Needs a display (X11 or Wayland); headless tools use EGL.
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
    explicit GlfwContext(const ContextOptions& o) {
        if (!glfwInit()) throw UnsupportedError("glfwInit failed: " + lastGlfwError());
        glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);  // legacy context: GL 2.1 or any compatible higher
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 1);
        glfwWindowHint(GLFW_VISIBLE, o.visibleWindow ? GLFW_TRUE : GLFW_FALSE);
        window_ = glfwCreateWindow(o.windowWidth, o.windowHeight, o.windowTitle.c_str(), nullptr, nullptr);
        if (!window_) {
            std::string why = lastGlfwError();
            glfwTerminate();
            throw UnsupportedError("glfwCreateWindow failed: " + why);
        }
        makeCurrent();
        glfwSwapInterval(0);
        initialiseGl("glfw");
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

std::unique_ptr<GlContext> createGlfw(const ContextOptions& o) { return std::make_unique<GlfwContext>(o); }

}  // namespace lidr::detail
