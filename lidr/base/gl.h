#pragma once
// The one include for GL in lidr: GLEW's loader (Debian's GLX build, also used under EGL; see context.cpp),
// or, in the web build (emscripten, WebGL), the GLES headers with the few desktop names lidr uses (gl_web.h).
#ifdef __EMSCRIPTEN__
#include "lidr/base/gl_web.h"
#else
#include <GL/glew.h>
#endif

#include <cstring>

namespace lidr {

// True when the current context is OpenGL ES (GL_VERSION "OpenGL ES N.M ..."). Asked of the context, not of a
// flag, so a program's own ES context (WebGL 1, an embedded ES 2.0 part) takes the ES path too.
inline bool currentContextIsGles() {
    const GLubyte* v = glGetString(GL_VERSION);
    return v != nullptr && std::strncmp(reinterpret_cast<const char*>(v), "OpenGL ES", 9) == 0;
}

// Calls whose desktop GL and OpenGL ES 2.0 forms differ (doc/contexts.md, "OpenGL ES 2.0").
// glClearDepth (double) is desktop only; ES has glClearDepthf.
inline void setClearDepth(float depth) {
    if (currentContextIsGles())
        glClearDepthf(depth);
    else
        glClearDepth(depth);
}
// glDrawBuffer / glReadBuffer are desktop only; an ES 2.0 FBO draws to and reads from COLOR_ATTACHMENT0 (more
// draw targets go through glDrawBuffers, EXT_draw_buffers), so there these do nothing for attachment 0.
// Whether glDrawBuffers may be called: GLEW's loaded entry point, or always in the web build (where it is a
// function, whose address would always be true).
inline bool hasDrawBuffersEntryPoint() {
#ifdef __EMSCRIPTEN__
    return true;
#else
    return glDrawBuffers != nullptr;
#endif
}
inline void drawToColorAttachment0() {
    if (!currentContextIsGles()) glDrawBuffer(GL_COLOR_ATTACHMENT0);
}
inline void readFromColorAttachment0() {
    if (!currentContextIsGles()) glReadBuffer(GL_COLOR_ATTACHMENT0);
}

}  // namespace lidr
