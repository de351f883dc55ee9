#include "lidr/technique/forward_pass.h"
#include "lidr/base/gl.h"

#include "lidr/render/depth_prepass.h"
#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"

namespace lidr {

void setShadingUniforms(const gl::Program& program, const CameraMatrices& camera, const ShadingParameters& shading) {
    program.set("uViewProj", camera.viewProjection);
    program.setIfDeclared("uEyePosition", camera.eye);  // shading.glsl's: a material shader may do without
    program.setIfDeclared("uAmbient", shading.ambient);
    // Every sampler gets its own unit even when unused: two sampler types on one unit (an unset sampler
    // defaults to unit 0, where the per-sample path binds a sampler2DMS) make draws fail.
    program.setIfDeclared("uMaterialTexture", int(gl::kUnitMaterial));
}

namespace {
// Per-sample index reads need texelFetch on sampler2DMS (GLSL 1.50) and gl_SampleID (ARB_sample_shading);
// the compatibility profile keeps every GLSL 1.20 construct the shaders use.
std::string perSampleVersion(std::string source) {
    const std::string v120 = "#version 120";
    const size_t at = source.find(v120);
    if (at == std::string::npos) throw Error("shader without #version 120");
    return source.replace(at, v120.size(), "#version 150 compatibility\n#extension GL_ARB_sample_shading : require");
}
}  // namespace

ForwardPass::ForwardPass(const PackingScheme& scheme, const LightTable& table, bool perSample,
                         const std::string& materialShader)
    : perSample_(perSample) {
    ShaderDefines defines = table.defines();
    for (const auto& d : scheme.unpackDefines()) defines.push_back(d);
    if (perSample) {
        defines.push_back({"LIDR_INDEX_SAMPLER", "sampler2DMS"});
        defines.push_back({"LIDR_FETCH_INDEX(s, uv)", "texelFetch(s, ivec2(gl_FragCoord.xy), gl_SampleID)"});
    }
    std::string vertex = buildShaderSource("geometry.vert");
    const ShaderIncludes unpack = {{"lidr_unpack.glsl", scheme.unpackShaderFile()}};
    std::string fragment = materialShader.empty()
                               ? buildShaderSource("lidr_forward.frag", defines, unpack)
                               : buildShaderSourceFromText("material shader", materialShader, defines, unpack);
    if (perSample) {
        vertex = perSampleVersion(vertex);
        fragment = perSampleVersion(fragment);
    }
    program_ = gl::Program::create(std::string(materialShader.empty() ? "lidr-forward-" : "lidr-material-") +
                                       scheme.name() + (perSample ? "-per-sample" : ""),
                                   vertex, fragment, geometryAttributes());
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
        indices.texture(i).bind(gl::kUnitIndexTarget0 + i);
        program_.set(("uIndexTex" + std::to_string(i)).c_str(), gl::kUnitIndexTarget0 + i);
    }
    table.bind(program_);
}

void ForwardPass::unbindInputs(const IndexTargets& indices) const {
    StateCache::current().apply(RenderState{});
    for (int i = 0; i < indices.count(); ++i) {
        glActiveTexture(GL_TEXTURE0 + gl::kUnitIndexTarget0 + i);
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    glActiveTexture(GL_TEXTURE0);
}

void ForwardPass::run(const RenderTargets& targets, const IndexTargets& indices, const GpuScene& scene,
                      const LightTable& table, const CameraMatrices& camera, const ShadingParameters& shading,
                      bool afterPrepass) const {
    StateCache& cache = StateCache::current();
    ClearAction clear;
    clear.color = true;
    clear.colorValue = glm::vec4(shading.background, 1.0f);
    // Without a pre-pass there is no depth to test against here: the MSAA target never had one, the
    // single-sample one holds the volume pass's cleared depth. Either way this pass writes its own.
    clear.depth = !afterPrepass;
    cache.beginPass(targets.colorPass(clear));
    RenderState s;
    s.depthTest = true;
    // Either way the last fragment drawn at the nearest depth is the one left (lidr/render/gpu_scene.h: DrawOrder).
    s.depthFunc = afterPrepass ? GL_EQUAL : GL_LEQUAL;
    s.depthWrite = !afterPrepass;
    s.sampleShading = perSample_;
    cache.apply(s);
    bindInputs(targets, indices, table, camera, shading);
    scene.draw(program_, DrawFilter::Opaque, true);
    unbindInputs(indices);
    checkGl("LIDR forward pass");
}

void ForwardPass::runTransparent(const RenderTargets& targets, const IndexTargets& indices, const GpuScene& scene,
                                 const LightTable& table, const CameraMatrices& camera,
                                 const ShadingParameters& shading) const {
    StateCache& cache = StateCache::current();
    cache.beginPass(targets.colorPass());
    RenderState s = transparentBlendState();
    s.sampleShading = perSample_;
    cache.apply(s);
    bindInputs(targets, indices, table, camera, shading);
    scene.drawTransparentSorted(program_, camera.eye);
    unbindInputs(indices);
    checkGl("LIDR transparent forward pass");
}

}  // namespace lidr
