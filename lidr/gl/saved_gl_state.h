#pragma once
// The caller's GL state around a frame: every renderer's render() (and presentFrame) saves it on entry and
// puts it back on exit, exceptions included, so lidr can draw inside a program's own context (GLFW, SDL, an
// engine, Dear ImGui after it) without disturbing it. What is kept is listed in doc/embedding.md; the GL
// state test (tests/test_embedding.cpp) sets all of it to unusual values and checks it after each mode.
#include <vector>

#include "lidr/base/gl_types.h"

namespace lidr {

class SavedGlState {
public:
    // Saves the state (with the bound vertex array object's attributes 0..7 and element buffer, where the
    // context has VAOs), then sets what lidr's passes take for granted: GL's default pixel store, polygon
    // offset, polygon mode, front face, logic op and alpha to coverage off, generic vertex arrays 0..7 off.
    SavedGlState();
    ~SavedGlState();  // restores it
    SavedGlState(const SavedGlState&) = delete;
    SavedGlState& operator=(const SavedGlState&) = delete;

    // Units 0..18: every unit lidr binds (lidr/gl/bindings.h: the shadow atlas on 16, the environment light on 17
    // and 18), as many as the context has.
    static constexpr int kMaxTextureUnits = 19;
    static constexpr int kMaxAttributes = 8;     // generic vertex attributes 0..7 (lidr uses 0..3)

private:
    struct Attribute {
        GLint enabled = 0, size = 4, type = 0, stride = 0, normalized = 0, buffer = 0;
        void* pointer = nullptr;
    };
    void save();
    // save()'s parts: the program, VAO and texture units; the pixel store (with the desktop-only polygon mode, logic
    // op and pixel buffers); the fixed-function state; framebuffers, buffers and attributes; then the GL defaults
    // lidr's passes assume.
    void saveBindings();
    void savePixelStore();
    void saveFixedFunction();
    void saveBuffers();
    void setDefaultsLidrAssumes();
    void restore() const;

    // gles_: OpenGL ES 2.0 has no row length / skip pixel store, polygon mode or logic op to save.
    bool gles_ = false;
    // clientArrays_: an attribute pointer without a buffer is client memory; false in WebGL, which has none.
    bool clientArrays_ = true;
    bool vao_ = false, readFramebuffer_ = false, depthClamp_ = false, sampleShading_ = false, multisampleTex_ = false;
    int units_ = 0, attributes_ = 0;
    GLint vertexArray_ = 0, program_ = 0, activeTexture_ = 0;
    GLint texture2D_[kMaxTextureUnits] = {}, texture2DMs_[kMaxTextureUnits] = {}, cubeMap_[kMaxTextureUnits] = {};
    GLint packAlignment_ = 4, unpackAlignment_ = 4, packRowLength_ = 0, unpackRowLength_ = 0, skip_[4] = {};
    GLint polygonMode_[2] = {};
    GLboolean logicOp_ = 0, alphaToCoverage_ = 0;
    GLint viewport_[4] = {}, scissorBox_[4] = {};
    GLboolean blend_ = 0, depthTest_ = 0, stencilTest_ = 0, cullFace_ = 0, scissorTest_ = 0, depthClampOn_ = 0,
              sampleShadingOn_ = 0, polygonOffsetFill_ = 0;
    GLfloat minSampleShading_ = 0.0f;
    GLint depthFunc_ = 0;
    GLboolean depthMask_ = 1;
    GLfloat depthClear_ = 1.0f;
    GLint stencilFunc_[2] = {}, stencilRef_[2] = {}, stencilValueMask_[2] = {}, stencilFail_[2] = {},
          stencilDepthFail_[2] = {}, stencilDepthPass_[2] = {}, stencilWriteMask_[2] = {}, stencilClear_ = 0;
    GLint blendEquationRgb_ = 0, blendEquationAlpha_ = 0, blendSrcRgb_ = 0, blendDstRgb_ = 0, blendSrcAlpha_ = 0,
          blendDstAlpha_ = 0;
    GLfloat blendColor_[4] = {}, clearColor_[4] = {};
    GLboolean colorMask_[4] = {1, 1, 1, 1};
    GLint cullFaceMode_ = 0, frontFace_ = 0;
    GLint drawFramebuffer_ = 0, readFramebufferBinding_ = 0, renderbuffer_ = 0;
    GLint arrayBuffer_ = 0, elementArrayBuffer_ = 0, pixelPackBuffer_ = 0, pixelUnpackBuffer_ = 0;
    Attribute attribute_[kMaxAttributes];
};

}  // namespace lidr
