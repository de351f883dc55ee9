#pragma once
// Dear ImGui's draw lists on OpenGL ES 2.0, for lidr-viewer --context glfw-gles2. Debian's libimgui-dev ships
// the OpenGL2 backend (fixed function and client-side arrays: not in ES 2.0) and an OpenGL3 backend built for
// desktop GL (its own loader, vertex array objects, glPolygonMode: not in ES 2.0 either), so the ES window
// draws ImDrawData itself: one GLSL ES 1.00 program, a vertex and an index buffer, the font texture as RGBA.
// Needs the ES context current; every GL error it meets throws lidr::GlError.
#include <cstdint>

#include "lidr/gl/gl_resources.h"

struct ImDrawData;

namespace lidr::viewer {

class ImGuiEs2Renderer {
public:
    ImGuiEs2Renderer();  // compiles the program, uploads the font atlas, registers as ImGui's renderer backend
    ~ImGuiEs2Renderer();
    ImGuiEs2Renderer(const ImGuiEs2Renderer&) = delete;
    ImGuiEs2Renderer& operator=(const ImGuiEs2Renderer&) = delete;

    // Draws into the bound framebuffer (the window's, fbw x fbh); leaves blending, scissor, the program, the
    // buffers, texture unit 0 and vertex attributes 0..2 as the viewer's window state has them: off, 0.
    void render(const ImDrawData* data, int fbw, int fbh) const;

private:
    gl::Program program_;
    uint32_t vertexBuffer_ = 0, indexBuffer_ = 0, fontTexture_ = 0;
    int projection_ = -1, texture_ = -1;
};

}  // namespace lidr::viewer
