#include "lidr/modes/g_buffer_unorm8.h"
#include "lidr/base/gl.h"

#include <algorithm>
#include <cstdio>

#include "lidr/base/error.h"
#include "lidr/gl/bindings.h"
#include "lidr/gl/gl_state.h"
#include "lidr/render/depth_prepass.h"

namespace lidr {

namespace {
constexpr const char* kSamplers[GBufferUnorm8::kTargets] = {"uGBuffer0", "uGBuffer1", "uGBuffer2", "uGBuffer3",
                                                             "uGBuffer4"};

int unitOf(int target) { return target < 4 ? gl::kUnitGBuffer0 + target : gl::kUnitGBuffer4; }

}  // namespace

GBufferUnorm8::GBufferUnorm8(const GlInfo& info, const RenderTargets& targets)
    : width_(targets.width()), height_(targets.height()) {
    if (!info.fragmentHighp)  // mediump (fp16) holds integers to 2048 only
        throw UnsupportedError("the RGBA8 G-buffer packs a 24-bit depth and 12-bit normals, which need highp "
                               "fragment floats (GL_FRAGMENT_PRECISION_HIGH); this OpenGL ES context has mediump only");
    if (info.maxTextureUnits <= gl::kUnitGBuffer4)
        throw UnsupportedError("the RGBA8 G-buffer's lighting passes sample texture unit " +
                               std::to_string(int(gl::kUnitGBuffer4)) + "; this context has " +
                               std::to_string(info.maxTextureUnits) + " texture units");
    for (gl::Texture& t : targets_) t = gl::Texture::create2D(GL_RGBA, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE);
    // Without EXT_draw_buffers an ES 2.0 FBO draws to COLOR_ATTACHMENT0 alone: one target a pass.
    const int perPass = std::clamp(info.drawBuffers ? info.maxDrawBuffers : 1, 1, kTargets);
    for (int first = 0; first < kTargets; first += perPass) {
        GeometryPass p;
        p.first = first;
        p.count = std::min(perPass, kTargets - first);
        p.fbo = gl::Framebuffer::create();
        for (int i = 0; i < p.count; ++i) p.fbo.attachTexture(GL_COLOR_ATTACHMENT0 + i, targets_[first + i]);
        p.fbo.attachDepthStencil(targets.depthStencil(), targets.separateStencil());
        p.fbo.requireComplete("the RGBA8 G-buffer", info.renderer);
        const ShaderDefines defines = {{"LIDR_GBUFFER_FIRST_TARGET", std::to_string(p.first)},
                                       {"LIDR_GBUFFER_PASS_TARGETS", std::to_string(p.count)}};
        p.program = gl::Program::create("g-buffer-rgba8-" + std::to_string(first), buildShaderSource("geometry.vert"),
                                        buildShaderSource("g_buffer_unorm8.frag", defines), geometryAttributes());
        passes_.push_back(std::move(p));
    }
    checkGl("GBufferUnorm8");
}

void GBufferUnorm8::draw(const GpuScene& scene, const CameraMatrices& camera) const {
    StateCache& cache = StateCache::current();
    for (const GeometryPass& p : passes_) {
        PassDescription pass{p.fbo.id(), glm::ivec4(0, 0, width_, height_), {}, {}};
        for (int i = 0; i < p.count; ++i) pass.drawBuffers.push_back(GL_COLOR_ATTACHMENT0 + i);
        pass.clear.color = true;  // 0: target 3's alpha 0 says no surface
        cache.beginPass(pass);
        RenderState s;
        s.depthTest = true;
        s.depthFunc = GL_EQUAL;  // one fragment a pixel: the pre-pass's
        cache.apply(s);
        p.program.use();
        p.program.set("uViewProj", camera.viewProjection);
        p.program.setIfDeclared("uEyePosition", camera.eye);
        p.program.setIfDeclared("uMaterialTexture", int(gl::kUnitMaterial));
        scene.draw(p.program, DrawFilter::Opaque, true, &camera, 0);
    }
}

void GBufferUnorm8::bind(const gl::Program& program) const {
    for (int i = 0; i < kTargets; ++i) {
        targets_[i].bind(unitOf(i));
        program.set(kSamplers[i], unitOf(i));
    }
}

}  // namespace lidr
