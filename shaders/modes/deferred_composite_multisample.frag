#version 150 compatibility
#extension GL_ARB_sample_shading : require
// Deferred shading's composite under MSAA (deferred_composite.frag once a sample): the sample's light-independent
// terms, directional lights and light sum through the output transform, into the MSAA colour target the frame's
// resolve then averages (the forward modes' order). Samples without a surface keep the background.
#include "shading.glsl"
#include "g_buffer_multisample.glsl"

uniform sampler2DMS uLightSumSamples;

void main() {
    LidrSurface s;
    if (!lidrGBufferSampleSurface(s)) discard;
    vec3 lights = texelFetch(uLightSumSamples, ivec2(gl_FragCoord.xy), gl_SampleID).rgb;
    gl_FragColor = lidrOutput(lidrAmbient(s) + lidrDirectionalLights(s) + lights, 1.0);
}
