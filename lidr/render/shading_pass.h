#pragma once
// The shading pass every mode shares once it knows its lights (LIDR's forward pass, tiled and clustered forward, the
// reference, multi-pass's ambient pass): where surfaces are shaded, with which depth test, and the per-frame
// uniforms of shading.glsl. Each mode then binds its own light lists and draws.
#include <vector>

#include "lidr/gl/frame_timer.h"
#include "lidr/gl/gl_resources.h"
#include "lidr/gl/gl_state.h"
#include "lidr/gl/render_targets.h"
#include "lidr/render/environment_maps.h"
#include "lidr/render/light_table.h"
#include "lidr/render/renderer.h"
#include "lidr/render/shadow_maps.h"
#include "lidr/scene/camera.h"

namespace lidr {

// Begins the opaque shading pass in targets.colorPass(): colour cleared to the background; depth EQUAL against
// the pre-pass depth (one shaded fragment per pixel), or, where that target had no pre-pass, depth and stencil
// cleared and LEQUAL with depth writes, so that, as with EQUAL, the last fragment drawn at the nearest depth
// stays (lidr/render/gpu_scene.h: DrawOrder). sampleShading: every sample shaded (the per-sample MSAA paths).
void beginOpaqueShading(const RenderTargets& targets, const ShadingParameters& shading, bool afterPrepass,
                        bool sampleShading = false);
// The same in `pass` (its own clear replaced): a target beside the RenderTargets sharing their depth-stencil.
void beginOpaqueShading(PassDescription pass, const ShadingParameters& shading, bool afterPrepass,
                        bool sampleShading = false);

// The state transparent layers are drawn with, in every mode: over the opaque depth, no depth writes,
// source-alpha blending, destination alpha kept.
RenderState transparentBlendState();
// Applies transparentBlendState() (with per-sample shading as asked) for the layers drawn next.
void beginTransparentShading(bool sampleShading = false);

// Sets output_transform.glsl's uniforms (every shading program's, and the multi-pass encode pass's).
void setOutputUniforms(const gl::Program& program, const OutputTransform& output);
// Sets shading.glsl's directional-light uniforms (lidrDirectionalLights) where the program declares them.
void setDirectionalLightUniforms(const gl::Program& program, const std::vector<DirectionalLight>& lights);
// Sets the per-frame uniforms of shading.glsl (eye, ambient, the directional lights, the output transform, the
// material texture's unit) and binds the frame's environment light (prepared for this frame).
void setShadingUniforms(const gl::Program& program, const CameraMatrices& camera, const ShadingParameters& shading,
                        const EnvironmentMaps& environment);
// The frame's shading variant key of `program` (shading_variants.h: suns, output, environment), for GpuScene::draw.
uint32_t shadingVariantKey(const gl::Program& program, const ShadingParameters& shading, const EnvironmentMaps& environment);
// Uses the program, sets shading.glsl's uniforms and binds the light table to it.
void useShadingProgram(const gl::Program& program, const CameraMatrices& camera, const ShadingParameters& shading,
                       const LightTable& table, const EnvironmentMaps& environment);

// The frame's shadow maps as every mode draws them, before its light table (issue 30): where shadows are on, the
// atlas's texture unit checked next to a `table`-format light table (ShadowMaps::checkUnits); the maps drawn in a
// timed "shadow-maps" pass; stats.shadowCasters and shadowMapsDrawn set. Returns the lights' first atlas tiles for
// LightTable::update (ShadowMaps::update).
const std::vector<int>& drawShadowMaps(ShadowMaps& shadows, FrameTimer& timer, FrameStats& stats, const GpuScene& scene,
                                       const std::vector<PointLight>& lights, const ShadingParameters& shading,
                                       LightTableFormat table);

}  // namespace lidr
