// lidr first, GLEW after it (GLEW refuses to follow <GL/gl.h>; lidr's headers do not include one), then GLFW.
#include <lidr/lidr.h>

#include <GL/glew.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

GLuint lidrIncludeCheckGlewAfter(const lidr::RenderTargets& targets) {
    glBindFramebuffer(GL_FRAMEBUFFER, targets.colorFramebuffer().id());
    return targets.colorFramebuffer().id();
}
