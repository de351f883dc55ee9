#pragma once
// GL contexts: one small interface over the headless and windowed backends lidr runs on.
// EGL surfaceless (Mesa) is the default; EGL device covers headless NVIDIA and other vendors; GLFW gives a
// window for the interactive demo; OSMesa exists only where the library does (gone from Mesa 25.1 on).
#include <memory>
#include <string>
#include <vector>

#include "lidr/gl/gl_info.h"

namespace lidr {

// EglGles2: EGL surfaceless with an OpenGL ES 2.0 context (EGL_OPENGL_ES_API), for ES 2.0-class hardware;
// the renderer then takes its ES path (GlInfo::gles; doc/contexts.md, "OpenGL ES 2.0"). GlfwGles2: a GLFW
// window with an OpenGL ES 2.0 context made through EGL (lidr-viewer and lidr-demo --window on the ES path).
// WebGl: a WebGL 1 context on a page's <canvas>, only in the web build (emscripten; doc/web.md), an ES 2.0
// context too.
enum class ContextBackend { Auto, EglSurfaceless, EglDevice, Glfw, OSMesa, EglGles2, WebGl, GlfwGles2 };

struct ContextOptions {
    ContextBackend backend = ContextBackend::Auto;  // Auto: LIDR_CONTEXT env, else surfaceless, then device
                                                     // (lidr_osmesa: osmesa)
    int windowWidth = 1024, windowHeight = 768;     // GLFW (glfw, glfw-gles2) only
    bool visibleWindow = false;                      // GLFW (glfw, glfw-gles2) only
    std::string windowTitle = "lidr";
    std::string canvasSelector = "#canvas";          // WebGL only (the web build): the page's <canvas>
};

class GlContext {
public:
    virtual ~GlContext() = default;
    const GlInfo& info() const { return info_; }
    virtual void makeCurrent() = 0;
    virtual void swapBuffers() {}
    virtual bool shouldClose() const { return false; }  // windowed backends
    virtual void pollEvents() {}
    virtual void* nativeWindow() const { return nullptr; }  // GLFWwindow* for the GLFW backend

    // Creates a context as asked; on failure throws UnsupportedError naming every backend tried and why.
    static std::unique_ptr<GlContext> create(const ContextOptions& options = {});

protected:
    // Fills info_ with currentContextGlInfo (lidr/gl/gl_info.h): loads entry points with GLEW (Debian's GLEW
    // is a GLX build: under EGL glewInit() returns GLEW_ERROR_NO_GLX_DISPLAY (4) after the entry points have
    // loaded, so 4 counts as success only if glGetString(GL_VERSION) answers).
    void initialiseGl(const std::string& backendName);
    GlInfo info_;
};

// "auto", "egl", "egl-device", "glfw", "osmesa", "egl-gles2", "webgl", "glfw-gles2"
ContextBackend parseContextBackend(const std::string& name);
const char* contextBackendName(ContextBackend b);
// The backends this library offers. lidr::lidr: egl, egl-device, egl-gles2 (and glfw, glfw-gles2 where built);
// lidr::lidr_osmesa: osmesa only, because OSMesa brings its own GL entry points (see doc/contexts.md); the web
// build: webgl only.
std::vector<ContextBackend> availableContextBackends();

namespace detail {
std::unique_ptr<GlContext> createEglSurfaceless();
std::unique_ptr<GlContext> createEglDevice();
std::unique_ptr<GlContext> createEglGles2();
std::unique_ptr<GlContext> createGlfw(const ContextOptions&);
std::unique_ptr<GlContext> createGlfwGles2(const ContextOptions&);
std::unique_ptr<GlContext> createOSMesa();
std::unique_ptr<GlContext> createWebGl(const ContextOptions&);
}  // namespace detail

}  // namespace lidr
