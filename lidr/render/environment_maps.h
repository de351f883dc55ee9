#pragma once
// The environment light on the GPU (issue 39), one per renderer like its shadow maps: the frame's Environment
// (ShadingParameters::environment) uploaded on first use and again when it changes, its lookup decided by what
// the context offers, and shading.glsl's uniforms and textures bound for every shading program:
//   - the prefiltered cube (lidr::storeEnvironment: half-float RGB where the context has float textures, else RGBM
//     in RGBA8), trilinear, faces clamped at their edges, levels down to 1 x 1;
//   - the split-sum table (half floats, or two bytes per value in RGBA8), bilinear;
//   - 9 spherical-harmonic coefficients times the intensity, as uniforms.
// The lookup (shading_variants.h, EnvironmentLookup) is compiled into the shading programs as LIDR_ENVIRONMENT:
// Lod where the context has ARB/EXT_shader_texture_lod, else Bias (textureCube's bias over the implicit LOD);
// DiffuseOnly where the frame's texture units are taken (bindings.h) or asked for. doc/colour.md, "Environment".
#include <memory>
#include <string>

#include "lidr/gl/gl_info.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/render/renderer.h"
#include "lidr/render/shading_variants.h"
#include "lidr/scene/environment.h"

namespace lidr {

class EnvironmentMaps {
public:
    // floatTextures false: RGBA8 storage even where the context has float textures (a renderer's
    // forceFixedLightTable: the path of contexts without them). Half floats need linear filtering of them
    // (GlInfo::halfFloatLinear: desktop float textures, ES OES_texture_half_float + _linear).
    EnvironmentMaps(const GlInfo& info, bool floatTextures);
    // The frame's environment: uploaded where it is another Environment than the last frame's (the intensity is a
    // uniform), the lookup chosen. indexTargets: the index targets LIDR's forward pass binds this frame (0 for
    // the other modes), which on a context with at most 18 texture units share the environment's units.
    void prepare(const EnvironmentLight& light, int indexTargets = 0);
    EnvironmentLookup lookup() const { return lookup_; }
    bool rgbm() const { return storage_ == EnvironmentStorage::Rgbm8; }
    // shadingVariantKey's environment bits for `program` (0 where it does not call lidrAmbient).
    uint32_t variantKey(const gl::Program& program) const;
    // Binds the textures to their units and sets the uniforms, where the program declares them. Every shading
    // program gets the sampler units, environment or not (a sampler left on unit 0 may clash with another type).
    void bind(const gl::Program& program) const;
    // "default, lod, half-float cube 128 x 128 x 6, 5 levels, intensity 1" / "none" / with why the specular term
    // was left out; FrameStats::environment.
    std::string describe() const;
    // What the GPU holds (null before the first environment): the CPU model reads the same values.
    const StoredEnvironment* stored() const { return stored_.get(); }
    int specularUnit() const { return specularUnit_; }
    int splitSumUnit() const { return splitSumUnit_; }
    // The lookup a context gives an environment asked for with `choice`, and the reason when it is not Lod.
    static EnvironmentLookup lookupFor(const GlInfo& info, EnvironmentLight::Lookup choice, std::string* reason = nullptr);

private:
    void upload(const Environment& environment);
    GlInfo info_;
    EnvironmentStorage storage_ = EnvironmentStorage::HalfFloat;
    int specularUnit_ = 0, splitSumUnit_ = 0;
    std::shared_ptr<const Environment> uploaded_;  // what the textures hold (kept alive: identity)
    std::unique_ptr<StoredEnvironment> stored_;
    gl::Texture cube_, splitSum_;
    EnvironmentLookup lookup_ = EnvironmentLookup::None;
    float intensity_ = 0.0f;
    std::string reason_;  // why the lookup is not Lod
};

}  // namespace lidr
