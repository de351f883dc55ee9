#include "lidr/technique/forward_pass.h"
#include "lidr/base/gl.h"

#include "lidr/render/depth_prepass.h"
#include "lidr/base/error.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/shader_source.h"
#include "lidr/render/shading_pass.h"
#include "lidr/render/shading_variants.h"

namespace lidr {

namespace {
// The frame's shading variant of a forward program: suns, output transform, and whether indices are region-local.
uint32_t variantKey(const gl::Program& program, const LightTable& table, const ShadingParameters& shading,
                    const EnvironmentMaps& environment, bool lights) {
    return shadingVariantKey(program, shading, environment) |
           regionMapVariantKey(program, lights && table.regionMapUniform().w > 0.5f);
}
}  // namespace

ForwardPass::ForwardPass(const PackingScheme& scheme, const LightTable& table, bool perSample,
                         const std::string& materialShader, DepthEmulation depth)
    : perSample_(perSample), maxLights_(scheme.config().budget) {
    defines_ = table.defines();
    for (const auto& d : scheme.unpackDefines()) defines_.push_back(d);
    if (perSample) {
        defines_.push_back({"LIDR_INDEX_SAMPLER", "sampler2DMS"});
        defines_.push_back({"LIDR_FETCH_INDEX(s, uv)", "texelFetch(s, ivec2(gl_FragCoord.xy), gl_SampleID)"});
    }
    if (depth.bits != 0 && !materialShader.empty())
        throw Error("emulated depth precision needs lidr's own forward shader: a material shader does not write the "
                    "rounded depth the pre-pass wrote");
    unpackFile_ = scheme.unpackShaderFile();
    materialShader_ = materialShader;
    depth_ = depth;
    const std::string name = std::string(materialShader.empty() ? "lidr-forward-" : "lidr-material-") +
                             packingSchemeName(scheme.config().scheme) + (perSample ? "-per-sample" : "");
    name_ = name;
    program_ = build({});
    // The lightless variant's sources, compiled only if a frame needs it (the includes are resolved before the
    // preprocessor drops the list code, so it takes the same ones).
    ShaderDefines none = {{"LIDR_NO_LIGHTS", "1"}};
    ShaderIncludes noUnpack = {{"lidr_unpack.glsl", scheme.unpackShaderFile()}};
    depth.apply(none, noUnpack);
    lightlessVertex_ = buildShaderSource("geometry.vert");
    lightlessFragment_ = materialShader.empty() ? buildShaderSource("lidr_forward.frag", none, noUnpack)
                                                : buildShaderSourceFromText("material shader", materialShader, none, noUnpack);
    lightlessName_ = name + "-no-lights";
    if (perSample) {  // shaded per sample like the lit program
        lightlessVertex_ = perSampleGlsl150(lightlessVertex_);
        lightlessFragment_ = perSampleGlsl150(lightlessFragment_);
    }
}

gl::Program ForwardPass::build(const ShaderDefines& extra) const {
    ShaderDefines defines = defines_;
    defines.insert(defines.end(), extra.begin(), extra.end());
    ShaderIncludes unpack = {{"lidr_unpack.glsl", unpackFile_}};
    depth_.apply(defines, unpack);
    std::string vertex = buildShaderSource("geometry.vert");
    std::string fragment = materialShader_.empty()
                               ? buildShaderSource("lidr_forward.frag", defines, unpack)
                               : buildShaderSourceFromText("material shader", materialShader_, defines, unpack);
    if (perSample_) {
        vertex = perSampleGlsl150(vertex);
        fragment = perSampleGlsl150(fragment);
    }
    return gl::Program::create(name_ + (extra.empty() ? "" : "-shadowed"), vertex, fragment, geometryAttributes());
}

const gl::Program& ForwardPass::bindInputs(const RenderTargets& targets, const IndexTargets& indices,
                                           const LightTable& table, const CameraMatrices& camera,
                                           const ShadingParameters& shading, const EnvironmentMaps& environment,
                                           bool lights, const ShadowMaps* shadows) const {
    if (!lights) {
        if (!lightless_)
            lightless_ = gl::Program::create(lightlessName_, lightlessVertex_, lightlessFragment_, geometryAttributes());
        lightless_.use();
        setShadingUniforms(lightless_, camera, shading, environment);
        return lightless_;
    }
    const gl::Program* chosen = &program_;
    if (shadows && shadows->active()) {
        const ShaderDefines extra = shadows->defines(shading.shadows);
        std::string key;
        for (const auto& d : extra) key += d.first + "=" + d.second + " ";
        auto found = shadowed_.find(key);
        if (found == shadowed_.end()) found = shadowed_.emplace(key, build(extra)).first;
        chosen = &found->second;
    }
    const gl::Program& program = *chosen;
    useShadingProgram(program, camera, shading, table, environment);
    if (shadows && shadows->active()) shadows->bind(program, shading.shadows);
    program.setIfDeclared("uLidrMaxLights", maxLights_);
    program.set("uInvViewportSize", glm::vec2(1.0f / targets.width(), 1.0f / targets.height()));
    program.setIfDeclared("uLidrRegionMap", table.regionMapUniform());
    for (int i = 0; i < indices.count(); ++i) {
        indices.texture(i).bind(gl::kUnitIndexTarget0 + i);
        program.set(("uIndexTex" + std::to_string(i)).c_str(), gl::kUnitIndexTarget0 + i);
    }
    return program;
}

void ForwardPass::unbindInputs(const IndexTargets& indices, bool lights) const {
    StateCache& cache = StateCache::current();
    cache.apply(RenderState{});
    cache.unbindTextures(gl::kUnitIndexTarget0, lights ? indices.count() : 0);
}

void ForwardPass::run(const RenderTargets& targets, const IndexTargets& indices, const GpuScene& scene,
                      const LightTable& table, const CameraMatrices& camera, const ShadingParameters& shading,
                      const EnvironmentMaps& environment, bool afterPrepass, bool lights, const ShadowMaps* shadows) const {
    // Without a pre-pass there is no depth to test against here: the MSAA target never had one, the
    // single-sample one holds the volume pass's cleared depth. Either way this pass writes its own.
    beginOpaqueShading(targets, shading, afterPrepass, perSample_);
    const gl::Program& program = bindInputs(targets, indices, table, camera, shading, environment, lights, shadows);
    scene.draw(program, DrawFilter::Opaque, true, &camera, variantKey(program, table, shading, environment, lights));
    unbindInputs(indices, lights);
    checkGl("LIDR forward pass");
}

void ForwardPass::runTransparent(const RenderTargets& targets, const IndexTargets& indices, const GpuScene& scene,
                                 const LightTable& table, const CameraMatrices& camera,
                                 const ShadingParameters& shading, const EnvironmentMaps& environment, bool lights,
                                 const ShadowMaps* shadows) const {
    StateCache::current().beginPass(targets.colorPass());
    beginTransparentShading(perSample_);
    const gl::Program& program = bindInputs(targets, indices, table, camera, shading, environment, lights, shadows);
    scene.drawTransparentSorted(program, camera.eye, variantKey(program, table, shading, environment, lights));
    unbindInputs(indices, lights);
    checkGl("LIDR transparent forward pass");
}

}  // namespace lidr
