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
    lidrGBufferDecode(texelFetch(uGBufferSamples0, texel, gl_SampleID), texelFetch(uGBufferSamples1, texel, gl_SampleID),
                      t2, texelFetch(uGBufferSamples3, texel, gl_SampleID), (vec2(texel) + 0.5) * uGBufferInvSize, s);
    return true;
}
