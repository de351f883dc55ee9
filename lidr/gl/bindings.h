#pragma once
// Every texture unit and vertex attribute slot lidr's programs use, in one place. A unit is shared only by
// passes that never run in the same draw; every sampler of one program has its own unit (two sampler types
// on one unit make draws fail, so unused samplers are pointed at their own units too).
#include "lidr/base/gl_types.h"

namespace lidr::gl {

enum TextureUnit : int {
    // LIDR forward pass: index target i on unit kUnitIndexTarget0 + i (up to 8: units 0..7).
    kUnitIndexTarget0 = 0,
    kUnitIndexTargetLast = 7,
    // Light volume pass, sphere tests: the copy of the pre-pass depth; sphere-span (and sphere-ray beside it): the
    // MSAA samples' depth spans (lidr/technique/depth_span_pass.h), which that pass draws reading the copy.
    kUnitDepthCopy = 0,
    kUnitDepthSpans = 1,
    kUnitDepthSpanSides = 2,  // sphere-span: the side moments beside the spans
    // Light volume pass drawing pixel lists (tests/pixel_list_geometry.h): the list step and the colour table.
    kUnitPixelListStep = 0,
    kUnitPixelListColors = 1,
    // Tiled forward: the tile grid and the light list (lidr/modes/light_grid.h).
    kUnitTileGrid = 0,
    kUnitTileList = 1,
    // Clustered forward: the cluster grid and the light list (lidr/modes/cluster_grid.h).
    kUnitClusterGrid = 0,
    kUnitClusterList = 1,
    // Tile depth bounds: the reduction input, then the min and max tile textures of the depth-bounds pass.
    kUnitReductionInput = 0,
    kUnitTileDepthMin = 1,
    kUnitTileDepthMax = 2,
    // Deferred modes: the four G-buffer targets (units 2..5, above the tile grid's) and the lights' sum.
    kUnitGBuffer0 = 2,
    kUnitLightSum = 6,
    // Every shading pass: the light table (lidr/render/light_table.h) above the index targets.
    kUnitLightPosRadius = 8,
    kUnitLightColor = 9,
    kUnitLightPosRadiusLow = 10,
    // Every shading pass: the material's base colour texture.
    kUnitMaterial = 11,
    // The other material textures, bound only by the shader variants that read them (lidr/render/material_variants.h);
    // a context with fewer units draws the material without the textures that do not fit (doc/colour.md).
    kUnitEmissive = 12,
    kUnitMetallicRoughness = 13,
    kUnitOcclusion = 14,
    kUnitNormal = 15,
    // The RGBA8 G-buffer's fifth target (lidr/modes/g_buffer_unorm8.h): the emissive texture's unit, which the
    // deferred lighting passes never bind (they read no material texture).
    kUnitGBuffer4 = kUnitEmissive,
    // Shading passes and LIDR's volume pass with shadows: the shadow atlas (lidr/render/shadow_maps.h), above
    // everything else where the context has more than 16 units; on 16 (WebGL's usual count) shadows need the
    // float light table and take the fixed table's unit (ShadowMaps::unit).
    kUnitShadowAtlas = 16,
    kUnitShadowAtlasOn16 = kUnitLightPosRadiusLow,
    // Every shading pass with an environment light (lidr/render/environment_maps.h): the prefiltered cube and the
    // split-sum table, above the shadow atlas where the context has more than 18 units; with fewer (WebGL's usual
    // 16) on the two highest index-target units, which only LIDR frames with more than 6 index targets (budget 16
    // at 16-bit indices) use: those frames take the environment's diffuse term alone (doc/colour.md). So the
    // environment never raises the units a shading pass needs (12).
    kUnitEnvironmentSpecular = 17,
    kUnitEnvironmentSplitSum = 18,
    kUnitEnvironmentSpecularLow = 6,
    kUnitEnvironmentSplitSumLow = 7,
    // LIDR's opaque pass under MSAA: the pre-pass's per-sample distances, four samples a texel (VisibleSamples: 19
    // samples 0-3, 20 samples 4-7), above the environment; only where the context has more units than that
    // (desktop GL 3.2+, where the distances exist at all).
    kUnitSampleDistances = 19,
    // FramePresenter: the frame.
    kUnitPresentedFrame = 0,
    // The highest unit a shading pass binds (capability checks).
    kUnitHighestShading = kUnitMaterial,
};

// Vertex attribute slots, bound before linking (no queries needed).
enum Attribute : GLuint {
    kPosition = 0,
    kNormal = 1,
    kTexCoord = 2,
    kVolumeSlot = 3,  // light volume batches: the copy a vertex belongs to (lidr/technique/light_volume_pass.h)
    kTexCoord1 = 4,   // scene geometry: the second texture coordinate set (material variants that read it)
    kTangent = 5,     // scene geometry: the tangent (material variants with a normal texture)
};

}  // namespace lidr::gl
