#version 150 compatibility
// GBufferMultisample::markEdgePixels, once a pixel into the single-sample edge mask: 1 where the pixel's samples hold
// different surfaces (an edge, or a surface beside the background), 0 where every sample holds sample 0's.
uniform sampler2DMS uGBufferSamples0;
uniform sampler2DMS uGBufferSamples1;
uniform sampler2DMS uGBufferSamples2;
uniform sampler2DMS uGBufferSamples3;
uniform int uSamples;

bool sameSurface(ivec2 texel, int k, vec4 t0, vec4 t1, vec4 t2, vec4 t3) {
    return texelFetch(uGBufferSamples0, texel, k) == t0 && texelFetch(uGBufferSamples1, texel, k) == t1 &&
           texelFetch(uGBufferSamples2, texel, k) == t2 && texelFetch(uGBufferSamples3, texel, k) == t3;
}

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 t0 = texelFetch(uGBufferSamples0, texel, 0);
    vec4 t1 = texelFetch(uGBufferSamples1, texel, 0);
    vec4 t2 = texelFetch(uGBufferSamples2, texel, 0);
    vec4 t3 = texelFetch(uGBufferSamples3, texel, 0);
    for (int k = 1; k < uSamples; ++k)
        if (!sameSurface(texel, k, t0, t1, t2, t3)) {
            gl_FragColor = vec4(1.0);
            return;
        }
    gl_FragColor = vec4(0.0);
}
