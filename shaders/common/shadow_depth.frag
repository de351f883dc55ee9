#version 120
// A shadow map's depth: the fragment's window depth plus ShadowAtlasOptions::slopeBias depth slopes, the slope
// taken here from the depth's screen derivatives, not from glPolygonOffset, whose slope GL lets each
// implementation estimate (softpipe's is small enough to leave acne at grazing incidence where llvmpipe's does
// not). The depth is computed from the interpolated world position, not read from gl_FragCoord.z, which GLSL ES
// 1.00 declares mediump (about 11 bits on Mesa).
// LIDR_SHADOW_PACKED (ShadowAtlas::packed: ES 2.0 without OES_depth_texture): the depth as a 24-bit number in R,
// G, B (high byte first), as depth_rgba8.frag packs it; needs fp32 fragment floats, and on ES
// OES_standard_derivatives for the slope (without it the maps have the lookup's constant bias alone).
// Otherwise (a depth texture on desktop GL) the depth goes to gl_FragDepth; ES 2.0's depth-texture maps use
// depth_only.frag and polygon offset (gl_FragDepth would need EXT_frag_depth there).
#ifdef LIDR_ALPHA_MASK  // a MASK material's variant: cut out as depth_only.frag does
#include "output_transform.glsl"
#include "material.glsl"
#else
varying vec3 vWorldPos;
#endif
uniform mat4 uViewProj;
uniform float uSlopeBias;  // ShadowAtlasOptions::slopeBias

void main() {
#ifdef LIDR_ALPHA_MASK
    lidrAlphaTest(lidrBaseColor().a);
#endif
    vec4 clip = uViewProj * vec4(vWorldPos, 1.0);
    float z = 0.5 * clip.z / clip.w + 0.5;
#if !defined(GL_ES) || defined(GL_OES_standard_derivatives)
    z += uSlopeBias * max(abs(dFdx(z)), abs(dFdy(z)));
#endif
    z = clamp(z, 0.0, 1.0);
#ifdef LIDR_SHADOW_PACKED
    // min: 16777215.5 rounds to 2^24 in fp32, which would pack as (256, 0, 0)
    float v = min(floor(z * 16777215.0 + 0.5), 16777215.0);
    float r = floor(v / 65536.0);
    float rest = v - r * 65536.0;
    float g = floor(rest / 256.0);
    float b = rest - g * 256.0;
    gl_FragColor = vec4(r, g, b, 255.0) / 255.0;
#else
    gl_FragDepth = z;
    gl_FragColor = vec4(0.0);
#endif
}
