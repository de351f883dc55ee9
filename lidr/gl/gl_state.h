#pragma once
// Every pass states all of its fixed-function state in one RenderState and applies it whole, so nothing one
// pass sets can leak into the next (the sokol way). apply() sets every field; it is called a few times per
// pass, never per light, so there is nothing to gain from diffing.
#include <glm/glm.hpp>

#include "lidr/base/gl.h"

namespace lidr {

struct StencilState {
    GLenum func = GL_ALWAYS;
    GLint ref = 0;
    GLuint readMask = 0xFF;
    GLenum stencilFail = GL_KEEP, depthFail = GL_KEEP, depthPass = GL_KEEP;
    GLuint writeMask = 0xFF;
};

struct RenderState {
    bool depthTest = false;
    GLenum depthFunc = GL_LESS;
    bool depthWrite = false;
    bool depthClamp = false;  // only where the context has ARB/NV_depth_clamp

    bool cull = false;
    GLenum cullFace = GL_BACK;

    bool stencilTest = false;
    StencilState stencil;

    bool blend = false;
    GLenum blendEquation = GL_FUNC_ADD;
    GLenum blendSrcRgb = GL_ONE, blendDstRgb = GL_ZERO, blendSrcAlpha = GL_ONE, blendDstAlpha = GL_ZERO;
    glm::vec4 blendColor{0.0f};

    glm::bvec4 colorMask{true, true, true, true};

    bool sampleShading = false;  // every sample shaded (ARB_sample_shading), for per-sample index reads

    bool scissor = false;
    glm::ivec4 scissorBox{0};
};

void applyRenderState(const RenderState& s);

}  // namespace lidr
