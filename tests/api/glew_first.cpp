// GLEW first, as a program using its own GLEW would, then lidr.
#include <GL/glew.h>

#include <lidr/lidr.h>

GLuint lidrIncludeCheckGlewFirst(const lidr::gl::Program& p) { return p.id() + GL_VERTEX_SHADER * 0; }
