#version 120
// DepthSpanPass: the MSAA pre-pass, drawn over the opaque meshes into a multisampled float target (depth LESS
// with writes), so each sample ends with what its own (nearest) surface's fragment writes. A fragment (run once per pixel and
// primitive, at the pixel centre, where the forward pass shades that primitive too) writes how far its depth
// lies past (r) and before (g) an anchor: the pixel centre's single-sample depth, or 0 and 1 where the centre
// sees no surface. Samples no surface covers keep 0. The resolve averages: times the sample count, each channel
// bounds every sample's, so the volume pass knows the depths [near, far] the pixel's samples shade.
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
varying vec3 vWorldPos;        // interpolated as the forward pass interpolates it: the point it shades

void main() {
#ifdef LIDR_ALPHA_MASK
    lidrAlphaTest(lidrBaseColor().a);
#endif
    vec4 clip = uViewProj * vec4(vWorldPos, 1.0);
    float d = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
#ifdef LIDR_CENTRE_PACKED
    float centre = lidrUnpackDepthUnits(texture2D(uDepth, gl_FragCoord.xy * uInvTargetSize)) / kLidrDepthUnits;
#else
    float centre = texture2D(uDepth, gl_FragCoord.xy * uInvTargetSize).r;
#endif
    vec2 excess = centre >= 1.0 ? vec2(d, 1.0 - d) : vec2(max(d - centre, 0.0), max(centre - d, 0.0));
    gl_FragColor = vec4(excess * uStoreScale, 0.0, 1.0);
}
