#include "lidr/gl/gl_info.h"

#include <cstdio>
#include <cstring>
#include <sstream>

#include "lidr/base/error.h"
#include "lidr/base/gl.h"

namespace lidr {

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

GlInfo currentContextGlInfo(const std::string& backendName) {
    GlInfo info;
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

    info.backend = backendName;
    info.version = reinterpret_cast<const char*>(version);
    auto str = [](GLenum e) {
        const GLubyte* s = glGetString(e);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
    };
    info.renderer = str(GL_RENDERER);
    info.vendor = str(GL_VENDOR);
    info.glslVersion = str(GL_SHADING_LANGUAGE_VERSION);
    std::sscanf(info.version.c_str(), "%d.%d", &info.major, &info.minor);
    int glslMajor = 0, glslMinor = 0;
    if (std::sscanf(info.glslVersion.c_str(), "%d.%d", &glslMajor, &glslMinor) == 2) info.glsl = glslMajor * 100 + glslMinor;
    const bool gl30 = info.major >= 3;
    info.framebufferObject = (gl30 || hasExtension("GL_ARB_framebuffer_object")) && glGenFramebuffers &&
                              glBindFramebuffer && glFramebufferTexture2D;
    info.textureFloat = gl30 || hasExtension("GL_ARB_texture_float");
    info.timerQuery = (hasExtension("GL_ARB_timer_query") && glGetQueryObjectui64v) ||
                       (hasExtension("GL_EXT_timer_query") && glGetQueryObjectui64vEXT);
    info.depthClamp = hasExtension("GL_ARB_depth_clamp") || hasExtension("GL_NV_depth_clamp");
    info.drawBuffers = glDrawBuffers != nullptr;
    info.multisampleFbo = (gl30 || hasExtension("GL_EXT_framebuffer_multisample") ||
                            hasExtension("GL_ARB_framebuffer_object")) && glRenderbufferStorageMultisample;
    if (info.multisampleFbo) glGetIntegerv(GL_MAX_SAMPLES, &info.maxSamples);
    const bool gl32 = info.major > 3 || (info.major == 3 && info.minor >= 2);
    const bool gl40 = info.major >= 4;
    info.multisampleTexture = (gl32 || hasExtension("GL_ARB_texture_multisample")) && glTexImage2DMultisample;
    // Per-sample reads are written in GLSL 1.50 (texelFetch on sampler2DMS) with ARB_sample_shading.
    info.sampleShading = (gl40 || hasExtension("GL_ARB_sample_shading")) && glMinSampleShading;
    if (info.glsl < 150) info.multisampleTexture = info.sampleShading = false;
    if (info.multisampleTexture) glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &info.maxColorTextureSamples);
    if (info.drawBuffers) glGetIntegerv(GL_MAX_DRAW_BUFFERS, &info.maxDrawBuffers);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &info.maxTextureSize);
    if (info.framebufferObject) glGetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &info.maxColorAttachments);
    glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &info.maxTextureUnits);
    GLint vertexUniformComponents = 0;
    glGetIntegerv(GL_MAX_VERTEX_UNIFORM_COMPONENTS, &vertexUniformComponents);
    if (vertexUniformComponents >= 512) info.maxVertexUniformVectors = vertexUniformComponents / 4;
    while (glGetError() != GL_NO_ERROR) {
    }
    if (info.major < 2 || (info.major == 2 && info.minor < 1))
        throw UnsupportedError(backendName + ": GL " + info.version + " is below the GL 2.1 lidr needs");
    return info;
}


std::string GlInfo::summary() const {
    std::ostringstream s;
    s << "backend " << backend << ", GL " << version << ", renderer " << renderer << ", GLSL " << glslVersion
      << ", FBO " << (framebufferObject ? "yes" : "no") << ", float textures " << (textureFloat ? "yes" : "no")
      << ", timer queries " << (timerQuery ? "yes" : "no") << ", max samples " << maxSamples;
    return s.str();
}

}  // namespace lidr
