// Links lidr::lidr_osmesa through find_package(lidr): an OSMesa context, an FBO cleared and read back.
#include <cstdio>

#include <lidr/platform/context.h>
#include <lidr/base/error.h>
#include <GL/glew.h>  // the program's own GL loader; lidr loaded its entry points into GLEW
#include <lidr/gl/gl_resources.h>

int main() {
    try {
        auto context = lidr::GlContext::create();  // auto: lidr_osmesa offers only OSMesa
        lidr::gl::Texture color = lidr::gl::Texture::create2D(GL_RGBA8, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE);
        lidr::gl::Framebuffer fbo = lidr::gl::Framebuffer::create();
        fbo.bind();
        fbo.attachTexture(GL_COLOR_ATTACHMENT0, color);
        fbo.checkComplete("consumer FBO");
        glViewport(0, 0, 4, 4);
        glClearColor(0.0f, 1.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        unsigned char p[4] = {1, 1, 1, 1};
        glReadPixels(2, 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
        lidr::checkGl("consumer read-back");
        const bool ok = context->info().backend == "osmesa" && p[0] == 0 && p[1] == 255 && p[2] == 0 && p[3] == 255;
        std::printf("consumer_osmesa: %s (%s)\n", ok ? "ok" : "FAILED", context->info().summary().c_str());
        return ok ? 0 : 1;
    } catch (const lidr::Error& e) {
        std::printf("consumer_osmesa: %s\n", e.what());
        return 1;
    }
}
