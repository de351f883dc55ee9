#include "lidr/platform/context.h"

#include <cstdlib>
#include <cstring>

#include "lidr/base/error.h"
#include "lidr/base/gl.h"

#ifndef LIDR_HAVE_WEBGL
#define LIDR_HAVE_WEBGL 0  // only the web build (LIDR_WEB, emscripten) has the WebGL backend
#endif

namespace lidr {

ContextBackend parseContextBackend(const std::string& name) {
    if (name == "auto") return ContextBackend::Auto;
    if (name == "egl" || name == "egl-surfaceless" || name == "surfaceless") return ContextBackend::EglSurfaceless;
    if (name == "egl-device" || name == "device") return ContextBackend::EglDevice;
    if (name == "glfw") return ContextBackend::Glfw;
    if (name == "glfw-gles2") return ContextBackend::GlfwGles2;
    if (name == "osmesa") return ContextBackend::OSMesa;
    if (name == "egl-gles2" || name == "gles2") return ContextBackend::EglGles2;
    if (name == "webgl") return ContextBackend::WebGl;
    throw Error("unknown GL context backend '" + name +
                "' (valid: auto, egl, egl-device, egl-gles2, glfw, glfw-gles2, osmesa, webgl)");
}

const char* contextBackendName(ContextBackend b) {
    switch (b) {
    case ContextBackend::Auto: return "auto";
    case ContextBackend::EglSurfaceless: return "egl";
    case ContextBackend::EglDevice: return "egl-device";
    case ContextBackend::Glfw: return "glfw";
    case ContextBackend::GlfwGles2: return "glfw-gles2";
    case ContextBackend::OSMesa: return "osmesa";
    case ContextBackend::EglGles2: return "egl-gles2";
    case ContextBackend::WebGl: return "webgl";
    }
    return "?";
}

static std::unique_ptr<GlContext> createOne(ContextBackend b, const ContextOptions& o) {
    switch (b) {
    case ContextBackend::EglSurfaceless: return detail::createEglSurfaceless();
    case ContextBackend::EglDevice: return detail::createEglDevice();
    case ContextBackend::EglGles2: return detail::createEglGles2();
    case ContextBackend::Glfw: return detail::createGlfw(o);
    case ContextBackend::GlfwGles2: return detail::createGlfwGles2(o);
    case ContextBackend::OSMesa: return detail::createOSMesa();
    case ContextBackend::WebGl: return detail::createWebGl(o);
    case ContextBackend::Auto: break;
    }
    throw Error("internal: no backend");
}

std::unique_ptr<GlContext> GlContext::create(const ContextOptions& options) {
    ContextBackend wanted = options.backend;
    if (wanted == ContextBackend::Auto) {
        if (const char* env = std::getenv("LIDR_CONTEXT"); env && *env) wanted = parseContextBackend(env);
    }
    std::vector<ContextBackend> order;
    if (wanted == ContextBackend::Auto)
        order = LIDR_HAVE_EGL ? std::vector<ContextBackend>{ContextBackend::EglSurfaceless, ContextBackend::EglDevice}
                              : availableContextBackends();
    else
        order = {wanted};
    std::string tried;
    for (ContextBackend b : order) {
        try {
            return createOne(b, options);
        } catch (const Error& e) {
            tried += std::string("\n  ") + contextBackendName(b) + ": " + e.what();
        }
    }
    throw UnsupportedError("no GL context could be created; tried:" + tried);
}

void GlContext::initialiseGl(const std::string& backendName) { info_ = currentContextGlInfo(backendName); }

std::vector<ContextBackend> availableContextBackends() {
    std::vector<ContextBackend> b;
    if (LIDR_HAVE_EGL) {
        b.push_back(ContextBackend::EglSurfaceless);
        b.push_back(ContextBackend::EglDevice);
        b.push_back(ContextBackend::EglGles2);
    }
    if (LIDR_HAVE_GLFW) {
        b.push_back(ContextBackend::Glfw);
        b.push_back(ContextBackend::GlfwGles2);
    }
    if (LIDR_HAVE_OSMESA) b.push_back(ContextBackend::OSMesa);
    if (LIDR_HAVE_WEBGL) b.push_back(ContextBackend::WebGl);
    return b;
}

// This file is compiled into each library with that library's set of backends; the others say why not.
namespace detail {
[[maybe_unused]] static const char* const kOnlyThisLibrarysBackends = LIDR_HAVE_WEBGL
    ? "the web build (emscripten) offers only the webgl backend"
    : "lidr::lidr_osmesa offers only the osmesa backend (OSMesa's GL entry points replace glvnd's in a "
      "program linked to it); link lidr::lidr for egl, egl-device, egl-gles2, glfw and glfw-gles2";
#if !LIDR_HAVE_EGL
std::unique_ptr<GlContext> createEglSurfaceless() { throw UnsupportedError(kOnlyThisLibrarysBackends); }
std::unique_ptr<GlContext> createEglDevice() { throw UnsupportedError(kOnlyThisLibrarysBackends); }
std::unique_ptr<GlContext> createEglGles2() { throw UnsupportedError(kOnlyThisLibrarysBackends); }
#endif
#if !LIDR_HAVE_GLFW
std::unique_ptr<GlContext> createGlfw(const ContextOptions&) {
    throw UnsupportedError(LIDR_HAVE_EGL ? "lidr was built without GLFW (libglfw3-dev not found at configure time)"
                                         : kOnlyThisLibrarysBackends);
}
std::unique_ptr<GlContext> createGlfwGles2(const ContextOptions& o) { return createGlfw(o); }
#endif
#if !LIDR_HAVE_OSMESA
std::unique_ptr<GlContext> createOSMesa() {
    throw UnsupportedError(LIDR_HAVE_WEBGL ? kOnlyThisLibrarysBackends : LIDR_OSMESA_FOUND
        ? "lidr::lidr does not offer OSMesa, whose GL entry points would clash with glvnd's: link the program "
          "against lidr::lidr_osmesa instead (see doc/contexts.md)"
        : "lidr was built without OSMesa (osmesa.pc not found at configure time; OSMesa is gone from Mesa 25.1 on)");
}
#endif
#if !LIDR_HAVE_WEBGL
std::unique_ptr<GlContext> createWebGl(const ContextOptions&) {
    throw UnsupportedError("WebGL contexts exist only in the web build (emscripten, LIDR_WEB=ON; doc/web.md)");
}
#endif
}  // namespace detail

}  // namespace lidr
