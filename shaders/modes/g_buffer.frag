#version 120
// The deferred modes' geometry pass: the surface lidrSurface() computes, into the four G-buffer targets
// (g_buffer.glsl has the layout), drawn with depth EQUAL after the depth pre-pass.
#include "shading.glsl"
#include "g_buffer.glsl"
uniform mat4 uViewProj;

void main() {
    LidrSurface s = lidrSurface();
    // The window depth from the interpolated position at full precision (gl_FragCoord.z is mediump on ES 2.0).
    vec4 clip = uViewProj * vec4(s.position, 1.0);
    float depth = clamp(clip.z / clip.w * 0.5 + 0.5, 0.0, 1.0);
    gl_FragData[0] = vec4(s.albedo, s.alpha);
    gl_FragData[1] = vec4(s.f0, lidrF90(s));
    gl_FragData[2] = vec4(lidrOctahedralEncode(s.normal), lidrSplitDepth(depth));
    gl_FragData[3] = vec4(s.emission, s.occlusion);
}
