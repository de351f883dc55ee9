#include "lidr/technique/forward_pass.h"

#include <algorithm>
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

const char* hiddenFragmentSkipName(HiddenFragmentSkip s) {
    switch (s) {
        case HiddenFragmentSkip::On: return "on";
        case HiddenFragmentSkip::Off: return "off";
        default: return "auto";
    }
}

HiddenFragmentSkip parseHiddenFragmentSkip(const std::string& name) {
    for (HiddenFragmentSkip s : {HiddenFragmentSkip::Auto, HiddenFragmentSkip::On, HiddenFragmentSkip::Off})
        if (name == hiddenFragmentSkipName(s)) return s;
    throw Error("unknown --msaa-skip-hidden '" + name + "' (valid: auto, on, off)");
}

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
    const bool visibleSamples =
        std::any_of(extra.begin(), extra.end(), [](const auto& d) { return d.first == "LIDR_VISIBLE_SAMPLES"; });
    if (perSample_ || visibleSamples) {
        vertex = perSampleGlsl150(vertex, perSample_);
        fragment = perSampleGlsl150(fragment, perSample_);
    }
    std::string name = name_;
    for (const auto& d : extra)
        if (d.first == "LIDR_SHADOWS") name += "-shadowed";
    if (visibleSamples) name += "-visible-samples";
    return gl::Program::create(name, vertex, fragment, geometryAttributes());
}

const gl::Program& ForwardPass::litProgram(const ShadowMaps* shadows, const ShadingParameters& shading,
                                           VisibleSamples visible) const {
    ShaderDefines extra;
    if (shadows && shadows->active()) extra = shadows->defines(shading.shadows);
    if (visible) extra.push_back({"LIDR_VISIBLE_SAMPLES", std::to_string(visible.samples)});
    if (extra.empty()) return program_;
    std::string key;
    for (const auto& d : extra) key += d.first + "=" + d.second + " ";
    auto found = twins_.find(key);
    if (found == twins_.end()) found = twins_.emplace(key, build(extra)).first;
    return found->second;
}

const gl::Program& ForwardPass::bindInputs(const RenderTargets& targets, const IndexTargets& indices,
                                           const LightTable& table, const CameraMatrices& camera,
                                           const ShadingParameters& shading, const EnvironmentMaps& environment,
                                           bool lights, const ShadowMaps* shadows, VisibleSamples visible) const {
    if (!lights) {
        if (!lightless_)
            lightless_ = gl::Program::create(lightlessName_, lightlessVertex_, lightlessFragment_, geometryAttributes());
        lightless_.use();
        setShadingUniforms(lightless_, camera, shading, environment);
        return lightless_;
    }
    const gl::Program& program = litProgram(shadows, shading, visible);
    useShadingProgram(program, camera, shading, table, environment);
    if (shadows && shadows->active()) shadows->bind(program, shading.shadows);
    program.setIfDeclared("uLidrMaxLights", maxLights_);
    program.set("uInvViewportSize", glm::vec2(1.0f / targets.width(), 1.0f / targets.height()));
    program.setIfDeclared("uLidrRegionMap", table.regionMapUniform());
    for (int i = 0; i < indices.count(); ++i) {
        indices.texture(i).bind(gl::kUnitIndexTarget0 + i);
        program.set(("uIndexTex" + std::to_string(i)).c_str(), gl::kUnitIndexTarget0 + i);
    }
    if (visible) {
        for (int t = 0; t < visible.textureCount(); ++t) {
            visible.distances[t]->bind(gl::kUnitSampleDistances + t);
            program.set(("uLidrSampleDistances" + std::to_string(t)).c_str(), gl::kUnitSampleDistances + t);
        }
    }
    return program;
}

void ForwardPass::unbindInputs(const IndexTargets& indices, bool lights, VisibleSamples visible) const {
    StateCache& cache = StateCache::current();
    cache.apply(RenderState{});
    cache.unbindTextures(gl::kUnitIndexTarget0, lights ? indices.count() : 0);
    if (visible) cache.unbindTextures(gl::kUnitSampleDistances, visible.textureCount());
}

void ForwardPass::run(const RenderTargets& targets, const IndexTargets& indices, const GpuScene& scene,
                      const LightTable& table, const CameraMatrices& camera, const ShadingParameters& shading,
                      const EnvironmentMaps& environment, bool afterPrepass, bool lights, const ShadowMaps* shadows,
                      VisibleSamples visible) const {
    // Without a pre-pass there is no depth to test against here: the MSAA target never had one, the
    // single-sample one holds the volume pass's cleared depth. Either way this pass writes its own.
    beginOpaqueShading(targets, shading, afterPrepass, perSample_);
    // The skip needs the pre-pass's distances (and compares them with the depth this pass tests EQUAL against).
    if (!lights || !afterPrepass || perSample_ || depth_.bits != 0) visible = {};
    const gl::Program& program = bindInputs(targets, indices, table, camera, shading, environment, lights, shadows, visible);
    scene.draw(program, DrawFilter::Opaque, true, &camera, variantKey(program, table, shading, environment, lights));
    unbindInputs(indices, lights, visible);
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
