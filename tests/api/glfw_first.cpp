// A program that includes GLFW (which includes <GL/gl.h>) before lidr: lidr's headers name no GL header,
// so this compiles, and GL names from <GL/gl.h> mix with lidr's (GLuint ids, GL_ constants).
#include <GLFW/glfw3.h>

#include <lidr/lidr.h>

GLuint lidrIncludeCheckGlfwFirst(const lidr::RenderTargets& targets) {
    glBindTexture(GL_TEXTURE_2D, targets.color().id());
    return targets.color().id();
}
