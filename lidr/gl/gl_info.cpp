#include "lidr/gl/gl_info.h"

#include <cstdio>
#include <algorithm>
#include <cstring>
#include <utility>
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

// GLEW parsed "OpenGL ES 2.0 Mesa ..." as GL 2.0 (the digits around the first '.') and, with glewExperimental,
// loaded every entry point by name through glvnd, whose dispatch serves ES contexts too; the ones lidr calls on
// ES are checked here, so a missing one is refused now rather than called as a null pointer later.
static void checkEsEntryPoints(const GlInfo& info) {
    const std::pair<const char*, const void*> entryPoints[] = {
        {"glCreateShader", reinterpret_cast<const void*>(glCreateShader)},
        {"glShaderSource", reinterpret_cast<const void*>(glShaderSource)},
        {"glCompileShader", reinterpret_cast<const void*>(glCompileShader)},
        {"glGetShaderiv", reinterpret_cast<const void*>(glGetShaderiv)},
        {"glGetShaderInfoLog", reinterpret_cast<const void*>(glGetShaderInfoLog)},
        {"glDeleteShader", reinterpret_cast<const void*>(glDeleteShader)},
        {"glCreateProgram", reinterpret_cast<const void*>(glCreateProgram)},
        {"glAttachShader", reinterpret_cast<const void*>(glAttachShader)},
        {"glDetachShader", reinterpret_cast<const void*>(glDetachShader)},
        {"glBindAttribLocation", reinterpret_cast<const void*>(glBindAttribLocation)},
        {"glLinkProgram", reinterpret_cast<const void*>(glLinkProgram)},
        {"glGetProgramiv", reinterpret_cast<const void*>(glGetProgramiv)},
        {"glGetProgramInfoLog", reinterpret_cast<const void*>(glGetProgramInfoLog)},
        {"glUseProgram", reinterpret_cast<const void*>(glUseProgram)},
        {"glDeleteProgram", reinterpret_cast<const void*>(glDeleteProgram)},
        {"glGetUniformLocation", reinterpret_cast<const void*>(glGetUniformLocation)},
        {"glUniform1i", reinterpret_cast<const void*>(glUniform1i)},
        {"glUniform1f", reinterpret_cast<const void*>(glUniform1f)},
        {"glUniform2fv", reinterpret_cast<const void*>(glUniform2fv)},
        {"glUniform3fv", reinterpret_cast<const void*>(glUniform3fv)},
        {"glUniform4fv", reinterpret_cast<const void*>(glUniform4fv)},
        {"glUniformMatrix4fv", reinterpret_cast<const void*>(glUniformMatrix4fv)},
        {"glVertexAttribPointer", reinterpret_cast<const void*>(glVertexAttribPointer)},
        {"glEnableVertexAttribArray", reinterpret_cast<const void*>(glEnableVertexAttribArray)},
        {"glDisableVertexAttribArray", reinterpret_cast<const void*>(glDisableVertexAttribArray)},
        {"glGetVertexAttribiv", reinterpret_cast<const void*>(glGetVertexAttribiv)},
        {"glGetVertexAttribPointerv", reinterpret_cast<const void*>(glGetVertexAttribPointerv)},
        {"glGenBuffers", reinterpret_cast<const void*>(glGenBuffers)},
        {"glBindBuffer", reinterpret_cast<const void*>(glBindBuffer)},
        {"glBufferData", reinterpret_cast<const void*>(glBufferData)},
        {"glDeleteBuffers", reinterpret_cast<const void*>(glDeleteBuffers)},
        {"glGenFramebuffers", reinterpret_cast<const void*>(glGenFramebuffers)},
        {"glBindFramebuffer", reinterpret_cast<const void*>(glBindFramebuffer)},
        {"glFramebufferTexture2D", reinterpret_cast<const void*>(glFramebufferTexture2D)},
        {"glFramebufferRenderbuffer", reinterpret_cast<const void*>(glFramebufferRenderbuffer)},
        {"glCheckFramebufferStatus", reinterpret_cast<const void*>(glCheckFramebufferStatus)},
        {"glDeleteFramebuffers", reinterpret_cast<const void*>(glDeleteFramebuffers)},
        {"glGenRenderbuffers", reinterpret_cast<const void*>(glGenRenderbuffers)},
        {"glBindRenderbuffer", reinterpret_cast<const void*>(glBindRenderbuffer)},
        {"glRenderbufferStorage", reinterpret_cast<const void*>(glRenderbufferStorage)},
        {"glDeleteRenderbuffers", reinterpret_cast<const void*>(glDeleteRenderbuffers)},
        {"glGenerateMipmap", reinterpret_cast<const void*>(glGenerateMipmap)},
        {"glActiveTexture", reinterpret_cast<const void*>(glActiveTexture)},
        {"glBlendEquation", reinterpret_cast<const void*>(glBlendEquation)},
        {"glBlendEquationSeparate", reinterpret_cast<const void*>(glBlendEquationSeparate)},
        {"glBlendFuncSeparate", reinterpret_cast<const void*>(glBlendFuncSeparate)},
        {"glBlendColor", reinterpret_cast<const void*>(glBlendColor)},
        {"glStencilFuncSeparate", reinterpret_cast<const void*>(glStencilFuncSeparate)},
        {"glStencilOpSeparate", reinterpret_cast<const void*>(glStencilOpSeparate)},
        {"glStencilMaskSeparate", reinterpret_cast<const void*>(glStencilMaskSeparate)},
        {"glClearDepthf", reinterpret_cast<const void*>(glClearDepthf)},
        {"glGetShaderPrecisionFormat", reinterpret_cast<const void*>(glGetShaderPrecisionFormat)},
    };
    for (const auto& [name, fn] : entryPoints)
        if (!fn) throw UnsupportedError(info.backend + ": " + info.version + ": no entry point for " + name);
}

// OpenGL ES 2.0 (and later ES, taken through the same ES 2.0 path): every capability from an ES 2.0 extension.
static GlInfo esContextGlInfo(GlInfo info) {
    std::sscanf(info.version.c_str(), "OpenGL ES %d.%d", &info.major, &info.minor);
    int glslMajor = 0, glslMinor = 0;
    if (std::sscanf(info.glslVersion.c_str(), "OpenGL ES GLSL ES %d.%d", &glslMajor, &glslMinor) == 2)
        info.glsl = glslMajor * 100 + (glslMinor >= 10 ? glslMinor : glslMinor * 10);
    if (info.major < 2)
        throw UnsupportedError(info.backend + ": " + info.version + " is below the OpenGL ES 2.0 lidr needs");
    checkEsEntryPoints(info);
    info.framebufferObject = hasExtension("GL_OES_packed_depth_stencil");  // lidr shares one depth-stencil
    info.textureFloat = hasExtension("GL_OES_texture_float");
    info.halfFloatColorBuffer =
        hasExtension("GL_OES_texture_half_float") && hasExtension("GL_EXT_color_buffer_half_float");
    info.timerQuery = false;
    info.occlusionQuery = false;
    // Mesa's ES 2.0 has EXT_depth_clamp, but applyRenderState turns clamping on through the desktop flags, and
    // the volume pass's far-plane fallback (vertices pulled onto the far plane) is the ES 2.0 path anyway.
    info.depthClamp = false;
    info.depthTexture = hasExtension("GL_OES_depth_texture");
    info.blendMinMax = hasExtension("GL_EXT_blend_minmax");
    info.readDepthStencil = hasExtension("GL_NV_read_depth_stencil");
    GLint range[2] = {0, 0}, precision = 0;
    glGetShaderPrecisionFormat(GL_FRAGMENT_SHADER, GL_HIGH_FLOAT, range, &precision);
    info.fragmentHighp = precision >= 23;  // fp32; ES 2.0 lets highp be absent in fragment shaders (precision 0)
    info.drawBuffers = hasExtension("GL_EXT_draw_buffers") && hasDrawBuffersEntryPoint();
    info.textureLod = hasExtension("GL_EXT_shader_texture_lod");
    info.halfFloatLinear = hasExtension("GL_OES_texture_half_float") && hasExtension("GL_OES_texture_half_float_linear");
    info.multisampleFbo = false;
    info.maxSamples = 0;
    info.multisampleTexture = info.sampleShading = false;
    if (info.drawBuffers) {
        glGetIntegerv(GL_MAX_DRAW_BUFFERS, &info.maxDrawBuffers);
        glGetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &info.maxColorAttachments);
    }
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &info.maxTextureSize);
    glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &info.maxTextureUnits);
    GLint vertexUniformVectors = 0;
    glGetIntegerv(GL_MAX_VERTEX_UNIFORM_VECTORS, &vertexUniformVectors);
    info.maxVertexUniformVectors = std::max(128, int(vertexUniformVectors));
    while (glGetError() != GL_NO_ERROR) {
    }
    return info;
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
    info.gles = info.version.rfind("OpenGL ES", 0) == 0;
    if (info.gles) return esContextGlInfo(std::move(info));
    std::sscanf(info.version.c_str(), "%d.%d", &info.major, &info.minor);
    int glslMajor = 0, glslMinor = 0;
    if (std::sscanf(info.glslVersion.c_str(), "%d.%d", &glslMajor, &glslMinor) == 2) info.glsl = glslMajor * 100 + glslMinor;
    const bool gl30 = info.major >= 3;
    info.framebufferObject = (gl30 || hasExtension("GL_ARB_framebuffer_object")) && glGenFramebuffers &&
                              glBindFramebuffer && glFramebufferTexture2D;
    info.textureFloat = gl30 || hasExtension("GL_ARB_texture_float");
    // Without ARB_color_buffer_float a GL 2.1 context clamps fragment colours to [0, 1] whatever the buffer (and
    // leaves blending into float buffers undefined); with it, and in GL 3.0, the default clamp is FIXED_ONLY.
    info.halfFloatColorBuffer = info.framebufferObject &&
                                (gl30 || (hasExtension("GL_ARB_texture_float") && hasExtension("GL_ARB_color_buffer_float")));
    info.timerQuery = (hasExtension("GL_ARB_timer_query") && glGetQueryObjectui64v) ||
                       (hasExtension("GL_EXT_timer_query") && glGetQueryObjectui64vEXT);
    info.depthClamp = hasExtension("GL_ARB_depth_clamp") || hasExtension("GL_NV_depth_clamp");
    info.pipelineStatistics = hasExtension("GL_ARB_pipeline_statistics_query");
    info.drawBuffers = hasDrawBuffersEntryPoint();
    info.textureLod = hasExtension("GL_ARB_shader_texture_lod");
    info.halfFloatLinear = info.textureFloat;  // RGB16F filters (GL 3.0 requires it; Mesa's ARB_texture_float does)
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
    if (gles) {
        s << "backend " << backend << ", " << version << ", renderer " << renderer << ", " << glslVersion
          << ", draw buffers " << (drawBuffers ? maxDrawBuffers : 1) << ", MAX blend " << (blendMinMax ? "yes" : "no")
          << ", float textures " << (textureFloat ? "yes" : "no") << ", half-float colour buffers "
          << (halfFloatColorBuffer ? "yes" : "no") << ", depth textures " << (depthTexture ? "yes" : "no")
          << ", fragment highp " << (fragmentHighp ? "yes" : "no") << ", depth clamp " << (depthClamp ? "yes" : "no")
          << ", texture LOD " << (textureLod ? "yes" : "no") << ", half-float filtering "
          << (halfFloatLinear ? "yes" : "no") << ", occlusion and timer queries no, MSAA no";
        return s.str();
    }
    s << "backend " << backend << ", GL " << version << ", renderer " << renderer << ", GLSL " << glslVersion
      << ", FBO " << (framebufferObject ? "yes" : "no") << ", float textures " << (textureFloat ? "yes" : "no")
      << ", half-float colour buffers " << (halfFloatColorBuffer ? "yes" : "no")
      << ", timer queries " << (timerQuery ? "yes" : "no") << ", max samples " << maxSamples;
    return s.str();
}

}  // namespace lidr
