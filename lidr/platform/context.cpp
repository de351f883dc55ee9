#include "lidr/platform/context.h"

#include <cstdlib>
#include <cstring>

#include "lidr/base/error.h"
#include "lidr/base/gl.h"

namespace lidr {

ContextBackend parseContextBackend(const std::string& name) {
    if (name == "auto") return ContextBackend::Auto;
    if (name == "egl" || name == "egl-surfaceless" || name == "surfaceless") return ContextBackend::EglSurfaceless;
    if (name == "egl-device" || name == "device") return ContextBackend::EglDevice;
    if (name == "glfw") return ContextBackend::Glfw;
    if (name == "osmesa") return ContextBackend::OSMesa;
    throw Error("unknown GL context backend '" + name + "' (valid: auto, egl, egl-device, glfw, osmesa)");
}

const char* contextBackendName(ContextBackend b) {
    switch (b) {
    case ContextBackend::Auto: return "auto";
    case ContextBackend::EglSurfaceless: return "egl";
    case ContextBackend::EglDevice: return "egl-device";
    case ContextBackend::Glfw: return "glfw";
    case ContextBackend::OSMesa: return "osmesa";
    }
    return "?";
}

static std::unique_ptr<GlContext> createOne(ContextBackend b, const ContextOptions& o) {
    switch (b) {
    case ContextBackend::EglSurfaceless: return detail::createEglSurfaceless();
    case ContextBackend::EglDevice: return detail::createEglDevice();
    case ContextBackend::Glfw: return detail::createGlfw(o);
    case ContextBackend::OSMesa: return detail::createOSMesa();
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

static bool hasExtension(const char* name) {
    // glGetString(GL_EXTENSIONS) is valid in every context lidr asks for (legacy / compatibility profiles).
    const char* ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
    if (!ext) return false;
    const size_t n = std::strlen(name);
    for (const char* p = ext; (p = std::strstr(p, name)) != nullptr; p += n) {
        const bool startOk = p == ext || p[-1] == ' ';
        const bool endOk = p[n] == ' ' || p[n] == '\0';
        if (startOk && endOk) return true;
    }
    return false;
}

void GlContext::initialiseGl(const std::string& backendName) {
    glewExperimental = GL_TRUE;
    const GLenum glewStatus = glewInit();
    const GLubyte* version = glGetString(GL_VERSION);
    if (glewStatus != GLEW_OK) {
        // 4 == GLEW_ERROR_NO_GLX_DISPLAY: expected from a GLX-built GLEW under EGL; fine if GL answers.
        if (!(glewStatus == 4 && version != nullptr))
            throw UnsupportedError(backendName + ": glewInit failed (" +
                                   reinterpret_cast<const char*>(glewGetErrorString(glewStatus)) + ")");
    }
    if (!version) throw UnsupportedError(backendName + ": glGetString(GL_VERSION) returned null");
    while (glGetError() != GL_NO_ERROR) {
    }  // glewInit can leave GL_INVALID_ENUM behind

    info_.backend = backendName;
    info_.version = reinterpret_cast<const char*>(version);
    auto str = [](GLenum e) {
        const GLubyte* s = glGetString(e);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
    };
    info_.renderer = str(GL_RENDERER);
    info_.vendor = str(GL_VENDOR);
    info_.glslVersion = str(GL_SHADING_LANGUAGE_VERSION);
    std::sscanf(info_.version.c_str(), "%d.%d", &info_.major, &info_.minor);
    int glslMajor = 0, glslMinor = 0;
    if (std::sscanf(info_.glslVersion.c_str(), "%d.%d", &glslMajor, &glslMinor) == 2) info_.glsl = glslMajor * 100 + glslMinor;
    const bool gl30 = info_.major >= 3;
    info_.framebufferObject = (gl30 || hasExtension("GL_ARB_framebuffer_object")) && glGenFramebuffers &&
                              glBindFramebuffer && glFramebufferTexture2D;
    info_.textureFloat = gl30 || hasExtension("GL_ARB_texture_float");
    info_.timerQuery = (hasExtension("GL_ARB_timer_query") && glGetQueryObjectui64v) ||
                       (hasExtension("GL_EXT_timer_query") && glGetQueryObjectui64vEXT);
    info_.depthClamp = hasExtension("GL_ARB_depth_clamp") || hasExtension("GL_NV_depth_clamp");
    info_.drawBuffers = glDrawBuffers != nullptr;
    info_.multisampleFbo = (gl30 || hasExtension("GL_EXT_framebuffer_multisample") ||
                            hasExtension("GL_ARB_framebuffer_object")) && glRenderbufferStorageMultisample;
    if (info_.multisampleFbo) glGetIntegerv(GL_MAX_SAMPLES, &info_.maxSamples);
    const bool gl32 = info_.major > 3 || (info_.major == 3 && info_.minor >= 2);
    const bool gl40 = info_.major >= 4;
    info_.multisampleTexture = (gl32 || hasExtension("GL_ARB_texture_multisample")) && glTexImage2DMultisample;
    // Per-sample reads are written in GLSL 1.50 (texelFetch on sampler2DMS) with ARB_sample_shading.
    info_.sampleShading = (gl40 || hasExtension("GL_ARB_sample_shading")) && glMinSampleShading;
    if (info_.glsl < 150) info_.multisampleTexture = info_.sampleShading = false;
    if (info_.multisampleTexture) glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &info_.maxColorTextureSamples);
    if (info_.drawBuffers) glGetIntegerv(GL_MAX_DRAW_BUFFERS, &info_.maxDrawBuffers);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &info_.maxTextureSize);
    if (info_.framebufferObject) glGetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &info_.maxColorAttachments);
    glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &info_.maxTextureUnits);
    GLint vertexUniformComponents = 0;
    glGetIntegerv(GL_MAX_VERTEX_UNIFORM_COMPONENTS, &vertexUniformComponents);
    if (vertexUniformComponents >= 512) info_.maxVertexUniformVectors = vertexUniformComponents / 4;
    while (glGetError() != GL_NO_ERROR) {
    }
    if (info_.major < 2 || (info_.major == 2 && info_.minor < 1))
        throw UnsupportedError(backendName + ": GL " + info_.version + " is below the GL 2.1 lidr needs");
}

std::vector<ContextBackend> availableContextBackends() {
    std::vector<ContextBackend> b;
    if (LIDR_HAVE_EGL) {
        b.push_back(ContextBackend::EglSurfaceless);
        b.push_back(ContextBackend::EglDevice);
    }
    if (LIDR_HAVE_GLFW) b.push_back(ContextBackend::Glfw);
    if (LIDR_HAVE_OSMESA) b.push_back(ContextBackend::OSMesa);
    return b;
}

// This file is compiled into each library with that library's set of backends; the others say why not.
namespace detail {
[[maybe_unused]] static const char* const kOnlyOSMesa =
    "lidr::lidr_osmesa offers only the osmesa backend (OSMesa's GL entry points replace glvnd's in a "
    "program linked to it); link lidr::lidr for egl, egl-device and glfw";
#if !LIDR_HAVE_EGL
std::unique_ptr<GlContext> createEglSurfaceless() { throw UnsupportedError(kOnlyOSMesa); }
std::unique_ptr<GlContext> createEglDevice() { throw UnsupportedError(kOnlyOSMesa); }
#endif
#if !LIDR_HAVE_GLFW
std::unique_ptr<GlContext> createGlfw(const ContextOptions&) {
    throw UnsupportedError(LIDR_HAVE_EGL ? "lidr was built without GLFW (libglfw3-dev not found at configure time)"
                                         : kOnlyOSMesa);
}
#endif
#if !LIDR_HAVE_OSMESA
std::unique_ptr<GlContext> createOSMesa() {
    throw UnsupportedError(LIDR_OSMESA_FOUND
        ? "lidr::lidr does not offer OSMesa, whose GL entry points would clash with glvnd's: link the program "
          "against lidr::lidr_osmesa instead (see doc/contexts.md)"
        : "lidr was built without OSMesa (osmesa.pc not found at configure time; OSMesa is gone from Mesa 25.1 on)");
}
#endif
}  // namespace detail

}  // namespace lidr
