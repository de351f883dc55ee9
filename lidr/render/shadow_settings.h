#pragma once
// Shadows as a frame asks for them (ShadingParameters::shadows; issue 30, doc/architecture.md "Shadows"). Which
// lights cast is each light's PointLight::castsShadow; these say how.
namespace lidr {

// Where LIDR applies a light's shadow (the paper's two ways). Every other mode looks up in its shading.
enum class ShadowLookup {
    // The volume pass's exact test discards surface points the map shadows: the light takes no slot there and
    // is not shaded (the paper's first way). The forward pass then looks up the lights that are left at the
    // point it shades, so the image is the reference's; transparent layers and front-face lists look up there.
    VolumePass,
    // Only the forward pass looks up, by index (the paper's second way): shadowed pixels keep their slots.
    ForwardPass,
};

struct ShadowAtlasOptions {
    int size = 2048;     // texels per side of the atlas
    int tileSize = 512;  // texels per side of one light's map: (size / tileSize)^2 maps at most
    // The maps' depths are pushed back by slopeBias x each occluder's depth slope per texel (computed in the
    // map's shader from screen derivatives; ES 2.0's depth-texture maps: glPolygonOffset): a surface slanted
    // towards its light does not shadow itself wherever a lookup's texels lie within slopeBias texels of the
    // point (the nearest texel is within 0.71, the filtered lookup's four within 1.5).
    float slopeBias = 2.0f;
    // The atlas as RGBA8 holding each texel's 24-bit depth (written by the map's shader, a depth renderbuffer
    // for the test) instead of a depth texture: what contexts without depth textures get (ES 2.0 without
    // OES_depth_texture); this forces it elsewhere (tests, comparisons).
    bool packedDepth = false;
};

struct ShadowSettings {
    bool enabled = false;  // off: no maps, no lookups, whatever the lights' castsShadow say
    ShadowAtlasOptions atlas{};
    // A point is shadowed when an occluder lies nearer to the light than it by more than biasTexels shadow-map
    // texels (a texel's footprint at the point's distance: what a surface slanted towards the light gains in
    // depth across a texel) plus biasRange x the light's range (shadow_lookup.glsl; doc/architecture.md).
    float biasTexels = 1.0f;
    float biasRange = 0.001f;
    bool filtered = false;  // the four nearest texels weighted bilinearly (filtered edges) instead of the nearest
    // ForwardPass by default: the same image, and on llvmpipe 1.07x faster a frame than VolumePass, whose
    // shorter lists pay where slots are scarce (a fixed budget) (doc/shadows.md, "LIDR: ...").
    ShadowLookup lidrLookup = ShadowLookup::ForwardPass;
};

}  // namespace lidr
