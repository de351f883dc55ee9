#include "lidr/base/gl.h"

#include "imgui_es2.h"

#include <cstddef>
#include <cstdint>
#include <string>

#include <imgui.h>

#include "lidr/base/error.h"
#include "lidr/gl/gl_resources.h"

namespace lidr::viewer {
namespace {

static_assert(sizeof(ImDrawIdx) == 2, "ES 2.0 draws 16-bit indices (32-bit ones need OES_element_index_uint)");

constexpr GLuint kPosition = 0, kUv = 1, kColor = 2;

const char* const kVertex = R"(#version 100
uniform mat4 uProjection;
attribute vec2 aPosition;
attribute vec2 aUv;
attribute vec4 aColor;
varying vec2 vUv;
varying vec4 vColor;
void main() {
    vUv = aUv;
    vColor = aColor;
    gl_Position = uProjection * vec4(aPosition, 0.0, 1.0);
}
)";
// mediump: colours and atlas coordinates of a UI (the atlas is far below 2048 texels).
const char* const kFragment = R"(#version 100
precision mediump float;
uniform sampler2D uTexture;
varying vec2 vUv;
varying vec4 vColor;
void main() {
    gl_FragColor = vColor * texture2D(uTexture, vUv);
}
)";

}  // namespace

ImGuiEs2Renderer::ImGuiEs2Renderer() {
    // Program::create throws GlError with the driver's log when a stage does not compile or link.
    program_ = gl::Program::create("imgui-es2", kVertex, kFragment,
                                   {{"aPosition", kPosition}, {"aUv", kUv}, {"aColor", kColor}});
    projection_ = glGetUniformLocation(program_.id(), "uProjection");
    texture_ = glGetUniformLocation(program_.id(), "uTexture");
    glGenBuffers(1, &vertexBuffer_);
    glGenBuffers(1, &indexBuffer_);

    ImGuiIO& io = ImGui::GetIO();
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    glGenTextures(1, &fontTexture_);
    glBindTexture(GL_TEXTURE_2D, fontTexture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);  // ES: unsized format
    glBindTexture(GL_TEXTURE_2D, 0);
    io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(intptr_t(fontTexture_)));
    io.BackendRendererName = "lidr-viewer ES 2.0";
    io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;  // handled by moving the attribute pointers
    checkGl("ImGui ES 2.0 renderer: set-up");
}

ImGuiEs2Renderer::~ImGuiEs2Renderer() {
    if (ImGui::GetCurrentContext()) {
        ImGui::GetIO().Fonts->SetTexID(nullptr);
        ImGui::GetIO().BackendRendererName = nullptr;
        ImGui::GetIO().BackendFlags &= ~ImGuiBackendFlags_RendererHasVtxOffset;
    }
    glDeleteTextures(1, &fontTexture_);
    glDeleteBuffers(1, &vertexBuffer_);
    glDeleteBuffers(1, &indexBuffer_);
}

void ImGuiEs2Renderer::render(const ImDrawData* data, int fbw, int fbh) const {
    if (!data || fbw <= 0 || fbh <= 0) return;
    const ImVec2 pos = data->DisplayPos, size = data->DisplaySize, scale = data->FramebufferScale;
    glViewport(0, 0, fbw, fbh);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_SCISSOR_TEST);
    glUseProgram(program_.id());
    // Display coordinates (y down) to clip space.
    const float l = pos.x, r = pos.x + size.x, t = pos.y, b = pos.y + size.y;
    const float ortho[16] = {2.0f / (r - l), 0, 0, 0, 0, 2.0f / (t - b), 0, 0, 0, 0, -1.0f, 0,
                             (r + l) / (l - r), (t + b) / (b - t), 0, 1.0f};
    glUniformMatrix4fv(projection_, 1, GL_FALSE, ortho);
    glUniform1i(texture_, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
    for (GLuint a : {kPosition, kUv, kColor}) glEnableVertexAttribArray(a);
    for (int n = 0; n < data->CmdListsCount; ++n) {
        const ImDrawList* list = data->CmdLists[n];
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(list->VtxBuffer.Size) * GLsizeiptr(sizeof(ImDrawVert)),
                     list->VtxBuffer.Data, GL_STREAM_DRAW);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(list->IdxBuffer.Size) * GLsizeiptr(sizeof(ImDrawIdx)),
                     list->IdxBuffer.Data, GL_STREAM_DRAW);
        for (const ImDrawCmd& cmd : list->CmdBuffer) {
            if (cmd.UserCallback) {
                if (cmd.UserCallback != ImDrawCallback_ResetRenderState) cmd.UserCallback(list, &cmd);
                continue;
            }
            const float x0 = (cmd.ClipRect.x - pos.x) * scale.x, y0 = (cmd.ClipRect.y - pos.y) * scale.y;
            const float x1 = (cmd.ClipRect.z - pos.x) * scale.x, y1 = (cmd.ClipRect.w - pos.y) * scale.y;
            if (x1 <= x0 || y1 <= y0) continue;
            glScissor(GLint(x0), GLint(float(fbh) - y1), GLsizei(x1 - x0), GLsizei(y1 - y0));
            glBindTexture(GL_TEXTURE_2D, GLuint(reinterpret_cast<intptr_t>(cmd.GetTexID())));
            // No base-vertex draws in ES 2.0: the vertex offset moves the attribute pointers instead.
            const size_t base = size_t(cmd.VtxOffset) * sizeof(ImDrawVert);
            glVertexAttribPointer(kPosition, 2, GL_FLOAT, GL_FALSE, sizeof(ImDrawVert),
                                  reinterpret_cast<void*>(base + offsetof(ImDrawVert, pos)));
            glVertexAttribPointer(kUv, 2, GL_FLOAT, GL_FALSE, sizeof(ImDrawVert),
                                  reinterpret_cast<void*>(base + offsetof(ImDrawVert, uv)));
            glVertexAttribPointer(kColor, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(ImDrawVert),
                                  reinterpret_cast<void*>(base + offsetof(ImDrawVert, col)));
            glDrawElements(GL_TRIANGLES, GLsizei(cmd.ElemCount), GL_UNSIGNED_SHORT,
                           reinterpret_cast<void*>(size_t(cmd.IdxOffset) * sizeof(ImDrawIdx)));
        }
    }
    for (GLuint a : {kPosition, kUv, kColor}) glDisableVertexAttribArray(a);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glUseProgram(0);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    checkGl("ImGui ES 2.0 renderer: drawing the UI");
}

}  // namespace lidr::viewer
