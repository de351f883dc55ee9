// EGL backends: surfaceless (Mesa's EGL_MESA_platform_surfaceless) and device (EGL_EXT_platform_device), desktop
// GL; and surfaceless with OpenGL ES 2.0 (egl-gles2). All make a context current with no surface at all
// (EGL_KHR_surfaceless_context): lidr renders into FBOs. Everything ES-specific beyond the context itself lives
// in lidr/gl (GlInfo::gles), so a non-EGL ES 2.0 context (WebGL 1) takes the same path.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <string>

#include "lidr/platform/context.h"
#include "lidr/base/error.h"

namespace lidr::detail {
namespace {

std::string eglErrorString(EGLint e) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "EGL error 0x%04x", static_cast<unsigned>(e));
    return buf;
}

bool hasEglExtension(EGLDisplay dpy, const char* name) {
    const char* ext = eglQueryString(dpy, EGL_EXTENSIONS);
    if (!ext) return false;
    std::string all = std::string(" ") + ext + " ";
    return all.find(std::string(" ") + name + " ") != std::string::npos;
}

enum class EglApi { DesktopGl, Gles2 };

class EglContext final : public GlContext {
public:
    EglContext(EGLDisplay dpy, const std::string& name, EglApi api = EglApi::DesktopGl) : display_(dpy) {
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display_, &major, &minor))
            throw UnsupportedError("eglInitialize failed (" + eglErrorString(eglGetError()) + ")");
        initialised_ = true;
        if (!hasEglExtension(display_, "EGL_KHR_surfaceless_context"))
            throw UnsupportedError("EGL display lacks EGL_KHR_surfaceless_context");
        const bool es = api == EglApi::Gles2;
        if (!eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API))
            throw UnsupportedError(es ? "eglBindAPI(EGL_OPENGL_ES_API) failed: OpenGL ES is not offered"
                                      : "eglBindAPI(EGL_OPENGL_API) failed: desktop GL is not offered");

        EGLConfig config = nullptr;
        const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, es ? EGL_OPENGL_ES2_BIT : EGL_OPENGL_BIT, EGL_NONE};
        EGLint count = 0;
        if (!eglChooseConfig(display_, configAttribs, &config, 1, &count) || count < 1) {
            // Mesa's surfaceless display has no config at all; lidr never needs one (no surface).
            if (!hasEglExtension(display_, "EGL_KHR_no_config_context"))
                throw UnsupportedError(std::string("no EGL config renders ") + (es ? "OpenGL ES 2" : "desktop GL") +
                                       ", and no EGL_KHR_no_config_context");
            config = nullptr;  // EGL_NO_CONFIG_KHR
        }
        // Desktop: no version or profile asked for, a legacy / compatibility context, the highest the driver
        // has. ES: client version 2; Mesa answers with the highest ES it has (3.2) unless
        // MESA_GLES_VERSION_OVERRIDE=2.0, and currentContextGlInfo takes either through the ES 2.0 path.
        const EGLint desktopAttribs[] = {EGL_NONE};
        const EGLint esAttribs[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, es ? esAttribs : desktopAttribs);
        if (context_ == EGL_NO_CONTEXT)
            throw UnsupportedError("eglCreateContext failed (" + eglErrorString(eglGetError()) + ")");
        makeCurrent();
        initialiseGl(name);
    }
    ~EglContext() override {
        if (context_ != EGL_NO_CONTEXT) {
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            eglDestroyContext(display_, context_);
        }
        if (initialised_) eglTerminate(display_);
    }
    void makeCurrent() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw UnsupportedError("eglMakeCurrent failed (" + eglErrorString(eglGetError()) + ")");
    }

private:
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    bool initialised_ = false;
};

PFNEGLGETPLATFORMDISPLAYEXTPROC platformDisplayFn() {
    auto fn = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!fn) throw UnsupportedError("EGL has no eglGetPlatformDisplayEXT (EGL_EXT_platform_base)");
    return fn;
}

bool clientHas(const char* name) {
    const char* ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!ext) return false;
    std::string all = std::string(" ") + ext + " ";
    return all.find(std::string(" ") + name + " ") != std::string::npos;
}

EGLDisplay surfacelessDisplay() {
    if (!clientHas("EGL_MESA_platform_surfaceless"))
        throw UnsupportedError("EGL client lacks EGL_MESA_platform_surfaceless (not Mesa?)");
    EGLDisplay dpy = platformDisplayFn()(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (dpy == EGL_NO_DISPLAY) throw UnsupportedError("no surfaceless EGL display");
    return dpy;
}

}  // namespace

std::unique_ptr<GlContext> createEglSurfaceless() {
    return std::make_unique<EglContext>(surfacelessDisplay(), "egl-surfaceless");
}

std::unique_ptr<GlContext> createEglGles2() {
    return std::make_unique<EglContext>(surfacelessDisplay(), "egl-gles2", EglApi::Gles2);
}

std::unique_ptr<GlContext> createEglDevice() {
    if (!clientHas("EGL_EXT_platform_device"))
        throw UnsupportedError("EGL client lacks EGL_EXT_platform_device");
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (!queryDevices) throw UnsupportedError("EGL has no eglQueryDevicesEXT");
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (!queryDevices(16, devices, &count) || count < 1) throw UnsupportedError("EGL reports no devices");
    std::string errors;
    for (EGLint i = 0; i < count; ++i) {  // the first device that gives a desktop GL context wins
        EGLDisplay dpy = platformDisplayFn()(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (dpy == EGL_NO_DISPLAY) continue;
        try {
            return std::make_unique<EglContext>(dpy, "egl-device");
        } catch (const Error& e) {
            errors += std::string(" [device ") + std::to_string(i) + ": " + e.what() + "]";
        }
    }
    throw UnsupportedError("no EGL device gave a GL context" + errors);
}

}  // namespace lidr::detail
