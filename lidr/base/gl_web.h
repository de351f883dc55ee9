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
