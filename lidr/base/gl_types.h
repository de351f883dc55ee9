#pragma once
// The GL scalar types lidr's headers name, without a GL header. The public headers include this one, never
// GLEW or <GL/gl.h>, so a program may include GLFW, SDL, <GL/gl.h>, <epoxy/gl.h> or GLEW before or after any
// lidr header (GLEW refuses to come after <GL/gl.h>; lidr/base/gl.h, the GLEW include, is for lidr's own .cpp
// files). The typedefs are the ones every GL header declares (Khronos: GLenum and GLuint are 32-bit unsigned,
// GLint and GLsizei 32-bit signed); C++ accepts a typedef repeated with the same type.
// GL enum values a header needs are lidr::glc constants with the GL value.
typedef unsigned int GLenum;
typedef unsigned int GLuint;
typedef int GLint;
typedef int GLsizei;
typedef float GLfloat;
typedef unsigned char GLboolean;

namespace lidr::glc {
constexpr GLenum kZero = 0, kOne = 1;
constexpr GLenum kLess = 0x0201, kEqual = 0x0202, kAlways = 0x0207;
constexpr GLenum kBack = 0x0405;
constexpr GLenum kKeep = 0x1E00;
constexpr GLenum kFuncAdd = 0x8006;
constexpr GLenum kNearest = 0x2600;
constexpr GLenum kStaticDraw = 0x88E4;
}  // namespace lidr::glc
