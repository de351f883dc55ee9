#version 120
// The RGBA8 G-buffer's geometry pass (g_buffer_unorm8.glsl has the layout): the surface lidrSurface() computes,
// encoded into the five targets, drawn with depth EQUAL after the depth pre-pass. A context with fewer than five
// draw buffers draws it in several passes: this one writes LIDR_GBUFFER_PASS_TARGETS targets from
// LIDR_GBUFFER_FIRST_TARGET on (lidr/modes/g_buffer_unorm8.h).
#define LIDR_GBUFFER_UNORM8 1
#include "shading.glsl"
#include "g_buffer.glsl"
uniform mat4 uViewProj;

void main() {
    LidrSurface s = lidrSurface();
    // The window depth from the interpolated position at full precision (gl_FragCoord.z is mediump on ES 2.0).
    vec4 clip = uViewProj * vec4(s.position, 1.0);
    vec4 t[5];
    t[0] = vec4(sqrt(s.albedo), sqrt(s.alpha));
    t[1] = vec4(sqrt(s.f0), lidrF90(s));
    t[2] = vec4(lidrGBuffer8Octahedral(s.normal), s.occlusion);
    t[3] = vec4(lidrGBuffer8Depth(clip.z / clip.w * 0.5 + 0.5), 1.0);
    t[4] = lidrGBuffer8SharedExponent(s.emission);
    gl_FragData[0] = t[LIDR_GBUFFER_FIRST_TARGET];
#if LIDR_GBUFFER_PASS_TARGETS > 1
    gl_FragData[1] = t[LIDR_GBUFFER_FIRST_TARGET + 1];
#endif
#if LIDR_GBUFFER_PASS_TARGETS > 2
    gl_FragData[2] = t[LIDR_GBUFFER_FIRST_TARGET + 2];
#endif
#if LIDR_GBUFFER_PASS_TARGETS > 3
    gl_FragData[3] = t[LIDR_GBUFFER_FIRST_TARGET + 3];
#endif
#if LIDR_GBUFFER_PASS_TARGETS > 4
    gl_FragData[4] = t[LIDR_GBUFFER_FIRST_TARGET + 4];
#endif
}
