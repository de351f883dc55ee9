#version 120
// The output transform applied to a finished linear frame: for modes that sum light in the framebuffer
// (multi-pass forward's additive blending), where no single shader sees a pixel's whole sum.
// LIDR_FRAME_PER_SAMPLE (GLSL 1.50 with ARB_sample_shading, lidr/render/present.h): the frame is a multisample
// texture, each sample transformed on its own, as the single-pass modes transform each sample they shade.
#include "output_transform.glsl"
#ifdef LIDR_FRAME_PER_SAMPLE
uniform sampler2DMS uFrame;
#else
uniform sampler2D uFrame;
#endif
varying vec2 vTexCoord;

void main() {
#ifdef LIDR_FRAME_PER_SAMPLE
    vec4 linearColor = texelFetch(uFrame, ivec2(gl_FragCoord.xy), gl_SampleID);
#else
    vec4 linearColor = texture2D(uFrame, vTexCoord);
#endif
    gl_FragColor = lidrOutput(linearColor.rgb, linearColor.a);
}
