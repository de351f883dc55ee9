#version 120
// A shadow map without depth textures (ShadowAtlas::packed: ES 2.0 without OES_depth_texture): each texel's
// window depth as a 24-bit number in R, G, B (high byte first), as depth_rgba8.frag packs it. The depth is
// computed here from the interpolated world position, not read from gl_FragCoord.z, which GLSL ES 1.00 declares
// mediump (about 11 bits on Mesa); the slope bias glPolygonOffset gives the depth-texture maps is added here
// from the depth's screen derivatives (GLSL 1.20; ES: OES_standard_derivatives, without which the maps have the
// constant bias alone). Needs fp32 fragment floats.
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
    // min: 16777215.5 rounds to 2^24 in fp32, which would pack as (256, 0, 0)
    float v = min(floor(clamp(z, 0.0, 1.0) * 16777215.0 + 0.5), 16777215.0);
    float r = floor(v / 65536.0);
    float rest = v - r * 65536.0;
    float g = floor(rest / 256.0);
    float b = rest - g * 256.0;
    gl_FragColor = vec4(r, g, b, 255.0) / 255.0;
}
