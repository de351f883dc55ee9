#pragma once
// The frame's shading features as shader variants (the Filament / bgfx way, next to material_variants.h): how many
// directional lights the frame has, which tone map and whether the output is sRGB-encoded are compiled into the
// shading programs as defines (LIDR_DIRECTIONAL_LIGHTS, LIDR_TONE_MAP, LIDR_SRGB_OUTPUT) instead of read from
// uniforms, because a SIMD rasteriser runs a uniform branch's both sides, and a uniform-bounded loop's body once,
// under a mask: on llvmpipe the four-sun loop of a frame without a sun was a sixth of LIDR's forward pass on the
// hall (doc/benchmarks.md). The key's bits lie above the material bits; GpuScene::draw ORs the two and compiles
// each combination on first use (gl::Program::variant). A program drawn without a key (0) reads the uniforms, as
// every program that is not drawn through GpuScene does.
#include <cstddef>
#include <cstdint>

#include "lidr/gl/gl_resources.h"
#include "lidr/gl/shader_source.h"
#include "lidr/render/output_transform.h"

namespace lidr {

// The key of `program` for a frame with `directionalLights` suns and `output`: 0 where the program uses neither
// shading.glsl's directional lights nor output_transform.glsl's lidrOutput (depth passes, a material shader of its own).
uint32_t shadingVariantKey(const gl::Program& program, size_t directionalLights, const OutputTransform& output);
// LIDR's forward programs (lidr_lights.glsl): whether the frame numbers its lights by screen region
// (LidrOptions::regionalIndices), compiled in as LIDR_REGION_MAP 0 or 1 instead of read from uLidrRegionMap.w,
// whose branch a SIMD rasteriser runs (a texture fetch a pixel) in every frame. 0 for a program without the map.
uint32_t regionMapVariantKey(const gl::Program& program, bool regions);
// How the frame's environment light is looked up (shading.glsl's LIDR_ENVIRONMENT): not at all (a frame without
// one runs the code it ran before environments existed), its specular cube at an explicit LOD (textureCubeLod),
// at a mip bias over the implicit LOD (contexts without ARB/EXT_shader_texture_lod), or its diffuse term alone
// (no texture: where its units are taken). rgbm: the cube and table are RGBA8 (RGBM, 16-bit pairs), else half floats.
enum class EnvironmentLookup { None = 0, Lod = 1, Bias = 2, DiffuseOnly = 3 };
const char* environmentLookupName(EnvironmentLookup lookup);  // "none", "lod", "bias", "diffuse-only"
// 0 where the program does not call lidrAmbient (its uAmbient is not used: depth passes, multi-pass's light passes).
uint32_t environmentVariantKey(const gl::Program& program, EnvironmentLookup lookup, bool rgbm);
// The defines of a key (empty for 0).
ShaderDefines shadingVariantDefines(uint32_t key);

}  // namespace lidr
