// The deferred modes' G-buffer (lidr/modes/g_buffer.h): four colour targets, written by g_buffer.frag from
// lidrSurface() and read back into the same LidrSurface by the lighting passes, so lidrShadeLight, lidrAmbient and
// the environment run on the values the forward modes compute in place.
//   target 0: albedo (base colour x (1 - metallic)), GGX alpha
//   target 1: F0, F90
//   target 2: the shading normal, octahedral (2 values), the window depth as hi + lo (2 values; see below)
//   target 3: emission, occlusion
// The position comes from the depth: the pixel centre unprojected at the stored window depth. The depth is split
// into hi = floor(d 2048) / 2048 (exact in a half float) and lo = the remainder x 2048, so a 16-bit float target
// holds it to about 2^-22 (a 32-bit one holds it whole). A cleared pixel has hi = 2: no surface.
// LIDR_GBUFFER_UNORM8: the RGBA8 G-buffer's layout and lidrGBufferSurface instead (g_buffer_unorm8.glsl).
uniform sampler2D uGBuffer0;
uniform sampler2D uGBuffer1;
uniform sampler2D uGBuffer2;
uniform sampler2D uGBuffer3;
uniform vec2 uGBufferInvSize;   // 1 / target size in pixels
uniform mat4 uInverseViewProj;  // clip -> world

vec2 lidrOctahedralEncode(vec3 n) {
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    vec2 e = n.xy;
    if (n.z < 0.0) e = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
    return e;
}

vec3 lidrOctahedralDecode(vec2 e) {
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
    return normalize(n);
}

vec2 lidrSplitDepth(float d) {
    float hi = floor(d * 2048.0) / 2048.0;
    return vec2(hi, (d - hi) * 2048.0);
}

#ifdef LIDR_GBUFFER_UNORM8
#include "g_buffer_unorm8.glsl"
#else
// The surface from the four targets' texels at a pixel whose centre is at `uv` (0..1): the one decoding of this
// layout, for the single-sample read below and the multisampled one (g_buffer_multisample.glsl).
void lidrGBufferDecode(vec4 t0, vec4 t1, vec4 t2, vec4 t3, vec2 uv, out LidrSurface s) {
    float depth = t2.z + t2.w * (1.0 / 2048.0);
    vec4 world = uInverseViewProj * vec4(uv * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    s.position = world.xyz / world.w;
    s.normal = lidrOctahedralDecode(t2.xy);
    s.toEye = normalize(uEyePosition - s.position);
    s.albedo = t0.rgb;
    s.alpha = t0.a;
    s.f0 = t1.rgb;
#ifdef LIDR_DIELECTRIC_SPECULAR
    s.f90 = t1.a;
#endif
    s.emission = t3.rgb;
    s.occlusion = t3.a;
}

// The surface at this pixel from the G-buffer; false where the pixel has none (the background).
bool lidrGBufferSurface(out LidrSurface s) {
    vec2 uv = gl_FragCoord.xy * uGBufferInvSize;
    vec4 t2 = texture2D(uGBuffer2, uv);
    if (t2.z > 1.5) return false;
    lidrGBufferDecode(texture2D(uGBuffer0, uv), texture2D(uGBuffer1, uv), t2, texture2D(uGBuffer3, uv), uv, s);
    return true;
}
#endif
