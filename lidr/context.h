#pragma once
// GL contexts: one small interface over the headless and windowed backends lidr runs on.
// EGL surfaceless (Mesa) is the default; EGL device covers headless NVIDIA and other vendors; GLFW gives a
// window for the interactive demo; OSMesa exists only where the library does (gone from Mesa 25.1 on).
#include <memory>
#include <string>
#include <vector>

namespace lidr {

enum class ContextBackend { Auto, EglSurfaceless, EglDevice, Glfw, OSMesa };

struct ContextOptions {
    ContextBackend backend = ContextBackend::Auto;  // Auto: LIDR_CONTEXT env, else surfaceless, then device
                                                     // (lidr_osmesa: osmesa)
    int windowWidth = 1024, windowHeight = 768;     // GLFW only
    bool visibleWindow = false;                      // GLFW only
    std::string windowTitle = "lidr";
};

// What the context turned out to be, and what the renderer may use. Filled after GLEW is initialised.
struct GlInfo {
    std::string backend;
    std::string version, renderer, vendor, glslVersion;
    int major = 0, minor = 0;
    int glsl = 0;  // GLSL version as a number: 120, 150, 450...
    bool framebufferObject = false;   // ARB_framebuffer_object or EXT_framebuffer_object + packed depth-stencil
    bool textureFloat = false;        // ARB_texture_float (light table in float textures)
    bool timerQuery = false;          // ARB_timer_query or EXT_timer_query
    bool depthClamp = false;          // ARB_depth_clamp or NV_depth_clamp
    bool drawBuffers = false;         // GL 2.0 glDrawBuffers
    bool multisampleFbo = false;      // EXT_framebuffer_multisample (or GL 3.0)
    int maxSamples = 0;
    // The optional per-sample MSAA index path (Trebilco's MSAA technique 1): multisample textures
    // (GL 3.2 / ARB_texture_multisample) read per sample (GL 4.0 / ARB_sample_shading).
    bool multisampleTexture = false;
    bool sampleShading = false;
    int maxColorTextureSamples = 0;
    int maxDrawBuffers = 1;
    int maxColorAttachments = 1;      // FBO colour attachments (index targets of one frame)
    int maxTextureUnits = 2;          // fragment-shader texture image units
    int maxVertexUniformVectors = 128;  // GL_MAX_VERTEX_UNIFORM_COMPONENTS / 4 (GL 2.1 guarantees 128)
    int maxTextureSize = 0;
    int stencilBits = 8;
    std::string summary() const;
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
    // Loads entry points with GLEW and fills info_. Debian's GLEW is a GLX build: under EGL glewInit()
    // returns GLEW_ERROR_NO_GLX_DISPLAY (4) after the entry points have loaded, so 4 counts as success
    // only if glGetString(GL_VERSION) answers.
    void initialiseGl(const std::string& backendName);
    GlInfo info_;
};

ContextBackend parseContextBackend(const std::string& name);  // "auto", "egl", "egl-device", "glfw", "osmesa"
const char* contextBackendName(ContextBackend b);
// The backends this library offers. lidr::lidr: egl, egl-device (and glfw where built); lidr::lidr_osmesa:
// osmesa only, because OSMesa brings its own GL entry points (see doc/contexts.md).
std::vector<ContextBackend> availableContextBackends();

namespace detail {
std::unique_ptr<GlContext> createEglSurfaceless();
std::unique_ptr<GlContext> createEglDevice();
std::unique_ptr<GlContext> createGlfw(const ContextOptions&);
std::unique_ptr<GlContext> createOSMesa();
}  // namespace detail

}  // namespace lidr
