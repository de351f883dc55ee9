#pragma once
// The one include for GL in lidr: GLEW's loader (Debian's GLX build, also used under EGL; see context.cpp),
// or, in the web build (emscripten, WebGL), the GLES headers with the few desktop names lidr uses (gl_web.h).
#ifdef __EMSCRIPTEN__
#include "lidr/base/gl_web.h"
#else
#include <GL/glew.h>
#endif
