#include "lidr/render/shading_pass.h"
#include "lidr/base/gl.h"

#include "lidr/gl/bindings.h"
#include "lidr/render/shading_variants.h"

#include <algorithm>

namespace lidr {

void beginOpaqueShading(const RenderTargets& targets, const ShadingParameters& shading, bool afterPrepass,
                        bool sampleShading) {
    beginOpaqueShading(targets.colorPass(), shading, afterPrepass, sampleShading);
}

void beginOpaqueShading(PassDescription pass, const ShadingParameters& shading, bool afterPrepass,
                        bool sampleShading) {
    StateCache& cache = StateCache::current();
    ClearAction& clear = pass.clear;
    clear = ClearAction{};
    clear.color = true;
    // The background is linear light like everything else: cleared to its output-transformed value.
    clear.colorValue = glm::vec4(glm::vec3(applyOutputTransform(glm::dvec3(shading.background), shading.output)), 1.0f);
    clear.depth = clear.stencil = !afterPrepass;  // without a pre-pass this pass writes its own depth
    cache.beginPass(pass);
    RenderState s;
    s.depthTest = true;
    s.depthFunc = afterPrepass ? GL_EQUAL : GL_LEQUAL;
    s.depthWrite = !afterPrepass;
    s.sampleShading = sampleShading;
    cache.apply(s);
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

void beginTransparentShading(bool sampleShading) {
    RenderState s = transparentBlendState();
    s.sampleShading = sampleShading;
    StateCache::current().apply(s);
}

void setOutputUniforms(const gl::Program& program, const OutputTransform& output) {
    program.setIfDeclared("uExposureStops", output.exposureStops);
    program.setIfDeclared("uToneMap", float(int(output.toneMap)));
    program.setIfDeclared("uSrgbOutput", output.srgb ? 1.0f : 0.0f);
}

void setDirectionalLightUniforms(const gl::Program& program, const std::vector<DirectionalLight>& lights) {
    if (!program.declares("uDirectionalLightCount")) return;  // a material shader without shading.glsl
    // validateDirectionalLights (every render() checks it first) keeps the count within the shader's arrays.
    glm::vec4 toLight[maxDirectionalLights], color[maxDirectionalLights];
    const int count = int(std::min(lights.size(), maxDirectionalLights));
    for (int i = 0; i < count; ++i) {
        toLight[i] = glm::vec4(-glm::normalize(lights[i].direction), 0.0f);
        color[i] = glm::vec4(lights[i].color, 0.0f);
    }
    program.set("uDirectionalLightCount", float(count));
    if (count == 0) return;
    program.uniform<glm::vec4>("uDirectionalLightToLight").setArray(toLight, count);
    program.uniform<glm::vec4>("uDirectionalLightColor").setArray(color, count);
}

uint32_t shadingVariantKey(const gl::Program& program, const ShadingParameters& shading, const EnvironmentMaps& environment) {
    return shadingVariantKey(program, shading.directionalLights.size(), shading.output) | environment.variantKey(program);
}

void setShadingUniforms(const gl::Program& program, const CameraMatrices& camera, const ShadingParameters& shading,
                        const EnvironmentMaps& environment) {
    program.set("uViewProj", camera.viewProjection);
    program.setIfDeclared("uEyePosition", camera.eye);  // shading.glsl's: a material shader may do without
    program.setIfDeclared("uAmbient", shading.ambient);
    setDirectionalLightUniforms(program, shading.directionalLights);
    setOutputUniforms(program, shading.output);
    // Every sampler gets its own unit even when unused: two sampler types on one unit (an unset sampler
    // defaults to unit 0, where the per-sample path binds a sampler2DMS) make draws fail.
    program.setIfDeclared("uMaterialTexture", int(gl::kUnitMaterial));
    environment.bind(program);
}

void useShadingProgram(const gl::Program& program, const CameraMatrices& camera, const ShadingParameters& shading,
                       const LightTable& table, const EnvironmentMaps& environment) {
    program.use();
    setShadingUniforms(program, camera, shading, environment);
    table.bind(program);
}

const std::vector<int>& drawShadowMaps(ShadowMaps& shadows, FrameTimer& timer, FrameStats& stats, const GpuScene& scene,
                                       const std::vector<PointLight>& lights, const ShadingParameters& shading,
                                       LightTableFormat table) {
    if (shading.shadows.enabled) shadows.checkUnits(table);
    TimedPass shadowMapsTime(timer, pass::kShadowMaps.name);
    const std::vector<int>& tiles = shadows.update(scene, lights, shading.shadows);
    shadowMapsTime.end();
    stats.shadowCasters = shadows.casters();
    stats.shadowMapsDrawn = shadows.mapsDrawn();
    return tiles;
}

}  // namespace lidr
