// The multisampled G-buffer (lidr/modes/g_buffer_multisample.h): g_buffer.glsl's layout and decoding, one surface a
// sample, fetched at gl_SampleID (the including file is GLSL 1.50 compatibility with ARB_sample_shading, so its pass
// runs once a sample). The geometry pass ran once a fragment and wrote that fragment's surface, interpolated at the
// pixel centre as the forward modes shade it, to every sample it covered: the position is rebuilt at the pixel
// centre, whatever gl_FragCoord says under per-sample shading.
#include "g_buffer.glsl"
uniform sampler2DMS uGBufferSamples0;
uniform sampler2DMS uGBufferSamples1;
uniform sampler2DMS uGBufferSamples2;
uniform sampler2DMS uGBufferSamples3;

// This sample's surface from the G-buffer; false where the sample has none (the background).
bool lidrGBufferSampleSurface(out LidrSurface s) {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 t2 = texelFetch(uGBufferSamples2, texel, gl_SampleID);
    if (t2.z > 1.5) return false;
    vec4 t0 = texelFetch(uGBufferSamples0, texel, gl_SampleID);
    vec4 t1 = texelFetch(uGBufferSamples1, texel, gl_SampleID);
    vec4 t3 = texelFetch(uGBufferSamples3, texel, gl_SampleID);
    vec2 uv = (vec2(texel) + 0.5) * uGBufferInvSize;
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
    return true;
}
