#pragma once
// Pass 3 of LIDR: the ordinary forward pass. Each fragment unpacks its light indices from the index
// targets (the scheme's unpack shader) and shades with those lights from the light table.
#include <map>
#include <string>

#include "lidr/scene/camera.h"
#include "lidr/gl/gl_state.h"
#include "lidr/render/depth_prepass.h"
#include "lidr/render/gpu_scene.h"
#include "lidr/render/light_table.h"
#include "lidr/technique/light_volume_pass.h"
#include "lidr/technique/packing_scheme.h"
#include "lidr/gl/render_targets.h"
#include "lidr/render/renderer.h"
#include "lidr/render/shading_pass.h"
#include "lidr/render/shadow_maps.h"

namespace lidr {

// The MSAA pre-pass's view distance per sample (drawn depth LEQUAL), four samples a texel
// (DepthSpanPass::packedTexture: samples 0-3, then 4-7): with it the opaque pass skips the light list of every
// fragment that keeps no sample (LIDR_VISIBLE_SAMPLES in lidr_lights.glsl). Needs GLSL 1.50 and texture units
// gl::kUnitSampleDistances and up, one a texture.
struct VisibleSamples {
    const gl::Texture* distances[2] = {nullptr, nullptr};
    int samples = 0;
    int textureCount() const { return (samples + 3) / 4; }
    explicit operator bool() const { return distances[0] != nullptr && samples > 0; }
};

// When LIDR's opaque pass under MSAA skips hidden fragments' lists (LidrOptions::hiddenFragmentSkip,
// --msaa-skip-hidden).
enum class HiddenFragmentSkip { Auto, On, Off };
const char* hiddenFragmentSkipName(HiddenFragmentSkip s);           // "auto", "on", "off"
HiddenFragmentSkip parseHiddenFragmentSkip(const std::string& name);  // throws lidr::Error naming the choices

class ForwardPass {
public:
    // perSample: the index targets are multisample textures read per sample (GLSL 1.50 compatibility +
    // ARB_sample_shading); the pass then shades every sample.
    // materialShader: a fragment shader of the program's own (GLSL 1.20, `#include "lidr_lights.glsl"` for
    // the light list, see doc/embedding.md) instead of lidr_forward.frag; empty: lidr_forward.frag. It is
    // built with the scheme's unpack file and the light table's defines, like the built-in one; a compile
    // or link error throws GlError with the log and the line of the material shader. depth: the depth precision
    // lidr_forward.frag emulates (LidrOptions::emulatedDepthBits; not with a material shader).
    ForwardPass(const PackingScheme& scheme, const LightTable& table, bool perSample = false,
                const std::string& materialShader = {}, DepthEmulation depth = {});
    // Clears colour and draws opaque geometry into targets.bindColor(): depth EQUAL against a pre-pass
    // depth there, or LEQUAL with depth writes when that target had no pre-pass (so that, as with EQUAL,
    // the last fragment drawn at the nearest depth stays).
    // lights false: the frame has no light to read (none reaches a visible surface); the program built for
    // that (LIDR_NO_LIGHTS, on first use) reads no index texture and no light table.
    // shadows (active: the frame has casters): the shadowed twin of the program (LIDR_SHADOWS and the maps'
    // defines, built on first use) looks each listed light's shadow up by its index (the paper's second way;
    // lidrLightShadow in lidr_lights.glsl), the table holding the lights' tiles (LightTable::update).
    // environment: the frame's environment light, prepared for `indices` (EnvironmentMaps::prepare).
    // visible (after an MSAA pre-pass that stored them): fragments that keep no sample skip their list; the image
    // is the same (the twin with LIDR_VISIBLE_SAMPLES, built on first use).
    void run(const RenderTargets& targets, const IndexTargets& indices, const GpuScene& scene,
             const LightTable& table, const CameraMatrices& camera, const ShadingParameters& shading,
             const EnvironmentMaps& environment, bool afterPrepass = true, bool lights = true,
             const ShadowMaps* shadows = nullptr, VisibleSamples visible = {}) const;
    // Transparent geometry over the opaque image, back to front, alpha blended, depth-tested against the
    // opaque depth without writing it; `indices` must come from a front-face volume pass.
    void runTransparent(const RenderTargets& targets, const IndexTargets& indices, const GpuScene& scene,
                        const LightTable& table, const CameraMatrices& camera, const ShadingParameters& shading,
                        const EnvironmentMaps& environment, bool lights = true, const ShadowMaps* shadows = nullptr) const;

private:
    // The program for this frame (lights or not) with its inputs bound.
    const gl::Program& bindInputs(const RenderTargets& targets, const IndexTargets& indices, const LightTable& table,
                                  const CameraMatrices& camera, const ShadingParameters& shading,
                                  const EnvironmentMaps& environment, bool lights, const ShadowMaps* shadows,
                                  VisibleSamples visible = {}) const;
    // The lit program of the frame: program_, or its twin with the shadow and visible-sample defines.
    const gl::Program& litProgram(const ShadowMaps* shadows, const ShadingParameters& shading,
                                  VisibleSamples visible) const;
    // The lit program with `extra` defines (the twins; LIDR_VISIBLE_SAMPLES compiles as GLSL 1.50).
    gl::Program build(const ShaderDefines& extra) const;
    void unbindInputs(const IndexTargets& indices, bool lights, VisibleSamples visible = {}) const;
    gl::Program program_;
    mutable std::map<std::string, gl::Program> twins_;  // by their extra defines, built on first use
    ShaderDefines defines_;
    std::string unpackFile_, materialShader_, name_;
    DepthEmulation depth_;
    mutable gl::Program lightless_;  // built on the first frame without lights
    std::string lightlessVertex_, lightlessFragment_, lightlessName_;
    bool perSample_ = false;
    int maxLights_ = 0;
};

}  // namespace lidr
