#version 120
// DepthSpanPass::readSampleDepths (tests, evaluation): four samples' shaded view distances a pixel, one per channel
// (0: the sample has no surface), from uFirstSample on. Compiled as GLSL 1.50 (perSampleGlsl150).
uniform sampler2DMS uSampleDistances;
uniform int uFirstSample;
uniform int uSampleCount;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 d = vec4(0.0);
    for (int c = 0; c < 4; ++c)
        if (uFirstSample + c < uSampleCount) d[c] = texelFetch(uSampleDistances, texel, uFirstSample + c).r;
    gl_FragColor = d;
}
