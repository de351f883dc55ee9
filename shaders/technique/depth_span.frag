#version 120
// DepthSpanPass: the MSAA pre-pass, drawn over the opaque meshes into a multisampled float target (depth LESS
// with writes), so each sample ends with what its own (nearest) surface's fragment writes. A fragment (run once per pixel and
// primitive, at the pixel centre, where the forward pass shades that primitive too) writes how far its depth
// lies past (r) and before (g) an anchor: the pixel centre's single-sample depth, or 0 and 1 where the centre
// sees no surface. Samples no surface covers keep 0. The resolve averages: times the sample count, each channel
// bounds every sample's, so the volume pass knows the depths [near, far] the pixel's samples shade.
//   LIDR_SPAN_SIDES (LIDR's lists): two targets. The first's b/a: 1 where the sample lies past / before the centre
//   by more than uSideMargin; the second: per side (rg past, ba before) x and x^2, x = the sample's view distance
//   from the centre's (0 where it sees none) times uMomentScale, so the resolve gives each side's count and first
//   two moments, and the volume pass Samuelson's bounds on the side's samples (DepthSpanPass::sideBounds).
//   LIDR_SAMPLE_DISTANCES (GL 3.2, a multisample R32F texture, nothing resolved): the point's view distance, which
//   the volume pass reads per sample; no centre depth is needed.
#ifdef LIDR_ALPHA_MASK  // the material variant of a MASK material: cut out as the pre-pass and the shading do
#include "output_transform.glsl"
#include "material.glsl"
#endif
#ifdef LIDR_CENTRE_PACKED
#include "depth_pack.glsl"
uniform sampler2D uDepth;      // the centre's depth packed in RGBA8 (tiled forward's pre-Z copy, depth_pack.glsl)
#else
uniform sampler2D uDepth;      // the single-sample pre-pass depth (the pixel centre's surface)
#endif
uniform vec2 uInvTargetSize;
uniform mat4 uViewProj;
uniform float uStoreScale;     // half floats keep small differences better scaled up
#ifdef LIDR_SPAN_SIDES
uniform vec2 uDepthToDistance; // window depth d -> view distance x / (d + y)
uniform float uMomentScale;
uniform float uSideMargin;
#endif
varying vec3 vWorldPos;        // interpolated as the forward pass interpolates it: the point it shades

void main() {
#ifdef LIDR_ALPHA_MASK
    lidrAlphaTest(lidrBaseColor().a);
#endif
    vec4 clip = uViewProj * vec4(vWorldPos, 1.0);
#ifdef LIDR_SAMPLE_DISTANCES
    gl_FragData[0] = vec4(clip.w, 0.0, 0.0, 1.0);
#else
    float d = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
#ifdef LIDR_CENTRE_PACKED
    float centre = lidrUnpackDepthUnits(texture2D(uDepth, gl_FragCoord.xy * uInvTargetSize)) / kLidrDepthUnits;
#else
    float centre = texture2D(uDepth, gl_FragCoord.xy * uInvTargetSize).r;
#endif
    vec2 excess = centre >= 1.0 ? vec2(d, 1.0 - d) : vec2(max(d - centre, 0.0), max(centre - d, 0.0));
#ifdef LIDR_SPAN_SIDES
    // The side: past the centre (or any surface where the centre sees none), before it; within uSideMargin of
    // the centre's depth the volume pass's centre test covers the sample.
    bool centreSurface = centre < 1.0;
    vec2 onSide = vec2((centreSurface ? d - centre : d) > uSideMargin ? 1.0 : 0.0,
                       centreSurface && centre - d > uSideMargin ? 1.0 : 0.0);
    float centreDistance = centreSurface ? uDepthToDistance.x / (centre + uDepthToDistance.y) : 0.0;
    float x = (clip.w - centreDistance) * uMomentScale;
    vec2 past = onSide.x * vec2(max(x, 0.0), x * x), before = onSide.y * vec2(max(-x, 0.0), x * x);
    gl_FragData[0] = vec4(excess * uStoreScale, onSide);
    gl_FragData[1] = vec4(past, before);
#else
    gl_FragData[0] = vec4(excess * uStoreScale, 0.0, 1.0);
#endif
#endif
}
