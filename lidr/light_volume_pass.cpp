#include "lidr/light_volume_pass.h"

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

#include "lidr/error.h"
#include "lidr/shader_source.h"

namespace lidr {

const char* volumeTestName(VolumeTest t) {
    switch (t) {
    case VolumeTest::BackFace: return "backface";
    case VolumeTest::ExactStencil: return "exact";
    case VolumeTest::FrontFace: return "frontface";
    }
    return "?";
}

VolumeTest parseVolumeTest(const std::string& name) {
    if (name == "backface" || name == "back-face") return VolumeTest::BackFace;
    if (name == "exact" || name == "exact-stencil") return VolumeTest::ExactStencil;
    if (name == "frontface" || name == "front-face") return VolumeTest::FrontFace;
    throw Error("unknown volume test '" + name + "' (valid: backface, exact, frontface)");
}

IndexTargets::IndexTargets(int count, int width, int height, const gl::Renderbuffer& depthStencil, int samples)
    : width_(width), height_(height), samples_(samples) {
    if (count < 1 || count > kMaxIndexTargets) throw Error("index target count must be 1..4");
    fbo_ = gl::Framebuffer::create();
    for (int i = 0; i < count; ++i) {
        textures_.push_back(samples > 0 ? gl::Texture::create2DMultisample(GL_RGBA8, width, height, samples)
                                        : gl::Texture::create2D(GL_RGBA8, width, height, GL_RGBA, GL_UNSIGNED_BYTE));
        fbo_.attachTexture(GL_COLOR_ATTACHMENT0 + i, textures_.back());
    }
    fbo_.attachRenderbuffer(GL_DEPTH_STENCIL_ATTACHMENT, depthStencil);
    fbo_.checkComplete("light-index targets");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

size_t IndexTargets::bytes() const { return size_t(count()) * width_ * height_ * 4 * std::max(samples_, 1); }

LightVolumePass::LightVolumePass(const GlInfo& info, VolumeTest test)
    : test_(test), depthClamp_(info.depthClamp), mesh_(makeLightVolumeMesh(2)) {
    vertices_ = gl::Buffer::create(GL_ARRAY_BUFFER, mesh_.positions.data(), mesh_.positions.size() * sizeof(glm::vec3));
    indices_ = gl::Buffer::create(GL_ELEMENT_ARRAY_BUFFER, mesh_.indices.data(),
                                  mesh_.indices.size() * sizeof(uint16_t));
    for (int n = 1; n <= kMaxIndexTargets; ++n) {
        if (n > 1 && n > info.maxDrawBuffers) break;
        const ShaderDefines defs = {{"LIDR_DRAW_TARGETS", std::to_string(n)}};
        programs_.push_back(gl::Program::create("light-volume-" + std::to_string(n),
                                                buildShaderSource("light_volume.vert", defs),
                                                buildShaderSource("light_volume.frag", defs),
                                                {{"aPosition", gl::kPosition}}));
    }
}

const gl::Program& LightVolumePass::programFor(int targetCount) const {
    if (targetCount < 1 || targetCount > static_cast<int>(programs_.size()))
        throw UnsupportedError("writing " + std::to_string(targetCount) +
                               " index targets at once needs that many draw buffers");
    return programs_[targetCount - 1];
}

void LightVolumePass::begin(const IndexTargets& targets, const CameraMatrices& camera) {
    targets_ = &targets;
    camera_ = camera;
    drawCalls_ = 0;
    targets.framebuffer().bind();
    std::vector<GLenum> all;
    for (int i = 0; i < targets.count(); ++i) all.push_back(GL_COLOR_ATTACHMENT0 + i);
    glDrawBuffers(static_cast<GLsizei>(all.size()), all.data());
    glViewport(0, 0, targets.width(), targets.height());
    applyRenderState(RenderState{});  // all masks open for the clear
    glClearColor(0, 0, 0, 0);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
    glEnableVertexAttribArray(gl::kPosition);
    glVertexAttribPointer(gl::kPosition, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    checkGl("light-volume pass begin");
}

void LightVolumePass::drawVolume(const VolumeLight& light) const {
    (void)light;
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh_.indices.size()), GL_UNSIGNED_SHORT, nullptr);
    ++drawCalls_;
}

void LightVolumePass::draw(const VolumeDraw& d, const std::vector<VolumeLight>& lights,
                           const std::function<IndexColors(uint32_t)>& colors) {
    if (!targets_) throw Error("LightVolumePass::draw outside begin/end");
    if (d.firstTarget < 0 || d.firstTarget + d.targetCount > targets_->count())
        throw Error("volume draw '" + d.name + "' addresses index targets outside the frame's set");
    const gl::Program& program = programFor(d.targetCount);
    program.use();
    program.set("uViewProj", camera_.viewProjection);
    std::vector<GLenum> buffers;
    for (int i = 0; i < d.targetCount; ++i) buffers.push_back(GL_COLOR_ATTACHMENT0 + d.firstTarget + i);
    glDrawBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    const GLint posLoc = program.uniform("uLightPosRadius");
    const GLint colorLoc = program.uniform("uIndexColor");
    const GLint clampLoc = program.uniform("uClampToFar");

    // The volume test proper: back faces (cull front) at or behind the surface.
    RenderState inside;
    inside.depthTest = true;
    inside.depthFunc = GL_GEQUAL;
    inside.depthClamp = depthClamp_;  // back faces past the far plane still mark the pixels in front of them
    inside.cull = true;
    inside.cullFace = GL_FRONT;
    inside.colorMask = d.colorMask;
    inside.blend = d.blend;
    inside.blendEquation = d.blendEquation;
    inside.blendSrcRgb = inside.blendSrcAlpha = d.blendSrc;
    inside.blendDstRgb = inside.blendDstAlpha = d.blendDst;
    inside.blendColor = d.blendColor;
    inside.stencilTest = true;

    RenderState mark, count, unmark;
    if (test_ == VolumeTest::BackFace || test_ == VolumeTest::FrontFace) {
        // Stencil counts every light that marks the pixel; with a slot limit only the first ones write.
        inside.stencil.func = d.slotLimit > 0 ? GL_GREATER : GL_ALWAYS;  // passes while limit > count
        inside.stencil.ref = d.slotLimit;
        inside.stencil.stencilFail = GL_INCR;
        inside.stencil.depthPass = GL_INCR;
        countBits_ = 8;
    } else {
        // Bit 7 marks "this pixel's surface lies in front of the volume" for the current light only;
        // bits 0..6 count the lights that really contain the surface.
        mark.depthTest = true;
        mark.depthFunc = GL_GREATER;  // front face behind the surface: surface in front of the light
        mark.depthClamp = depthClamp_;
        mark.cull = true;
        mark.cullFace = GL_BACK;
        mark.colorMask = glm::bvec4(false);
        mark.stencilTest = true;
        mark.stencil.func = GL_ALWAYS;
        mark.stencil.ref = 0x80;
        mark.stencil.depthPass = GL_REPLACE;
        mark.stencil.writeMask = 0x80;
        unmark = mark;
        unmark.stencil.ref = 0;
        // Marked pixels hold >= 128, so "limit > stencil" and "128 > stencil" both reject them.
        inside.stencil.func = GL_GREATER;
        inside.stencil.ref = d.slotLimit > 0 ? d.slotLimit : 0x80;
        inside.stencil.writeMask = 0;
        count = inside;
        count.colorMask = glm::bvec4(false);
        count.blend = false;
        count.stencil.ref = 0x7F;  // saturate the 7-bit count at 127
        count.stencil.depthPass = GL_INCR;
        count.stencil.writeMask = 0x7F;
        countBits_ = 7;
    }

    // Without depth clamp, a back face beyond the far plane would be clipped and would not mark the pixels
    // in front of it: such lights are pulled onto the far plane in the vertex shader and skip the depth test
    // (conservative: the whole footprint is marked).
    const float outside = mesh_.outsideRadius;
    auto depthOf = [&](const VolumeLight& l) { return glm::dot(glm::vec3(l.posRadius) - camera_.eye, camera_.forward); };
    auto reachesFar = [&](const VolumeLight& l) {
        return depthOf(l) + l.posRadius.w * outside >= camera_.farPlane * 0.999f;
    };
    RenderState insideNoDepth = inside;
    insideNoDepth.depthFunc = GL_ALWAYS;
    // Front-face test: front faces at or before the surface. A volume reaching in front of the near plane
    // (or holding the camera) has its front faces clipped there; it is drawn by its back faces without a
    // depth test instead, which marks every ray that is inside the volume anywhere past the near plane.
    RenderState front = inside;
    front.depthFunc = GL_LEQUAL;
    front.cullFace = GL_BACK;
    auto reachesNear = [&](const VolumeLight& l) {
        return depthOf(l) - l.posRadius.w * outside <= camera_.nearPlane * 1.001f;
    };

    enum Choice { kInside, kInsideNoDepth, kFront };
    int applied = -1;  // re-applied only when the choice changes
    for (const VolumeLight& l : lights) {
        glUniform4fv(posLoc, 1, glm::value_ptr(l.posRadius));
        const IndexColors c = colors(l.index);
        glUniform4fv(colorLoc, d.targetCount, glm::value_ptr(c[0]));
        const bool clampToFar = !depthClamp_ && reachesFar(l);
        glUniform1f(clampLoc, clampToFar ? 1.0f : 0.0f);
        if (test_ == VolumeTest::ExactStencil) {
            applyRenderState(mark);
            drawVolume(l);
            applyRenderState(clampToFar ? insideNoDepth : inside);
            drawVolume(l);
            RenderState c2 = count;
            if (clampToFar) c2.depthFunc = GL_ALWAYS;
            applyRenderState(c2);
            drawVolume(l);
            applyRenderState(unmark);
            drawVolume(l);
            applied = -1;
            continue;
        }
        int want = clampToFar ? kInsideNoDepth : kInside;
        if (test_ == VolumeTest::FrontFace) want = reachesNear(l) ? kInsideNoDepth : kFront;
        if (want != applied) {
            applyRenderState(want == kInside ? inside : want == kFront ? front : insideNoDepth);
            applied = want;
        }
        drawVolume(l);
    }
    checkGl(("light-volume draw '" + d.name + "'").c_str());
}

void LightVolumePass::end() {
    glDisableVertexAttribArray(gl::kPosition);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    applyRenderState(RenderState{});
    targets_ = nullptr;
    checkGl("light-volume pass end");
}

}  // namespace lidr
