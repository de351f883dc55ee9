#version 150 compatibility
// GBufferMultisample::readSample (tests): one sample's stored window depth (1 where it has no surface; g_buffer.glsl's
// hi + lo split) and its light count (the light sum's alpha), a pixel each.
uniform sampler2DMS uGBufferSamples2;
uniform sampler2DMS uLightSumSamples;
uniform int uSample;
uniform float uHasLightSum;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 t2 = texelFetch(uGBufferSamples2, texel, uSample);
    float depth = t2.z > 1.5 ? 1.0 : t2.z + t2.w * (1.0 / 2048.0);
    float count = uHasLightSum > 0.5 ? texelFetch(uLightSumSamples, texel, uSample).a : 0.0;
    gl_FragColor = vec4(depth, count, 0.0, 1.0);
}
