#pragma once
// GL for the web build (emscripten, a WebGL 1 context; included by lidr/base/gl.h only under __EMSCRIPTEN__).
// emscripten implements the GLES 2 entry points on WebGL 1, the extension ones (glDrawBuffers through
// WEBGL_draw_buffers, vertex arrays, EXT_disjoint_timer_query's queries) once the extension is enabled, and the
// GLES 3 ones on WebGL 2 only: lidr calls each of those only where GlInfo says the context has it.
// What desktop GL has and WebGL does not is given here the way GLEW gives a missing entry point: a null
// function pointer (so `if (glMinSampleShading)` reads false), and enums with desktop GL's values.
#define GL_GLEXT_PROTOTYPES 1
#include <GLES3/gl31.h>
#include <GLES2/gl2ext.h>

// Desktop GL 1.x-2.x names; ES spells glClearDepth with floats.
inline void glClearDepth(double depth) { glClearDepthf(static_cast<GLfloat>(depth)); }
// Entry points desktop GL has and WebGL has not: null, as GLEW leaves them where the context lacks them.
inline constexpr void (*glDrawBuffer)(GLenum) = nullptr;
inline constexpr void (*glPolygonMode)(GLenum, GLenum) = nullptr;
inline constexpr void (*glTexImage2DMultisample)(GLenum, GLsizei, GLenum, GLsizei, GLsizei, GLboolean) = nullptr;
inline constexpr void (*glMinSampleShading)(GLfloat) = nullptr;
inline constexpr void (*glGetQueryObjectui64v)(GLuint, GLenum, GLuint64*) = nullptr;

#define GL_RGBA32F_ARB 0x8814
#define GL_RGB16F_ARB 0x881B
#define GL_RGBA16F_ARB 0x881A
#define GL_TEXTURE_MAX_LOD 0x813B
#define GL_LUMINANCE8 0x8040
#define GL_LUMINANCE8_ALPHA8 0x8045
#define GL_SAMPLES_PASSED 0x8914
#define GL_DEPTH_CLAMP 0x864F
#define GL_POLYGON_MODE 0x0B40
#define GL_FILL 0x1B02
#define GL_COLOR_LOGIC_OP 0x0BF2
#define GL_STENCIL_INDEX 0x1901
#define GL_STACK_OVERFLOW 0x0503
#define GL_STACK_UNDERFLOW 0x0504
#define GL_SAMPLE_SHADING 0x8C36
#define GL_MIN_SAMPLE_SHADING_VALUE 0x8C37

// GLEW's loader and the extension flags lidr reads directly: WebGL needs no loading, and has no depth clamp.
#define GLEW_OK 0
inline GLboolean glewExperimental = GL_FALSE;
inline GLenum glewInit() { return GLEW_OK; }
inline const GLubyte* glewGetErrorString(GLenum) { return reinterpret_cast<const GLubyte*>(""); }
#define GLEW_ARB_depth_clamp false
#define GLEW_NV_depth_clamp false

// WebGL names the ES 2.0 extensions lidr looks for its own way. The web build reports them under their ES
// names too, so the GLES 2.0 path's detection (lidr/gl/gl_info.cpp) reads a WebGL 1 context like an ES one:
// WEBGL_draw_buffers is EXT_draw_buffers (same enums, same GLSL #extension name), WEBGL_depth_texture is
// OES_depth_texture, and packed depth-stencil (OES_packed_depth_stencil) is core in WebGL 1 (DEPTH_STENCIL).
#include <cstring>
#include <string>
inline const GLubyte* lidrWebGetString(GLenum name) {
    const GLubyte* s = glGetString(name);
    if (name != GL_EXTENSIONS || s == nullptr) return s;
    static std::string extensions;
    extensions = reinterpret_cast<const char*>(s);
    const std::string padded = " " + extensions + " ";
    if (padded.find(" WEBGL_draw_buffers ") != std::string::npos) extensions += " GL_EXT_draw_buffers";
    if (padded.find(" WEBGL_depth_texture ") != std::string::npos) extensions += " GL_OES_depth_texture";
    extensions += " GL_OES_packed_depth_stencil";
    return reinterpret_cast<const GLubyte*>(extensions.c_str());
}
#define glGetString lidrWebGetString

// WebGL 1's packed depth-stencil renderbuffer is DEPTH_STENCIL (0x84F9) attached at DEPTH_STENCIL_ATTACHMENT
// (0x821A); ES 2.0 names it DEPTH24_STENCIL8_OES (0x88F0, WebGL 2 only) and attaches it as depth and as stencil,
// which WebGL 1 refuses. The web build translates both: the renderbuffers made as packed depth-stencil are
// remembered, and their depth attachment becomes the DEPTH_STENCIL one, their stencil attachment nothing more.
#include <set>
inline std::set<GLuint>& lidrWebDepthStencilRenderbuffers() {
    static std::set<GLuint> ids;
    return ids;
}
inline void lidrWebRenderbufferStorage(GLenum target, GLenum format, GLsizei width, GLsizei height) {
    GLint bound = 0;
    glGetIntegerv(GL_RENDERBUFFER_BINDING, &bound);
    if (format == GL_DEPTH24_STENCIL8) {
        lidrWebDepthStencilRenderbuffers().insert(GLuint(bound));
        format = GL_DEPTH_STENCIL;
    } else {
        lidrWebDepthStencilRenderbuffers().erase(GLuint(bound));
    }
    glRenderbufferStorage(target, format, width, height);
}
inline void lidrWebFramebufferRenderbuffer(GLenum target, GLenum attachment, GLenum renderbufferTarget,
                                           GLuint renderbuffer) {
    if (lidrWebDepthStencilRenderbuffers().count(renderbuffer)) {
        if (attachment == GL_STENCIL_ATTACHMENT) return;
        if (attachment == GL_DEPTH_ATTACHMENT) attachment = GL_DEPTH_STENCIL_ATTACHMENT;
    }
    glFramebufferRenderbuffer(target, attachment, renderbufferTarget, renderbuffer);
}
#define glRenderbufferStorage lidrWebRenderbufferStorage
#define glFramebufferRenderbuffer lidrWebFramebufferRenderbuffer
