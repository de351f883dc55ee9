#include "lidr/base/error.h"

#include "lidr/base/gl.h"

namespace lidr {

static const char* glErrorName(GLenum e) {
    switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    default: return "unknown GL error";
    }
}

void checkGl(const char* where) {
    std::string errors;
    for (int guard = 0; guard < 32; ++guard) {  // a lost context can report errors forever
        GLenum e = glGetError();
        if (e == GL_NO_ERROR) break;
        if (!errors.empty()) errors += ", ";
        errors += glErrorName(e);
    }
    if (!errors.empty()) throw GlError(std::string("GL error in ") + where + ": " + errors);
}

}  // namespace lidr
