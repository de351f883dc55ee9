#include "lidr/forward_pass.h"

#include "lidr/depth_prepass.h"
#include "lidr/error.h"
#include "lidr/gl_state.h"
#include "lidr/shader_source.h"

namespace lidr {

void setShadingUniforms(const gl::Program& program, const CameraMatrices& camera, const ShadingParameters& shading) {
    program.set("uViewProj", camera.viewProjection);
    program.set("uEyePosition", camera.eye);
    program.set("uAmbient", shading.ambient);
}

ForwardPass::ForwardPass(const PackingScheme& scheme, const LightTable& table) {
    ShaderDefines defines = table.defines();
    for (const auto& d : scheme.unpackDefines()) defines.push_back(d);
    program_ = gl::Program::create(
        "lidr-forward-" + scheme.name(), buildShaderSource("geometry.vert"),
        buildShaderSource("lidr_forward.frag", defines, {{"lidr_unpack.glsl", scheme.unpackShaderFile()}}),
        geometryAttributes());
}

RenderState transparentBlendState() {
    RenderState s;
    s.depthTest = true;
    s.depthFunc = GL_LEQUAL;
    s.depthWrite = false;
    s.blend = true;
    s.blendSrcRgb = GL_SRC_ALPHA;
    s.blendDstRgb = GL_ONE_MINUS_SRC_ALPHA;
    s.blendSrcAlpha = GL_ZERO;  // keep the opaque alpha of 1
    s.blendDstAlpha = GL_ONE;
    return s;
}

void ForwardPass::bindInputs(const RenderTargets& targets, const IndexTargets& indices, const LightTable& table,
                             const CameraMatrices& camera, const ShadingParameters& shading) const {
    program_.use();
    setShadingUniforms(program_, camera, shading);
    program_.set("uInvViewportSize", glm::vec2(1.0f / targets.width(), 1.0f / targets.height()));
    for (int i = 0; i < indices.count(); ++i) {
        indices.texture(i).bind(i);
        program_.set(("uIndexTex" + std::to_string(i)).c_str(), i);
    }
    table.bind(program_);
}

void ForwardPass::unbindInputs(const IndexTargets& indices) const {
    applyRenderState(RenderState{});
    for (int i = 0; i < indices.count(); ++i) {
        glActiveTexture(GL_TEXTURE0 + i);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    glActiveTexture(GL_TEXTURE0);
}

void ForwardPass::run(const RenderTargets& targets, const IndexTargets& indices, const GpuScene& scene,
                      const LightTable& table, const CameraMatrices& camera, const ShadingParameters& shading,
                      bool afterPrepass) const {
    targets.bindColor();
    applyRenderState(RenderState{});
    glClearColor(shading.background.r, shading.background.g, shading.background.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    RenderState s;
    s.depthTest = true;
    s.depthFunc = afterPrepass ? GL_EQUAL : GL_LESS;  // after a pre-pass: one shaded fragment per pixel
    s.depthWrite = !afterPrepass;
    applyRenderState(s);
    bindInputs(targets, indices, table, camera, shading);
    scene.draw(program_, DrawFilter::Opaque, true);
    unbindInputs(indices);
    checkGl("LIDR forward pass");
}

void ForwardPass::runTransparent(const RenderTargets& targets, const IndexTargets& indices, const GpuScene& scene,
                                 const LightTable& table, const CameraMatrices& camera,
                                 const ShadingParameters& shading) const {
    targets.bindColor();
    applyRenderState(transparentBlendState());
    bindInputs(targets, indices, table, camera, shading);
    scene.drawTransparentSorted(program_, camera.eye);
    unbindInputs(indices);
    checkGl("LIDR transparent forward pass");
}

}  // namespace lidr
