#version 150 compatibility
#extension GL_ARB_sample_shading : require
// GBufferMultisample::beginAccumulation, once a sample: the window depth of the surface the sample stores (the pixel
// centre's, g_buffer.glsl's hi + lo split; 1 where it has none) into the light sum's depth, which the light volumes
// test against.
uniform sampler2DMS uGBufferSamples2;

void main() {
    vec4 t2 = texelFetch(uGBufferSamples2, ivec2(gl_FragCoord.xy), gl_SampleID);
    gl_FragDepth = t2.z > 1.5 ? 1.0 : t2.z + t2.w * (1.0 / 2048.0);
    gl_FragColor = vec4(0.0);
}
