#pragma once
// Every pass states all of its fixed-function state in one RenderState and applies it whole, so nothing one
// pass sets can leak into the next (the sokol way). apply() sets every field; it is called a few times per
// pass, never per light, so there is nothing to gain from diffing.
#include <glm/glm.hpp>

#include "lidr/base/gl_types.h"

namespace lidr {

struct StencilState {
    GLenum func = glc::kAlways;
    GLint ref = 0;
    GLuint readMask = 0xFF;
    GLenum stencilFail = glc::kKeep, depthFail = glc::kKeep, depthPass = glc::kKeep;
    GLuint writeMask = 0xFF;
};

struct RenderState {
    bool depthTest = false;
    GLenum depthFunc = glc::kLess;
    bool depthWrite = false;
    bool depthClamp = false;  // only where the context has ARB/NV_depth_clamp

    bool cull = false;
    GLenum cullFace = glc::kBack;

    bool stencilTest = false;
    StencilState stencil;

    bool blend = false;
    GLenum blendEquation = glc::kFuncAdd;
    GLenum blendSrcRgb = glc::kOne, blendDstRgb = glc::kZero, blendSrcAlpha = glc::kOne, blendDstAlpha = glc::kZero;
    glm::vec4 blendColor{0.0f};

    glm::bvec4 colorMask{true, true, true, true};

    bool sampleShading = false;  // every sample shaded (ARB_sample_shading), for per-sample index reads

    bool scissor = false;
    glm::ivec4 scissorBox{0};
};

void applyRenderState(const RenderState& s);

}  // namespace lidr
