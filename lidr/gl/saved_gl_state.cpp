#include "lidr/gl/saved_gl_state.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "lidr/gl/gl_state.h"

namespace lidr {

namespace {
void enable(GLenum cap, GLboolean on) { on ? glEnable(cap) : glDisable(cap); }
}  // namespace

namespace {
// What the current context has, from its version and extension strings (GLEW's flags cannot say: with
// glewExperimental they report whatever entry points the driver exports, e.g. GL 4.0 on softpipe's 3.3).
struct Features {
    bool gles, vao, readFramebuffer, depthClamp, sampleShading, multisampleTexture, clientArrays;
};

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

Features currentFeatures() {
    int major = 0, minor = 0;
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    if (version) std::sscanf(version, "%d.%d", &major, &minor);
    const int v = major * 10 + minor;
    const char* ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
    Features f;
    f.gles = currentContextIsGles();
    // WebGL has no client-side vertex arrays; its GL_VERSION names it ("WebGL 1.0 ...", which emscripten reports
    // as "OpenGL ES 2.0 (WebGL 1.0 ...)").
    f.clientArrays = !(version && std::strstr(version, "WebGL"));
    if (f.gles) {  // OpenGL ES 2.0: lidr binds no VAO and no read framebuffer there, so neither is saved
        f.vao = f.readFramebuffer = f.sampleShading = f.multisampleTexture = false;
        f.depthClamp = hasExtension(ext, "GL_EXT_depth_clamp");
        return f;
    }
    f.vao = v >= 30 || hasExtension(ext, "GL_ARB_vertex_array_object");
    f.readFramebuffer = v >= 30 || hasExtension(ext, "GL_ARB_framebuffer_object") ||
                        hasExtension(ext, "GL_EXT_framebuffer_blit");
    f.depthClamp = v >= 32 || hasExtension(ext, "GL_ARB_depth_clamp") || hasExtension(ext, "GL_NV_depth_clamp");
    f.sampleShading = (v >= 40 || hasExtension(ext, "GL_ARB_sample_shading")) && glMinSampleShading;
    f.multisampleTexture = v >= 32 || hasExtension(ext, "GL_ARB_texture_multisample");
    return f;
}
}  // namespace

SavedGlState::SavedGlState() {
    const Features f = currentFeatures();
    gles_ = f.gles;
    vao_ = f.vao;
    readFramebuffer_ = f.readFramebuffer;
    depthClamp_ = f.depthClamp;
    sampleShading_ = f.sampleShading;
    multisampleTex_ = f.multisampleTexture;
    clientArrays_ = f.clientArrays;
    save();
    StateCache::current().invalidate();  // the caller's state is unknown to lidr's cache
}

SavedGlState::~SavedGlState() {
    restore();
    StateCache::current().invalidate();  // the caller's state is back, behind the cache's back
}

void SavedGlState::save() {
    saveBindings();
    savePixelStore();
    saveFixedFunction();
    saveBuffers();
    setDefaultsLidrAssumes();
}

void SavedGlState::saveBindings() {
    // The caller's vertex array object stays bound: lidr's vertex setup changes its attributes 0..7 and
    // element buffer, which are saved here and put back. (Switching to VAO 0 instead crashed softpipe,
    // Mesa 22.3, in a later draw.)
    if (vao_) glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
    GLint units = 0;
    glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &units);
    units_ = std::min<int>(units, kMaxTextureUnits);
    for (int i = 0; i < units_; ++i) {
        glActiveTexture(GL_TEXTURE0 + i);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture2D_[i]);
        glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &cubeMap_[i]);  // the environment light's cube (GL 1.3, ES 2.0)
        if (multisampleTex_) glGetIntegerv(GL_TEXTURE_BINDING_2D_MULTISAMPLE, &texture2DMs_[i]);
    }
    glActiveTexture(activeTexture_);
}

void SavedGlState::savePixelStore() {
    glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment_);
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &unpackAlignment_);
    if (!gles_) {
        glGetIntegerv(GL_PACK_ROW_LENGTH, &packRowLength_);
        glGetIntegerv(GL_UNPACK_ROW_LENGTH, &unpackRowLength_);
        glGetIntegerv(GL_PACK_SKIP_ROWS, &skip_[0]);
        glGetIntegerv(GL_PACK_SKIP_PIXELS, &skip_[1]);
        glGetIntegerv(GL_UNPACK_SKIP_ROWS, &skip_[2]);
        glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &skip_[3]);
        glGetIntegerv(GL_POLYGON_MODE, polygonMode_);
        logicOp_ = glIsEnabled(GL_COLOR_LOGIC_OP);
        glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &pixelPackBuffer_);  // GL 2.1 core; ES 2.0 has none
        glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &pixelUnpackBuffer_);
    }
}

void SavedGlState::saveFixedFunction() {
    alphaToCoverage_ = glIsEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glGetIntegerv(GL_VIEWPORT, viewport_);
    glGetIntegerv(GL_SCISSOR_BOX, scissorBox_);
    blend_ = glIsEnabled(GL_BLEND);
    depthTest_ = glIsEnabled(GL_DEPTH_TEST);
    stencilTest_ = glIsEnabled(GL_STENCIL_TEST);
    cullFace_ = glIsEnabled(GL_CULL_FACE);
    scissorTest_ = glIsEnabled(GL_SCISSOR_TEST);
    polygonOffsetFill_ = glIsEnabled(GL_POLYGON_OFFSET_FILL);
    if (depthClamp_) depthClampOn_ = glIsEnabled(GL_DEPTH_CLAMP);
    if (sampleShading_) {
        sampleShadingOn_ = glIsEnabled(GL_SAMPLE_SHADING);
        glGetFloatv(GL_MIN_SAMPLE_SHADING_VALUE, &minSampleShading_);
    }
    glGetIntegerv(GL_DEPTH_FUNC, &depthFunc_);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
    glGetFloatv(GL_DEPTH_CLEAR_VALUE, &depthClear_);
    const GLenum stencil[2][7] = {
        {GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_VALUE_MASK, GL_STENCIL_FAIL, GL_STENCIL_PASS_DEPTH_FAIL,
         GL_STENCIL_PASS_DEPTH_PASS, GL_STENCIL_WRITEMASK},
        {GL_STENCIL_BACK_FUNC, GL_STENCIL_BACK_REF, GL_STENCIL_BACK_VALUE_MASK, GL_STENCIL_BACK_FAIL,
         GL_STENCIL_BACK_PASS_DEPTH_FAIL, GL_STENCIL_BACK_PASS_DEPTH_PASS, GL_STENCIL_BACK_WRITEMASK}};
    for (int f = 0; f < 2; ++f) {
        glGetIntegerv(stencil[f][0], &stencilFunc_[f]);
        glGetIntegerv(stencil[f][1], &stencilRef_[f]);
        glGetIntegerv(stencil[f][2], &stencilValueMask_[f]);
        glGetIntegerv(stencil[f][3], &stencilFail_[f]);
        glGetIntegerv(stencil[f][4], &stencilDepthFail_[f]);
        glGetIntegerv(stencil[f][5], &stencilDepthPass_[f]);
        glGetIntegerv(stencil[f][6], &stencilWriteMask_[f]);
    }
    glGetIntegerv(GL_STENCIL_CLEAR_VALUE, &stencilClear_);
    glGetIntegerv(GL_BLEND_EQUATION_RGB, &blendEquationRgb_);
    glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &blendEquationAlpha_);
    glGetIntegerv(GL_BLEND_SRC_RGB, &blendSrcRgb_);
    glGetIntegerv(GL_BLEND_DST_RGB, &blendDstRgb_);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &blendSrcAlpha_);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &blendDstAlpha_);
    glGetFloatv(GL_BLEND_COLOR, blendColor_);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clearColor_);
    glGetBooleanv(GL_COLOR_WRITEMASK, colorMask_);
    glGetIntegerv(GL_CULL_FACE_MODE, &cullFaceMode_);
    glGetIntegerv(GL_FRONT_FACE, &frontFace_);
}

void SavedGlState::saveBuffers() {
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &drawFramebuffer_);
    if (readFramebuffer_) glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebufferBinding_);
    glGetIntegerv(GL_RENDERBUFFER_BINDING, &renderbuffer_);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &arrayBuffer_);
    glGetIntegerv(GL_ELEMENT_ARRAY_BUFFER_BINDING, &elementArrayBuffer_);
    GLint attributes = 0;
    glGetIntegerv(GL_MAX_VERTEX_ATTRIBS, &attributes);
    attributes_ = std::min<int>(attributes, kMaxAttributes);
    for (int i = 0; i < attributes_; ++i) {
        Attribute& a = attribute_[i];
        glGetVertexAttribiv(i, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &a.enabled);
        glGetVertexAttribiv(i, GL_VERTEX_ATTRIB_ARRAY_SIZE, &a.size);
        glGetVertexAttribiv(i, GL_VERTEX_ATTRIB_ARRAY_TYPE, &a.type);
        glGetVertexAttribiv(i, GL_VERTEX_ATTRIB_ARRAY_STRIDE, &a.stride);
        glGetVertexAttribiv(i, GL_VERTEX_ATTRIB_ARRAY_NORMALIZED, &a.normalized);
        glGetVertexAttribiv(i, GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, &a.buffer);
        glGetVertexAttribPointerv(i, GL_VERTEX_ATTRIB_ARRAY_POINTER, &a.pointer);
    }
}

void SavedGlState::setDefaultsLidrAssumes() {
    // lidr's passes set every RenderState field and assume GL's defaults for the rest: pixel store (read-backs
    // into tight buffers), polygon offset and mode, front face, logic op, alpha to coverage.
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    if (!gles_) {
        for (GLenum e : {GL_PACK_ROW_LENGTH, GL_UNPACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS,
                         GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS})
            glPixelStorei(e, 0);
        // A program's pixel buffers would take lidr's read-backs and feed its uploads (the light table).
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
        glDisable(GL_COLOR_LOGIC_OP);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glFrontFace(GL_CCW);
    // lidr enables the arrays it draws with; one the caller left enabled (perhaps a client-memory pointer, or
    // a buffer since deleted) would be fetched by drivers that read every enabled array (softpipe does).
    for (int i = 0; i < attributes_; ++i) glDisableVertexAttribArray(i);
}

void SavedGlState::restore() const {
    for (int i = 0; i < attributes_; ++i) {
        const Attribute& a = attribute_[i];
        glBindBuffer(GL_ARRAY_BUFFER, a.buffer);
        // No buffer and no client-side arrays (WebGL): the caller's buffer was deleted while the attribute named
        // it (deleting a buffer unbinds it from the current attributes, the offset stays). WebGL refuses an offset
        // without a buffer (GL_INVALID_OPERATION), and one into a buffer that is gone means nothing: put back
        // with none, as WebGL allows. (Contexts with client-side arrays take the pointer as it was.)
        const void* pointer = a.buffer == 0 && !clientArrays_ ? nullptr : a.pointer;
        glVertexAttribPointer(i, a.size, a.type, a.normalized ? GL_TRUE : GL_FALSE, a.stride, pointer);
        a.enabled ? glEnableVertexAttribArray(i) : glDisableVertexAttribArray(i);
    }
    glBindBuffer(GL_ARRAY_BUFFER, arrayBuffer_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, elementArrayBuffer_);
    if (readFramebuffer_) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, readFramebufferBinding_);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, drawFramebuffer_);
    } else {
        glBindFramebuffer(GL_FRAMEBUFFER, drawFramebuffer_);
    }
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer_);
    // A program the caller deleted while it was current stayed current (GL keeps it until it is replaced); lidr
    // replaced it, so it is gone now and glUseProgram would fail (GL_INVALID_VALUE): none is current instead.
    glUseProgram(program_ != 0 && glIsProgram(GLuint(program_)) ? GLuint(program_) : 0);
    for (int i = 0; i < units_; ++i) {
        glActiveTexture(GL_TEXTURE0 + i);
        glBindTexture(GL_TEXTURE_2D, texture2D_[i]);
        glBindTexture(GL_TEXTURE_CUBE_MAP, cubeMap_[i]);
        if (multisampleTex_) glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, texture2DMs_[i]);
    }
    glActiveTexture(activeTexture_);
    glPixelStorei(GL_PACK_ALIGNMENT, packAlignment_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, unpackAlignment_);
    if (!gles_) {
        glPixelStorei(GL_PACK_ROW_LENGTH, packRowLength_);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, unpackRowLength_);
        glPixelStorei(GL_PACK_SKIP_ROWS, skip_[0]);
        glPixelStorei(GL_PACK_SKIP_PIXELS, skip_[1]);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, skip_[2]);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, skip_[3]);
        glBindBuffer(GL_PIXEL_PACK_BUFFER, pixelPackBuffer_);
        glBindBuffer(GL_PIXEL_UNPACK_BUFFER, pixelUnpackBuffer_);
        // GL_POLYGON_MODE reads front and back (compatibility profile); they are set together here.
        glPolygonMode(GL_FRONT, GLenum(polygonMode_[0]));
        glPolygonMode(GL_BACK, GLenum(polygonMode_[1]));
        enable(GL_COLOR_LOGIC_OP, logicOp_);
    }
    enable(GL_SAMPLE_ALPHA_TO_COVERAGE, alphaToCoverage_);
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    glScissor(scissorBox_[0], scissorBox_[1], scissorBox_[2], scissorBox_[3]);
    enable(GL_BLEND, blend_);
    enable(GL_DEPTH_TEST, depthTest_);
    enable(GL_STENCIL_TEST, stencilTest_);
    enable(GL_CULL_FACE, cullFace_);
    enable(GL_SCISSOR_TEST, scissorTest_);
    enable(GL_POLYGON_OFFSET_FILL, polygonOffsetFill_);
    if (depthClamp_) enable(GL_DEPTH_CLAMP, depthClampOn_);
    if (sampleShading_) {
        enable(GL_SAMPLE_SHADING, sampleShadingOn_);
        glMinSampleShading(minSampleShading_);
    }
    glDepthFunc(depthFunc_);
    glDepthMask(depthMask_);
    setClearDepth(depthClear_);
    const GLenum faces[2] = {GL_FRONT, GL_BACK};
    for (int f = 0; f < 2; ++f) {
        glStencilFuncSeparate(faces[f], stencilFunc_[f], stencilRef_[f], GLuint(stencilValueMask_[f]));
        glStencilOpSeparate(faces[f], stencilFail_[f], stencilDepthFail_[f], stencilDepthPass_[f]);
        glStencilMaskSeparate(faces[f], GLuint(stencilWriteMask_[f]));
    }
    glClearStencil(stencilClear_);
    glBlendEquationSeparate(blendEquationRgb_, blendEquationAlpha_);
    glBlendFuncSeparate(blendSrcRgb_, blendDstRgb_, blendSrcAlpha_, blendDstAlpha_);
    glBlendColor(blendColor_[0], blendColor_[1], blendColor_[2], blendColor_[3]);
    glClearColor(clearColor_[0], clearColor_[1], clearColor_[2], clearColor_[3]);
    glColorMask(colorMask_[0], colorMask_[1], colorMask_[2], colorMask_[3]);
    glCullFace(cullFaceMode_);
    glFrontFace(frontFace_);
    if (vao_) glBindVertexArray(vertexArray_);
}

}  // namespace lidr
