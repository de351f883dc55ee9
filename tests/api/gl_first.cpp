// <GL/gl.h> (with glext.h) before lidr, then lidr's umbrella header.
#include <GL/gl.h>

#include <lidr/lidr.h>

GLenum lidrIncludeCheckGlFirst(const lidr::RenderState& s) { return s.depthTest ? GL_LEQUAL : s.depthFunc; }
